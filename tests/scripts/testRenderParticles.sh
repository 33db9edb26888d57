#!/bin/bash
# bin/tools/renderParticles on two small cases: the 2D elastic gate run for
# 4 ms at dp = 2 mm (water, tank, gate; snapshots, snapping of -times,
# animation frames) and writeParticleCase's 3D case with its time
# directories removed (body types then told by the fields, dp estimated;
# iso view, -output). The PNGs must have the asked size and show the
# particles: colours of the fluid's and the walls' maps, not only white.
# Also the errors (no VTK/, bad options) and the exit 0 without pvbatch;
# -cut and -surface on the 3D hydrostatic tank.
# Without ParaView, or where it cannot render, skipped (exit 77) after the
# checks that need no ParaView.
. "$(dirname "$0")/testLib.sh"

render="$SPHVCPM_DIR/bin/tools/renderParticles"

# Errors, and no pvbatch: exit 0 with a message (tutorials go on).
mkdir -p "$scratch/empty"
"$render" -case "$scratch/empty" > "$scratch/log.noVtk" 2>&1
check "no VTK/: exit 1" [ $? -eq 1 ]
expectIn "no VTK/: says to run particlesToVTK" "$scratch/log.noVtk" \
    "no VTK/\*\.vtp\.series in .*: run particlesToVTK first"
"$render" -view side > "$scratch/log.badView" 2>&1
check "-view side: exit 1" [ $? -eq 1 ]
"$render" -bogus > "$scratch/log.bogus" 2>&1
check "unknown option: exit 1" [ $? -eq 1 ]
expectIn "unknown option named" "$scratch/log.bogus" "unknown option '-bogus'"
mkdir -p "$scratch/empty/VTK" "$scratch/noPv"
touch "$scratch/empty/VTK/water.vtp.series"
for tool in bash dirname ls sed grep; do
    ln -s "$(command -v $tool)" "$scratch/noPv/$tool"
done
PATH="$scratch/noPv" "$render" -case "$scratch/empty" > "$scratch/log.noPv" 2>&1
check "no pvbatch: exit 0" [ $? -eq 0 ]
expectIn "no pvbatch: says so" "$scratch/log.noPv" "pvbatch \(ParaView\) not found"

if ! command -v pvbatch > /dev/null; then
    echo "pvbatch not found: rendering checks skipped"
    finish || exit 1
    exit 77
fi

