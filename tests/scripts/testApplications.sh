#!/bin/bash
# Common behaviour of every application: -help, unknown options, -case, the
# banner and log words, FATAL ERROR blocks with file/line/keyword, and the
# RunFunctions that tutorials use.
. "$(dirname "$0")/testLib.sh"

apps="generateParticles particlesToVTK sphVcpmFsi"
case2D="$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D"

for app in $apps; do
    out="$scratch/$app.help"
    "$app" -help > "$out" 2>&1
    check "$app -help exits 0" [ $? -eq 0 ]
    expectIn "$app -help prints the usage" "$out" "^Usage: $app "
    expectIn "$app -help lists -case" "$out" "-case <dir>"

    "$app" -bogus > "$out" 2>&1
    check "$app -bogus exits non-zero" [ $? -ne 0 ]
    expectIn "$app -bogus says Invalid option" "$out" "Invalid option: -bogus"

    "$app" -case "$scratch/noSuchCase" > "$out" 2>&1
    check "$app on a missing case exits non-zero" [ $? -ne 0 ]
    expectIn "$app on a missing case: FATAL ERROR" "$out" "SPHVCPM FATAL ERROR"
    expectIn "$app on a missing case names it" "$out" "noSuchCase"
done

# Banner and log words on a real run.
cp -r "$case2D" "$scratch/case"
(cd "$scratch/case" && ./Allclean > /dev/null)
generateParticles -case "$scratch/case" > "$scratch/log.gen" 2>&1
check "generateParticles runs the 2D tank" [ $? -eq 0 ]
for word in "^Build  : " "^Exec   : generateParticles -case" "^Host   : " \
            "^Case   : $scratch/case" "^Threads: [0-9]+" "^Device : cpu" \
            "ExecutionTime = [0-9.e+-]+ s  ClockTime = [0-9]+ s" "^End"; do
    expectIn "generateParticles log has /$word/" "$scratch/log.gen" "$word"
done

# Bad dictionaries: a misspelled keyword and a missing semicolon.
dict="$scratch/case/system/generateParticlesDict"
cp "$dict" "$scratch/dict.orig"
sed -i 's/^dp  /dpp /' "$dict"
line=$(grep -n '^dpp' "$dict" | cut -d: -f1)
generateParticles -case "$scratch/case" > "$scratch/log.bad1" 2>&1
check "misspelled keyword exits 1" [ $? -eq 1 ]
expectIn "misspelled keyword: FATAL IO ERROR" "$scratch/log.bad1" "SPHVCPM FATAL IO ERROR"
expectIn "misspelled keyword: names the keyword" "$scratch/log.bad1" "dpp"
expectIn "misspelled keyword: names file and line" "$scratch/log.bad1" \
    "system/generateParticlesDict.* at line $line"
expectIn "misspelled keyword: suggests dp" "$scratch/log.bad1" "'dp'"

cp "$scratch/dict.orig" "$dict"
sed -i 's/^nDimensions     2;/nDimensions     2/' "$dict"
generateParticles -case "$scratch/case" > "$scratch/log.bad2" 2>&1
check "missing semicolon exits 1" [ $? -eq 1 ]
expectIn "missing semicolon: FATAL IO ERROR with the file" "$scratch/log.bad2" \
    "file: .*system/generateParticlesDict at line [0-9]+"

# RunFunctions: log.<app>, refusal to overwrite, exit status.
cp "$scratch/dict.orig" "$dict"
(
    cd "$scratch/case" || exit 1
    . "$SPHVCPM_DIR/bin/tools/RunFunctions"
    runApplication generateParticles > out1 2>&1; echo "status1=$?"
    runApplication generateParticles > out2 2>&1; echo "status2=$?"
    runApplication -overwrite generateParticles > out3 2>&1; echo "status3=$?"
    runApplication -s bad particlesToVTK -time nonsense > out4 2>&1; echo "status4=$?"
) > "$scratch/run.status"
expectIn "runApplication runs and succeeds" "$scratch/run.status" "^status1=0$"
check "runApplication writes log.generateParticles" \
    grep -q "^End" "$scratch/case/log.generateParticles"
expectIn "runApplication refuses to re-run" "$scratch/run.status" "^status2=[1-9]"
expectIn "runApplication explains the refusal" "$scratch/case/out2" \
    "already run .*remove log file 'log.generateParticles'"
expectIn "runApplication -overwrite re-runs" "$scratch/run.status" "^status3=0$"
expectIn "runApplication passes a failure on" "$scratch/run.status" "^status4=[1-9]"
check "runApplication -s writes log.<app>.<suffix>" \
    [ -f "$scratch/case/log.particlesToVTK.bad" ]

# checkValue: within the limit passes, beyond it or not a finite number
# (a missing or broken result) fails.
(
    cd "$scratch/case" || exit 1
    . "$SPHVCPM_DIR/bin/tools/RunFunctions"
    for v in 4.9 -4.9 1e-3 5.1 -nan nan inf -inf "" abc; do
        validationFailures=0
        checkValue "value $v" "$v" 5 % > /dev/null
        echo "value '$v': $validationFailures"
    done
) > "$scratch/check.status"
for v in 4.9 -4.9 1e-3; do
    expectIn "checkValue passes $v within 5" "$scratch/check.status" "^value '$v': 0$"
done
for v in 5.1 -nan nan inf -inf "" abc; do
    expectIn "checkValue fails '$v' against 5" "$scratch/check.status" "^value '$v': 1$"
done

# A known failure (validation/knownFailures: name | value | band) is not
# counted while its value stays in the band; outside it, not a number, a
# pass, or a line without its band, it is.
mkdir -p "$scratch/case/validation"
printf '# comment | 1 | 2\nbroken result | -19.5 | 3\nno band\n' \
    > "$scratch/case/validation/knownFailures"
(
    cd "$scratch/case" || exit 1
    . "$SPHVCPM_DIR/bin/tools/RunFunctions"
    for v in -19.5 -17 -22.4 -23 -15 nan "" 4; do
        validationFailures=0 validationKnownFailures=0
        checkValue "broken result" "$v" 10 % > "$scratch/known.out"
        echo "known '$v': $validationFailures $validationKnownFailures"
    done
    validationFailures=0
    checkValue "no band" 20 10 % > "$scratch/noBand.out"
    echo "no band: $validationFailures"
) > "$scratch/known.status"
for v in -19.5 -17 -22.4; do
    expectIn "known failure $v in -19.5 +- 3: not counted" "$scratch/known.status" \
        "^known '$v': 0 1$"
done
for v in -23 -15 nan "" 4; do
    expectIn "known failure '$v' outside the band, or passing: counted" \
        "$scratch/known.status" "^known '$v': 1 0$"
done
expectIn "a listed check without its band: counted" "$scratch/known.status" "^no band: 1$"
expectIn "a listed check without its band: says so" "$scratch/noBand.out" \
    "without '\| <known value> \| <band>' after its name"
rm -r "$scratch/case/validation"
finish
