#!/bin/bash
# generateParticles on bodies from STL surfaces, the way a user runs it: a
# closed STL solid, water filled from a seed in an open tank with wall
# layers on it, a 2D cut of an STL and a polygon; then bad input (missing
# file, open surface where a closed one is needed, seed outside, an open
# tank without a level; a clamp with no particle, nu 0.6, a one-layer solid)
# must end in a FATAL error that names the file or
# the keyword, with a non-zero exit.
. "$(dirname "$0")/testLib.sh"

# writeBoxStl file x0 y0 z0 x1 y1 z1 [open]: an ASCII STL box, outward
# normals; "open" leaves out the top face (a tank without a lid).
writeBoxStl()
{
    local file="$1" open="${8:-}"
    mkdir -p "$(dirname "$file")"
    awk -v a="$2" -v b="$3" -v c="$4" -v A="$5" -v B="$6" -v C="$7" \
        -v open="$open" '
    function v(i, j, k) { return (i ? A : a) " " (j ? B : b) " " (k ? C : c) }
    function tri(p, q, r) {
        print " facet normal 0 0 0\n  outer loop"
        print "   vertex " p "\n   vertex " q "\n   vertex " r
        print "  endloop\n endfacet"
    }
    function quad(p, q, r, s) { tri(p, q, r); tri(p, r, s) }
    BEGIN {
        print "solid box"
        quad(v(0,0,0), v(0,1,0), v(1,1,0), v(1,0,0))
        if (open != "open") quad(v(0,0,1), v(1,0,1), v(1,1,1), v(0,1,1))
        quad(v(0,0,0), v(1,0,0), v(1,0,1), v(0,0,1))
        quad(v(0,1,0), v(0,1,1), v(1,1,1), v(1,1,0))
        quad(v(0,0,0), v(0,0,1), v(0,1,1), v(0,1,0))
        quad(v(1,0,0), v(1,1,0), v(1,1,1), v(1,0,1))
        print "endsolid box"
    }' > "$file"
}

# runCase name: generateParticles on $scratch/name, log in log.name,
# status in $status.
runCase()
{
    generateParticles -case "$scratch/$1" > "$scratch/log.$1" 2>&1
    status=$?
}

# A 3D case: a closed STL solid, an open tank with 3 wall layers outside
# and water up to 0.3 inside.
c3="$scratch/tank3D"
writeBoxStl "$c3/constant/geometry/tank.stl" 0 0 0 1 1 1 open
writeBoxStl "$c3/constant/geometry/block.stl" 2 0 0 2.5 0.5 0.5
mkdir -p "$c3/system"
cat > "$c3/system/generateParticlesDict" <<'DICT'
nDimensions 3;
dp          0.05;
bodies
{
    block
    {
        type    solid;
        rho     2700;
        shapes { b { shape stl; file "constant/geometry/block.stl"; } }
    }
    walls
    {
        type    wall;
        rho     1000;
        shapes
        {
            t { shape surfaceLayers; file "constant/geometry/tank.stl";
                layers 3; side outside; }
        }
    }
    water
    {
        type    fluid;
        rho     1000;
        shapes
        {
            w { shape seedFill; file "constant/geometry/tank.stl";
                seed (0.5 0.5 0.1); level 0.3; }
        }
    }
}
DICT
runCase tank3D
check "3D STL case runs" [ "$status" -eq 0 ]
log="$scratch/log.tank3D"
expectIn "stl solid: 10 x 10 x 10 particles, zero volume error" "$log" \
    "block \(solid\): 1000 particles, .*error [+-]0.00 %"
expectIn "seedFill water: 20 x 20 x 6 particles" "$log" \
    "water \(fluid\): 2400 particles"
expectIn "surfaceLayers walls have particles" "$log" \
    "walls \(wall\): [1-9][0-9]* particles"
check "no water dropped next to the walls" \
    bash -c "! grep -E 'water .*dropped' '$log'"
for body in block walls water; do
    check "0/$body/position written" [ -f "$c3/0/$body/position" ]
done

# A 2D case: the cut of a box across z = 0 and a polygon.
c2="$scratch/cut2D"
writeBoxStl "$c2/constant/geometry/box.stl" 0 0 -0.5 1 1 0.5
mkdir -p "$c2/system"
cat > "$c2/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.1;
bodies
{
    plate
    {
        type    solid;
        rho     2700;
        shapes { b { shape stl; file "constant/geometry/box.stl"; } }
    }
    water
    {
        type    fluid;
        rho     1000;
        shapes { p { shape polygon; points ((2 0) (4 0) (4 1) (3 1) (3 2) (2 2)); } }
    }
}
DICT
runCase cut2D
check "2D STL cut and polygon run" [ "$status" -eq 0 ]
expectIn "2D cut of a box: 10 x 10 particles, area error 0" \
    "$scratch/log.cut2D" "plate \(solid\): 100 particles, .*error [+-]0.00 %"
expectIn "polygon: an L of 300 particles" \
    "$scratch/log.cut2D" "water \(fluid\): 300 particles, .*error [+-]0.00 %"

