#!/bin/bash
# Restart: a run stopped at 0.05 s and continued with startFrom latestTime
# to 0.06 s ends where the uninterrupted run ends (coarse 2D dam break,
# ascii fields at 17 digits so that the restart reads back exactly what was
# written). Particles sharing a cell may be summed in another order after
# a restart, so the runs agree to round-off (grown over the 150 steps after
# the restart), not bit for bit; a restart that lost or changed any state
# (velocity, density, time step, speed of sound) differs by far more.
# Both time schemes (symplectic, Verlet). The same for a coupled run: the
# dam break against an elastic plate (stopped at 0.3 s, after the water
# reached it, continued to 0.32 s).
. "$(dirname "$0")/testLib.sh"
. "$(dirname "$0")/fieldTools.sh"

source="$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D"
setEnd() { sed -i "s/^endTime .*/endTime         $2;/" "$1/system/controlDict"; }

# sameStates <what> <tol> <timeDirA> <timeDirB> "<fields>" <body>...: each
# body has the same particles in both, and its fields by id agree within
# tol. (The order of particles sharing a cell can differ after a restart,
# so sums are added in another order: round-off, nothing more.)
sameStates()
{
    local what="$1" tol="$2" a="$3" b="$4" fields="$5" body d
    shift 5
    for body in "$@"; do
        bodyTable "$a" $body $fields > "$scratch/a.$body"
        bodyTable "$b" $body $fields > "$scratch/b.$body"
        check "$what: $body has the same particles" \
            [ -s "$scratch/a.$body" -a "$(wc -l < "$scratch/a.$body")" = "$(wc -l < "$scratch/b.$body")" ]
        d=$(maxDifference "$scratch/a.$body" "$scratch/b.$body")
        check "$what: $body restarted equals uninterrupted (max |diff| $d)" \
            isFinite "$d" "v < $tol"
    done
}

# restartPair <scheme>: the dam break run whole and in two halves with the
# time scheme of system/sphSchemes (the Verlet scheme takes an Euler step
# after each write, so that a restart repeats the steps it continues).
restartPair()
{
    local scheme=$1 whole="$scratch/whole.$1" halves="$scratch/halves.$1"
    local c a b tol
    for c in "$whole" "$halves"; do
        cp -r "$source" "$c"
        sed -i 's/^writeFormat .*/writeFormat     ascii;/; s/^writePrecision .*/writePrecision  17;/; s/^writeInterval .*/writeInterval   0.01;/' \
            "$c/system/controlDict"
        echo "timeScheme $scheme;" >> "$c/system/sphSchemes"
        (cd "$c" && generateParticles > log.generateParticles 2>&1)
    done

    setEnd "$whole" 0.06
    (cd "$whole" && sphVcpmFsi > log.sphVcpmFsi 2>&1)
    check "$scheme: uninterrupted run to 0.06 s succeeds" grep -q '^End' "$whole/log.sphVcpmFsi"
    expectIn "$scheme: the log names the scheme" "$whole/log.sphVcpmFsi" "time scheme $scheme"

    setEnd "$halves" 0.05
    (cd "$halves" && sphVcpmFsi > log.first 2>&1)
    check "$scheme: first half to 0.05 s succeeds" grep -q '^End' "$halves/log.first"
    setEnd "$halves" 0.06
    (cd "$halves" && sphVcpmFsi > log.second 2>&1)
    check "$scheme: second half succeeds" grep -q '^End' "$halves/log.second"
    expectIn "$scheme: second half starts from the latest time" "$halves/log.second" \
        '^Reading time 0.05'
    check "$scheme: second half writes function objects under the restart time" \
        [ -f "$halves/postProcessing/energy/0.05/energy.dat" ]

    a=$(timeEntry "$whole" index); b=$(timeEntry "$halves" index)
    check "$scheme: the same number of steps ($a, $b)" [ "$a" = "$b" ]
    a=$(timeEntry "$whole" deltaT); b=$(timeEntry "$halves" deltaT)
    check "$scheme: the same last time step ($a, $b)" \
        awk -v a="$a" -v b="$b" 'BEGIN { d = (a - b)/a; exit !(d < 1e-9 && d > -1e-9) }'

    # Float round-off (rho of 1000 has ulps of 6e-5) grows over the same steps.
    tol=1e-9
    singleBuild "$whole/log.sphVcpmFsi" && tol=1e-3
    sameStates "$scheme" "$tol" "$whole/0.06" "$halves/0.06" "position U rho" water box
}
timeEntry() { awk -v k=$2 '$1 == k { sub(";", "", $2); print $2 }' "$1/0.06/uniform/time"; }
restartPair symplectic
restartPair verlet

