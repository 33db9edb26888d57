#!/bin/bash
t0=$(date +%s)
cmake -S . -B /tmp/b -DSPHVCPM_CUDA=OFF -DBUILD_TESTING=OFF > /tmp/c.log 2>&1 && cmake --build /tmp/b -j16 > /tmp/bl.log 2>&1 || { tail -30 /tmp/bl.log; exit 1; }
export PATH=$PWD/platforms/bin:$PATH SPHVCPM_DIR=$PWD
cd tutorials/sphVcpmFsi/damBreakElasticGateStl3D
OMP_NUM_THREADS=16 timeout $(( 570 - ($(date +%s) - t0) )) ./Allrun > $OUT/allrun.txt 2>&1
cp log.sphVcpmFsi $OUT/log.txt; cp postProcessing/gateTip/0/displacement.dat $OUT/tip.dat
tail -12 $OUT/allrun.txt
