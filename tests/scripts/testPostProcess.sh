#!/bin/bash
# sphVcpmFsi -postProcess (docs/postProcessing.md): the function objects
# evaluated on written times must give what the run sampled at those
# times. On the short rolling tank (a moving tank, a plate clamped to it,
# oil; the tank's force with its moment about the pivot, the forces on
# the tank's floor and the plate's top, probes riding on the plate) every
# type samples at the write times in the run; the tables are
# moved aside and -postProcess writes them again from the time
# directories: identical on the CPU (binary writes), within round-off
# where the run was on the GPU. Likewise solidPoints in a run of solids
# alone. Then the options: -func (an entry with enabled false), -funcs,
# -dict, -time, the refusal to write over tables and -overwrite, and the
# mistakes (an unknown entry, no functions, options without -postProcess,
# -device).
source "$(dirname "$0")/testLib.sh"

# sameTables <what> <run dir> <post-processed dir>: every table of the one
# in the other; on the GPU within 1e-8 of each column's largest value
# (1e-4 in a single-precision build), else byte for byte.
sameTables()
{
    local what="$1" run="$2" post="$3" f bad=0 n=0 tol=1e-8
    singleBuild "$scratch/log.run" && tol=1e-4
    for f in "$run"/*/*/*.dat; do
        local g="$post/${f#"$run"/}"
        n=$((n + 1))
        if [ "${SPHVCPM_DEVICE:-cpu}" != cuda ]; then
            cmp -s "$f" "$g" || { bad=1; echo "    differs: $g"; diff "$f" "$g" | head -6; }
        else
            awk -v tol=$tol '
                FNR == 1 { file++ }
                /^#/ { next }
                file == 1 { for (i = 1; i <= NF; ++i) { a[FNR, i] = $i
                            if ($i > big[i]) big[i] = $i; if (-$i > big[i]) big[i] = -$i }
                            rows1++; next }
                { rows2++; for (i = 1; i <= NF; ++i) { d = $i - a[FNR, i]; if (d < 0) d = -d
                  if (d > tol*big[i] + 1e-300) { print "    row " FNR " column " i ": " a[FNR, i] " against " $i; bad = 1 } } }
                END { if (rows1 != rows2) { print "    rows: " rows1 " against " rows2; bad = 1 } exit bad }
            ' "$f" "$g" || { bad=1; echo "    differs: $g"; }
        fi
    done
    check "$what: $n tables of the run, the same from -postProcess" [ $bad -eq 0 -a $n -gt 0 ]
}

# --- the rolling tank: every type, moving walls and a solid ----------------
c="$scratch/rollingTank"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/rollingTank2D" "$c"
(cd "$c" && ./Allclean > /dev/null 2>&1)
python3 - "$c/system/controlDict" <<'PY'
import re, sys
p = sys.argv[1]
s = open(p).read()
s = re.sub(r'(?m)^endTime .*$', 'endTime 0.2;', s)
s = re.sub(r'(?m)^writeInterval .*$', 'writeInterval 0.1;', s)
s = re.sub(r'(?m)^writeFormat .*$', 'writeFormat binary;', s)
at = "writeControl runTime; writeInterval 0.1;"
s = s[:s.index("functions\n{")] + """functions
{
    tip { type solidPoints; body plate; points ((0.3045 0.1145 0)); %s }
    levels { type freeSurfaceGauges; locations ((0.0185 -0.05 0) (0.5905 -0.05 0));
             maxHeight 0.35; %s }
    tankForce { type forces; body tank; CofR (0.3045 0 0); %s }
    plateForce { type forces; body plate; %s }
    probe { type probes; probeLocations ((0.03 0.01 0) (0.3 0.05 0)); %s }
    energy { type energy; %s }
    front { type surgeFront; direction (1 0 0); %s }
    tankFloor { type forces; body tank; CofR (0.3045 0 0);
                shapes { floor { shape box; min (-1 -1 0); max (1 0 0); } } %s }
    plateTop { type forces; body plate;
               shapes { top { shape box; min (0.3 0.06 0); max (0.31 1 0); } } %s }
    onPlate { type probes; onSolid plate; probeLocations ((0.3025 0.1 0) (0.3065 0.05 0)); %s }
    spare { type probes; probeLocations ((0.1 0.02 0)); enabled false; }
}
""" % ((at,)*10)
open(p, 'w').write(s)
PY
generateParticles -case "$c" > "$scratch/log.gen" 2>&1
sphVcpmFsi -case "$c" > "$scratch/log.run" 2>&1
check "rolling tank: the run ends" grep -q '^End' "$scratch/log.run"
check "rolling tank: written at 0.1 and 0.2" [ -d "$c/0.1" -a -d "$c/0.2" ]
mv "$c/postProcessing" "$c/postProcessing.run"
sphVcpmFsi -case "$c" -postProcess > "$scratch/log.post" 2>&1
check "-postProcess ends" grep -q '^End' "$scratch/log.post"
check "-postProcess: every time, once" [ "$(grep -c '^Time = ' "$scratch/log.post")" -eq 3 ]
check "-postProcess: enabled false is left out" [ ! -e "$c/postProcessing/spare" ]
sameTables "rolling tank" "$c/postProcessing.run" "$c/postProcessing"

