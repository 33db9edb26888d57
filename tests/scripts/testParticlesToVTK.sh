#!/bin/bash
# particlesToVTK on a known case (water + tank at times 0, 0.1, 0.2 written
# by the test helper writeParticleCase): the log, the files, the series
# growing with a later -latestTime, -fields and -time, the FATAL ERRORs,
# then ParaView itself (pvpython + checkVtk.py) opens the series and checks
# counts, arrays, values and times. Without pvpython the ParaView part is
# skipped (exit 77 when everything else passed).
. "$(dirname "$0")/testLib.sh"

helper="${SPHVCPM_TESTBIN:-$SPHVCPM_DIR/platforms/tests}/writeParticleCase"
if [ ! -x "$helper" ]; then
    echo "FAIL: test helper $helper not built (./Allwmake -test builds it)"
    exit 1
fi
if ! command -v particlesToVTK > /dev/null; then
    echo "FAIL: particlesToVTK not on the PATH (./Allwmake builds it)"
    exit 1
fi

run="$scratch/case"
mkdir -p "$run"
"$helper" -case "$run" -times '(0 0.1)' > "$scratch/log.helper" 2>&1
check "helper writes times 0 and 0.1" [ $? -eq 0 -a -d "$run/0.1/water" ]
# 0/ as generateParticles writes it: no uniform/time, so time index 0.
rm -rf "$run/0/uniform"

# Every time.
log="$scratch/log.all"
particlesToVTK -case "$run" > "$log" 2>&1
check "particlesToVTK converts every time (exit 0)" [ $? -eq 0 ]
expectIn "log: banner" "$log" "^Exec   : particlesToVTK -case "
expectIn "log: Time = 0" "$log" "^Time = 0$"
expectIn "log: water at 0" "$log" \
    "^    water: 200 particles -> VTK/water/water_0\.vtp$"
expectIn "log: tank at 0" "$log" \
    "^    tank: 78 particles -> VTK/tank/tank_0\.vtp$"
expectIn "log: Time = 0.1" "$log" "^Time = 0\.1$"
expectIn "log: water at 0.1 has index 100" "$log" \
    "^    water: 200 particles -> VTK/water/water_100\.vtp$"
expectIn "log: ExecutionTime" "$log" \
    "^ExecutionTime = [0-9.e+-]+ s  ClockTime = [0-9]+ s$"
expectIn "log: End" "$log" "^End$"
for f in water/water_0.vtp water/water_100.vtp tank/tank_0.vtp \
         tank/tank_100.vtp water.vtp.series tank.vtp.series; do
    check "VTK/$f written" [ -s "$run/VTK/$f" ]
done
check "no temporary files left in VTK/" \
    [ -z "$(find "$run/VTK" -name '.*' -type f)" ]

# A later time converted alone joins the series; older files stay as they
# were.
touch -d @1000000000 "$run/VTK/water/water_100.vtp"
"$helper" -case "$run" -times '(0.2)' > "$scratch/log.helper2" 2>&1
log="$scratch/log.latest"
particlesToVTK -case "$run" -latestTime > "$log" 2>&1
check "particlesToVTK -latestTime (exit 0)" [ $? -eq 0 ]
expectIn "-latestTime converts 0.2" "$log" \
    "^    water: 200 particles -> VTK/water/water_200\.vtp$"
check "-latestTime converts only 0.2" [ "$(grep -c '^Time = ' "$log")" = 1 ]
check "-latestTime leaves water_100.vtp alone" \
    [ "$(stat -c %Y "$run/VTK/water/water_100.vtp")" = 1000000000 ]
for body in water tank; do
    series="$run/VTK/$body.vtp.series"
    check "$body.vtp.series lists 3 files" \
        [ "$(grep -c '"name"' "$series")" = 3 ]
    expectIn "$body.vtp.series: time 0.2 of ${body}_200.vtp" "$series" \
        "\"name\" : \"$body/${body}_200\.vtp\", \"time\" : 0\.2 "
done
cat "$run/VTK/water.vtp.series"

# -time and -fields on a copy (the series above is checked by ParaView).
cp -r "$run" "$scratch/copy"
log="$scratch/log.fields"
particlesToVTK -case "$scratch/copy" -time '0.05:0.15' -fields '(rho)' \
    > "$log" 2>&1
check "-time '0.05:0.15' -fields '(rho)' (exit 0)" [ $? -eq 0 ]
check "-time '0.05:0.15' converts only 0.1" \
    [ "$(grep '^Time = ' "$log")" = "Time = 0.1" ]
header=$(head -c 3000 "$scratch/copy/VTK/water/water_100.vtp" | tr -d '\0')
arrays=$(echo "$header" | sed -n 's/.*<DataArray [^>]*Name="\([^"]*\)".*/\1/p' \
    | tr '\n' ' ')
check "-fields '(rho)' keeps rho and id (got: $arrays)" \
    [ "$arrays" = "TimeValue rho id Points connectivity offsets " ]

# Errors: the FATAL ERROR block, the culprit named, exit status 1.
expectFatal() { expectFatalOf "$@"; }
expectFatal "unknown field" "Field 'bogus' given by -fields" \
    particlesToVTK -case "$run" -fields '(rho bogus)'
expectFatal "bad -time" "Invalid -time 'x'" \
    particlesToVTK -case "$run" -time x
expectFatal "empty -time range" "range '0.5:0.1' is empty" \
    particlesToVTK -case "$run" -time 0.5:0.1
expectFatal "-time selecting nothing" "No time of case .* is selected by -time '5:6'" \
    particlesToVTK -case "$run" -time 5:6
mkdir -p "$scratch/empty/system"
expectFatal "case without time directories" \
    "No time directories in case .*: run generateParticles first to write 0/" particlesToVTK -case "$scratch/empty"

# ParaView.
if ! command -v pvpython > /dev/null; then
    echo "pvpython not found: ParaView checks skipped"
    finish || exit 1
    exit 77
fi
# checkVtk.py compares values bit for bit with doubles: a single-precision
# build writes Float32, so only that ParaView reads it is checked there.
single=0
singleBuild "$scratch/log.all" && single=1
# Reading needs no display; offscreen keeps Qt from looking for one.
QT_QPA_PLATFORM=offscreen pvpython "$SPHVCPM_DIR/tests/scripts/checkVtk.py" \
    "$run" 0,0.1,0.2 20 10 2 > "$scratch/log.pvpython" 2>&1
status=$?
cat "$scratch/log.pvpython"
if [ $single = 1 ]; then
    check "ParaView reads the series (checkVtk.py; single: values not compared)" \
        [ $(grep -c '^FAIL' "$scratch/log.pvpython") -eq \
          $(grep -c '^FAIL:.*\(bit-exact\|values\|range\)' "$scratch/log.pvpython") ]
else
    check "ParaView reads the series (checkVtk.py)" [ $status -eq 0 ]
fi

finish
