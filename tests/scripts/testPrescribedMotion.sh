#!/bin/bash
# Prescribed motions (constant/motion, docs/motion.md) in the solvers.
#
# 1. Still water in a 2D tank rotated slowly by 10 degrees about its
#    bottom centre (a quarter period of 16 s, started with a 4 s ramp): in
#    the lab frame the free surface stays horizontal, the levels 0.15 m
#    either side of the axis within 1 dp of each other throughout (a
#    surface that turned with the tank would differ by 0.3 tan 10 deg =
#    5.3 dp) and at the still level; the tank's particles are where the
#    rigid rotation puts them; no particle is lost. Gauges and probes with
#    frame tank move and tilt with it: in its axes the surface slopes by
#    -tan 10 deg, and a probe reads what a lab probe at its moved place
#    reads, the hydrostatic pressure.
# 2. A clamped rubber strip (solids alone) turned rigidly by 90 degrees
#    about its clamp in 1 s, then held, with damping: at rest it lies on
#    the rigid rotation of its reference lattice and carries no stress
#    (the bond forces follow the bonds' current direction exactly).
# 3. Water in a 2D tank accelerated along x: a = a0 (1 - cos(pi t/2))/2
#    for 2 s, then a0 = 1 m/s^2 held (an offset table). In the tank's frame
#    the free surface tilts to the slope -a0/g of the effective gravity
#    g - a (within 10 %; averaged over two writes half a sloshing period
#    apart, which cancels the first mode the ramp leaves): measured -0.1050.
#    The walls' acceleration in their extrapolated pressure (g - a_w) moves
#    it little (-0.1063 without it, in one trial run): this checks the
#    accelerated tank as a whole, not that term alone.
# 4. Bad input: a 2D motion about an axis out of the plane, and a motion of
#    a solid body with no clamped particle, each a clear error.
# 5. What users write by mistake, each a clear error or warning: a motion
#    already under way at the start time (the wall moved into the fluid), a
#    misspelt constant/motions, a body the case has not, dimensions of the
#    wrong kind, a phase in degrees, a roll too fast for c0 (warned of) or
#    far too fast (stopped before the run), a blow-up while the walls move (the
#    diagnosis gives their speed); endTime raised during the run past
#    what the domain was sized for (a warning at once, an error saying to
#    restart when the tank leaves it; the restart runs on).
source "$(dirname "$0")/testLib.sh"
source "$(dirname "$0")/fieldTools.sh"

# rotationError <case> <time> <body> <angle deg> <ox> <oy>: the largest
# distance of the body's particles at <time> from R(angle) (X - o) + o,
# X their positions in 0/ (matched by id).
rotationError()
{
    # One table at a time: bodyTable's scratch files are per shell.
    bodyTable "$1/0" "$3" position > "$scratch/.before"
    bodyTable "$1/$2" "$3" position > "$scratch/.after"
    paste -d ' ' "$scratch/.before" "$scratch/.after" |
    awk -v a="$4" -v ox="$5" -v oy="$6" '
        BEGIN { c = cos(a*atan2(0, -1)/180); s = sin(a*atan2(0, -1)/180) }
        { if ($1 != $5) { bad = 1; exit }
          x = ox + c*($2 - ox) - s*($3 - oy); y = oy + s*($2 - ox) + c*($3 - oy)
          d = sqrt(($6 - x)^2 + ($7 - y)^2); if (d > m) m = d }
        END { if (bad) print "ids differ"; else if (NR == 0) print "no particles";
              else printf "%.3g\n", m + 0 }'
}