# pngInfo file: "width height white grey colours": the shares of white and
# of mid-grey (walls) pixels, the number of colours (a PNG decoder
# of the standard library: 8-bit RGB or RGBA, as ParaView writes them).
pngInfo()
{
    python3 - "$1" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat = 8, b""
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    if kind == b"IHDR":
        w, h, depth, ctype = struct.unpack(">IIBB", data[pos + 8:pos + 18])
    if kind == b"IDAT":
        idat += data[pos + 8:pos + 8 + n]
    pos += 12 + n
bpp = {2: 3, 6: 4}[ctype]
raw, stride = zlib.decompress(idat), w*bpp
prev, colours, white, grey = bytearray(stride), set(), 0, 0
for y in range(h):
    f, line = raw[y*(stride + 1)], bytearray(raw[y*(stride + 1) + 1:(y + 1)*(stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b)//2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    for i in range(0, stride, bpp):
        rgb = bytes(line[i:i + 3])
        colours.add(rgb)
        white += rgb == b"\xff\xff\xff"
        grey += rgb[0] == rgb[1] == rgb[2] and 60 <= rgb[0] <= 235
    prev = line
print(w, h, "%.3f %.3f" % (white/(w*h), grey/(w*h)), len(colours))
PY
}

# checkPng what file width height: the size, not blank, walls' grey (1 %
# of the pixels at least; text alone makes 0.1 %), many colours.
checkPng()
{
    local info
    if [ ! -s "$2" ]; then fail "$1: $2 written"; return; fi
    info=$(pngInfo "$2")
    read -r w h white grey colours <<< "$info"
    check "$1: ${3}x$4 (got ${w}x$h)" [ "$w" = "$3" -a "$h" = "$4" ]
    check "$1: particles and walls drawn (white $white, grey $grey, $colours colours)" \
        awk -v w="$white" -v g="$grey" -v c="$colours" \
        'BEGIN { exit !(w < 0.97 && g > 0.01 && c > 100) }'
}

# 2D: the elastic gate, 4 ms.
gate="$scratch/gate2D"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/damBreakElasticGate2D" "$gate"
sed -i "s/^dp .*/dp 0.002;/" "$gate/system/generateParticlesDict"
sed -i "s/^endTime .*/endTime 0.004;/; s/^writeInterval .*/writeInterval 0.002;/" \
    "$gate/system/controlDict"
(cd "$gate" && generateParticles > log.generateParticles 2>&1 \
    && sphVcpmFsi > log.sphVcpmFsi 2>&1 && particlesToVTK > log.particlesToVTK 2>&1)
check "gate2D: run and converted" [ -s "$gate/VTK/gate.vtp.series" ]

log="$scratch/log.render2D"
(cd "$gate" && "$render" -times "0 0.0035" -animate 2 -view iso -size 480x320) \
    > "$log" 2>&1
status=$?
cat "$log"
if grep -q "cannot render here" "$log"; then
    echo "Skipped: $(grep 'cannot render here' "$log")"
    finish || exit 1
    exit 77
fi
check "2D: exit 0" [ $status -eq 0 ]
expectIn "2D: 0.0035 snaps to 0.004" "$log" "time 0\.0035 -> written time 0\.004"
expectIn "2D: front view whatever -view says" "$log" "2D case: front view"
expectIn "2D: range of |U| printed" "$log" "colour range of \|U\| \[m/s\]: 0 to [0-9.e+-]+$"
expectIn "2D: range of von Mises printed" "$log" "colour range of von Mises \[Pa\]: 0 to [0-9.e+-]+$"
checkPng "2D t = 0" "$gate/images/gate2D_t0.png" 480 320
checkPng "2D t = 0.004" "$gate/images/gate2D_t0.004.png" 480 320
differ() { ! cmp -s "$1" "$2"; }
check "2D: the two times differ" differ "$gate/images/gate2D_t0.png" \
    "$gate/images/gate2D_t0.004.png"
check "2D: animation frames 0 and 1, no more" [ -s "$gate/images/animation/frame_0000.png" \
    -a -s "$gate/images/animation/frame_0001.png" \
    -a ! -e "$gate/images/animation/frame_0002.png" ]

# -surface where the surface was written for other times only: an error
# naming them (ParaView would draw the nearest time's surface unsaid), said
# once; then with a surface at every time drawn, a picture.
(cd "$gate" && particlesToVTK -freeSurface -latestTime > log.surfaceLatest 2>&1)
(cd "$gate" && "$render" -times 0.002 -surface -size 480x320) \
    > "$scratch/log.surfaceMissing" 2>&1
check "-surface, none at 0.002: exit 1" [ $? -eq 1 ]
expectIn "-surface, none at 0.002: names the time and what to run" \
    "$scratch/log.surfaceMissing" \
    "-surface: VTK/freeSurface.vtp.series has no surface at t = 0.002 of the 1 times to draw \(it has 1, 0.004 to 0.004\): run particlesToVTK -freeSurface"
check "-surface, none at 0.002: the error said once (no 'pvbatch failed')" \
    bash -c "! grep -q 'pvbatch failed' '$scratch/log.surfaceMissing'"
(cd "$gate" && "$render" -times 0.004 -surface -size 480x320 -output surfaced) \
    > "$scratch/log.surfaceThere" 2>&1
check "-surface at 0.004, where it was written: exit 0" [ $? -eq 0 ]
checkPng "2D surface" "$gate/surfaced/gate2D_t0.004.png" 480 320

# A body converted without the field it is coloured by: said, one colour.
(cd "$gate" && particlesToVTK -fields '(p)' > log.pOnly 2>&1 \
    && "$render" -times 0.004 -size 480x320 -output pOnly) > "$scratch/log.pOnly" 2>&1
check "fields (p) only: exit 0" [ $? -eq 0 ]
expectIn "fields (p) only: the water drawn in one colour, said" "$scratch/log.pOnly" \
    "gate2D has no U in its VTK files|water has no U in its VTK files"
expectIn "fields (p) only: the gate too" "$scratch/log.pOnly" \
    "gate has no vonMises in its VTK files \(written with particlesToVTK -fields\?\): drawn in one colour"

# 3D without time directories: fields and nearest neighbours tell.
helper="${SPHVCPM_TESTBIN:-$SPHVCPM_DIR/platforms/tests}/writeParticleCase"
if [ -x "$helper" ]; then
    c3="$scratch/sheet3D"
    mkdir -p "$c3"
    "$helper" -case "$c3" -times '(0 0.1)' -nDimensions 3 -nx 4 -ny 2 > "$scratch/log.helper" 2>&1
    particlesToVTK -case "$c3" > "$scratch/log.p2v3D" 2>&1
    rm -rf "$c3"/0 "$c3"/0.1
    log="$scratch/log.render3D"
    "$render" -case "$c3" -size 400x300 -output pictures > "$log" 2>&1
    status=$?
    cat "$log"
    check "3D: exit 0" [ $status -eq 0 ]
    expectIn "3D: the latest time without -times" "$log" "no -times: the latest time, 0\.1$"
    expectIn "3D: dp estimated" "$log" \
        "water: no bodyProperties, dp estimated as 0\.01$"
    checkPng "3D iso view" "$c3/pictures/sheet3D_t0.1.png" 400 300
else
    fail "test helper $helper not built"
fi

# -cut: a 3D tank at t = 0, whole and cut through the middle of y.
tank="$scratch/tank3D"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank3D" "$tank"
(cd "$tank" && generateParticles > log.generateParticles 2>&1 \
    && particlesToVTK > log.particlesToVTK 2>&1)
(cd "$tank" && "$render" -size 400x300 -output whole > "$scratch/log.whole" 2>&1)
(cd "$tank" && "$render" -size 400x300 -output cut -cut y > "$scratch/log.cut" 2>&1)
check "-cut y: exit 0" [ $? -eq 0 ]
cat "$scratch/log.cut"
expectIn "-cut y: the plane printed" "$scratch/log.cut" \
    "fluids and solids cut at y = [0-9.e+-]+, the half away from the camera shown"
checkPng "3D cut" "$tank/cut/tank3D_t0.png" 400 300
check "-cut y: the picture differs from the whole tank's" differ \
    "$tank/whole/tank3D_t0.png" "$tank/cut/tank3D_t0.png"
(cd "$tank" && "$render" -view front -cut x > "$scratch/log.cutAcross" 2>&1)
check "-cut x in the front view: exit 1" [ $? -eq 1 ]
expectIn "-cut x in the front view: says why" "$scratch/log.cutAcross" \
    "-cut x: the x axis lies across the front view"
"$render" -cut w > "$scratch/log.cutBad" 2>&1
check "-cut w: exit 1" [ $? -eq 1 ]

# -surface: the tank's water as its free surface (particlesToVTK
# -freeSurface); without the surface written, an error that says how.
(cd "$tank" && "$render" -surface > "$scratch/log.noSurface" 2>&1)
check "-surface before -freeSurface: exit 1" [ $? -eq 1 ]
expectIn "-surface before -freeSurface: says how" "$scratch/log.noSurface" \
    "run particlesToVTK -freeSurface first"
(cd "$tank" && particlesToVTK -freeSurface > log.surface 2>&1)
(cd "$tank" && "$render" -size 400x300 -output plain > "$scratch/log.plain" 2>&1)
check "the surface's series is no body: the same picture without -surface" \
    cmp -s "$tank/whole/tank3D_t0.png" "$tank/plain/tank3D_t0.png"
(cd "$tank" && "$render" -size 400x300 -output surface -surface \
    > "$scratch/log.surface" 2>&1)
check "-surface: exit 0" [ $? -eq 0 ]
checkPng "3D surface" "$tank/surface/tank3D_t0.png" 400 300
check "-surface: the picture differs from the particles'" differ \
    "$tank/whole/tank3D_t0.png" "$tank/surface/tank3D_t0.png"

finish
