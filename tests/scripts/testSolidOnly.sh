#!/bin/bash
# sphVcpmFsi with solids and no fluid: a 2D plane-strain cantilever (6
# layers, 60 free columns, 2 clamped) relaxed under gravity with damping.
# Its tip deflection must match Euler-Bernoulli with the lattice's bending
# stiffness error of thinMemberStiffnessError (read from generateParticles'
# warning) within 2 %: measured 0.001 %; the Timoshenko shear term left
# out is about 1 % at L/H = 10, so 2 % still catches a wrong stiffness
# (uncorrected beam theory is 19 % off).
source "$(dirname "$0")/testLib.sh"

c="$scratch/cantilever"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.01;
bodies
{
    beam
    {
        type    solid;
        shapes { b { shape box; min (-0.02 -0.03 -1); max (0.6 0.03 1); } }
        clamp  { c { shape box; min (-1 -1 -1); max (0 1 1); } }
    }
}
DICT
cat > "$c/constant/solidProperties" <<'DICT'
beam { rho 1000; E 1e8; nu 0.3; lattice square2D; plane planeStrain; damping 60; }
DICT
cat > "$c/constant/g" <<'DICT'
dimensions [0 1 -2 0 0 0 0];
value      (0 -9.81 0);
DICT
cat > "$c/system/controlDict" <<'DICT'
application     sphVcpmFsi;
startFrom       latestTime;
startTime       0;
stopAt          endTime;
endTime         0.3;
deltaT          1e-5;
writeControl    adjustableRunTime;
writeInterval   0.1;
writeFormat     ascii;
logInterval     10000;
DICT

generateParticles -case "$c" > "$scratch/log.gen" 2>&1
check "generateParticles" [ $? -eq 0 ]
sphVcpmFsi -case "$c" > "$scratch/log.run" 2>&1
check "sphVcpmFsi runs the solid alone" [ $? -eq 0 ]
log="$scratch/log.run"
expectIn "log names the solid" "$log" "beam \(solid\): 372 particles, 12 clamped"
expectIn "log gives the stable step" "$log" "stable deltaT = 8.17"
expectIn "writes 0.3" "$log" "Writing time 0.3"
expectIn "End" "$log" "^End"
check "no FATAL" bash -c "! grep -q FATAL '$log'"
for f in position U displacement stressXX stressXY stressYY vonMises clamped; do
    check "0.3/beam/$f written" [ -f "$c/0.3/beam/$f" ]
done

err=$(sed -nE 's/.*expected ([-+0-9.]+) % off.*/\1/p' "$scratch/log.gen")
check "thin-member error reported" [ -n "$err" ]
check "tip deflection within 2 % of corrected Euler-Bernoulli" \
python3 - "$c" "${err:-0}" <<'PY'
import re, sys
c, err = sys.argv[1], float(sys.argv[2])/100
def vec(f):
    return [tuple(map(float, m)) for m in re.findall(
        r'^\(([-\d.e+]+) ([-\d.e+]+) ([-\d.e+]+)\)$', open(f).read(), re.M)]
X = vec(c + '/0/beam/position')
U = vec(c + '/0.3/beam/displacement')
xm = max(x[0] for x in X)
tip = [u[1] for x, u in zip(X, U) if abs(x[0] - xm) < 1e-9]
w = -sum(tip)/len(tip)
E, nu, rho, g, H, L = 1e8, 0.3, 1000, 9.81, 0.06, 0.6
EI = E/(1 - nu**2)*H**3/12*(1 + err)
ref = rho*g*H*L**4/(8*EI)
print("tip deflection %.6g m, corrected Euler-Bernoulli %.6g m (%+.3f %%)"
      % (w, ref, 100*(w/ref - 1)))
sys.exit(0 if abs(w/ref - 1) < 0.02 else 1)
PY
finish
