#!/bin/bash
# The pictures of sluiceGate3D -fine (docs/validation/sluiceGate3DFine.jpg)
# on a machine with ParaView, from fields packed where the case ran:
#   there:  for t in 0.3 0.5 0.8 1.2; do
#               docs/validation/scripts/fieldsForPictures.py pack CASE fine_$t.npz $t water:U gate:vonMises
#           done
#   here:   docs/validation/scripts/sluiceGate3DFinePictures.sh DIR_OF_THE_NPZ
# (the flume's walls do not move: they come from generateParticles here).
# Debian: python3-numpy, python3-pil, paraview.
set -e
npz=$(cd "$1" && pwd)
R=$(cd "$(dirname "$0")/../../.." && pwd)
export PATH=$R/platforms/bin:$PATH SPHVCPM_DIR=$R
c=$(mktemp -d)/sluiceGate3D
cp -r "$R/tutorials/sphVcpmFsi/sluiceGate3D" "$c"
cd "$c"
generateParticles -dict system/generateParticlesDict.fine > log.generateParticles
for t in 0.3 0.5 0.8 1.2; do
    python3 "$R/docs/validation/scripts/fieldsForPictures.py" unpack "$npz/fine_$t.npz" .
done
particlesToVTK -noZero -fields '(U vonMises)' > log.particlesToVTK
"$R/bin/tools/renderParticles" -times "0.3 0.5 0.8 1.2" -view iso
python3 - "$R/docs/validation/sluiceGate3DFine.jpg" <<'PY'
import sys
from PIL import Image, ImageDraw, ImageFont
times = ["0.3", "0.5", "0.8", "1.2"]
ims = [Image.open(f"images/sluiceGate3D_t{t}.png").convert("RGB") for t in times]
box = (420, 170, 1180, 730)                 # the flume in a 1600x900 picture
w, h = box[2] - box[0], box[3] - box[1]
bar = ims[0].crop((150, 770, 1450, 880))    # the two colour bars
out = Image.new("RGB", (2*w, 2*h + bar.size[1] + 40), "white")
font = ImageFont.truetype("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 26)
d = ImageDraw.Draw(out)
for k, (im, t) in enumerate(zip(ims, times)):
    x, y = (k % 2)*w, (k//2)*h + 40
    out.paste(im.crop(box), (x, y))
    d.text((x + 20, y + 10), f"t = {t} s", fill="black", font=font)
d.text((20, 5), "sluiceGate3D -fine: 1,050,948 particles (2.5 mm), H100; "
       "water by |U|, gate by von Mises", fill="black", font=font)
out.paste(bar, ((2*w - bar.size[0])//2, 2*h + 40))
out = out.resize((int(out.size[0]*0.8), int(out.size[1]*0.8)), Image.LANCZOS)
out.save(sys.argv[1], quality=88, optimize=True)
print(sys.argv[1])
PY
