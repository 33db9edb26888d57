#!/bin/bash
# Device run: CPU build, then the FSI cases in parallel.
set -x
nproc
cmake -S . -B /tmp/b -DSPHVCPM_CUDA=OFF -DBUILD_TESTING=OFF -DCMAKE_BUILD_TYPE=Release > /tmp/cmake.log 2>&1 || { tail -30 /tmp/cmake.log; exit 1; }
cmake --build /tmp/b -j16 > /tmp/build.log 2>&1 || { grep -B2 -A5 error /tmp/build.log | head -60; exit 1; }
export PATH=$PWD/platforms/bin:$PATH
run() { (cd devrun/$1 && generateParticles > log.gen 2>&1 && OMP_NUM_THREADS=$2 OMP_PROC_BIND=false sphVcpmFsi > log.run 2>&1; echo "$1 done rc=$?") & }
run g2 6; run g1 3; run g3 3; run g4 2; run p1 2
wait
for c in g1 g2 g3 g4; do cp devrun/$c/postProcessing/gateTip/0/displacement.dat $OUT/$c.dat; tail -12 devrun/$c/log.run; done
cp devrun/p1/postProcessing/midSpan/0/displacement.dat $OUT/p1.dat; cp devrun/p1/postProcessing/plateLoad/0/force.dat $OUT/p1force.dat
tail -15 devrun/p1/log.run; grep -i warn -A2 devrun/*/log.gen
