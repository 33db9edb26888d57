#!/bin/bash
# sphVcpmFsi with a fluid and an elastic solid. Without gravity and walls,
# a water block thrown at a free rubber block (and, in a second run, at a
# block of half the spacing: multi-resolution r = 2) must keep the total
# momentum of fluid and solid to round-off: the solid receives exactly the
# reaction of the fluid's forces over each step. The solid must also have
# been pushed (it takes momentum from the fluid), no fluid particle may
# end inside the solid, and the log reports the sub-steps. A third run
# does the same in 3D (simple cubic lattice, r = 1). Then a block far too
# stiff (a warning), last -timers.
source "$(dirname "$0")/testLib.sh"
source "$(dirname "$0")/fieldTools.sh"

makeCase()   # makeCase <dir> <solid dp> <nDimensions>
{
    local c="$1" waterMax="(0.1 0.1 0)" blockMin="(0.105 0.02 0)"
    local blockMax="(0.145 0.08 0)" lattice="square2D; plane planeStrain"
    if [ "$3" = 3 ]; then
        waterMax="(0.05 0.05 0.05)"; blockMin="(0.055 0.01 0.01)"
        blockMax="(0.085 0.04 0.04)"; lattice="simpleCubic3D"
    fi
    mkdir -p "$c/system" "$c/constant"
    cat > "$c/system/generateParticlesDict" <<DICT
nDimensions $3;
dp          0.01;
bodies
{
    water { type fluid; U (1 0 0); shapes { b { shape box; min (0 0 0); max $waterMax; } } }
    block
    {
        type solid;
        dp   $2;
        shapes { b { shape box; min $blockMin; max $blockMax; } }
    }
}
DICT
    cat > "$c/constant/solidProperties" <<DICT
block { rho 1100; E 2e6; nu 0.3; lattice $lattice; }
DICT
    writeWaterModel "$c" "c0 40;"
    writeGravity "$c" "(0 0 0)"
    writeFsiControl "$c" 0.03 1e-5 0.03 1000 \
        'functions { blockForce { type forces; body block; } }'
}

# Total momentum "px py scale" of the water and the block in time
# directory $2 (scale: the sum of m |u_x|).
momentum()
{
    local b
    for b in water block; do
        paste -d ' ' <(fieldValues "$1/$2/$b/mass") <(fieldValues "$1/$2/$b/U")
    done | awk '{ px += $1*$2; py += $1*$3; s += $1*($2 < 0 ? -$2 : $2) }
                END { printf "%.17g %.17g %.17g\n", px, py, s }'
}