# The coupled case: damBreakSmall2D with a rubber plate in the water's way.
fsi="$scratch/fsiSource"
cp -r "$source" "$fsi"
sed -i 's/^writeFormat .*/writeFormat     ascii;/; s/^writePrecision .*/writePrecision  17;/; s/^writeInterval .*/writeInterval   0.02;/' \
    "$fsi/system/controlDict"
awk '{ print } prev == "bodies" && $0 == "{" {
    print "    plate"
    print "    {"
    print "        type solid;"
    print "        shapes { p { shape box; min (0.5 0 0); max (0.54 0.15 0); } }"
    print "        clamp  { c { shape box; min (0 -1 0); max (1 0.02 0); } }"
    print "    }" } { prev = $0 }' "$source/system/generateParticlesDict" \
    > "$fsi/system/generateParticlesDict"
cat > "$fsi/constant/solidProperties" <<'DICT'
plate { rho 1000; E 1e7; nu 0.3; lattice square2D; plane planeStrain; }
DICT
# fsiRestartPair <scheme>: the coupled case run to 0.32 s at once and in
# two halves (to 0.3, then on) with that time scheme; the two end states
# agree. Under Verlet the solid's force 1.5 F^n - 0.5 F^{n-1} is not in the
# written state: the Euler step after each write takes F^n alone, in both
# runs. Its cases: fsiWhole<scheme>, fsiHalves<scheme>.
fsiRestartPair()
{
    local s="$1" whole="$scratch/fsiWhole$1" halves="$scratch/fsiHalves$1" c
    for c in "$whole" "$halves"; do
        cp -r "$fsi" "$c"
        echo "timeScheme $s;" >> "$c/system/sphSchemes"
        (cd "$c" && generateParticles > log.generateParticles 2>&1)
    done
    check "fsi $s: the case has a plate" [ -d "$whole/0/plate" ]
    setEnd "$whole" 0.32
    (cd "$whole" && sphVcpmFsi > log.sphVcpmFsi 2>&1)
    check "fsi $s: uninterrupted run to 0.32 s succeeds" grep -q '^End' "$whole/log.sphVcpmFsi"
    setEnd "$halves" 0.3
    (cd "$halves" && sphVcpmFsi > log.first 2>&1)
    setEnd "$halves" 0.32
    (cd "$halves" && sphVcpmFsi > log.second 2>&1)
    check "fsi $s: the continued run succeeds" grep -q '^End' "$halves/log.second"
    expectIn "fsi $s: it starts from 0.3" "$halves/log.second" '^Reading time 0.3$'
    # In float the stiff plate's round-off grows to about 1 cm/s in U.
    local tol=1e-9
    singleBuild "$halves/log.second" && tol=0.05
    sameStates "fsi $s" "$tol" "$whole/0.32" "$halves/0.32" "position U" water plate
    # The plate had moved: the comparison is not between two resting plates.
    local u
    u=$(fieldValues "$whole/0.32/plate/displacement" | awk '{ m2 = $1*$1 + $2*$2; if (m2 > m) m = m2 } END { print sqrt(m) }')
    check "fsi $s: the plate moved ($u m)" awk -v u="$u" 'BEGIN { exit !(u > 1e-4) }'
}
fsiRestartPair symplectic
fsiRestartPair verlet
# The damaged restarts below start from the symplectic pair's cases.
mv "$scratch/fsiWholesymplectic" "$scratch/fsiWhole"
mv "$scratch/fsiHalvessymplectic" "$scratch/fsiHalves"

