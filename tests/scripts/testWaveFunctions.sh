#!/bin/bash
# bin/tools/WaveFunctions (the wave flumes' validation) on synthetic gauge
# records, whose answers are known: a progressive wave about the still
# level 0.25 m, sampled unevenly with a sample more or less in the windows
# (the plain Fourier sum of the raw level was off by up to 15 % there), its
# k 0.6 % below linear theory (which read as a reflection coefficient of
# 0.2 % with the linear k); the same with a reflected wave of 0.3 %; a
# motion given by frequency, |g| from constant/g; no period or frequency.
source "$(dirname "$0")/testLib.sh"
source "$SPHVCPM_DIR/bin/tools/RunFunctions"
source "$SPHVCPM_DIR/bin/tools/WaveFunctions"

# flume <dir> <period key and value> <g> <k factor> <Kr> <dt> <jitter>:
# a case directory with constant/motion, constant/g (g empty: none), a
# solver log and the six gauges over 0-12 s, sampled every dt plus up to
# jitter dt.
flume()
{
    local c="$1"
    mkdir -p "$c/constant" "$c/postProcessing/waves/0"
    printf 'piston\n{\n    offset\n    {\n        type pistonWave;\n        waveHeight 0.035;\n        depth 0.25;\n        %s;\n    }\n}\n' \
        "$2" > "$c/constant/motion"
    [ -n "$3" ] && printf 'dimensions [0 1 -2 0 0 0 0];\nvalue (0 -%s 0);\n' "$3" > "$c/constant/g"
    printf 'Step = 1 x 1\n' > "$c/log.sphVcpmFsi"
    awk -v g="${3:-9.81}" -v kf="$4" -v Kr="$5" -v dt="$6" -v jit="$7" 'BEGIN {
        pi = atan2(0, -1); w = 2*pi; d = 0.25; k = w*w/g
        for (i = 0; i < 50; i++) { th = (exp(2*k*d) - 1)/(exp(2*k*d) + 1)
            k -= (g*k*th - w*w)/(g*th + g*k*d*(1 - th*th)) }
        k *= kf; a = 0.0175; srand(7)
        for (j = 0; j < 6; j++) { x[j] = 0.75 + 0.25*j; printf "# Gauge %d (%g 0 0)\n", j, x[j] }
        print "# Time h0 h1 h2 h3 h4 h5"
        for (n = 0; n*dt < 12; n++) { t = (n + jit*rand())*dt; printf "%.10g", t
            for (j = 0; j < 6; j++)
                printf " %.10g", d + a*cos(k*x[j] - w*t) + Kr*a*cos(k*x[j] + w*t + 0.7)
            printf "\n" } }' > "$c/postProcessing/waves/0/height.dat"
}

# checkOf <what> <output> <check's letter> <largest |value|>
checkOf()
{
    local v
    v=$(sed -nE "s/^ *\($3\)[^:]*: +([-+0-9.e]+) .*/\1/p" "$2")
    check "$1: ($3) $v, |value| <= $4" awk -v v="$v" -v l="$4" \
        'BEGIN { exit !(v != "" && (v < 0 ? -v : v) <= l) }'
}

# A progressive wave, k 0.6 % short, 199 samples in each window, jittered.
c="$scratch/progressive"
flume "$c" "period 1" "" 0.994 0 0.01005 0.5
(cd "$c" && waveFlumeValidation progressive piston) > "$c/out" 2>&1
check "progressive: validated" [ $? -eq 0 ]
checkOf "progressive" "$c/out" a 0.001
checkOf "progressive" "$c/out" b 0.601
checkOf "progressive" "$c/out" c 0.001
checkOf "progressive" "$c/out" d 0.001
expectIn "progressive: the linear k's false reflection shown" "$c/out" \
    "\(0\.002[0-9] with the linear k; floor 0\.0000"

# The same with a reflected wave of 0.3 %: found with the measured k.
c="$scratch/reflected"
flume "$c" "period 1" "" 0.994 0.003 0.00995 0.5
(cd "$c" && waveFlumeValidation reflected piston) > "$c/out" 2>&1
check "reflected: validated" [ $? -eq 0 ]
checkOf "reflected" "$c/out" c 0.301
expectIn "reflected: 0.3 % found" "$c/out" "\(c\)[^:]*: +0\.(29[5-9]|30[0-5])"

# frequency instead of period; |g| from constant/g (the period 1 s wave
# of g = 9.80665 has k = 4.8201 1/m).
c="$scratch/frequency"
flume "$c" "frequency 1" 9.80665 1 0 0.01 0
(cd "$c" && waveFlumeValidation frequency piston) > "$c/out" 2>&1
check "frequency: validated" [ $? -eq 0 ]
expectIn "frequency: T from it" "$c/out" "T = 1 s"
expectIn "frequency: k with constant/g's |g|" "$c/out" "linear theory: k = 4\.8201 "
checkOf "frequency" "$c/out" b 0.001

# Neither period nor frequency: an error, not a division by zero.
c="$scratch/noPeriod"
flume "$c" "rampTime 2" "" 1 0 0.01 0
(cd "$c" && waveFlumeValidation noPeriod piston) > "$c/out" 2>&1
check "no period: refused" [ $? -ne 0 ]
expectIn "no period: says so" "$c/out" "no positive period or frequency"

finish
