#!/bin/bash
# particlesToVTK -freeSurface on the 2D hydrostatic tank as generated (water
# 1 x 0.5 m, dp 10 mm): the log (segments, enclosed area against the
# particles'), the files and series, -surfaceRefine, the errors, then
# ParaView reads the outline: lines, the fields, normals, the water's top
# at y = 0.5. The surface's geometry is tested in tests/unit/sph
# (testFreeSurface.C). Without pvpython the ParaView part is skipped (exit
# 77 when everything else passed).
. "$(dirname "$0")/testLib.sh"

for app in generateParticles particlesToVTK; do
    if ! command -v $app > /dev/null; then
        echo "FAIL: $app not on the PATH (./Allwmake builds it)"
        exit 1
    fi
done

run="$scratch/tank"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D" "$run"
generateParticles -case "$run" > "$scratch/log.generate" 2>&1
check "generateParticles (exit 0)" [ $? -eq 0 ]

log="$scratch/log.surface"
particlesToVTK -case "$run" -freeSurface > "$log" 2>&1
check "particlesToVTK -freeSurface (exit 0)" [ $? -eq 0 ]
cat "$log"
expectIn "log: water converted" "$log" \
    "^    water: 5000 particles -> VTK/water/water_0\.vtp$"
expectIn "log: the outline" "$log" \
    "^    freeSurface: [0-9]+ segments -> VTK/freeSurface/freeSurface_0\.vtp$"
expectIn "log: enclosed area against the particles'" "$log" \
    "^        encloses 0\.49[0-9]* m\^2 \(the particles' 0\.5, -?0\.[0-9]+ %\)$"
nSegments=$(sed -n 's/^    freeSurface: \([0-9]*\) segments.*/\1/p' "$log")
# The outline of a 1 x 0.5 m block on a grid of dp/2: about 3 m, 600
# squares of 5 mm, each two triangles and so two segments.
check "about 1200 segments (got $nSegments)" \
    [ "${nSegments:-0}" -ge 1180 -a "${nSegments:-0}" -le 1300 ]
check "VTK/freeSurface/freeSurface_0.vtp written" \
    [ -s "$run/VTK/freeSurface/freeSurface_0.vtp" ]
expectIn "freeSurface.vtp.series lists it" "$run/VTK/freeSurface.vtp.series" \
    '"name" : "freeSurface/freeSurface_0\.vtp", "time" : 0 '
area=$(sed -n 's/^        encloses \([0-9.e+-]*\) m^2.*/\1/p' "$log")
check "enclosed area within 0.5 % of 0.5 m^2 (got $area)" \
    awk -v a="$area" 'BEGIN { exit !(a > 0.4975 && a < 0.5025) }'

log="$scratch/log.refine"
cp -r "$run" "$scratch/refine"
particlesToVTK -case "$scratch/refine" -surfaceRefine 4 > "$log" 2>&1
check "-surfaceRefine 4 alone writes the surface (exit 0)" [ $? -eq 0 ]
fine=$(sed -n 's/^    freeSurface: \([0-9]*\) segments.*/\1/p' "$log")
check "-surfaceRefine 4: twice the segments ($nSegments, $fine)" \
    [ "${fine:-0}" -ge $((2*nSegments - 20)) -a \
      "${fine:-0}" -le $((2*nSegments + 20)) ]

# Errors: the FATAL ERROR block, the culprit named, exit status 1, nothing
# converted first.
expectFatal()
{
    expectFatalOf "$@"
    check "$1: nothing converted" \
        [ -z "$(grep '^Time = ' "$scratch/log.error")" ]
}
expectFatal "-surfaceLevel 1.5" "level 1\.5 is not in \(0, 1\)" \
    particlesToVTK -case "$run" -surfaceLevel 1.5
expectFatal "-surfaceLevel x" "Option -surfaceLevel expects a number, not 'x'" \
    particlesToVTK -case "$run" -surfaceLevel x
expectFatal "-surfaceRefine 0" "expects a whole number from 1 to 16, not '0'" \
    particlesToVTK -case "$run" -surfaceRefine 0
expectFatal "-surfaceRefine 1.5" "Option -surfaceRefine expects a whole number" \
    particlesToVTK -case "$run" -surfaceRefine 1.5
expectFatal "-surfaceRefine 4294967297" "from 1 to 16, not '4294967297'" \
    particlesToVTK -case "$run" -surfaceRefine 4294967297
