#!/bin/bash
export PATH=$PWD/platforms/bin:$PATH
[ -x platforms/bin/sphVcpmFsi ] || { cmake -S . -B /tmp/b -DSPHVCPM_CUDA=OFF -DBUILD_TESTING=OFF > /tmp/cmake.log 2>&1; cmake --build /tmp/b -j16 > /tmp/build.log 2>&1; }
run() { (cd devrun/$1 && rm -rf 0 [0-9]* postProcessing && generateParticles > log.gen 2>&1 && OMP_NUM_THREADS=$2 timeout 555 sphVcpmFsi > log.run 2>&1; echo "$1 rc=$?") & }
run g2 8; run g1 3; run g3 3; run p1 2
wait
cd devrun && tar czf $OUT/pp.tgz */postProcessing */log.run */log.gen
for c in g1 g2 g3 p1; do grep -A3 "Run summary" $c/log.run; done
