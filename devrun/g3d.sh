#!/bin/bash
t0=$(date +%s)
cmake -S . -B /tmp/b -DSPHVCPM_CUDA=OFF -DBUILD_TESTING=OFF > /tmp/c.log 2>&1 && cmake --build /tmp/b -j16 > /tmp/bl.log 2>&1 || { tail -30 /tmp/bl.log; exit 1; }
echo "build $(( $(date +%s) - t0 )) s"
export PATH=$PWD/platforms/bin:$PATH SPHVCPM_DIR=$PWD
cd tutorials/sphVcpmFsi/damBreakElasticGate3D
OMP_NUM_THREADS=16 timeout $(( 590 - ($(date +%s) - t0) )) ./Allrun > $OUT/allrun.txt 2>&1
tail -25 $OUT/allrun.txt
cp log.sphVcpmFsi $OUT/log3d.txt 2>/dev/null
cp postProcessing/gateTip/0/displacement.dat $OUT/tip3d.dat 2>/dev/null
cp 2D/postProcessing/gateTip/0/displacement.dat $OUT/tip2d.dat 2>/dev/null
cp damBreakElasticGate3D.png $OUT/ 2>/dev/null