for run in r1 r2 3D; do
    r=${run#r}; nDim=2
    [ "$run" = 3D ] && { r=1; nDim=3; }
    c="$scratch/fsi$run"
    makeCase "$c" "$(python3 -c "print(0.01/$r)")" $nDim
    generateParticles -case "$c" > "$scratch/log.gen$run" 2>&1
    check "$run: generateParticles" [ $? -eq 0 ]
    sphVcpmFsi -case "$c" > "$scratch/log.run$run" 2>&1
    check "$run: sphVcpmFsi runs fluid and solid" [ $? -eq 0 ]
    log="$scratch/log.run$run"
    expectIn "$run: log names the solid" "$log" "block \(solid\)"
    expectIn "$run: log reports the solid steps" "$log" "solid steps per fluid step"
    expectIn "$run: log gives the sub-steps a fluid step holds" "$log" \
        "solid block: about [0-9]+ sub-steps of .* s per fluid step of"
    check "$run: no warning of slow sub-cycling" \
        bash -c "! grep -q 'sub-steps in each fluid step' '$log'"
    expectIn "$run: End" "$log" "^End"
    check "$run: forces on the block written" \
        [ -s "$c/postProcessing/blockForce/0/force.dat" ]
    for f in position U displacement vonMises p; do
        check "$run: 0.03/block/$f written" [ -f "$c/0.03/block/$f" ]
    done
    read p0x p0y s0 <<< "$(momentum "$c" 0)"
    read p1x p1y s1 <<< "$(momentum "$c" 0.03)"
    # Float's round-off in a single-precision build: 1e-6 of the momentum.
    rel=1e-12
    singleBuild "$log" && rel=1e-6
    check "$run: total momentum conserved to round-off ($p0x $p0y -> $p1x $p1y)" \
        python3 -c "import sys; sys.exit(0 if abs($p1x-$p0x) < $rel*$s0 and abs($p1y-$p0y) < $rel*$s0 else 1)"
    # The block took momentum from the water.
    pb=$(python3 - "$c/0.03/block" <<'PY'
import re, sys
t = open(sys.argv[1] + '/U').read(); t = t[t.index('value'):]
u = [float(m) for m in re.findall(r'^\(([-\d.e+]+) ', t, re.M)]
print(sum(u)/len(u))
PY
)
    check "$run: the block moves with the water (mean u $pb m/s)" \
        python3 -c "import sys; sys.exit(0 if $pb > 0.05 else 1)"
    # No water inside the block: every water particle stays outside the
    # block's particle hull, shrunk by a quarter of the solid spacing.
    check "$run: no water inside the block" python3 - "$c/0.03" "$r" <<'PY'
import re, sys
d, r = sys.argv[1], int(sys.argv[2])
def vec(f):
    t = open(f).read(); t = t[t.index('value'):]
    return [tuple(map(float, m)) for m in re.findall(
        r'^\(([-\d.e+]+) ([-\d.e+]+) ([-\d.e+]+)\)$', t, re.M)]
b = vec(d + '/block/position'); w = vec(d + '/water/position')
q = 0.25*0.01/r
x0 = min(p[0] for p in b) + q; x1 = max(p[0] for p in b) - q
y0 = min(p[1] for p in b) + q; y1 = max(p[1] for p in b) - q
z0 = min(p[2] for p in b) + q; z1 = max(p[2] for p in b) - q
flat = z1 < z0     # 2D: every z is 0
inside = [p for p in w if x0 < p[0] < x1 and y0 < p[1] < y1
          and (flat or z0 < p[2] < z1)]
print(len(inside), "water particles inside the block")
sys.exit(1 if inside else 0)
PY
done

# A block 1e10 times too stiff (E in the wrong unit): the solver says so
# before the run crawls.
c="$scratch/fsiStiff"
makeCase "$c" 0.01 2
sed -i 's/E 2e6;/E 2e16;/' "$c/constant/solidProperties"
echo "blok { rho 1000; E 1e6; nu 0.3; }" >> "$c/constant/solidProperties"
sed -i 's/^endTime .*/endTime 1e-5;/' "$c/system/controlDict"
# and a displacement point a metre off the block: followed, with a warning.
sed -i 's/functions {/functions { far { type solidPoints; body block; points ((1 1 0)); }/' \
    "$c/system/controlDict"
generateParticles -case "$c" > "$scratch/log.genStiff" 2>&1
sphVcpmFsi -case "$c" > "$scratch/log.runStiff" 2>&1
check "E 2e16: the short run ends" [ $? -eq 0 ]
expectIn "E 2e16: warns of the sub-steps, naming the solid" "$scratch/log.runStiff" \
    "Solid 'block' needs about [0-9.e+]+ sub-steps in each fluid step"
expectIn "E 2e16: the warning points to solidProperties" "$scratch/log.runStiff" \
    "file: .*constant/solidProperties"
expectIn "an entry of solidProperties for no solid is warned of" "$scratch/log.runStiff" \
    "Entry 'blok' of constant/solidProperties names no solid body of the case \\(solids: block\\)"
expectIn "a solidPoints point far off the solid is warned of" "$scratch/log.runStiff" \
    "the point \\(1 1 0\\) is [0-9.]+ m from solid 'block'"

# -timers: the run summary has the time of each phase of the step, which
# add up to no more than the time loop's wall clock and to most of it; the
# timing changes no result.
c="$scratch/fsiTimers"
makeCase "$c" 0.01 2
generateParticles -case "$c" > "$scratch/log.genTimers" 2>&1
sphVcpmFsi -case "$c" -timers > "$scratch/log.runTimers" 2>&1
check "-timers: sphVcpmFsi runs" [ $? -eq 0 ]
log="$scratch/log.runTimers"
for phase in "sort and cell list" "wall extrapolation" "fluid rates" \
    "solids and coupling" "predictor, corrector, wall motion" "function objects"; do
    expectIn "-timers: the summary times '$phase'" "$log" "^ +$phase +[0-9.]+ s +[0-9.]+ %"
done
check "-timers: the phases add up to 50-100 % of the loop's wall clock" python3 - "$log" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
loop = float(re.search(r"^Run summary: .* in ([0-9.e+-]+) s wall clock", t, re.M).group(1))
phases = [float(x) for x in re.findall(r"^ {8}[a-z, ]+? +([0-9.]+) s +[0-9.]+ %", t, re.M)]
print(len(phases), "phases,", sum(phases), "s of", loop, "s")
sys.exit(0 if len(phases) == 6 and 0.5*loop <= sum(phases) <= loop*1.01 + 0.003 else 1)
PY
check "-timers: the same block positions as without" \
    cmp "$c/0.03/block/position" "$scratch/fsir1/0.03/block/position"
finish