cp -r "$run" "$scratch/clash"
mv "$scratch/clash/0/tank" "$scratch/clash/0/freeSurface"
out="$scratch/log.clash"
particlesToVTK -case "$scratch/clash" -freeSurface > "$out" 2>&1
check "a body named freeSurface: exit 1" [ $? -eq 1 ]
expectIn "a body named freeSurface: named" "$out" \
    "has a body named 'freeSurface'"

# Without system/sphSchemes the surface has no kernel: said before any time
# is converted.
cp -r "$run" "$scratch/noSchemes"
rm -rf "$scratch/noSchemes/VTK" "$scratch/noSchemes/system/sphSchemes"
particlesToVTK -case "$scratch/noSchemes" -freeSurface > "$scratch/log.noSchemes" 2>&1
check "no system/sphSchemes: exit 1" [ $? -eq 1 ]
expectIn "no system/sphSchemes: named" "$scratch/log.noSchemes" \
    "-freeSurface takes the solver's kernel and h from the case's system/sphSchemes and constant/fluidProperties, and there is no .*noSchemes/system/sphSchemes"
check "no system/sphSchemes: nothing converted" [ ! -e "$scratch/noSchemes/VTK" ]

# A time that fails to convert (its positions cut short) leaves the series
# of the times before it, for ParaView to open.
broken="$scratch/broken"
cp -r "$run" "$broken"
rm -rf "$broken/VTK"
cp -r "$broken/0" "$broken/0.1"
mkdir -p "$broken/0.1/uniform"
printf 'FoamFile { format ascii; class dictionary; object time; }\nbeginTime 0;\nvalue 0.1;\nname "0.1";\nindex 7;\ndeltaT 1e-4;\ndeltaT0 1e-4;\nc0 44;\n' \
    > "$broken/0.1/uniform/time"
head -c 200 "$broken/0/water/position" > "$broken/0.1/water/position"
particlesToVTK -case "$broken" -freeSurface > "$scratch/log.broken" 2>&1
check "a broken time: exit 1" [ $? -eq 1 ]
expectIn "a broken time: time 0 in the water's series" "$broken/VTK/water.vtp.series" \
    '"name" : "water/water_0\.vtp", "time" : 0 '
expectIn "a broken time: and in the surface's" "$broken/VTK/freeSurface.vtp.series" \
    '"name" : "freeSurface/freeSurface_0\.vtp", "time" : 0 '

# ParaView.
if ! command -v pvpython > /dev/null; then
    echo "pvpython not found: ParaView checks skipped"
    finish || exit 1
    exit 77
fi
cat > "$scratch/read.py" << 'EOF'
import sys
from paraview.simple import OpenDataFile
from paraview import servermanager
reader = OpenDataFile(sys.argv[1])
reader.UpdatePipeline(0.0)
d = servermanager.Fetch(reader)
pd = d.GetPointData()
names = sorted(pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays()))
types = set(d.GetCellType(i) for i in range(d.GetNumberOfCells()))
top = [d.GetPoint(i)[1] for i in range(d.GetNumberOfPoints())
       if 0.05 < d.GetPoint(i)[0] < 0.95 and d.GetPoint(i)[1] > 0.25]
print("cells", d.GetNumberOfCells())
print("types", sorted(types))
print("arrays", " ".join(names))
print("normals", pd.GetNormals() is not None)
print("top", len(top), min(top), max(top))
EOF
QT_QPA_PLATFORM=offscreen pvpython "$scratch/read.py" \
    "$run/VTK/freeSurface.vtp.series" > "$scratch/log.pvpython" 2>&1
cat "$scratch/log.pvpython"
expectIn "ParaView: the segments" "$scratch/log.pvpython" "^cells $nSegments$"
expectIn "ParaView: line cells (VTK_LINE 3)" "$scratch/log.pvpython" \
    "^types \[3\]$"
# 0/ as generated has no p (the solver writes it).
expectIn "ParaView: fields" "$scratch/log.pvpython" "^arrays Normals U rho$"
expectIn "ParaView: Normals are the normals" "$scratch/log.pvpython" \
    "^normals True$"
top=$(sed -n 's/^top //p' "$scratch/log.pvpython")
check "ParaView: the top at y = 0.5 to 0.1 mm ($top)" \
    awk -v t="$top" 'BEGIN { split(t, a, " ");
        exit !(a[1] > 50 && a[2] > 0.4999 && a[3] < 0.5001) }'

finish
