#!/bin/bash
t0=$(date +%s)
if [ ! -x platforms/bin/sphVcpmFsi ]; then
  cmake -S . -B /tmp/b -DSPHVCPM_CUDA=OFF -DBUILD_TESTING=OFF > /tmp/c.log 2>&1 && cmake --build /tmp/b -j16 > /tmp/bl.log 2>&1 || { tail -30 /tmp/bl.log; exit 1; }
fi
echo "build $(( $(date +%s) - t0 )) s"
left=$(( 585 - ($(date +%s) - t0) ))
( OMP_NUM_THREADS=12 timeout $left benchmarks/runSpeedVsError damBreakElasticGate2D > $OUT/gate.txt 2>&1; cp docs/validation/damBreakElasticGate2D.md $OUT/ ) &
OMP_NUM_THREADS=4 timeout $left benchmarks/runSpeedVsError hydrostaticPlate2D > $OUT/plate.txt 2>&1; cp docs/validation/hydrostaticPlate2D.md $OUT/
wait
cp docs/validation/damBreakElasticGate2D.md $OUT/ 2>/dev/null
tail -5 $OUT/gate.txt $OUT/plate.txt