# 1. Still water in a slowly rotated tank
c="$scratch/stillWater"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.01;
bodies
{
    tank  { type wall; container { min (0 0 0); max (0.4 0.3 0); layers 3; openTop yes; } }
    water { type fluid; shapes { b { shape box; min (0 0 0); max (0.4 0.1 0); } } }
}
DICT
cat > "$c/constant/motion" <<'DICT'
roll
{
    bodies  (tank);
    origin  (0.2 0 0);
    axis    (0 0 1);
    angle   { type sinusoid; amplitude 10; period 16; rampTime 4; units degrees; }
}
DICT
writeWaterModel "$c" "coefSound 10;"
writeGravity "$c" "(0 -9.81 0)"
writeFsiControl "$c" 4 1e-4 2 5000 \
    'functions' \
    '{' \
    '    levels { type freeSurfaceGauges; writeControl runTime; writeInterval 0.05;' \
    '             locations ((0.05 0 0) (0.35 0 0)); maxHeight 0.3; }' \
    '    tankLevels { type freeSurfaceGauges; writeControl runTime; writeInterval 0.05;' \
    '             locations ((0.05 0 0) (0.35 0 0)); maxHeight 0.3; frame tank; }' \
    '    tankProbes { type probes; writeControl runTime; writeInterval 0.05;' \
    '             probeLocations ((0.35 0.02 0) (0.05 0.02 0)); frame tank; }' \
    '    labProbes { type probes; writeControl runTime; writeInterval 0.05;' \
    '             probeLocations ((0.344248199 0.045743382 0) (0.048805873 -0.006351072 0)); }' \
    '    pivotMoment { type forces; body tank; CofR (0.2 0 0); writeControl runTime; writeInterval 0.05; }' \
    '    tankMoment { type forces; body tank; CofR (0.3 0.05 0); frame tank;' \
    '             writeControl runTime; writeInterval 0.05; }' \
    '}'
generateParticles -case "$c" > "$scratch/log.genWater" 2>&1
check "still water: generateParticles" [ $? -eq 0 ]
sphVcpmFsi -case "$c" > "$scratch/log.water" 2>&1
check "still water: sphVcpmFsi runs the rotating tank" [ $? -eq 0 ]
log="$scratch/log.water"
expectIn "still water: the log names the motion" "$log" "motion roll: rotation of tank"
expectIn "still water: End" "$log" "^End"
check "still water: no particle removed" bash -c "! grep -q Removed '$log'"
err=$(rotationError "$c" 4 tank 10 0.2 0)
check "still water: the tank is turned by 10 degrees at t = 4 s (max error $err m)" \
    python3 -c "import sys; sys.exit(0 if float('${err// /_}') < 1e-9 else 1)" 2>/dev/null
dat="$c/postProcessing/levels/0/height.dat"
read h0 h1 <<< "$(awk '!/^#/ { a = $2; b = $3 } END { print a, b }' "$dat")"
echo "    levels at t = 4 s: $h0 m (x = 0.05), $h1 m (x = 0.35)"
check "still water: free surface horizontal in the lab frame (|h0 - h1| = $(python3 -c "print(abs($h0-$h1))") m < dp)" \
    python3 -c "import sys; sys.exit(0 if abs($h0 - $h1) < 0.01 else 1)"
worst=$(awk '!/^#/ { d = $2 - $3; if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }' "$dat")
check "still water: levels within 1 dp of each other throughout (worst $worst m)" \
    python3 -c "import sys; sys.exit(0 if $worst < 0.01 else 1)"
check "still water: the level is the still level (h0 = $h0 m, 0.1 m at rest)" \
    python3 -c "import sys; sys.exit(0 if abs(0.5*($h0 + $h1) - 0.1) < 0.01 else 1)"
# Points in the tank's frame (frame tank): they move with the roll, and a
# gauge's line turns with it. In the tank's axes the still surface slopes
# by -tan 10 deg and, the area under it kept, stands 0.1 m above the floor
# mid-tank: the gauges 0.15 m either side read 0.1 +- 0.15 tan 10 deg
# (0.1264, 0.0736 m). A probe at reference point X reads what a lab probe
# at R (X - o) + o reads at 10 degrees (t = 4 s; the labProbes' points),
# and the hydrostatic pressure under the level that the lab gauges see.
read g0 g1 <<< "$(awk '!/^#/ { a = $2; b = $3 } END { print a, b }' "$c/postProcessing/tankLevels/0/height.dat")"
echo "    tank-frame levels at t = 4 s: $g0 m, $g1 m (0.1264, 0.0736 m)"
check "frame tank: the gauges tilt with the tank (levels $g0, $g1 m within dp/2 of 0.1 +- 0.15 tan 10 deg)" \
    python3 -c "import math, sys; t = 0.15*math.tan(math.radians(10)); sys.exit(0 if abs($g0 - 0.1 - t) < 0.005 and abs($g1 - 0.1 + t) < 0.005 else 1)"
first0=$(awk '!/^#/ { print $2; exit }' "$c/postProcessing/tankLevels/0/height.dat")
firstLab0=$(awk '!/^#/ { print $2; exit }' "$dat")
check "frame tank: at the start the tank's frame is the lab's ($first0 = $firstLab0 m)" \
    python3 -c "import sys; sys.exit(0 if abs($first0 - $firstLab0) < 1e-9 else 1)"
