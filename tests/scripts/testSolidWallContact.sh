#!/bin/bash
# Solid-wall contact (docs/fsi.md): a free rubber block dropped 5 cm onto
# the dry floor of a tank (water only in a far corner) must land and stay
# on the floor: without contact it falls through the wall layers and out
# of the domain. The block is damped (20 1/s) so that it settles: at the
# end it rests at the contact distance (its lowest particle within 0.5 mm
# of it, a fifth of it; measured 2.44 mm against 2.5 mm) and its mean
# vertical speed is small against the 1 m/s it lands with (below 20 mm/s;
# measured 9.8 mm/s, the block still rocking on the contact).
source "$(dirname "$0")/testLib.sh"
source "$(dirname "$0")/fieldTools.sh"

c="$scratch/drop"
mkdir -p "$c/system" "$c/constant"
cat > "$c/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.01;
bodies
{
    tank  { type wall; container { min (0 0 0); max (0.6 0.4 0); layers 3; openTop yes; } }
    water { type fluid; shapes { b { shape box; min (0 0 0); max (0.1 0.1 0); } } }
    block { type solid; dp 0.005; shapes { b { shape box; min (0.3 0.05 0); max (0.4 0.1 0); } } }
}
DICT
cat > "$c/constant/solidProperties" <<'DICT'
block { rho 1100; E 1e6; nu 0.3; lattice square2D; plane planeStrain; damping 20; }
DICT
writeWaterModel "$c" "coefSound 20;"
writeFsiControl "$c" 0.8 1e-5 0.4 10000
generateParticles -case "$c" > "$scratch/log.gen" 2>&1
check "generateParticles" [ $? -eq 0 ]
sphVcpmFsi -case "$c" > "$scratch/log.run" 2>&1
check "sphVcpmFsi runs the drop to 0.8 s" [ $? -eq 0 ]
log="$scratch/log.run"
expectIn "the log describes the contact" "$log" "solid-wall contact: hard, at a gap of dp_s/2"
expectIn "End" "$log" "^End"
# The floor's top wall row is at y = -dp/2; d0 = (0.01 + 0.005)/2.
read lowest vy <<< "$(paste -d ' ' <(fieldValues "$c/0.8/block/position") <(fieldValues "$c/0.8/block/U") |
    awk '{ if (!n++ || $2 < m) m = $2; v += $5 } END { printf "%.6g %.6g\n", m, v/n }')"
echo "    lowest block particle at y = $lowest m, mean vertical speed $vy m/s"
check "the block rests on the floor at the contact distance (lowest y $lowest m, contact at 0.0025 m)" \
    python3 -c "import sys; sys.exit(0 if abs($lowest - 0.0025) < 0.0005 else 1)"
check "the block is at rest (mean vertical speed $vy m/s)" \
    python3 -c "import sys; sys.exit(0 if abs($vy) < 0.02 else 1)"
finish
