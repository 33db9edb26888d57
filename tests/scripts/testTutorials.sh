#!/bin/bash
# Runs a tutorial's Allclean and Allrun in a scratch copy, checks the logs
# (no FATAL, End present) and the particle counts against the geometry.
#
#   testTutorials.sh [tutorial name...]      (default: every tutorial)
# CTest runs one tutorial per test, so that they share the cores.
. "$(dirname "$0")/testLib.sh"

# expectedCount <tutorial> <body>: lattice nodes of the generating dictionary
# (box of L/dp x H/dp nodes; container = outer box minus inner box).
expectedCount()
{
    case "$1/$2" in
        hydrostaticTank2D/water) echo $((100*50)) ;;
        hydrostaticTank2D/tank)  echo $((106*83 - 100*80)) ;;   # 3 layers, open top
        hydrostaticTank3D/water) echo $((15*15*10)) ;;
        damBreak2D/water)        echo $((40*80)) ;;                  # a/40
        damBreak2D/tank)         echo $((246*99 - 240*96)) ;;        # 3 layers, open top
        damBreakLobovsky2D/water) echo $((86*43)) ;;                 # 0.6 m = 85.7 dp
        damBreakLobovsky2D/tank)  echo $((236*146 - 230*143)) ;;
        damBreakElasticGate2D/water) echo $((100*140)) ;;
        damBreakElasticGate2D/gate)  echo $((5*160)) ;;
        damBreakElasticGate2D/tank)  echo $((506*203 - 500*200)) ;;
        hydrostaticPlate2D/water) echo $((100*200)) ;;
        hydrostaticPlate2D/plate) echo $((106*5)) ;;                 # 3 layers into each support
        hydrostaticPlate2D/walls) echo $((2*3*220)) ;;
        hydrostaticTank3D/tank)  echo $((21*21*18 - 15*15*15)) ;;
        damBreak3D/water)        echo $((40*67*30)) ;;
        waveFlume2D/water)       echo $((400*25)) ;;
        waveFlume2D/flume)       echo $((438*54 - 430*50)) ;;      # 4 layers, open top
        waveFlume2D/paddle)      echo $((5*45)) ;;
        waveFlumeFlap2D/water)   echo $((400*25)) ;;               # waveFlume2D's flume
        waveFlumeFlap2D/flume)   echo $((438*54 - 430*50)) ;;
        waveFlumeFlap2D/paddle)  echo $((5*45)) ;;
        damBreak3D/tank)         echo $((166*73*43 - 160*67*40)) ;;
        sluiceGate3D/water)      echo $((24*8*20)) ;;
        sluiceGate3D/gate)       echo $((6*16*56)) ;;                     # dp/2: 6 layers
        sluiceGate3D/flume)      echo $((74*14*35 - 68*8*32 + 3*14*16 + 2*24*3*16)) ;;  # + raised end
        damBreakElasticGate3D/water) echo $((50*10*70)) ;;
        damBreakElasticGate3D/gate)  echo $((5*20*160)) ;;               # dp/2
        damBreakElasticGate3D/tank)  echo $((181*16*83 - 175*10*80)) ;;  # 3 layers, open top
        # The same boxes from STL (docs/geometry.md); surfaceLayers round
        # the tank's rim, so its count is the one measured there.
        damBreakElasticGateStl3D/water) echo $((50*10*70)) ;;
        damBreakElasticGateStl3D/gate)  echo $((5*20*160)) ;;
        damBreakElasticGateStl3D/tank)  echo 102666 ;;
        # The default dictionaries (dp 4 mm; lattice from x = 0.0005 m: 153
        # columns over the 0.612 m, the plate's one left out of the oil;
        # walls 86 rows up the 0.3445 m)
        rollingTank2D/plate)    echo $((4*115)) ;;                     # dp/4
        rollingTank2D/oil)      echo $((152*29)) ;;
        rollingTank2D/tank)     echo $((159*89 - 153*86)) ;;           # 3 layers, open top
        rollingTank3D/plate)    echo $((4*40*115)) ;;
        rollingTank3D/oil)      echo $((152*10*29)) ;;
        rollingTank3D/tank)     echo $((159*16*89 - 153*10*86)) ;;
        rollingTank3DCoarse/plate)    echo $((3*15*42)) ;;               # dp/3, 8 mm thick
        rollingTank3DCoarse/oil)      echo $((38*5*14)) ;;
        rollingTank3DCoarse/oilRight) echo $((37*5*14)) ;;
        # The fine dictionaries (system/generateParticlesDict.fine)
        rollingTank3D.fine/plate)    echo $((5*50*144)) ;;               # 0.8 mm
        rollingTank3D.fine/oil)      echo $((190*25*72)) ;;
        rollingTank3D.fine/oilRight) echo $((189*25*72)) ;;  # a column dropped at the end wall
        rollingTank2D.fine/plate)    echo $((5*144)) ;;
        rollingTank2D.fine/oil)      echo $((190*72)) ;;
        rollingTank2D.fine/oilRight) echo $((189*72)) ;;
        sluiceGate3D.fine/water)     echo 480000 ;;
        sluiceGate3D.fine/gate)      echo 84000 ;;
        *) echo "" ;;
    esac
}

