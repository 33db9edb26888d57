#!/bin/bash
# CPU and GPU agree: the coarse 2D dam break (also with a damping zone), the
# 3D dam break tutorial and the 2D and 3D elastic gates (the 2D cases with
# both time schemes) run a short time with -device cpu and -device cuda,
# and their fields and function-object histories are compared. The two
# sum a particle's neighbours in another order (each pair once on the
# host, per particle on the GPU; cells of h and of 2h/3 by default), so
# they agree to round-off grown over
# the steps run, not bit for bit; a wrong term on either side differs by
# orders of magnitude more. Skipped (77) where no GPU can be used.
. "$(dirname "$0")/testLib.sh"
. "$(dirname "$0")/fieldTools.sh"

skipWithoutGpu "the CPU-GPU agreement"

# within <difference> <tolerance>: a finite difference <= tolerance (a nan
# one, from a non-finite value or tables with no rows, fails)
within() { isFinite "$1" "v <= $2"; }

# runBoth <name> <case source> <endTime> [<time scheme>]: the case run to
# endTime on each device, ascii at 17 digits, written only at the end;
# a time scheme given replaces the case's.
runBoth()
{
    local name=$1 source=$2 end=$3 scheme=${4:-} d
    for d in cpu cuda; do
        cp -r "$source" "$scratch/$name.$d"
        rm -rf "$scratch/$name.$d"/[0-9]* "$scratch/$name.$d/postProcessing"
        sed -i "s/^endTime .*/endTime         $end;/; s/^writeInterval .*/writeInterval   $end;/; s/^writeFormat .*/writeFormat     ascii;/; s/^writePrecision .*/writePrecision  17;/" \
            "$scratch/$name.$d/system/controlDict"
        if [ -n "$scheme" ]; then
            sed -i '/^timeScheme /d' "$scratch/$name.$d/system/sphSchemes"
            echo "timeScheme $scheme;" >> "$scratch/$name.$d/system/sphSchemes"
        fi
        (cd "$scratch/$name.$d" && generateParticles > log.generateParticles 2>&1 \
            && sphVcpmFsi -device $d > log.sphVcpmFsi 2>&1)
        check "$name: the $d run succeeds" grep -q '^End' "$scratch/$name.$d/log.sphVcpmFsi"
    done
    grep "Run summary" -A2 "$scratch/$name.cuda/log.sphVcpmFsi"
}