# Tables already there are not written over, unless asked.
cp "$c/postProcessing/energy/0/energy.dat" "$scratch/energy.before"
sphVcpmFsi -case "$c" -postProcess > "$scratch/log.again" 2>&1
check "-postProcess again: refused (exit 1)" [ $? -eq 1 ]
expectIn "-postProcess again: the error names the directory and -overwrite" "$scratch/log.again" \
    "Function object '.*': .*postProcessing/.*/0 already holds tables .*-overwrite"
check "-postProcess again: the tables are kept" cmp -s "$scratch/energy.before" "$c/postProcessing/energy/0/energy.dat"
sphVcpmFsi -case "$c" -postProcess -overwrite > "$scratch/log.overwrite" 2>&1
check "-overwrite: written again, the same" cmp -s "$scratch/energy.before" "$c/postProcessing/energy/0/energy.dat"

# -func: one entry, also with enabled false; -time: from the first time
# chosen.
sphVcpmFsi -case "$c" -postProcess -func spare -time '0.1:' > "$scratch/log.func" 2>&1
check "-func spare -time '0.1:': two rows in postProcessing/spare/0.1" \
    [ "$(grep -vc '^#' "$c/postProcessing/spare/0.1/p.dat" 2>/dev/null)" = 2 ]
check "-func spare: nothing else written" [ ! -e "$c/postProcessing/energy/0.1" ]
sphVcpmFsi -case "$c" -postProcess -funcs '(tip front)' -latestTime > "$scratch/log.funcs" 2>&1
check "-funcs '(tip front)' -latestTime: those two" \
    [ -f "$c/postProcessing/tip/0.2/displacement.dat" -a -f "$c/postProcessing/front/0.2/front.dat" \
      -a ! -e "$c/postProcessing/energy/0.2" ]
check "-latestTime: the row of 0.2" [ "$(grep -v '^#' "$c/postProcessing/front/0.2/front.dat" | cut -d' ' -f1)" = 0.2 ]
printf 'functions { corner { type probes; probeLocations ((0.02 0.02 0)); } }\n' > "$c/system/probesDict"
sphVcpmFsi -case "$c" -postProcess -dict system/probesDict -time 0.1 > "$scratch/log.dict" 2>&1
check "-dict system/probesDict -time 0.1: its probe, one row" \
    [ "$(grep -vc '^#' "$c/postProcessing/corner/0.1/p.dat" 2>/dev/null)" = 1 ]

# Mistakes: each an error (exit 1) naming the fault.
mistake()
{
    local what="$1" pattern="$2"; shift 2
    sphVcpmFsi -case "$c" "$@" > "$scratch/log.mistake" 2>&1
    local status=$?
    check "$what: exit 1" [ $status -eq 1 ]
    expectIn "$what: the error" "$scratch/log.mistake" "$pattern"
}
mistake "-func of no entry" \
    "Function object 'tipp' is not in functions \{\}; its entries are \(tip levels tankForce plateForce probe energy front tankFloor plateTop onPlate spare\) \(did you mean 'tip'\?\)" \
    -postProcess -func tipp
