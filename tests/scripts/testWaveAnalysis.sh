#!/bin/bash
# bin/tools/waveAnalysis on gauge tables of known waves: a run and its
# restart (two start times, the first's rows past the restart dropped), the
# gauges sampled unevenly (as the solver's first step after each write
# time), three gauges along x in 0.5 m of water under an incident wave of
# height 0.04 m, period 1.2 s, with a second harmonic of 0.004 m and a
# reflected wave of 0.01 m (Kr 0.25): the mean level, the zero-crossing
# and spectral heights, the first harmonic, the split into incident and
# reflected waves (two and three gauges); then the errors.
. "$(dirname "$0")/testLib.sh"

tool="$SPHVCPM_DIR/bin/tools/waveAnalysis"
c="$scratch/flume"
mkdir -p "$c/postProcessing/waves/0" "$c/postProcessing/waves/7.5" "$c/constant"
echo "value (0 -9.81 0);" > "$c/constant/g"
python3 - "$c/postProcessing/waves" <<'PY'
import math, sys
d, T, g = 0.5, 1.2, 9.81
w = 2*math.pi/T
k = w*w/g
for _ in range(60):
    k -= (g*k*math.tanh(k*d) - w*w)/(g*math.tanh(k*d) + g*k*d/math.cosh(k*d)**2)
xs = [1.0, 1.3, 1.7]
def eta(x, t):
    return (0.02*math.cos(k*x - w*t) + 0.002*math.cos(2*(k*x - w*t))
            + 0.005*math.cos(k*x + w*t + 0.7))
def table(path, t0, t1):
    with open(path, "w") as f:
        for j, x in enumerate(xs):
            f.write("# Gauge %d (%g 0 0)\n" % (j, x))
        f.write("# Time h0 h1 h2\n")
        n = 0
        while True:
            t = t0 + 0.01*n + 0.004*((7*n) % 10)/10    # uneven, as the solver's
            if t > t1: break
            f.write("%.10g %s\n" % (t, " ".join("%.10g" % (d + eta(x, t)) for x in xs)))
            n += 1