# A 2D gate from a closed STL, clamped by a second STL at its top, with its
# material from constant/solidProperties: 5 x 40 particles, the top 2 rows
# clamped, and a warning that 5 layers are too few at nu = 0.4 without the
# surface correction (with it, the default, 5 layers are within 3 %).
cg="$scratch/gate2D"
writeBoxStl "$cg/constant/geometry/gate.stl" 0 0 -0.5 0.05 0.4 0.5
writeBoxStl "$cg/constant/geometry/support.stl" -1 0.38 -0.5 1 1 0.5
mkdir -p "$cg/system"
cat > "$cg/system/generateParticlesDict" <<'DICT'
nDimensions 2;
dp          0.01;
bodies
{
    gate
    {
        type    solid;
        shapes { plate { shape stl; file "constant/geometry/gate.stl"; } }
        clamp  { top { shape stl; file "constant/geometry/support.stl"; } }
    }
}
DICT
cat > "$cg/constant/solidProperties" <<'PROPS'
gate { rho 1100; E 12e6; nu 0.4; plane planeStress; surfaceCorrection off; }
PROPS
runCase gate2D
check "clamped 2D gate runs" [ "$status" -eq 0 ]
expectIn "gate: 200 particles, 10 clamped" "$scratch/log.gate2D" \
    "gate \(solid\): 200 particles.*, 10 clamped"
expectIn "thin gate warned" "$scratch/log.gate2D" \
    "thinnest member is 5 layers thick.*19 layers give at most 5 %"
check "0/gate/clamped written" [ -f "$cg/0/gate/clamped" ]
check "10 ones in 0/gate/clamped" \
    [ "$(grep -cx 1 "$cg/0/gate/clamped")" -eq 10 ]

# gateFatal name file sed-expression pattern...: a copy of the gate case
# with file (relative to it) edited must fail with every pattern.
gateFatal()
{
    local name="$1" file="$2" edit="$3"; shift 3
    rm -rf "$scratch/$name"
    cp -r "$cg" "$scratch/$name"
    rm -rf "$scratch/$name/0"
    sed -i "$edit" "$scratch/$name/$file"
    runCase "$name"
    check "$name exits non-zero" [ "$status" -ne 0 ]
    local p
    for p in "SPHVCPM FATAL (IO )?ERROR" "$@"; do
        expectIn "$name: /$p/" "$scratch/log.$name" "$p"
    done
}
gateFatal clampEmpty constant/geometry/support.stl 's/0\.38/0.45/g' \
    "Solid 'gate': its clamp holds none of its 200 particles" \
    "generateParticlesDict at line 9"
gateFatal nuTooLarge constant/solidProperties 's/nu 0.4/nu 0.6/' \
    "Keyword 'nu' of solid 'gate'" "outside the admissible range" \
    "solidProperties at line 1"
gateFatal gateOneLayer constant/geometry/gate.stl 's/0\.05 /0.01 /g' \
    "Solid 'gate' is too thin" "1 particle thick"

# Bad input: each a copy of the 3D case with one change. expectFatal name
# sed-expression pattern...: the run fails with FATAL and every pattern.
expectFatal()
{
    local name="$1" edit="$2"; shift 2
    rm -rf "$scratch/$name"
    cp -r "$c3" "$scratch/$name"
    rm -rf "$scratch/$name/0"
    sed -i "$edit" "$scratch/$name/system/generateParticlesDict"
    runCase "$name"
    check "$name exits non-zero" [ "$status" -ne 0 ]
    expectIn "$name: FATAL" "$scratch/log.$name" "SPHVCPM FATAL (IO )?ERROR"
    local p
    for p in "$@"; do
        expectIn "$name: /$p/" "$scratch/log.$name" "$p"
    done
}

# Lines of the dictionary that the errors must name.
dict3="$c3/system/generateParticlesDict"
blockLine=$(grep -n 'block.stl' "$dict3" | cut -d: -f1)
seedLine=$(grep -n 'seed (' "$dict3" | cut -d: -f1)

expectFatal missingFile 's|geometry/block.stl|geometry/nothere.stl|' \
    "Keyword 'file'" "nothere.stl" "generateParticlesDict at line $blockLine"
expectFatal openWhereClosed 's|shape stl; file "constant/geometry/block.stl"|shape stl; file "constant/geometry/tank.stl"|' \
    "not closed" "4 open edges" "checkClosed" "tank.stl" \
    "Shape 'b' \(.*generateParticlesDict line $blockLine\)"
expectFatal seedOutside 's|seed (0.5 0.5 0.1)|seed (1.5 0.5 0.1)|' \
    "Keyword 'seed'" "outside the bounding box" "tank.stl" \
    "generateParticlesDict at line $seedLine"
expectFatal noLevel 's| level 0.3;||' \
    "Keyword 'seed'" "not inside a container" "give a level"
expectFatal badSide 's|side outside|side out|' \
    "'side'" "unknown value 'out'"
# A second fluid filled into the same tank: its every particle would sit
# on one of the first's.
expectFatal twoFluidsOverlap 's|^    water$|    water2 { type fluid; rho 1000; shapes { w { shape box; min (0.1 0.1 0.05); max (0.4 0.4 0.2); } } }\n    water|' \
    "Body 'water2?' \\(fluid\\) overlaps the fluid body water2?: [0-9]+ of its lattice nodes"

finish
