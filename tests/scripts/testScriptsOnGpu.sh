#!/bin/bash
# The solver's script tests again with SPHVCPM_DEVICE=cuda: bad input and
# blow-up diagnoses, particles leaving the domain, restart, the stability
# suites and the coupling, each on the GPU with its own checks and
# tolerances. Skipped (77) where no GPU can be used.
. "$(dirname "$0")/testLib.sh"

probe="$scratch/probe"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$probe"
(cd "$probe" && generateParticles > log.generateParticles 2>&1 \
    && sed -i "s/^endTime .*/endTime 0.001;/" system/controlDict \
    && sphVcpmFsi -device cuda > log.cuda 2>&1)
if grep -q "no GPU can be used" "$probe/log.cuda"; then
    echo "Skipped: no GPU ($(grep -o 'no GPU can be used.*' "$probe/log.cuda" | head -1))"
    exit 77
fi

for test in testSolverInput testRestart testStability testFsiStability testFsiCoupling; do
    SPHVCPM_DEVICE=cuda bash "$(dirname "$0")/$test.sh" > "$scratch/$test.log" 2>&1
    status=$?
    summary=$(tail -1 "$scratch/$test.log")
    check "$test on the GPU ($summary)" [ $status -eq 0 ]
    [ $status -eq 0 ] || grep '^FAIL' "$scratch/$test.log" | head -10
done

finish
