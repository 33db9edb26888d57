#!/bin/bash
# Stability suite (coarse, for CI): a violent dam break in a closed box run
# to ten times its impact time, a long hydrostatic run, dam breaks with a
# low and a high speed of sound, short dam breaks with each selectable
# model switched on, and the first two again with the Verlet time scheme.
# Each must end normally with no NaN, no fluid particle through a wall or
# removed, the fluid mass conserved
# exactly and the mechanical energy (kinetic + potential above the floor)
# never above its start by more than 1 %.
. "$(dirname "$0")/testLib.sh"
. "$(dirname "$0")/fieldTools.sh"

damBreak="$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D"
tank="$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D"

# setEntry <file> <keyword> <value>: replaces a top-level entry.
setEntry() { sed -i "s|^$2 .*|$2 $3;|" "$1"; }

# prepare <name> <source> <dp> <endTime> <writeInterval>
prepare()
{
    local c="$scratch/$1"
    cp -r "$2" "$c"
    (cd "$c" && ./Allclean > /dev/null 2>&1; rm -rf 0)
    setEntry "$c/system/generateParticlesDict" dp "$3"
    setEntry "$c/system/controlDict" endTime "$4"
    setEntry "$c/system/controlDict" writeInterval "$5"
    setEntry "$c/system/controlDict" writeFormat ascii
    setEntry "$c/system/controlDict" logInterval 5000
}

# run <name>: generateParticles and the solver, logs in the case.
run()
{
    local c="$scratch/$1"
    (cd "$c" && generateParticles > log.generateParticles 2>&1 \
             && sphVcpmFsi > log.sphVcpmFsi 2>&1)
    check "$1: the run ends normally" grep -q '^End' "$c/log.sphVcpmFsi"
}

