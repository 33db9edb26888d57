#!/bin/bash
# particlesToVTK's time options as a user mixes them: -time with
# -latestTime is an error (exit 1, not the latest time alone), and a -time
# no directory matches takes the nearest one, saying which.
. "$(dirname "$0")/testLib.sh"

helper="${SPHVCPM_TESTBIN:-$SPHVCPM_DIR/platforms/tests}/writeParticleCase"
if [ ! -x "$helper" ]; then
    echo "FAIL: test helper $helper not built (./Allwmake -test builds it)"
    exit 1
fi

run="$scratch/case"
mkdir -p "$run"
"$helper" -case "$run" -times '(0 0.1 0.6)' > "$scratch/log.helper" 2>&1
check "helper writes times 0, 0.1 and 0.6" [ $? -eq 0 -a -d "$run/0.6/water" ]

# Both orders: the FATAL ERROR names both options, nothing is converted.
for options in "-time 0.1 -latestTime" "-latestTime -time 0.1"; do
    log="$scratch/log.conflict"
    particlesToVTK -case "$run" $options > "$log" 2>&1
    check "$options: exit 1" [ $? -eq 1 ]
    expectIn "$options: FATAL ERROR" "$log" "SPHVCPM FATAL ERROR"
    expectIn "$options: says they conflict" "$log" \
        "Options -time '0\.1' and -latestTime conflict"
    check "$options: converts nothing" [ ! -d "$run/VTK" ]
done

# -time 0.7: 0.6, and a line saying so.
log="$scratch/log.nearest"
particlesToVTK -case "$run" -time 0.7 > "$log" 2>&1
check "-time 0.7: exit 0" [ $? -eq 0 ]
expectIn "-time 0.7: names the nearest time" "$log" \
    "^-time 0\.7: the nearest time written is 0\.6$"
check "-time 0.7: converts only 0.6" \
    [ "$(grep '^Time = ' "$log")" = "Time = 0.6" ]

# A time that exists, or a range: no such line.
log="$scratch/log.exact"
particlesToVTK -case "$run" -time '0.6,0:0.2' > "$log" 2>&1
check "-time '0.6,0:0.2': exit 0" [ $? -eq 0 ]
check "-time '0.6,0:0.2': no nearest-time line" \
    [ -z "$(grep 'nearest time' "$log")" ]
check "-time '0.6,0:0.2': converts 0, 0.1 and 0.6" \
    [ "$(grep -c '^Time = ' "$log")" = 3 ]

finish
