#!/bin/bash
# The rolling tanks' post-processing (tutorials/sphVcpmFsi/rollingTank2D/
# rollingFunctions) on synthetic records, whose answers are known: the
# period and amplitude of a sine sampled unevenly, with ripples about zero
# that must add no crossing; tables from a restart merged in time order;
# rollingResults and rollingChecks on a synthetic case (the real roll
# record, a plate tip, two gauges and an energy table). A table that is
# empty, header-only, missing or holds nan, -nan or inf gives nan ("none"
# for a period), which the checks fail.
source "$(dirname "$0")/testLib.sh"
source "$SPHVCPM_DIR/bin/tools/RunFunctions"
source "$SPHVCPM_DIR/tutorials/sphVcpmFsi/rollingTank2D/rollingFunctions"

# sine <file> <period> <amplitude> <ripple amplitude>: "t x" over 0-5 s,
# x = a sin(2 pi t/T) + r sin(2 pi 40 t), sampled every 1 ms plus up to
# 0.5 ms
sine()
{
    awk -v T="$2" -v a="$3" -v r="$4" 'BEGIN { pi = atan2(0, -1); srand(7)
        for (n = 0; n < 5000; n++) { t = (n + 0.5*rand())*0.001
            printf "%.10g %.10g\n", t, a*sin(2*pi*t/T) + r*sin(2*pi*40*t) } }' > "$1"
}

# near <what> <value> <expected> <relative tolerance>
near()
{
    check "$1: $2 (expected $3 within $4 of it)" \
        isFinite "$2" "(v - $3 < 0 ? $3 - v : v - $3) <= $4*($3 < 0 ? -$3 : $3)"
}

# notFinite <value>: empty, nan, inf or no number
notFinite() { ! isFinite "$1"; }

# failsCheck <what> <value> <limit>: checkValue counts it as a failure
failsCheck()
{
    local before=$validationFailures
    checkValue "$1" "$2" "$3" > /dev/null
    check "$1: '$2' fails checkValue (limit $3)" [ "$validationFailures" -gt "$before" ]
}

d="$scratch/tables"
mkdir -p "$d"

# A sine of period 1.214 s (the roll's) and amplitude 0.0123.
sine "$d/sine.dat" 1.214 0.0123 0
near "sine: period after 1.5 s" "$(periodOf "$d/sine.dat" 2 1.5)" 1.214 1e-3
near "sine: amplitude after 1.5 s" "$(amplitudeOf "$d/sine.dat" 2 1.5)" 0.0123 1e-3
near "sine: period from the start" "$(periodOf "$d/sine.dat" 2 0)" 1.214 1e-3

# Ripples of 3 % of the amplitude at 40 Hz cross zero several times at each
# crossing (their slope is 1.5 times the sine's): they add none.
sine "$d/ripples.dat" 0.8 0.02 0.0006
near "ripples: period" "$(periodOf "$d/ripples.dat" 2 1.5)" 0.8 5e-3
near "ripples: amplitude" "$(amplitudeOf "$d/ripples.dat" 2 1.5)" 0.0206 2e-3

# Fewer than two crossings after t0: no period.
check "one crossing after 4.5 s: no period" \
    [ "$(periodOf "$d/sine.dat" 2 4.5)" = none ]

# Broken tables: empty, header-only, missing, a nan, -nan or inf after t0.
: > "$d/empty.dat"
echo "# t x" > "$d/header.dat"
for bad in nan -nan inf; do
    awk -v b=$bad '!/^#/ && $1 > 3 && !done { $2 = b; done = 1 } { print }' "$d/sine.dat" > "$d/$bad.dat"
done
for f in empty header missing nan -nan inf; do
    a=$(amplitudeOf "$d/$f.dat" 2 1.5 2> /dev/null)
    p=$(periodOf "$d/$f.dat" 2 1.5 2> /dev/null)
    check "$f table: no amplitude ($a)" notFinite "$a"
    check "$f table: no period ($p)" [ "$p" = none ]
    failsCheck "$f table: amplitude" "$a" 1e300
    failsCheck "$f table: period against the roll's, as rollingChecks" \
        "$(awk -v a=$p -v b=1.214 'BEGIN { print 100*(a - b)/b }')" 5
done
# A nan before t0 is not in the window.
awk '!/^#/ && $1 > 1 && !done { $2 = "nan"; done = 1 } { print }' "$d/sine.dat" > "$d/early.dat"
near "a nan before t0: amplitude after it" "$(amplitudeOf "$d/early.dat" 2 1.5)" 0.0123 1e-3