# A damaged restart time is refused, naming what is missing, instead of
# going on from defaults: a field that carries the state, a body, every
# particle of the solid (that one crashed a function object).
c="$scratch/damaged"
cp -r "$scratch/fsiHalves" "$c"
setEnd "$c" 0.34
wall=$(cd "$c/0" && ls -d */ | tr -d / | grep -vx -e water -e plate -e uniform | head -1)
restartFails()    # restartFails <what> <pattern>: exit 1 saying pattern
{
    (cd "$c" && sphVcpmFsi > log.damaged 2>&1)
    check "$1: exit status 1" [ $? -eq 1 ]
    expectIn "$1: says what is wrong" "$c/log.damaged" "$2"
    rm -rf "$c/0.32"
    cp -r "$scratch/fsiHalves/0.32" "$c/0.32"
}
rm "$c/0.32/water/U"
restartFails "restart without water/U" "Field .*0.32/water/U is missing: a restart needs it"
withFirstValue "$scratch/fsiHalves/0.32/plate/clamped" 7 > "$c/0.32/plate/clamped"
restartFails "clamped 7" "particle id [0-9]+ has clamped 7 in .*0.32/plate/clamped: expected 0 \\(free\\) or 1"
rm "$c/0.32/plate/Umean"
restartFails "restart without plate/Umean" "0.32/plate/Umean is missing"
rm -r "$c/0.32/$wall"
restartFails "restart without the walls" "Body $wall of 0/ is missing from the restart time"
# emptyFields <body dir>: every field of the body with no particles.
emptyFields()
{
    local f
    for f in "$1"/*; do
        [ "${f##*/}" = bodyProperties ] && continue
        python3 - "$f" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
open(sys.argv[1], 'w').write(re.sub(r'(nonuniform List<\w+>)\s*\d+\s*\(.*?\)\s*;',
                                    r'\1 0();', t, flags=re.S))
PY
    done
}
emptyFields "$c/0.32/plate"
restartFails "restart with an empty plate" "Body plate of .*0.32 has no particles"

# A fluid body may lose every particle through the domain bounds, and the
# solver writes it empty: a restart from there goes on (the solid and the
# walls alone), saying so.
emptyFields "$c/0.32/water"
(cd "$c" && sphVcpmFsi > log.emptyWater 2>&1)
check "restart with an empty water: the run ends" grep -q '^End' "$c/log.emptyWater"
expectIn "restart with an empty water: the log says so" "$c/log.emptyWater" \
    "water \\(fluid\\): no particles left"
rm -rf "$c"/0.3[0-9]*
cp -r "$scratch/fsiHalves/0.32" "$c/0.32"

# A write that fails (here past a file-size limit, as on a full disk)
# stops the run naming the file and the reason, not killed by SIGXFSZ
# without a word; the time it was writing is not left half written, and a
# run without the limit starts again from the last complete time.
# limited <blocks> <log> <application>: runs it in $c under a file-size
# limit of that many KiB; its log is written by cat, outside the limit.
limited()
{
    (cd "$c" && ulimit -f "$1" && exec "$3") 2>&1 | cat > "$c/$2"
    return "${PIPESTATUS[0]}"
}
c="$scratch/fileLimit"
cp -r "$source" "$c"
setEnd "$c" 0.02
(cd "$c" && generateParticles > log.generateParticles 2>&1)
limited 2 log.limited sphVcpmFsi
check "file-size limit, function object: exit status 1" [ $? -eq 1 ]
expectIn "file-size limit, function object: names the file and the reason" "$c/log.limited" \
    "Function object '[a-zA-Z]+': cannot write .*postProcessing/.*\\.dat: File too large \\(the file ends with the last whole row\\)"
# The row the limit cut is cut off again: every table ends with a newline
# and its rows (after the header) all have as many columns as the first.
torn=""
for f in $(find "$c/postProcessing" -name '*.dat'); do
    [ -s "$f" ] || continue
    [ -z "$(tail -c 1 "$f")" ] || torn="$torn $f(no final newline)"
    awk '!/^#/ { if (n == 0) n = NF; else if (NF != n) bad = 1 } END { exit bad }' "$f" \
        || torn="$torn $f(a short row)"
