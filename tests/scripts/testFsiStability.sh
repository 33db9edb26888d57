#!/bin/bash
# FSI stability suite (coarse, for CI): a dam break (water 0.2 x 0.4 m,
# dp = 10 mm, in a 0.8 x 0.5 m box) hits an elastic plate standing on the
# floor at x = 0.5 m, held by its clamped lowest 2 layers, run to 1 s (the
# front reaches the plate at about 0.25 s): a stiff aluminium plate
# (E = 70 GPa, rho = 2700: about 85 solid steps per fluid step), a very
# soft one with large deformation (E = 1 MPa, nu = 0.49), a thin plate of
# 3 layers; and a fast jet (a water block at 5 m/s, no gravity) hitting a
# plate. Each run must end normally with every written state finite, no
# fluid particle inside the solid (3 or more solid particles within dp_s
# of it), no fluid particle removed, the fluid's mechanical energy never
# above its start by more than 1 % (the solid takes energy, it must not
# give more), and the plate's largest displacement below its height (a
# bounded response; the stiff plate below 1e-5 m, what 700 kPa would bend
# it: measured 1.8e-8 m). A plate far too soft for its load must stop with the
# collapse diagnosis and a restorable last good state.
. "$(dirname "$0")/testLib.sh"
. "$(dirname "$0")/fieldTools.sh"

# makeCase <name> <E> <nu> <rho> <thickness> <height> <jet: yes|no>
makeCase()
{
    local c="$scratch/$1" E="$2" nu="$3" rho="$4" t="$5" H="$6" jet="$7"
    mkdir -p "$c/system" "$c/constant"
    local water="min (0 0 0); max (0.2 0.4 0);" U="(0 0 0)" g="(0 -9.81 0)"
    local sound="coefSound 20;"
    if [ "$jet" = yes ]; then
        water="min (0.05 0.1 0); max (0.25 0.2 0);"; U="(5 0 0)"; g="(0 0 0)"
        sound="c0 60;"
    fi
    cat > "$c/system/generateParticlesDict" <<DICT
nDimensions 2;
dp 0.01;
bodies
{
    plate
    {
        type solid;
        shapes { p { shape box; min (0.5 0 0); max ($(awk -v t=$t 'BEGIN { print 0.5 + t }') $H 0); } }
        clamp  { c { shape box; min (0 -1 0); max (1 0.02 0); } }
    }
    box { type wall; container { min (0 0 0); max (0.8 0.5 0); layers 3; openTop no; } }
    water { type fluid; U $U; shapes { w { shape box; $water } } }
}
DICT
    cat > "$c/constant/solidProperties" <<DICT
plate { rho $rho; E $E; nu $nu; lattice square2D; plane planeStrain; }
DICT
    writeWaterModel "$c" "$sound"
    writeGravity "$c" "$g"
    cat > "$c/system/controlDict" <<'DICT'
application sphVcpmFsi; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1; deltaT 1e-5; adjustTimeStep yes; maxCo 0.2; maxDeltaT 1e-3;
writeControl adjustableRunTime; writeInterval 0.1; writeFormat ascii;
writePrecision 12; logInterval 100000;
functions { energy { type energy; writeControl timeStep; writeInterval 10; } }
DICT
}