# compareFields <name> <time> <field tolerance pairs...>: every body of the
# time directory, by particle id.
compareFields()
{
    local name=$1 time=$2; shift 2
    local a="$scratch/$name.cpu/$time" b="$scratch/$name.cuda/$time" body
    check "$name: both wrote $time" [ -d "$a" -a -d "$b" ]
    for body in $(cd "$a" && ls -d */ | tr -d /); do
        [ -f "$a/$body/U" ] || continue
        local pairs=("$@")
        while [ ${#pairs[@]} -gt 0 ]; do
            local field=${pairs[0]} tolerance=${pairs[1]}
            pairs=("${pairs[@]:2}")
            [ -f "$a/$body/$field" ] || continue
            bodyTable "$a" "$body" "$field" > "$scratch/t.cpu"
            bodyTable "$b" "$body" "$field" > "$scratch/t.cuda"
            check "$name: $body has the same particles on both" \
                [ "$(wc -l < "$scratch/t.cpu")" = "$(wc -l < "$scratch/t.cuda")" ]
            local diff
            diff=$(maxDifference "$scratch/t.cpu" "$scratch/t.cuda")
            check "$name: $body $field agrees (max |diff| $diff <= $tolerance)" \
                within "$diff" "$tolerance"
        done
    done
}

# compareHistory <name> <file under postProcessing> <relative tolerance>:
# every number of the two files, relative to the column's largest value.
compareHistory()
{
    local name=$1 file=$2 tolerance=$3
    local a="$scratch/$name.cpu/postProcessing/$file" b="$scratch/$name.cuda/postProcessing/$file"
    check "$name: both wrote $file" [ -s "$a" -a -s "$b" ]
    local diff
    diff=$(paste -d ' ' <(grep -v '^#' "$a") <(grep -v '^#' "$b") | awk "$awkFinite"'
        { n = NF/2; rows++; if (NF % 2) bad = 1
          for (i = 1; i <= n; i++) {
            if (!finite($i) || !finite($(n+i))) { bad = 1; continue }
            d = $i - $(n+i); if (d < 0) d = -d; if (d > m[i]) m[i] = d
            s = $i < 0 ? -$i : $i; if (s > big[i]) big[i] = s } }
        END { if (!rows || bad) { print "nan"; exit }
              for (i in m) if (big[i] > 0 && m[i]/big[i] > r) r = m[i]/big[i]
              printf "%.3g\n", r + 0 }')
    check "$name: $file agrees (largest relative diff $diff <= $tolerance)" \
        within "$diff" "$tolerance"
}

# 2D dam break, coarse: 0.1 s, some 400 steps through the collapse.
runBoth damBreak2D "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" 0.1
compareFields damBreak2D 0.1 position 1e-7 U 1e-5 rho 1e-3 p 1e-1
compareHistory damBreak2D energy/0/energy.dat 1e-6
compareHistory damBreak2D wallForce/0/force.dat 1e-4

# The same with the Verlet time scheme.
runBoth damBreak2DVerlet "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" 0.1 verlet
expectIn "damBreak2DVerlet: the GPU ran the Verlet scheme" \
    "$scratch/damBreak2DVerlet.cuda/log.sphVcpmFsi" 'time scheme verlet'
compareFields damBreak2DVerlet 0.1 position 1e-7 U 1e-5 rho 1e-3 p 1e-1
compareHistory damBreak2DVerlet energy/0/energy.dat 1e-6

# With a damping zone over the right half of the tank, both time schemes.
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$scratch/damped"
echo "beach { start (0.1 0 0); end (0.4 0 0); rate 20; }" > "$scratch/damped/constant/dampingZones"
for scheme in symplectic verlet; do
    runBoth damped2D$scheme "$scratch/damped" 0.1 $scheme
    expectIn "damped2D$scheme: the GPU read the zone" \
        "$scratch/damped2D$scheme.cuda/log.sphVcpmFsi" 'beach: from'
    compareFields damped2D$scheme 0.1 position 1e-7 U 1e-5 rho 1e-3 p 1e-1
    compareHistory damped2D$scheme energy/0/energy.dat 1e-6
done

# 3D dam break tutorial (about 170,000 particles): 0.02 s.
runBoth damBreak3D "$SPHVCPM_DIR/tutorials/sphVcpmFsi/damBreak3D" 0.02
compareFields damBreak3D 0.02 position 1e-7 U 1e-5 rho 1e-3 p 1e-1

# The 2D elastic gate, with its solid sub-cycled on the host: 0.05 s, the
# water already pushing the gate.
runBoth gate2D "$SPHVCPM_DIR/tutorials/sphVcpmFsi/damBreakElasticGate2D" 0.05 symplectic
compareFields gate2D 0.05 position 1e-7 U 1e-5 rho 1e-3 p 1e-1 displacement 1e-8
compareHistory gate2D gateTip/0/displacement.dat 1e-4

# The 2D gate with the Verlet scheme: the solid sub-cycled over whole steps.
runBoth gate2DVerlet "$SPHVCPM_DIR/tutorials/sphVcpmFsi/damBreakElasticGate2D" 0.05 verlet
compareFields gate2DVerlet 0.05 position 1e-7 U 1e-5 rho 1e-3 p 1e-1 displacement 1e-8
compareHistory gate2DVerlet gateTip/0/displacement.dat 1e-4

# The 3D gate (simple cubic lattice, 16,000 solid particles): 0.01 s.
runBoth gate3D "$SPHVCPM_DIR/tutorials/sphVcpmFsi/damBreakElasticGate3D" 0.01
compareFields gate3D 0.01 position 1e-7 U 1e-5 rho 1e-3 p 1e-1 displacement 1e-8
compareHistory gate3D gateTip/0/displacement.dat 1e-4

finish