done
check "file-size limit, function object: no half row left${torn:+:$torn}" [ -z "$torn" ]
sed -i '/^functions/,$d' "$c/system/controlDict"
limited 10 log.limited sphVcpmFsi
check "file-size limit, fields: exit status 1" [ $? -eq 1 ]
expectIn "file-size limit, fields: names the file and the reason" "$c/log.limited" \
    "Error writing .*/\\.0\\.02\\.tmp\\.[0-9]+/[a-z]+/[A-Za-z]+.: File too large"
check "file-size limit: no time half written" [ "$(cd "$c" && ls -A | grep -c '^\.\?0\.')" = 0 ]
(cd "$c" && sphVcpmFsi > log.sphVcpmFsi 2>&1)
check "file-size limit lifted: the run ends" grep -q '^End' "$c/log.sphVcpmFsi"
check "file-size limit lifted: 0.02 written" [ -f "$c/0.02/water/position" ]
limited 2 log.vtkLimited particlesToVTK
check "file-size limit, particlesToVTK: exit status 1" [ $? -eq 1 ]
expectIn "file-size limit, particlesToVTK: names the file and the reason" "$c/log.vtkLimited" \
    "Error writing .*VTK/.*: File too large"
check "file-size limit, particlesToVTK: no temporary file left" \
    [ -z "$(find "$c/VTK" -name '.*tmp*' 2>/dev/null)" ]

