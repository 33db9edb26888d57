#!/bin/bash
# finePictures.sh sluiceGate3D|rollingTank3D DIR_OF_THE_NPZ
# The pictures of a tutorial's -fine run (docs/validation/<case>Fine.jpg) on
# a machine with ParaView, from fields packed where the case ran
# (fieldsForPictures.py pack; a million particles' time directory is about
# 70 MB, the device machine returns at most 16 MiB a file):
#   sluiceGate3D, times 0.3 0.5 0.8 1.2:
#       $P pack CASE fine_$t.npz $t water:U gate:vonMises
#     (the flume's walls do not move: they come from generateParticles here)
#   rollingTank3D, times 1.3 1.9 3.7 4.3 (the rolling tank in three files):
#       $P pack CASE fine_${t}_oil.npz $t oil:U
#       $P pack CASE fine_${t}_oilRight.npz $t oilRight:U
#       $P pack CASE fine_${t}_tankPlate.npz $t tank: plate:vonMises
#     its centre plane (y = 0.020 m) seen from the front, as the 2D case is
# with P=docs/validation/scripts/fieldsForPictures.py.
# Debian: python3-numpy, python3-pil, paraview.
set -e
tutorial=$1
case "$tutorial" in
    sluiceGate3D)
        times="0.3 0.5 0.8 1.2" view=(-view iso) box=420,170,1180,730
        title="sluiceGate3D -fine: 1,050,948 particles (2.5 mm), H100; water by |U|, gate by von Mises" ;;
    rollingTank3D)
        times="1.3 1.9 3.7 4.3" view=(-view front -cut y -stressRange 0 3e5) box=255,400,1345,725
        title="rollingTank3D -fine: 1,287,054 particles (oil 1.6 mm, plate 0.8 mm), H100; centre plane" ;;
    *) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 1 ;;
esac
npz=$(cd "$2" && pwd)
R=$(cd "$(dirname "$0")/../../.." && pwd)
export PATH=$R/platforms/bin:$PATH SPHVCPM_DIR=$R
c=$(mktemp -d)/$tutorial
cp -r "$R/tutorials/sphVcpmFsi/$tutorial" "$c"
cd "$c"
generateParticles -dict system/generateParticlesDict.fine > log.generateParticles
shopt -s nullglob
pictures=()
for t in $times; do
    files=("$npz/fine_$t.npz" "$npz"/fine_${t}_*.npz)
    [ -e "${files[0]}" ] || files=("${files[@]:1}")
    [ ${#files[@]} -gt 0 ] || { echo "no fine_$t*.npz in $npz" 1>&2; exit 1; }
    for f in "${files[@]}"; do
        python3 "$R/docs/validation/scripts/fieldsForPictures.py" unpack "$f" .
    done
    pictures+=("images/${tutorial}_t$t.png=t = $t s")
done
particlesToVTK -noZero -fields '(U vonMises)' > log.particlesToVTK
"$R/bin/tools/renderParticles" -times "$times" "${view[@]}"
python3 "$R/docs/validation/scripts/composePictures.py" \
    "$R/docs/validation/${tutorial}Fine.jpg" "$title" $box "${pictures[@]}"
