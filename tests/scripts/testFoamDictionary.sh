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

finish