printf 'functions { }\n' > "$c/system/emptyDict"
mistake "-dict with no entries" "has no enabled entry to evaluate" -postProcess -dict system/emptyDict
printf 'deltaT 1;\n' > "$c/system/noFunctions"
mistake "-dict without functions" "noFunctions has no functions \{\} to evaluate" -postProcess -dict system/noFunctions
mistake "-dict of no file" "-dict nothere: there is no file .*nothere" -postProcess -dict nothere
mistake "-latestTime without -postProcess" "-latestTime is an option of -postProcess, which was not given" -latestTime
mistake "-postProcess -device cuda" "-postProcess runs on the CPU" -postProcess -device cuda
mistake "-time of no time" "-time" -postProcess -time 5:6
mistake "-funcs '()'" "-funcs '\(\)' names no function object" -postProcess -funcs '()'
check "the mistakes wrote no time directory" [ "$(cd "$c" && ls -d [0-9]* | tr '\n' ' ')" = "0 0.1 0.2 " ]
# A time without uniform/time (copied in by hand, say) would be read as an
# initial state: refused before anything is read or written.
mv "$c/0.1/uniform" "$scratch/uniform.0.1"
rm -rf "$c/postProcessing"
mistake "a time without uniform/time" \
    "Time 0.1 of .* has no uniform/time: it cannot be told from an initial state" -postProcess
check "a time without uniform/time: no table written" [ ! -e "$c/postProcessing" ]
mv "$scratch/uniform.0.1" "$c/0.1/uniform"

# --- the walls' pressures as written: those of the written state ----------
# With a forces function due at a write or not, the run writes the same
# walls (both extrapolated from the state written).
d="$scratch/damBreak"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$d"
sed -i 's/^endTime .*/endTime 0.04;/; s/^writeInterval .*/writeInterval 0.02;/' "$d/system/controlDict"
generateParticles -case "$d" > "$scratch/log.gen" 2>&1
cp -r "$d" "$d.noForces"
sed -i '/wallForce/d' "$d.noForces/system/controlDict"
sphVcpmFsi -case "$d" > "$scratch/log.forces" 2>&1
sphVcpmFsi -case "$d.noForces" > "$scratch/log.noForces" 2>&1
check "dam break with and without forces: both run" \
    [ -f "$d/0.04/box/p" -a -f "$d.noForces/0.04/box/p" ]
check "dam break with and without forces: the walls' p written alike at 0.02 and 0.04" \
    bash -c 'cmp -s "$1/0.02/box/p" "$2/0.02/box/p" && cmp -s "$1/0.04/box/p" "$2/0.04/box/p"' _ "$d" "$d.noForces"

# --- solids alone: solidPoints ---------------------------------------------
s="$scratch/beam"
mkdir -p "$s/system" "$s/constant"
cat > "$s/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.01;
bodies
{
    beam
    {
        type    solid;
        shapes { b { shape box; min (-0.02 -0.03 -1); max (0.4 0.03 1); } }
        clamp  { c { shape box; min (-1 -1 -1); max (0 1 1); } }
    }
}
DICT
cat > "$s/constant/solidProperties" <<'DICT'
beam { rho 1000; E 1e8; nu 0.3; lattice square2D; plane planeStrain; }
DICT
writeGravity "$s" "(0 -9.81 0)"
cat > "$s/system/controlDict" <<'DICT'
application     sphVcpmFsi;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         0.02;
deltaT          1e-5;
writeControl    adjustableRunTime;
writeInterval   0.01;
writeFormat     binary;
logInterval     10000;
functions
{
    tip { type solidPoints; body beam; points ((0.395 0.005 0) (0.2 -0.025 0));
          writeControl runTime; writeInterval 0.01; }
}
DICT
generateParticles -case "$s" > "$scratch/log.gen" 2>&1
sphVcpmFsi -case "$s" > "$scratch/log.run" 2>&1
check "solids alone: the run ends" grep -q '^End' "$scratch/log.run"
mv "$s/postProcessing" "$s/postProcessing.run"
sphVcpmFsi -case "$s" -postProcess > "$scratch/log.post" 2>&1
check "solids alone: -postProcess ends" grep -q '^End' "$scratch/log.post"
sameTables "solids alone" "$s/postProcessing.run" "$s/postProcessing"
check "solids alone: the beam has moved" \
    awk '!/^#/ && $1 == 0.02 { exit !($3 < -1e-5) }' "$s/postProcessing/tip/0/displacement.dat"

finish