# Time names that would repeat: timeFormat fixed with 1 digit names 5e-05
# and 1e-04 both "0.0"; the solver raises the precision, says so, and
# writes two directories, each holding its own time.
c="$scratch/names"
cp -r "$source" "$c"
sed -i 's/^writeInterval .*/writeInterval   5e-5;\ntimeFormat fixed; timePrecision 1;/' "$c/system/controlDict"
setEnd "$c" 1e-4
(cd "$c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.sphVcpmFsi 2>&1)
check "names: the run ends" grep -q '^End' "$c/log.sphVcpmFsi"
expectIn "names: the precision raised, with a warning" "$c/log.sphVcpmFsi" \
    "Increased the timePrecision from 1 to 5"
check "names: 0.00005 and 0.00010 written" [ -d "$c/0.00005/water" -a -d "$c/0.00010/water" ]
check "names: 0.00005 holds its own time" grep -q '^value *5e-05;' "$c/0.00005/uniform/time"
# purgeWrite across a restart: the writes of the run before it count, so
# that a run stopped and continued keeps the initial time and the last two,
# as one never stopped (each restart had left the earlier run's behind).
pw="$scratch/purged"
cp -r "$source" "$pw"
sed -i 's/^writeInterval .*/writeInterval   0.005;\npurgeWrite 2;/' "$pw/system/controlDict"
setEnd "$pw" 0.015
(cd "$pw" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.first 2>&1)
check "purgeWrite: the first run keeps 0 and its last two" [ "$(cd "$pw" && ls -d [0-9]* | sort -g | tr '\n' ' ')" = "0 0.01 0.015 " ]
setEnd "$pw" 0.025
(cd "$pw" && sphVcpmFsi > log.second 2>&1)
check "purgeWrite: the restart ends" grep -q '^End' "$pw/log.second"
check "purgeWrite: after the restart, 0 and the last two ($(cd "$pw" && ls -d [0-9]* | sort -g | tr '\n' ' '))" \
    [ "$(cd "$pw" && ls -d [0-9]* | sort -g | tr '\n' ' ')" = "0 0.02 0.025 " ]

# What interrupted writes left (hidden .<time>.tmp.<pid>) is removed when
# its writer is gone and <time> was written; it is kept while its writer
# runs (this shell stands for one), and where <time> is missing beside a
# .old (a write stopped between its two renames leaves the time's only
# copies there). A .tmp alone never got its name (a partial write), and a
# .purge was being deleted (purgeWrite): both removed.
true & wait $!; gone=$!
mkdir -p "$c/.0.00005.tmp.$gone/water" "$c/.0.00005.tmp.$$/water" \
    "$c/.0.0003.old.$gone/water" "$c/.0.0003.tmp.$gone/water" \
    "$c/.0.0007.tmp.$gone/water" "$c/.0.00001.purge.$gone/water"
(cd "$c" && sphVcpmFsi > log.leftovers 2>&1)
check "leftovers: the run ends" grep -q '^End' "$c/log.leftovers"
check "leftovers: a dead writer's is removed" [ ! -d "$c/.0.00005.tmp.$gone" ]
expectIn "leftovers: the log says so" "$c/log.leftovers" "Removed .0.00005.tmp.$gone, left by an interrupted write"
check "leftovers: a running writer's is kept" [ -d "$c/.0.00005.tmp.$$" ]
check "leftovers: a .old whose time is missing is kept" [ -d "$c/.0.0003.old.$gone" ]
check "leftovers: so is the .tmp beside it" [ -d "$c/.0.0003.tmp.$gone" ]
expectIn "leftovers: a warning says where the missing time is, and how to keep it" "$c/log.leftovers" \
    "Time 0.0003 is missing: a run was stopped between the two renames of its write, and its only copies are hidden in .0.0003.old.$gone .*and .0.0003.tmp.$gone \\(the new write, complete\\). To keep the new write: mv .0.0003.tmp.$gone 0.0003"
check "leftovers: a .tmp alone whose time is missing is removed" [ ! -d "$c/.0.0007.tmp.$gone" ]
check "leftovers: a purge left half-done is removed" [ ! -d "$c/.0.00001.purge.$gone" ]
rm -rf "$c/.0.00005.tmp.$$" "$c/.0.0003.old.$gone" "$c/.0.0003.tmp.$gone"
# A name with a number beyond any process id is not the writer's: kept,
# and no crash on reading it.
mkdir -p "$c/.0.00005.tmp.99999999999999999999/water"
(cd "$c" && sphVcpmFsi > log.longPid 2>&1)
check "leftovers: a name beyond any process id: the run ends" grep -q '^End' "$c/log.longPid"
check "leftovers: a name beyond any process id is kept" [ -d "$c/.0.00005.tmp.99999999999999999999" ]
rm -rf "$c/.0.00005.tmp.99999999999999999999"

# A fluid-only restart needs no 0/: with 0/ archived it compares the
# restart time with the earliest time left, and goes on.
mv "$c/0" "$c/0.archived"
setEnd "$c" 1.5e-4
(cd "$c" && sphVcpmFsi > log.noZero 2>&1)
check "restart without 0/: the run ends" grep -q '^End' "$c/log.noZero"
check "restart without 0/: 0.00015 written" [ -d "$c/0.00015/water" ]
mv "$c/0.archived" "$c/0"

# A time directory copied under another name (its uniform/time says
# another time) is refused, naming the file, not restarted at the wrong time.
cp -r "$c/0.00005" "$c/0.0002"
(cd "$c" && sphVcpmFsi > log.copied 2>&1)
check "copied time: exit status 1" [ $? -eq 1 ]
expectIn "copied time: says what is wrong" "$c/log.copied" \
    "the time 5.0000000000000002e-05 is not the time of its directory '0.0002'"
expectIn "copied time: names the file" "$c/log.copied" "0.0002/uniform/time at line"

# A non-zero time without uniform/time (0/ copied there, without its
# uniform/) starts as a fresh start from it, with a warning: every write
# of the solvers has one.
rm -rf "$c/0.0002"
cp -r "$c/0" "$c/0.0003"
rm -rf "$c/0.0003/uniform"
setEnd "$c" 3.5e-4
(cd "$c" && sphVcpmFsi > log.noUniform 2>&1)
check "time without uniform/time: the run ends" grep -q '^End' "$c/log.noUniform"
expectIn "time without uniform/time: a warning" "$c/log.noUniform" \
    "Time 0.0003 has no uniform/time: it starts as a fresh start"

finish
