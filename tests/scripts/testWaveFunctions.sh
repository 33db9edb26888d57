#!/bin/bash
# bin/tools/WaveFunctions (the wave flumes' validation) on synthetic gauge
# records, whose answers are known: a progressive wave about the still
# level 0.25 m, sampled unevenly with a sample more or less in the windows
# (the plain Fourier sum of the raw level was off by up to 15 % there), its
# k 0.6 % below linear theory (which read as a reflection coefficient of
# 0.2 % with the linear k); the same with a reflected wave of 0.3 %; the
# theory is the solver's (its log's wavemaker line: height, period, depth,
# |g| and k), so a log without that line is refused.
source "$(dirname "$0")/testLib.sh"
source "$SPHVCPM_DIR/bin/tools/RunFunctions"
source "$SPHVCPM_DIR/bin/tools/WaveFunctions"

# flume <dir> <period> <g> <k factor> <Kr> <dt> <jitter>: a case directory
# with a solver log whose wavemaker line gives the linear k of that period
# and |g| in depth 0.25 m (g empty: no such line), and the six gauges over
# 0-12 s, sampled every dt plus up to jitter dt, of a wave with k times the
# k factor.
flume()
{
    local c="$1"
    mkdir -p "$c/postProcessing/waves/0"
    awk -v T="$2" -v g="$3" -v kf="$4" -v Kr="$5" -v dt="$6" -v jit="$7" -v logFile="$c/log.sphVcpmFsi" 'BEGIN {
        pi = atan2(0, -1); w = 2*pi/T; d = 0.25; k = w*w/(g == "" ? 9.81 : g)
        for (i = 0; i < 50; i++) { th = (exp(2*k*d) - 1)/(exp(2*k*d) + 1)
            k -= ((g == "" ? 9.81 : g)*k*th - w*w)/((g == "" ? 9.81 : g)*(th + k*d*(1 - th*th))) }
        if (g != "")
            printf "    paddle: pistonWave of height 0.035 m, period %g s in depth 0.25 m (|g| %g): k = %.6g 1/m, wavelength %g m\n",
                T, g, k, 2*pi/k > logFile
        print "Step = 1 x 1" > logFile
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
flume "$c" 1 9.81 0.994 0 0.01005 0.5
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
flume "$c" 1 9.81 0.994 0.003 0.00995 0.5
(cd "$c" && waveFlumeValidation reflected piston) > "$c/out" 2>&1
check "reflected: validated" [ $? -eq 0 ]
checkOf "reflected" "$c/out" c 0.301
expectIn "reflected: 0.3 % found" "$c/out" "\(c\)[^:]*: +0\.(29[5-9]|30[0-5])"

# Another period and |g|: the log's k is the one used (the period 0.8 s
# wave of g = 9.80665 has k = 6.7385 1/m, by scipy; the awk Newton solver above
# computed it, as the solver's waveNumber does).
c="$scratch/solverK"
flume "$c" 0.8 9.80665 1 0 0.01 0
(cd "$c" && waveFlumeValidation solverK piston) > "$c/out" 2>&1
check "another period and |g|: validated" [ $? -eq 0 ]
expectIn "another period and |g|: T from the log" "$c/out" "T = 0.8 s"
expectIn "another period and |g|: the log's k" "$c/out" "linear theory: k = 6\.7385 "
checkOf "another period and |g|" "$c/out" b 0.001

# No wavemaker line in the log: an error saying so, not a division by zero.
c="$scratch/noWavemaker"
flume "$c" 1 "" 1 0 0.01 0
(cd "$c" && waveFlumeValidation noWavemaker piston) > "$c/out" 2>&1
check "no wavemaker line: refused" [ $? -ne 0 ]
expectIn "no wavemaker line: says so" "$c/out" "log.sphVcpmFsi has no pistonWave or flapWave line"

finish