table(sys.argv[1] + "/0/height.dat", 0, 9)           # the killed run went on to 9 s
table(sys.argv[1] + "/7.5/height.dat", 7.5, 14.4)    # the restart from 7.5 s
print("k =", k)
PY
out="$scratch/log.analysis"
"$tool" -case "$c" -func waves -time 2.4:14.4 -reflection > "$out" 2>&1
check "three gauges, -reflection: exit 0" [ $? -eq 0 ]
cat "$out"
expectIn "the two tables joined" "$out" "waves, 2 tables joined, [0-9]+ rows from 2.4"
# row: | gauge | position | mean | waves | Hmean | H1/3 | Hmax | Tmean | Hm0 | H1 | phase | H2/H1 |
col() { awk -F'|' -v g="$1" -v c="$2" '$2 + 0 == g && $3 ~ /\(/ { print $(c + 1) }' "$out"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
check "mean level 0.5 m at gauge 0 ($(col 0 3))" near "$(col 0 3)" 0.5 2e-4
check "mean period 1.2 s at gauge 1 ($(col 1 8))" near "$(col 1 8)" 1.2 0.01
# The first harmonic at a gauge: incident and reflected add with the
# phase 2kx + 0.7 between them.
expected=$(python3 -c "
import math, cmath
d, T, g = 0.5, 1.2, 9.81
w = 2*math.pi/T; k = w*w/g
for _ in range(60): k -= (g*k*math.tanh(k*d) - w*w)/(g*math.tanh(k*d) + g*k*d/math.cosh(k*d)**2)
print(' '.join('%.6f' % (2*abs(0.02 + 0.005*cmath.exp(1j*(2*k*x + 0.7)))) for x in (1.0, 1.3, 1.7)))")
read -r e0 e1 e2 <<< "$expected"
check "first harmonic H1 at gauge 0: $(col 0 10) against $e0 m" near "$(col 0 10)" "$e0" 1e-4
check "first harmonic H1 at gauge 2: $(col 2 10) against $e2 m" near "$(col 2 10)" "$e2" 1e-4
check "second harmonic H2/H1 at gauge 0 about 0.1 ($(col 0 12))" near "$(col 0 12)" "$(awk -v e=$e0 'BEGIN { print 0.004/e }')" 0.01
HI=$(sed -nE 's/.*H_I = ([^ ]+) m.*/\1/p' "$out"); HR=$(sed -nE 's/.*H_R = ([^ ]+) m.*/\1/p' "$out")
Kr=$(sed -nE 's/.*Kr = H_R\/H_I = ([^;]+);.*/\1/p' "$out")
check "incident height 0.04 m ($HI)" near "$HI" 0.04 1e-4
check "reflected height 0.01 m ($HR)" near "$HR" 0.01 1e-4
check "Kr 0.25 ($Kr)" near "$Kr" 0.25 0.003
expectIn "the depth and g used are printed" "$out" "depth 0.49998 m \(gauge 0's mean level\), \|g\| 9.81"

# Two gauges (Goda and Suzuki), the period given.
"$tool" -case "$c" -func waves -time 2.4: -gauges "0 2" -period 1.2 -reflection > "$scratch/log.two" 2>&1
check "two gauges: exit 0" [ $? -eq 0 ]
Kr2=$(sed -nE 's/.*Kr = H_R\/H_I = ([^;]+);.*/\1/p' "$scratch/log.two")
check "two gauges: Kr 0.25 ($Kr2)" near "$Kr2" 0.25 0.003

# Errors: each names what to do; exit 1.
bad() # bad <what> <pattern> <args...>
{
    local what="$1" pattern="$2"; shift 2
    "$tool" -case "$c" "$@" > "$scratch/log.bad" 2>&1
    check "$what: exit 1" [ $? -eq 1 ]
    expectIn "$what: says why" "$scratch/log.bad" "$pattern"
}
bad "no -func" "-func <name> is required" -time 1:2
bad "no such entry" "no .*postProcessing/wavez: run the solver" -func wavez
bad "-time backwards" "t0 must be below t1" -func waves -time 3:2
bad "-time of no rows" "at least 10 are needed" -func waves -time 100:200
bad "-gauges out of range" "no gauge 5; the table has gauges 0 to 2" -func waves -gauges "0 5"
bad "-reflection with one gauge" "needs two gauges at least" -func waves -gauges 1 -reflection
bad "-period 0" "-period must be positive" -func waves -period 0
bad "unknown option" "unknown option '-bogus'" -func waves -bogus 1
# Gauges half a wavelength apart: the split is ill-posed.
L=$(sed -nE 's/.*L = ([^ )]+) m\).*/\1/p' "$out")
mkdir -p "$scratch/half/postProcessing/w/0"
python3 - "$scratch/half/postProcessing/w/0/height.dat" "$L" <<'PY'
import math, sys
L = float(sys.argv[2]); w = 2*math.pi/1.2; k = 2*math.pi/L
with open(sys.argv[1], "w") as f:
    f.write("# Gauge 0 (1 0 0)\n# Gauge 1 (%.10g 0 0)\n# Time h0 h1\n" % (1 + L/2))
    for n in range(600):
        t = 0.01*n
        f.write("%g %g %g\n" % (t, 0.5 + 0.02*math.cos(k - w*t), 0.5 + 0.02*math.cos(k*(1 + L/2) - w*t)))
PY
"$tool" -case "$scratch/half" -func w -reflection > "$scratch/log.half" 2>&1
check "gauges L/2 apart: exit 1" [ $? -eq 1 ]
expectIn "gauges L/2 apart: says to choose others" "$scratch/log.half" \
    "too near a whole number of half wavelengths apart .*between 0.05 and 0.45 L apart"
finish
