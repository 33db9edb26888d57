#!/bin/bash
# The solver's script tests again with SPHVCPM_DEVICE=cuda: bad input and
# blow-up diagnoses, particles leaving the domain, restart, stopping a run
# (stopAt, controlDict changed, signals), -postProcess, the stability
# suites, the coupling, prescribed motions and the solid-wall contact,
# each on the GPU with its own checks and tolerances. Skipped (77) where
# no GPU can be used.
. "$(dirname "$0")/testLib.sh"

skipWithoutGpu "running the script tests on the GPU"

for test in testSolverInput testRestart testRunControl testPostProcess testStability testFsiStability testFsiCoupling \
    testPrescribedMotion testSolidWallContact; do
    SPHVCPM_DEVICE=cuda bash "$(dirname "$0")/$test.sh" > "$scratch/$test.log" 2>&1
    status=$?
    summary=$(tail -1 "$scratch/$test.log")
    check "$test on the GPU ($summary)" [ $status -eq 0 ]
    [ $status -eq 0 ] || grep '^FAIL' "$scratch/$test.log" | head -10
done

finish