read tp0 tp1 <<< "$(awk '!/^#/ { a = $2; b = $3 } END { print a, b }' "$c/postProcessing/tankProbes/0/p.dat")"
read lp0 lp1 <<< "$(awk '!/^#/ { a = $2; b = $3 } END { print a, b }' "$c/postProcessing/labProbes/0/p.dat")"
echo "    tank-frame probes at t = 4 s: $tp0, $tp1 Pa; lab probes at their places: $lp0, $lp1 Pa"
check "frame tank: a probe reads what a lab probe at its turned place reads ($tp0 = $lp0, $tp1 = $lp1 Pa)" \
    python3 -c "import sys; sys.exit(0 if abs($tp0 - $lp0) < 1e-3 and abs($tp1 - $lp1) < 1e-3 else 1)"
hydro=$(python3 -c "
ys = 0.5*($h0 + $h1)
print('%.1f %.1f' % (1000*9.81*(ys - 0.045743382), 1000*9.81*(ys + 0.006351072)))")
check "frame tank: the probes read the hydrostatic pressure within 3 % ($tp0, $tp1 Pa against $hydro)" \
    python3 -c "import sys; a, b = map(float, '$hydro'.split()); sys.exit(0 if abs($tp0/a - 1) < 0.03 and abs($tp1/b - 1) < 0.03 else 1)"
expectIn "frame tank: the header says how the points move" "$c/postProcessing/tankProbes/0/p.dat" \
    "^# The points move with body tank \\(motion roll\\)"
# forces with frame tank: the moment about a CofR that turns with the
# tank, P = o + R (P0 - o), is the pivot's less (P - o) x F (t = 4 s).
pm="$c/postProcessing/pivotMoment/0"
read fx fy <<< "$(awk '!/^#/ { a = $2; b = $3 } END { print a, b }' "$pm/force.dat")"
mo=$(awk '!/^#/ { a = $4 } END { print a }' "$pm/moment.dat")
mp=$(awk '!/^#/ { a = $4 } END { print a }' "$c/postProcessing/tankMoment/0/moment.dat")
expected=$(python3 -c "
import math
c, s = math.cos(math.radians(10)), math.sin(math.radians(10))
px, py = 0.1*c - 0.05*s, 0.1*s + 0.05*c
print(repr($mo - (px*$fy - py*$fx)))")
echo "    moment about the turning point at t = 4 s: $mp N m/m; from the pivot's: $expected"
check "frame tank: forces take the moment about a CofR that turns with the tank ($mp = $expected N m/m)" \
    python3 -c "import sys; sys.exit(0 if abs($mp - $expected) < 1e-6*abs($mo) + 1e-9 else 1)"
# frame of a body in no motion, of the fluid, of a body the case has not.
b="$scratch/stillWaterBadFrame"
rm -rf "$b"; mkdir -p "$b"; cp -r "$c/system" "$c/constant" "$c/0" "$b/"
rm "$b/constant/motion"
sphVcpmFsi -case "$b" > "$scratch/log.badTankFrame" 2>&1
check "frame tank, no motion: exit status 1" [ $? -eq 1 ]
expectIn "frame tank, no motion: says what to do" "$scratch/log.badTankFrame" \
    "Function object 'tankLevels': frame tank: body tank is in no motion of constant/motion, so its points would stand still; no body moves in this case \\(it has no constant/motion\\), so leave frame out"
cp "$c/constant/motion" "$b/constant/motion"
badFrame()   # badFrame <frame> <pattern>: the error for frame <frame>
{
    sed -i "s/frame [a-z]*; }/frame $1; }/" "$b/system/controlDict"
    sphVcpmFsi -case "$b" > "$scratch/log.badTankFrame" 2>&1
    check "frame $1: exit status 1" [ $? -eq 1 ]
    expectIn "frame $1: says why, and the choices" "$scratch/log.badTankFrame" "$2"
}
badFrame water "frame water: water is the fluid, which constant/motion cannot move; give lab \\(the points stand still, the default\\) or a body that constant/motion moves: \\(tank\\)\$"
badFrame tnak "frame tnak: there is no body tnak \\(did you mean tank\\?\\); give lab"
badFrame roll "frame roll: roll is a motion of constant/motion; frame names a body it moves, \\(tank\\); give lab"
# A restart of the tilted tank weighs c0 against the flow as read, not the
# tilted water's height (which would call for a c0 the start did not).
r="$scratch/stillWaterRestart"
cp -r "$c" "$r"
sed -i 's/^endTime .*/endTime 4.01;/' "$r/system/controlDict"
sphVcpmFsi -case "$r" > "$scratch/log.waterRestart" 2>&1
check "still water: the restart runs" grep -q '^End' "$scratch/log.waterRestart"
check "still water: the restart at 10 degrees gives no speed-of-sound warning" \
    bash -c "! grep -q 'speed of sound' '$scratch/log.waterRestart'"
# constant/motion changed after the run: the tank would go on by the new
# motion's increments from where the old one left it (at 10 degrees where
# the new puts it at 12), off the motion the tank-frame probes follow.
r="$scratch/stillWaterChanged"
cp -r "$c" "$r"
sed -i 's/^endTime .*/endTime 4.01;/' "$r/system/controlDict"
sed -i 's/amplitude 10;/amplitude 12;/' "$r/constant/motion"
sphVcpmFsi -case "$r" > "$scratch/log.waterChanged" 2>&1
check "still water, motion changed: the restart stops (exit 1)" [ $? -eq 1 ]
expectIn "still water, motion changed: says how far and what to do" "$scratch/log.waterChanged" \
    "Wall tank of the restart time 4 is up to 0.01[0-9]* m \\([0-9.]+ dp\\) from where constant/motion puts it at that time: the motion has changed since the run that wrote it"

# 2. A clamped strip turned rigidly by 90 degrees
c="$scratch/strip"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.002;
bodies
{
    strip
    {
        type    solid;
        shapes { b { shape box; min (0 0 0); max (0.1 0.02 0); } }
        clamp  { c { shape box; min (-1 -1 -1); max (0.004 1 1); } }
    }
}
DICT
cat > "$c/constant/solidProperties" <<'DICT'
strip { rho 1000; E 1e6; nu 0.3; lattice square2D; plane planeStrain; damping 50; }
DICT
writeGravity "$c" "(0 0 0)"
# 0 -> 90 degrees in 1 s along t - sin(2 pi t)/(2 pi) (no jump in the
# velocity at either end), held after.
python3 -c "
import math
for i in range(101):
    t = i/100
    print(t, 90*(t - math.sin(2*math.pi*t)/(2*math.pi)))" > "$c/constant/turn.dat"
cat > "$c/constant/motion" <<'DICT'
turn
{
    bodies  (strip);
    origin  (0.002 0.01 0);
    axis    (0 0 1);
    angle   { type table; file "constant/turn.dat"; units degrees; }
}
DICT
cat > "$c/system/controlDict" <<'DICT'
application     sphVcpmFsi;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         2;
deltaT          1e-5;
writeControl    adjustableRunTime;
writeInterval   1;
writeFormat     ascii;
writePrecision  17;
logInterval     100000;
functions
{
    lab   { type solidPoints; body strip; points ((0.099 0.011 0)); }
    turns { type solidPoints; body strip; points ((0.099 0.011 0)); frame clamp; }
}
DICT
generateParticles -case "$c" > "$scratch/log.genStrip" 2>&1
check "strip: generateParticles" [ $? -eq 0 ]
sphVcpmFsi -case "$c" > "$scratch/log.strip" 2>&1
check "strip: sphVcpmFsi runs the turning strip" [ $? -eq 0 ]
expectIn "strip: End" "$scratch/log.strip" "^End"
err=$(rotationError "$c" 2 strip 90 0.002 0.01)
check "strip: at rest on the rigid rotation by 90 degrees (max error $err m)" \
    python3 -c "import sys; sys.exit(0 if float('${err// /_}') < 1e-8 else 1)" 2>/dev/null
vm=$(fieldValues "$c/2/strip/vonMises" | awk '{ v = $1 < 0 ? -$1 : $1; if (v > m) m = v } END { printf "%.3g\n", m + 0 }')
check "strip: unstrained after the turn (max von Mises $vm Pa, E = 1 MPa)" \
    python3 -c "import sys; sys.exit(0 if $vm < 1e-2 else 1)"
# solidPoints at the free end: in the lab, the turn's 0.137 m; with frame
# clamp, relative to the turn, what the strip adds: nothing at rest, and
# no more than a small lag while it turns (the clamp leads the strip).
lastRow() { awk '!/^#/ { r = $0 } END { print r }' "$1"; }
labEnd=$(lastRow "$c/postProcessing/lab/0/displacement.dat")
relEnd=$(lastRow "$c/postProcessing/turns/0/displacement.dat")
check "strip: solidPoints in the lab: the tip moved by the turn, 0.137 m ($labEnd)" \
    awk -v r="$labEnd" 'BEGIN { split(r, a, " "); d = sqrt(a[2]^2 + a[3]^2); exit !(a[1] == 2 && d > 0.13 && d < 0.14) }'
check "strip: solidPoints frame clamp: nothing left at rest ($relEnd)" \
    awk -v r="$relEnd" 'BEGIN { split(r, a, " "); exit !(a[1] == 2 && a[2]^2 + a[3]^2 < 1e-16) }'
relMax=$(awk '!/^#/ { d = sqrt($2^2 + $3^2); if (d > m) m = d } END { printf "%.3g\n", m }' \
    "$c/postProcessing/turns/0/displacement.dat")
check "strip: solidPoints frame clamp: a small lag while it turns ($relMax m, the lab's 0.14 m)" \
    awk -v m="$relMax" 'BEGIN { exit !(m > 0 && m < 0.005) }'
expectIn "strip: frame clamp: the header says so" "$c/postProcessing/turns/0/displacement.dat" \
    "^# Displacement R\\^T \\(x - T\\(X\\)\\) of solid strip relative to its clamp's motion turn"
# A restart of the turned strip runs on; with the turn's table changed
# after the run (to 80 degrees) its clamp is off the motion: an error.
r="$scratch/stripRestart"
cp -r "$c" "$r"
sed -i 's/^endTime .*/endTime 2.001;/' "$r/system/controlDict"
sphVcpmFsi -case "$r" > "$scratch/log.stripRestart" 2>&1
check "strip: the restart with its motion unchanged runs (exit $?)" grep -q '^End' "$scratch/log.stripRestart"
rm -rf "$r"/2.001
awk '{ print $1, $2*80/90 }' "$c/constant/turn.dat" > "$r/constant/turn.dat"
sphVcpmFsi -case "$r" > "$scratch/log.stripChanged" 2>&1
check "strip, motion changed: the restart stops (exit 1)" [ $? -eq 1 ]
expectIn "strip, motion changed: names the clamp" "$scratch/log.stripChanged" \
    "The clamp of solid strip of the restart time 2 is up to [0-9.e-]+ m .* from where constant/motion puts it"
# frame clamp for a solid in no motion, and a frame that is neither.
b="$scratch/stripBadFrame"
rm -rf "$b"; cp -r "$c" "$b"; rm -rf "$b"/[1-9]* "$b/postProcessing" "$b/constant/motion"
sphVcpmFsi -case "$b" > "$scratch/log.badFrame" 2>&1
check "frame clamp, no motion: exit status 1" [ $? -eq 1 ]
expectIn "frame clamp, no motion: says what to do" "$scratch/log.badFrame" \
    "Function object 'turns': frame clamp, but solid 'strip' is in no motion of constant/motion"
cp "$c/constant/motion" "$b/constant/motion"
sed -i 's/frame clamp;/frame body;/' "$b/system/controlDict"
sphVcpmFsi -case "$b" > "$scratch/log.badFrame" 2>&1
check "frame body: exit status 1" [ $? -eq 1 ]
expectIn "frame body: names the choices" "$scratch/log.badFrame" \
    "frame 'body' is not one of: lab .*, clamp"

# 3. A tank accelerated along x
c="$scratch/accelerated"
mkdir -p "$c/system" "$c/constant"
cp "$scratch/stillWater/system/generateParticlesDict" "$c/system/"
# The offset s(t) of a = a0 (1 - cos(pi t/Tr))/2 up to Tr, a0 after.
python3 -c "
import math
a0, Tr = 1.0, 2.0
sTr, vTr = a0*Tr**2/4 - a0*Tr**2/math.pi**2, a0*Tr/2
for i in range(801):
    t = i*0.005
    if t < Tr:
        s = a0*t*t/4 + a0*Tr**2/(2*math.pi**2)*(math.cos(math.pi*t/Tr) - 1)
    else:
        s = sTr + vTr*(t - Tr) + a0*(t - Tr)**2/2
    print(t, s)" > "$c/constant/offset.dat"
cat > "$c/constant/motion" <<'DICT'
push
{
    bodies      (tank);
    direction   (1 0 0);
    offset      { type table; file "constant/offset.dat"; }
}
DICT
writeWaterModel "$c" "coefSound 15;"
writeGravity "$c" "(0 -9.81 0)"
# First sloshing period of 0.4 m x 0.1 m: 2 pi/sqrt(g k tanh(k h)), k =
# pi/0.4: 0.884 s; writes every half period.
writeFsiControl "$c" 3.094 1e-4 0.442 10000
generateParticles -case "$c" > "$scratch/log.genPush" 2>&1
check "accelerated tank: generateParticles" [ $? -eq 0 ]
sphVcpmFsi -case "$c" > "$scratch/log.push" 2>&1
check "accelerated tank: sphVcpmFsi runs" [ $? -eq 0 ]
check "accelerated tank: no particle removed" bash -c "! grep -q Removed '$scratch/log.push'"
# surfaceSlope <time>: least-squares slope of the highest water particle of
# each 1 cm column, 0.05 to 0.35 m from the tank's inside rear wall (x = 0
# in its frame: the tank's leftmost particle sits 2.5 dp behind it).
surfaceSlope()
{
    local shift
    shift=$(fieldValues "$c/$1/tank/position" | awk '!n++ || $1 < m { m = $1 } END { printf "%.17g\n", m + 0.025 }')
    fieldValues "$c/$1/water/position" | awk -v s="$shift" '
        { x = $1 - s; k = int(x/0.01); if (!(k in top) || $2 > top[k]) top[k] = $2 }
        END { for (k in top) { x = (k + 0.5)*0.01; if (x < 0.05 || x > 0.35) continue
                  n++; sx += x; sy += top[k]; sxx += x*x; sxy += x*top[k] }
              printf "%.4f\n", (n*sxy - sx*sy)/(n*sxx - sx*sx) }'
}
s1=$(surfaceSlope 2.652)
s2=$(surfaceSlope 3.094)
slope=$(awk -v a="$s1" -v b="$s2" 'BEGIN { printf "%.4f\n", (a + b)/2 }')
echo "    free-surface slope in the tank's frame: $s1 at 2.652 s, $s2 at 3.094 s; -a0/g = -0.1019"
check "accelerated tank: free-surface slope $slope within 10 % of -a0/g = -0.1019" \
    python3 -c "import sys; sys.exit(0 if abs($slope + 0.1019) < 0.1*0.1019 else 1)"

# 4. Bad input
bad="$scratch/badAxis"
cp -r "$scratch/stillWater" "$bad"
rm -rf "$bad"/[1-9]* "$bad/postProcessing"
sed -i 's/axis    (0 0 1);/axis    (1 0 0);/' "$bad/constant/motion"
sphVcpmFsi -case "$bad" > "$scratch/log.badAxis" 2>&1
check "2D axis out of the plane: non-zero exit" [ $? -ne 0 ]
expectIn "2D axis out of the plane: says what is allowed" \
    "$scratch/log.badAxis" "Motion roll of a 2D case: its axis must be \(0 0 1\)"
expectIn "2D axis out of the plane: names the file and the line" \
    "$scratch/log.badAxis" "constant/motion at line 3"
bad="$scratch/badBody"
cp -r "$scratch/strip" "$bad"
rm -rf "$bad"/[1-9]*
sed -i 's/clamp  { c { shape box; min (-1 -1 -1); max (0.004 1 1); } }//' "$bad/system/generateParticlesDict"
generateParticles -case "$bad" > /dev/null 2>&1
sphVcpmFsi -case "$bad" > "$scratch/log.badBody" 2>&1
check "motion of an unclamped solid: non-zero exit" [ $? -ne 0 ]
expectIn "motion of an unclamped solid: names the body and what can move" \
    "$scratch/log.badBody" "strip is not a solid body with clamped particles"

# 5. Mistakes: one step of the still-water tank each (stopAt writeNow).
mistake()   # mistake <what> <sed expression on constant/motion> <pattern> [status]
{
    local m="$scratch/mistake"
    rm -rf "$m"; cp -r "$scratch/stillWater" "$m"
    rm -rf "$m"/[1-9]* "$m"/0.* "$m/postProcessing"
    sed -i 's/^stopAt .*/stopAt writeNow;/' "$m/system/controlDict"
    sed -i "$2" "$m/constant/motion"
    sphVcpmFsi -case "$m" > "$scratch/log.mistake" 2>&1
    check "$1: exit status ${4:-0}" [ $? -eq "${4:-0}" ]
    expectIn "$1: says so" "$scratch/log.mistake" "$3"
}
mistake "a tank tilted 10 degrees at the start" \
    's/angle   { .* }/angle   { type constant; value 10; units degrees; }/' \
    "Wall tank is moved 0.0[0-9]+ m by its motion at the start time 0 .*, into the fluid: [0-9]+ particles of water lie closer to it than the contact gap"
# A motion in the wrong unit: weighed against c0 before the run, its
# bodies' speed (the corners of their boxes, sampled to endTime) counts as
# the fluid's. In radians where degrees were meant the tank's corners go
# at 1.6 m/s against c0 = 9.9 m/s: warned of. A million degrees throws the
# tank at 1e4 m/s: an error before the first step.
mistake "a roll in radians where degrees were meant" \
    's/units degrees; }/units radians; }/' \
    "the bodies of motion roll \(constant/motion, lengths in m\) move at up to 1\.[0-9]+ m/s \(body tank, time [0-9.]+ s\)\): expect density errors"
m="$scratch/thrown"
rm -rf "$m"; cp -r "$scratch/stillWater" "$m"
rm -rf "$m"/[1-9]* "$m"/0.* "$m/postProcessing"
sed -i 's/^endTime .*/endTime 0.05;/' "$m/system/controlDict"
sed -i 's/angle   { .* }/angle   { type sinusoid; amplitude 1e6; period 1; units degrees; }/' \
    "$m/constant/motion"
timeout 300 sphVcpmFsi -case "$m" > "$scratch/log.thrown" 2>&1
check "a tank thrown by its motion: exit status 1" [ $? -eq 1 ]
expectIn "a tank thrown by its motion: stopped before the run, naming the motion and its speed" \
    "$scratch/log.thrown" "c0 = [0-9.]+ m/s is far too low for this scene: the bodies of motion roll \(constant/motion, lengths in m\) move at up to [0-9.e+]+ m/s"
check "a tank thrown by its motion: no step taken" \
    bash -c "! grep -q '^Time = ' '$scratch/log.thrown'"
# A run that blows up while the walls move says how fast they went: a
# fixed step 20 times the CFL limit fails whatever the motion, and the
# diagnosis tells the slow roll (well below c0) from a motion gone wrong.
m="$scratch/tooLongSteps"
rm -rf "$m"; cp -r "$scratch/stillWater" "$m"
rm -rf "$m"/[1-9]* "$m"/0.* "$m/postProcessing"
sed -i -e 's/^endTime .*/endTime 0.5;/' -e 's/^deltaT .*/deltaT 4e-3;/' \
    -e 's/^adjustTimeStep .*/adjustTimeStep no;/' "$m/system/controlDict"
timeout 300 sphVcpmFsi -case "$m" > "$scratch/log.tooLong" 2>&1
check "a step too long in a moving tank: exit status 1" [ $? -eq 1 ]
expectIn "a step too long in a moving tank: names the fixed step as the usual cause" \
    "$scratch/log.tooLong" "a time step too large for the forces \(lower deltaT, or set adjustTimeStep yes\)"
expectIn "a step too long in a moving tank: gives the walls' speed when it failed" \
    "$scratch/log.tooLong" "Walls move here \(constant/motion\), at up to [0-9.e+-]+ m/s at time [0-9.]+: check that the motion is the one meant"
# rollingStep <name> <log> <command...>: one step of the rollingTank2D
# tutorial, its constant/motion edited by the command (given the file last).
rollingStep()
{
    local m="$scratch/$1" log="$2"; shift 2
    rm -rf "$m"; cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/rollingTank2D" "$m"
    (cd "$m" && ./Allclean > /dev/null 2>&1)
    "$@" "$m/constant/motion"
    sed -i 's/^stopAt .*/stopAt writeNow;/' "$m/system/controlDict"
    generateParticles -case "$m" > /dev/null 2>&1
    sphVcpmFsi -case "$m" > "$log" 2>&1
}
# The rolling tank turned 8 degrees at the start: its tank and its plate
# (a solid placed by its clamp's motion) both crowd the oil.
rollingStep rolledAtStart "$scratch/log.rolled" python3 -c '
import sys
s = open(sys.argv[1]).read()
i = s.index("    angle\n"); j = s.index("    }\n", i) + 6
open(sys.argv[1], "w").write(s[:i] + "    angle { type constant; value 8; units degrees; }\n" + s[j:])'
check "rolling tank turned at the start: one step runs" grep -q '^End' "$scratch/log.rolled"
expectIn "rolling tank turned at the start: the tank crowds the oil" "$scratch/log.rolled" \
    "Wall tank is moved .* into the fluid: [0-9]+ particles of oil"
expectIn "rolling tank turned at the start: so does the plate its clamp placed" "$scratch/log.rolled" \
    "Solid plate is moved .* into the fluid: [0-9]+ particles of oil"
check "rolling tank: the plate's clamp moves with the tank, no warning of its root" \
    bash -c "! grep -q 'is clamped next to wall' '$scratch/log.rolled'"
# The plate left out of the tank's motion: its clamp would stay while the
# floor it stands on rolls through its root.
rollingStep plateLeftOut "$scratch/log.leftOut" sed -i 's/bodies *(tank plate);/bodies (tank);/'
check "plate left out of the tank's motion: the run goes on" grep -q '^End' "$scratch/log.leftOut"
expectIn "plate left out of the tank's motion: warned, with the fix" "$scratch/log.leftOut" \
    "Solid 'plate' is clamped next to wall 'tank' \\([0-9]+ clamped particles within a spacing of it\\), which moves by constant/motion while the clamp stays where it is .*bodies \\(tank plate\\);"
mistake "a body the case has not" 's/bodies  (tank);/bodies  (tnk);/' \
    "the case has no body tnk \\(did you mean tank\\?\\)" 1
mistake "a period in metres" 's/period 16;/period [m] 16;/' \
    "Keyword 'period': dimensions do not match: expected \\[0 0 1 0 0 0 0\\], found \\[0 1 0 0 0 0 0\\]" 1
mistake "a phase of 90 with units degrees" 's/rampTime 4;/rampTime 4; phase 90;/' \
    "Keyword 'phase' .*: 90 is in radians, more than a turn; for 90 degrees write 1.5707"
m="$scratch/mistake"; mv "$m/constant/motion" "$m/constant/motions"
cp "$m/constant/fluidProperties" "$m/constant/fluidProperties.orig"
touch "$m/constant/gx" "$m/constant/motion~"
rm -rf "$m"/0.*
sphVcpmFsi -case "$m" > "$scratch/log.mistake" 2>&1
expectIn "constant/motions: not read, and said" "$scratch/log.mistake" \
    "constant/motions is not read: did you mean constant/motion\\?"
check "copies beside (fluidProperties.orig, motion~) and short names (gx): no warning" \
    [ "$(grep -c 'is not read' "$scratch/log.mistake")" -eq 1 ]

# endTime raised during the accelerated tank's run past its domain.
m="$scratch/raisedEndTime"
cp -r "$scratch/accelerated" "$m"; rm -rf "$m"/[1-9]* "$m"/0.* "$m/postProcessing"
# Steps of at most 5e-5 s: 20,000 to endTime 1, seconds longer than the
# solver takes to see the change (a second at most, and the file half a
# second old) on any machine.
sed -i 's/^endTime .*/endTime 1;/; s/^logInterval .*/logInterval 100;/; s/^maxDeltaT .*/maxDeltaT 5e-5;/' "$m/system/controlDict"
sphVcpmFsi -case "$m" > "$scratch/log.raised" 2>&1 &
pid=$!
for ((i = 0; i < 600; ++i)); do grep -q "^Time = " "$scratch/log.raised" && break; sleep 0.1; done
sed -i 's/^endTime .*/endTime 4;/' "$m/system/controlDict"
for ((i = 0; i < 1200; ++i)); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
kill -9 $pid 2>/dev/null
wait $pid
check "endTime raised during the run: the tank leaves the domain, exit 1" [ $? -eq 1 ]
expectIn "endTime raised during the run: warns at once that the tank will leave the domain" \
    "$scratch/log.raised" "With endTime 4 the moving bodies leave the domain .* sized for their motion up to endTime 1 when the run started"
expectIn "endTime raised during the run: the error says how to go on" \
    "$scratch/log.raised" "Wall particle .* lies outside the domain bounds .*, which were sized at the start for its motion up to endTime 1: start the run again from its latest time"
r="$scratch/raisedRestart"
cp -r "$m" "$r"
sed -i 's/^endTime .*/endTime 1.2;/' "$r/system/controlDict"
sphVcpmFsi -case "$r" > "$scratch/log.raisedRestart" 2>&1
check "endTime raised: the restart sizes the domain anew and runs on" grep -q '^End' "$scratch/log.raisedRestart"
finish
