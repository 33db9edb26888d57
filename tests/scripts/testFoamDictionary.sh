#!/bin/bash
# OpenFOAM's own foamDictionary must read every dictionary we ship in
# tutorials/ and every ascii file the suite writes (fields, bodyProperties,
# uniform/time). Skipped (77) when OpenFOAM is not installed.
. "$(dirname "$0")/testLib.sh"

if ! command -v foamDictionary > /dev/null 2>&1; then
    echo "foamDictionary not found (Debian package openfoam): skipped"
    exit 77
fi
# foamDictionary only needs to find OpenFOAM's etc/controlDict.
for dir in /usr/share/openfoam /usr/lib/openfoam/openfoam*; do
    [ -f "$dir/etc/controlDict" ] && export WM_PROJECT_DIR="$dir" && break
done

foamRead()
{
    foamDictionary "$1" > "$scratch/foam.out" 2>&1
    if [ $? -eq 0 ]; then pass "foamDictionary reads ${1#$2/}"; else
        fail "foamDictionary reads ${1#$2/}"; tail -n 8 "$scratch/foam.out"
    fi
}

# Every dictionary shipped in the tutorials.
for f in $(find "$SPHVCPM_DIR/tutorials" -path '*/system/*' -type f -o \
                -path '*/constant/*' -type f ! -name '*.stl*' | sort); do
    foamRead "$f" "$SPHVCPM_DIR"
done

# Everything the suite writes, from a run of each tutorial.
for gen in $(find "$SPHVCPM_DIR/tutorials" -name generateParticlesDict | sort); do
    src=$(dirname "$(dirname "$gen")")
    run="$scratch/$(basename "$src")"
    cp -r "$src" "$run"
    # The ascii files are OpenFOAM's format; binary fields are our own.
    sed -i 's/^writeFormat .*/writeFormat ascii;/' "$run/system/controlDict"
    generateParticles -case "$run" > "$run/log" 2>&1 || { fail "generateParticles on $run"; continue; }
    for f in $(find "$run/0" -type f | sort); do
        foamRead "$f" "$scratch"
    done
    # A value read back by OpenFOAM equals what we wrote.
    for props in "$run"/0/*/bodyProperties; do
        t=$(foamDictionary -entry type -value "$props" 2>/dev/null)
        check "foamDictionary reads type of ${props#$scratch/} ($t)" \
            bash -c "[ '$t' = fluid ] || [ '$t' = wall ] || [ '$t' = solid ]"
    done
done

# What the solver writes: a time directory (fields with p, uniform/time
# with the solver's c0), from two steps of the 2D tank.
run="$scratch/solverRun"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D" "$run"
sed -i 's/^writeFormat .*/writeFormat ascii;/; s/^endTime .*/endTime 1e-4;/; s/^writeInterval .*/writeInterval 1e-4;/; /^functions/,$d' \
    "$run/system/controlDict"
(cd "$run" && rm -rf [0-9]* && generateParticles > log.gen 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "sphVcpmFsi writes time 0.0001" [ -f "$run/0.0001/uniform/time" ]
for f in $(find "$run/0.0001" -type f | sort); do
    foamRead "$f" "$scratch"
done
c0=$(foamDictionary -entry c0 -value "$run/0.0001/uniform/time" 2>/dev/null)
check "foamDictionary reads the solver's c0 in uniform/time ($c0)" \
    awk -v c="$c0" 'BEGIN { exit !(c > 40 && c < 50) }'

finish