# checkGeneratedCounts <name> <case>: the counts that generateParticles
# logged for the case's bodies against expectedCount <name> <body>.
checkGeneratedCounts()
{
    local body want
    for body in $(cd "$2/0" && ls -d */ | tr -d /); do
        [ "$body" = uniform ] && continue
        want=$(expectedCount "$1" "$body")
        [ -n "$want" ] && expectIn "$1: $body has $want particles" \
            "$2/log.generateParticles" "$body \([a-z]+\): $want particles"
    done
}

for allrun in $(find "$SPHVCPM_DIR/tutorials" -name Allrun | sort); do
    src=$(dirname "$allrun")
    name=$(basename "$src")
    if [ $# -gt 0 ] && [[ " $* " != *" $name "* ]]; then
        continue
    fi
    # The other particle dictionaries of a case (the GPU-scale variants
    # that an Allrun option selects) generate, with their counts.
    for dict in "$src"/system/generateParticlesDict.*; do
        [ -f "$dict" ] || continue
        variant="$name.${dict##*.}"
        run="$scratch/$variant"
        cp -r "$src" "$run"
        (cd "$run" && generateParticles -dict "system/$(basename "$dict")" > log.generateParticles 2>&1)
        check "$variant: generateParticles -dict $(basename "$dict") succeeds" [ $? -eq 0 ]
        checkGeneratedCounts "$variant" "$run"
        rm -rf "$run"
    done
    # Cases too long for a 2-core CI (marked '# sphvcpm: long run' in their
    # Allrun) only generate their particles, unless SPHVCPM_LONG_TUTORIALS=1.
    if grep -q '^# sphvcpm: long run' "$allrun" && [ "${SPHVCPM_LONG_TUTORIALS:-0}" != 1 ]; then
        run="$scratch/$name"
        cp -r "$src" "$run"
        (cd "$run" && generateParticles > log.generateParticles 2>&1)
        check "$name (long run, particles only): generateParticles succeeds" [ $? -eq 0 ]
        checkGeneratedCounts "$name" "$run"
        continue
    fi
    run="$scratch/$name"
    cp -r "$src" "$run"
    "$run/Allclean" > /dev/null 2>&1
    "$run/Allrun" > "$scratch/$name.out" 2>&1
    check "$name: Allrun succeeds (its validation checks pass)" [ $? -eq 0 ]
    # The validation lines, for the record.
    grep -E '\(limit .*\) (PASS|FAIL)|^Validation' "$scratch/$name.out" | sed "s/^ */    $name: /"
    for log in "$run"/log.*; do
        [ -f "$log" ] || continue
        check "$name: $(basename "$log") ends with End" grep -q "^End" "$log"
        check "$name: $(basename "$log") has no FATAL" bash -c "! grep -q FATAL '$log'"
    done
    for bodyDir in "$run"/0/*/; do
        body=$(basename "$bodyDir")
        [ "$body" = uniform ] && continue
        # The count in the field's header, ascii or binary.
        n=$(LC_ALL=C grep -a -o -m 1 'List<vector> *[0-9][0-9]*' "$bodyDir/position" \
            | LC_ALL=C grep -o '[0-9]*$')
        [ -n "$n" ] || n=$(LC_ALL=C sed -n '/List<vector>/{n;p;q}' "$bodyDir/position")
        want=$(expectedCount "$name" "$body")
        if [ -n "$want" ]; then
            check "$name: $body has $want particles (found $n)" [ "$n" = "$want" ]
            expectIn "$name: log reports $body's count" "$run/log.generateParticles" \
                "$body \([a-z]+\): $want particles"
        fi
        check "$name: VTK series for $body" [ -f "$run/VTK/$body.vtp.series" ]
        check "$name: VTK file for $body" [ -f "$run/VTK/$body/${body}_0.vtp" ]
    done
    # Cleaning leaves exactly what is in the repository.
    "$run/Allclean" > /dev/null 2>&1
    check "$name: Allclean restores the case" \
        diff -r -q -x 'log.*' "$src" "$run"
done

[ $((nPassed + nFailed)) -gt 0 ] || fail "no tutorial named: $*"
finish