# checkRun <name> <xmax> <ymax> <dp> <energyFile>: the checks of the suite.
# A fluid particle is through a wall when its centre is past the first
# layer of wall particles (dp/2 outside the wall face).
checkRun()
{
    local name="$1" c="$scratch/$1" xmax="$2" ymax="$3" dp="$4" energy="$5"
    check "$name: no particle removed" bash -c "! grep -q '^Removed' '$c/log.sphVcpmFsi'"
    local bad=0 t worst
    for t in $(cd "$c" && ls -d [0-9]* | grep -v '^0$'); do
        worst=$(fieldValues "$c/$t/water/position" | awk -v X="$xmax" -v Y="$ymax" -v e="$dp" "$awkFinite"'
            { if (!(finite($1) && finite($2))) { nan = 1; exit }
              o = -e/2 - $1; if ($1 - X - e/2 > o) o = $1 - X - e/2
              if (-e/2 - $2 > o) o = -e/2 - $2; if ($2 - Y - e/2 > o) o = $2 - Y - e/2
              if (n++ == 0 || o > m) m = o }
            END { if (nan) print "NaN"; else if (n) printf "%.3g\n", m }')
        isFinite "$worst" 'v <= 0' \
            || { bad=$((bad + 1)); echo "    time $t: a fluid particle $worst m past the first wall layer"; }
        fieldValues "$c/$t/water/rho" | awk "$awkFinite"'
            { if (!finite($1) || $1 <= 0) bad++ } END { exit bad > 0 || NR == 0 }' || bad=$((bad + 1))
    done
    check "$name: every written state is finite, with no fluid through a wall" [ $bad -eq 0 ]
    check "$name: fluid mass conserved exactly" \
        awk "$awkFinite"'!/^#/ { if (!finite($2)) bad = 1; if (!n++) m0 = $2 ""; else if ($2 "" != m0) bad = 1 }
            END { exit bad || !n }' "$c/$energy"
    # The largest mechanical energy over the start: nan for a non-finite
    # row or a table without rows.
    local rise
    rise=$(awk "$awkFinite"'!/^#/ { if (!finite($3) || !finite($4)) bad = 1; e = $3 + $4
                                    if (n++ == 0) e0 = m = e; if (e > m) m = e }
                END { if (!n || bad || e0 == 0) print "nan"; else printf "%.4g\n", (m - e0)/e0 }' "$c/$energy")
    check "$name: energy bounded (largest rise $rise of the start)" isFinite "$rise" 'v <= 0.01'
}

# surfaceDrift <case>: the gauge's last level less its first, in dp = 0.02
# m (postProcessing/surface/0/height.dat); nan for a non-finite level or a
# table without rows.
surfaceDrift()
{
    awk "$awkFinite"'!/^#/ { if (!finite($2)) bad = 1; if (n++ == 0) h0 = $2; h = $2 }
        END { if (!n || bad) print "nan"; else printf "%.4g\n", (h - h0)/0.02 }' \
        "$scratch/$1/postProcessing/surface/0/height.dat"
}

# 1. Violent dam break: the front hits the far wall at about 0.32 s.
prepare violentDamBreak "$damBreak" 0.02 3.2 0.4
run violentDamBreak
checkRun violentDamBreak 0.8 0.5 0.02 postProcessing/energy/0/energy.dat

# 2. Long hydrostatic run (coarse): the surface stays put.
prepare longHydrostatic "$tank" 0.02 3 1
run longHydrostatic
checkRun longHydrostatic 1 0.8 0.02 postProcessing/energy/0/energy.dat
drift=$(surfaceDrift longHydrostatic)
check "longHydrostatic: surface drift $drift dp over $(awk '/^Step = / { s = $3 } END { print s }' \
    "$scratch/longHydrostatic/log.sphVcpmFsi") steps (limit 0.5 dp)" \
    isFinite "$drift" 'v < 0.5 && v > -0.5'

# 3. Low and high speeds of sound.
for cs in 10 80; do
    prepare "soundSpeed$cs" "$damBreak" 0.02 0.6 0.3
    setEntry "$scratch/soundSpeed$cs/constant/fluidProperties" coefSound $cs
    run "soundSpeed$cs"
    checkRun "soundSpeed$cs" 0.8 0.5 0.02 postProcessing/energy/0/energy.dat
done
# 4. The selectable models, each switched on once in the violent dam break
#    (short): cubic spline (with its tensile correction), Molteni-Colagrossi
#    diffusion, artificial viscosity, SPS turbulence, Fickian shifting.
variant()
{
    local name="$1"; shift
    prepare "$name" "$damBreak" 0.02 0.6 0.3
    local c="$scratch/$name"
    local v
    while [ $# -gt 0 ]; do
        v="$2"; [ "${v#\{}" = "$v" ] && v="$v;"     # a sub-dictionary takes no ';'
        sed -i "s|^$1 .*|$1 $v|" "$c/$3"
        grep -q "^$1 " "$c/$3" || echo "$1 $v" >> "$c/$3"
        shift 3
    done
    run "$name"
    expectIn "$name: the log names the model" "$c/log.sphVcpmFsi" "$expect"
    checkRun "$name" 0.8 0.5 0.02 postProcessing/energy/0/energy.dat
}
expect="kernel cubicSpline"
variant cubicSpline kernel cubicSpline system/sphSchemes
expect="density diffusion molteniColagrossi"
variant molteniColagrossi densityDiffusion "{ type molteniColagrossi; delta 0.1; }" system/sphSchemes
expect="viscosity laminar .*turbulence SPS"
variant sps viscosity "{ type laminar; }" system/sphSchemes turbulence SPS constant/fluidProperties
expect="shifting fickian"
variant shifting shifting "{ type fickian; }" system/sphSchemes

# 5. The Verlet time scheme: the violent dam break to ten times its impact
#    time, and the long hydrostatic run.
for base in violentDamBreak longHydrostatic; do
    name="${base}Verlet"
    if [ $base = violentDamBreak ]; then
        prepare $name "$damBreak" 0.02 3.2 0.4
    else
        prepare $name "$tank" 0.02 3 1
    fi
    echo "timeScheme verlet;" >> "$scratch/$name/system/sphSchemes"
    run $name
    expectIn "$name: the log names the scheme" "$scratch/$name/log.sphVcpmFsi" \
        'time scheme verlet'
    if [ $base = violentDamBreak ]; then
        checkRun $name 0.8 0.5 0.02 postProcessing/energy/0/energy.dat
    else
        checkRun $name 1 0.8 0.02 postProcessing/energy/0/energy.dat
    fi
done
drift=$(surfaceDrift longHydrostaticVerlet)
check "longHydrostaticVerlet: surface drift $drift dp (limit 0.5 dp)" \
    isFinite "$drift" 'v < 0.5 && v > -0.5'

expectIn "the low speed of sound is warned about" "$scratch/soundSpeed10/log.sphVcpmFsi" \
    'speed of sound c0 = .* is below'

finish