# checkCase <name> <plate height> [<displacement bound> <why>]: the bound
# is the plate's height unless given.
checkCase()
{
    local name="$1" c="$scratch/$1" H="$2" bound="${3:-$2}" why="${4:-its height}"
    (cd "$c" && generateParticles > log.generateParticles 2>&1 \
             && sphVcpmFsi > log.sphVcpmFsi 2>&1)
    check "$name: the run ends normally" grep -q '^End' "$c/log.sphVcpmFsi"
    check "$name: no particle removed" bash -c "! grep -q '^Removed' '$c/log.sphVcpmFsi'"
    local bad=0 t inside umax="" u
    for t in $(cd "$c" && ls -d [0-9]* | grep -v '^0$'); do
        # Finite fluid state, and no fluid inside the plate.
        inside=$(python3 - "$c/$t" <<'PY'
import math, re, sys
d = sys.argv[1]
def vec(f):
    t = open(f).read(); t = t[t.index('value'):]
    return [tuple(map(float, m)) for m in re.findall(
        r'^\(([^ ()]+) ([^ ()]+) ([^ ()]+)\)$', t, re.M)]
w = vec(d + '/water/position'); s = vec(d + '/plate/position')
if any(not all(map(math.isfinite, p)) for p in w + s):
    print("NaN"); sys.exit()
cells = {}
for p in s:
    cells.setdefault((int(p[0]//0.01), int(p[1]//0.01)), []).append(p)
n = 0
for p in w:
    i, j = int(p[0]//0.01), int(p[1]//0.01)
    near = sum(1 for a in (-1, 0, 1) for b in (-1, 0, 1)
               for q in cells.get((i + a, j + b), ())
               if (q[0]-p[0])**2 + (q[1]-p[1])**2 < 1e-4)
    n += near >= 3
print(n)
PY
)
        [ "$inside" = 0 ] || { bad=$((bad + 1)); echo "    time $t: $inside fluid particles inside the plate (or NaN)"; }
        # The largest |displacement|: nan from a non-finite value or no rows
        # (umax stays empty, and fails, without a written time).
        u=$(fieldValues "$c/$t/plate/displacement" | awk "$awkFinite"'
            { if (!finite($1) || !finite($2)) bad = 1; m2 = $1*$1 + $2*$2; if (m2 > m) m = m2 }
            END { if (!NR || bad) print "nan"; else print sqrt(m) }')
        umax=$(awk -v a="$umax" -v b="$u" "$awkFinite"'BEGIN {
            print (a == "" ? b : !finite(a) || !finite(b) ? "nan" : b > a ? b : a) }')
    done
    check "$name: every written state finite, no fluid inside the plate" [ $bad -eq 0 ]
    check "$name: the plate's largest displacement ($umax m) is below $why, $bound m" \
        isFinite "$umax" "v < $bound"
    local e=postProcessing/energy/0/energy.dat
    # The largest rise: nan from a non-finite row or a table without rows.
    check "$name: fluid energy never above its start by more than 1 %" awk "$awkFinite"'
        !/^#/ { if (!finite($3) || !finite($4)) bad = 1; E = $3 + $4
                if (n++ == 0) E0 = Emax = E; if (E > Emax) Emax = E }
        END { d = (!n || bad || E0 == 0) ? "nan" : (Emax - E0)/(E0 < 0 ? -E0 : E0)
              printf "    max rise %.3g of the start\n", d; exit !(finite(d) && d <= 0.01) }' "$c/$e"
    grep -E "solid steps per fluid step" "$c/log.sphVcpmFsi" | sed "s/^ */    $name: /"
}

makeCase stiffPlate 70e9 0.3 2700 0.04 0.1 no
# Aluminium, 4 cm thick, 8 cm free above its clamp: a uniform 700 kPa on
# it (a hundred times the front's rho v^2, v = 2.8 m/s) would bend its top
# q L^4/(8 E t^3/12) = 1e-5 m; anything more is the coupling's fault.
checkCase stiffPlate 0.1 1e-5 "what 700 kPa on it would bend it"
makeCase softPlate 1e6 0.49 1000 0.04 0.2 no
checkCase softPlate 0.2
makeCase thinPlate 1e7 0.3 1000 0.03 0.15 no
checkCase thinPlate 0.15
# 3 layers of dp fill the support 2h = 3 dp; under h = 2 dp (support 4 dp)
# the log says that fluid on both sides of the plate interacts across it.
check "thinPlate: no note of a solid thinner than the support" \
    bash -c "! grep -q 'interacts across it' '$scratch/thinPlate/log.sphVcpmFsi'"
makeCase widePlate 1e7 0.3 1000 0.03 0.15 no
sed -i 's/hOverDp 1.5;/hOverDp 2;/' "$scratch/widePlate/system/sphSchemes"
sed -i "s/layers 3;/layers 4;/" "$scratch/widePlate/system/generateParticlesDict"
sed -i 's/^endTime 1;/endTime 0.001;/' "$scratch/widePlate/system/controlDict"
(cd "$scratch/widePlate" && generateParticles > log.generateParticles 2>&1 \
     && sphVcpmFsi > log.sphVcpmFsi 2>&1)
expectIn "widePlate (h = 2 dp): the log notes the plate is thinner than the support" \
    "$scratch/widePlate/log.sphVcpmFsi" \
    "solid plate: 3 layers \\(0.03 m\\) thick .* support 2h = 0.04 m .* interacts across it"
check "widePlate: a note, not a warning" bash -c "! grep -q 'Warning' '$scratch/widePlate/log.sphVcpmFsi'"
makeCase fastJet 1e7 0.3 1000 0.04 0.3 yes
checkCase fastJet 0.3

# A plate far too soft for its load (E = 10 Pa: its own weight and the
# water's pressure are kPa) and without lattice damping collapses: the run
# stops in the solid's sub-cycle naming the solid, its E and the bond, and
# writes the state at the start of that step, solids included (restored
# from the step's start: no bond of it is near collapse, nothing in it is
# non-finite).
makeCase crushedPlate 10 0.3 1000 0.04 0.15 no
sed -i 's/plane planeStrain;/plane planeStrain; latticeDamping 0;/' \
    "$scratch/crushedPlate/constant/solidProperties"
c="$scratch/crushedPlate"
(cd "$c" && generateParticles > log.generateParticles 2>&1 \
         && timeout 300 sphVcpmFsi > log.sphVcpmFsi 2>&1)
check "crushedPlate: exit status 1" [ $? -eq 1 ]
expectIn "crushedPlate: the diagnosis names the solid, its E and the bond" \
    "$c/log.sphVcpmFsi" "collapsing lattice \\(solid plate: the bond of particles id [0-9]+ .* is [0-9.e-]+ of its rest length 0\\.01 m; E = 10 Pa, latticeDamping 0\\)"
ratio=$(sed -n 's/.* is \([0-9.e-]*\) of its rest length.*/\1/p' "$c/log.sphVcpmFsi" | head -1)
check "crushedPlate: the bond named is below a quarter of its length (${ratio:-?})" \
    awk -v r="$ratio" 'BEGIN { exit !(r != "" && r + 0 < 0.25) }'
# Where the last good state is: written now, or the write just before.
t=$(sed -n 's/.*\(was written to\|is the last write,\) \([^/]*\)\/.*/\2/p' "$c/log.sphVcpmFsi" | head -1)
check "crushedPlate: the last good state ${t:-?}/ on disk" [ -n "$t" -a -f "$c/$t/plate/position" ]
fieldValues "$c/$t/plate/position" > "$scratch/plate.xyz"
fieldValues "$c/$t/water/position" > "$scratch/water.xyz"
check "crushedPlate: its state is finite and the plate's particles are more than dp/4 apart" \
python3 - "$scratch/plate.xyz" "$scratch/water.xyz" <<'PY'
import math, sys
s, w = ([tuple(map(float, l.split())) for l in open(f)] for f in sys.argv[1:3])
if not s or any(not all(map(math.isfinite, p)) for p in w + s):
    print("    non-finite state"); sys.exit(1)
closest = min(math.dist(p, q) for i, p in enumerate(s) for q in s[i + 1:])
print("    closest plate particles %.4g m apart" % closest)
sys.exit(0 if closest > 0.25*0.01 else 1)
PY

# A light plate at rest in still water under the Verlet scheme (docs/fsi.md,
# "Light solids"): 0.2 m of soft rubber 0.55 times the water's density,
# wetted on both sides, clamped at the floor. With the solid's whole step
# under the force of its start and the fluid seeing its mean velocity over
# the whole step, round-off grew until its force swung with a standard
# deviation of 38 N/m over 0.75-1 s and 65 N/m over 1-1.25 s; with the
# force 1.5 F^n - 0.5 F^{n-1} and the last quarter's mean velocity, 0.00.
c="$scratch/lightPlate"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/generateParticlesDict" <<'DICT'
nDimensions 2; dp 0.01;
bodies
{
    tank  { type wall; container { min (0 0 0); max (1 0.4 0); layers 4; openTop yes; } }
    plate { type solid; dp 0.0025;
            shapes { p { shape box; min (0.5 0 0); max (0.51 0.2 0); } }
            clamp  { foot { shape box; min (0.49 0 0); max (0.52 0.005 0); } } }
    water { type fluid; shapes { w { shape box; min (0 0 0); max (1 0.25 0); } } }
}
DICT
echo "plate { rho 550; E 0.625e6; nu 0.4; lattice square2D; plane planeStrain; }" \
    > "$c/constant/solidProperties"
writeWaterModel "$c" "coefSound 15;"
sed -i 's/hOverDp 1.5;/hOverDp 2;/' "$c/system/sphSchemes"
echo "timeScheme verlet;" >> "$c/system/sphSchemes"
cat > "$c/system/controlDict" <<'DICT'
application sphVcpmFsi; startFrom latestTime; startTime 0; stopAt endTime;
endTime 1.25; deltaT 1e-5; maxCo 0.2; maxDeltaT 1e-3;
writeControl adjustableRunTime; writeInterval 1.25; logInterval 100000;
functions { f { type forces; body plate; writeControl runTime; writeInterval 0.005; } }
DICT
(cd "$c" && generateParticles > log.generateParticles 2>&1 \
         && timeout 300 sphVcpmFsi > log.sphVcpmFsi 2>&1)
check "lightPlate (Verlet, 0.55 times the water): the run ends" grep -q '^End' "$c/log.sphVcpmFsi"
check "lightPlate: at rest in still water (Fx std over 0.75-1.25 s below 1 N/m)" \
    awk '!/^#/ && $1 >= 0.75 { n++; s += $2; q += $2*$2 }
         END { if (!n) exit 1; sd = sqrt(q/n - (s/n)^2)
               print "    Fx std " sd " N/m over " n " rows"; exit !(sd < 1) }' \
        "$c/postProcessing/f/0/force.dat"
check "lightPlate at 0.55: no light-solid warning" \
    bash -c "! grep -q 'times the fluid.s density' '$c/log.sphVcpmFsi'"
# Lighter than the coupling was found stable: warned of at the start.
for scheme in verlet symplectic; do
    sed -i "s/^timeScheme .*/timeScheme $scheme;/" "$c/system/sphSchemes"
    sed -i 's/rho 550;/rho 200;/; s/rho 550 /rho 200 /' "$c/constant/solidProperties"
    sed -i 's/endTime 1.25;/endTime 0.001;/' "$c/system/controlDict"
    rm -rf "$c"/[1-9]* "$c/postProcessing"
    (cd "$c" && sphVcpmFsi > log.light 2>&1)
    expectIn "a plate 0.2 times the water ($scheme): warned" "$c/log.light" \
        "Solid plate is 0.2 times the fluid's density \(200 against 1000 kg/m\^3\). Under timeScheme $scheme a plate lighter than 0.[23]5* times the fluid's density drifted into a growing oscillation"
done
finish