# ratio: signed per cent
check "ratio 1.1 1: +10.0 % ($(ratio 1.1 1))" [ "$(ratio 1.1 1)" = "+10.0 %" ]

# A synthetic case: the measured roll (the tutorial's csv, lines ending in
# CR LF), the plate tip swinging 20 mm at 1.214 s, the left and right
# gauges 10 and 12 mm about the still level 0.116 m (read from 0.05 m below
# the floor), the energy written in two parts (a restart at 2.5 s, rows
# overlapping), the mass 10 kg but 9.995 kg once, the kinetic energy 0.5 +-
# 0.5 J, the potential 20 J.
c="$scratch/case"
mkdir -p "$c/validation" "$c/postProcessing/plateTip/0" "$c/postProcessing/levels/0" \
    "$c/postProcessing/energy/0" "$c/postProcessing/energy/2.5"
cp "$SPHVCPM_DIR/tutorials/sphVcpmFsi/rollingTank2D/validation/ROLLING_TANK_IDELSOHN_REFERENCE.csv" \
    "$c/validation/"
pp="$c/postProcessing"
awk -v tip="$pp/plateTip/0/displacement.dat" -v levels="$pp/levels/0/height.dat" \
    -v e0="$pp/energy/0/energy.dat" -v e1="$pp/energy/2.5/energy.dat" 'BEGIN {
    pi = atan2(0, -1); w = 2*pi/1.214
    print "# Time dx dy dz" > tip; print "# Time left right" > levels
    print "# Time mass kinetic potential" > e0; print "# Time mass kinetic potential" > e1
    for (n = 0; n <= 2500; n++) { t = n*0.002; s = sin(w*t)
        printf "%.6g %.8g 0 0\n", t, 0.02*s > tip
        printf "%.6g %.8g %.8g\n", t, 0.166 + 0.01*s, 0.166 - 0.012*s > levels
        m = (n == 2000) ? 9.995 : 10; e = sprintf("%.6g %g %.8g 20\n", t, m, 0.5 + 0.5*s)
        if (t <= 2.6) printf "%s", e > e0
        if (t >= 2.5) printf "%s", e > e1 } }'

check "seriesOf: the restart's rows once, in time order" \
    awk '!/^#/ { n++; if (n > 1 && $1 <= last) bad = 1; last = $1 }
         END { exit !(n == 2501 && !bad) }' <(seriesOf "$c" energy energy.dat)

rollingResults "$c"
near "the roll record's period" "$rollPeriod" 1.214 2e-3
near "the roll record's amplitude (about 3.96 deg)" \
    "$(amplitudeOf "$c/postProcessing/rolling/roll.dat" 2 1.5)" 3.96 2e-3
near "tip period, tank frame" "$tipPeriod" 1.214 0.05
near "left gauge's period" "$leftPeriod" 1.214 1e-3
near "left gauge's amplitude" "$leftAmplitude" 0.01 1e-3
near "right gauge's amplitude" "$rightAmplitude" 0.012 1e-3
near "mass at the start" "$mass0" 10 1e-12
near "potential energy at the start" "$pot0" 20 1e-12
near "least mass" "$massMin" 9.995 1e-12
near "largest mass" "$massMax" 10 1e-12
near "largest kinetic energy" "$kinMax" 1 1e-5
validationFailures=0
rollingChecks $tipPeriod $leftPeriod $massMin $mass0 $kinMax $pot0 > "$scratch/checks.out"
check "rollingChecks on the synthetic case: all pass" [ "$validationFailures" -eq 0 ]

# A NaN row of the energy (dropped by the max before) and a header-only
# energy table: nan, and rollingChecks fails.
for bad in nanRow header; do
    cp -r "$c" "$c.$bad"
    rm -rf "$c.$bad/postProcessing/rolling"
    e="$c.$bad/postProcessing/energy/2.5/energy.dat"
    if [ $bad = nanRow ]; then
        sed -i '100s/^\([^ ]*\) \([^ ]*\) [^ ]*/\1 \2 nan/' "$e"
    else
        echo "# Time mass kinetic potential" > "$e"
        echo "# Time mass kinetic potential" > "$c.$bad/postProcessing/energy/0/energy.dat"
    fi
    rollingResults "$c.$bad"
    check "$bad energy: largest kinetic energy not finite ($kinMax)" notFinite "$kinMax"
    check "$bad energy: least mass not finite ($massMin)" notFinite "$massMin"
    validationFailures=0
    rollingChecks $tipPeriod $leftPeriod $massMin $mass0 $kinMax $pot0 > "$scratch/checks.out"
    check "$bad energy: rollingChecks fails the mass and energy checks" [ "$validationFailures" -eq 2 ]
done

finish
