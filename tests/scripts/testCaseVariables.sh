#!/bin/bash
# Case input as OpenFOAM users write it: variables in
# generateParticlesDict, some from a file included through $FOAM_CASE
# (set by the application), a switch written 1, and 'value uniform' in a
# field file of 0/. A misspelled keyword that no $name uses still stops.
. "$(dirname "$0")/testLib.sh"

# The same case written with literal values: the particles to expect.
reference="$scratch/reference"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$reference"
sed -i 's/openTop no;/openTop yes;/' "$reference/system/generateParticlesDict"
generateParticles -case "$reference" > "$scratch/log.reference" 2>&1
check "generateParticles on the literal case (exit 0)" [ $? -eq 0 ]

run="$scratch/case"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$run"
printf 'L 0.8;\nH 0.5;\n' > "$run/system/caseParams"
cat > "$run/system/generateParticlesDict" <<'DICT'
#include "$FOAM_CASE/system/caseParams"
nDimensions     2;
dpVal           0.01;
dp              $dpVal;
columnH         0.4;
bodies
{
    box
    {
        type        wall;
        container { min (0 0 0); max ($L $H 0); layers 3; openTop 1; }
    }
    water
    {
        type        fluid;
        shapes { column { shape box; min (0 0 0); max (0.2 $columnH 0); } }
    }
}
DICT
# From elsewhere, with another case's FOAM_CASE inherited.
(cd "$scratch" && FOAM_CASE=/no/such/case generateParticles -case "$run") \
    > "$scratch/log.variables" 2>&1
check "variables, \$FOAM_CASE include, openTop 1 (exit 0)" [ $? -eq 0 ]
for body in box water; do
    check "$body: the particles of the literal case" \
        cmp -s "$run/0/$body/position" "$reference/0/$body/position"
done

# A misspelling no $name uses: the usual FATAL IO ERROR.
sed -i 's/^columnH         0.4;/columnH 0.4;\ncolunmH 0.3;/' \
    "$run/system/generateParticlesDict"
generateParticles -case "$run" > "$scratch/log.misspelt" 2>&1
check "unused misspelt keyword: exit 1" [ $? -eq 1 ]
expectIn "unused misspelt keyword: named" "$scratch/log.misspelt" \
    "Unknown keyword 'colunmH' in dictionary"

# value uniform in 0/water/U: read (particlesToVTK reads every field), and
# a scalar there is an error naming the field.
U="$run/0/water/U"
sed -i '/^value/,$d' "$U"
cp "$U" "$scratch/U.header"
echo "value           uniform (0 -1 0);" >> "$U"
particlesToVTK -case "$run" > "$scratch/log.uniform" 2>&1
check "value uniform (0 -1 0) in 0/water/U: particlesToVTK (exit 0)" \
    [ $? -eq 0 ]
# The column 0.2 x 0.4 at dp 0.01: 20 x 40 particles.
expectIn "value uniform: all 800 water particles converted" \
    "$scratch/log.uniform" "^    water: 800 particles"
{ cat "$scratch/U.header"; echo "value           uniform 0;"; } > "$U"
particlesToVTK -case "$run" > "$scratch/log.uniformBad" 2>&1
check "value uniform 0 in U: exit 1" [ $? -eq 1 ]
expectIn "value uniform 0 in U: says why" "$scratch/log.uniformBad" \
    "The uniform value '0' is not a vector"

finish
