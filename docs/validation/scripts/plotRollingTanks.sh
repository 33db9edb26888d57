#!/bin/bash
# plotRollingTanks.sh OUT.png TITLE CASE=LABEL ...
# The plate tip's deflection (tank frame) and the free-surface elevation at
# both end walls of rolling-tank runs, one line per run, as rollingTank3D's
# Allrun plots them: CASE is a finished run's directory, whose
# postProcessing/rolling/ rollingResults (tutorials/sphVcpmFsi/rollingTank2D/
# rollingFunctions) has written. Colours in the order of the runs: red,
# blue, black, green, grey, orange. (Debian: gnuplot.)
[ $# -ge 3 ] || { sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 1; }
out=$1 title=${2//\'/\'\'}; shift 2   # gnuplot: '' in a '...' string
colours=(red blue black dark-green gray50 orange)
plotOf() # column file: one gnuplot plot command over the runs
{
    local k=0 sep="plot" run
    for run in "$@"; do
        printf "%s '%s/postProcessing/rolling/%s' u 1:%s w l lw %s lc rgb '%s' t '%s'" \
            "$sep" "${run%%=*}" "$file" "$column" "$([ $k = 0 ] && echo 2 || echo 1)" \
            "${colours[k]}" "${run#*=}"
        sep=","; k=$((k + 1))
    done
    echo
}
{
    echo "set terminal pngcairo size 1200,900; set output '$out'"
    echo "set multiplot layout 3,1 title '$title'"
    echo "set xlabel 't [s]'; set xrange [0:5]; set grid; set key outside right"
    echo "set ylabel 'tip deflection x [m]'"
    file=tipTankFrame.dat column=3 plotOf "$@"
    echo "set ylabel 'elevation, left [m]'"
    file=elevation.dat column=2 plotOf "$@"
    echo "set ylabel 'elevation, right [m]'"
    file=elevation.dat column=3 plotOf "$@"
    echo "unset multiplot"
} | gnuplot && echo "$out"
