#!/bin/bash
# Case input as OpenFOAM users write it: variables in
# generateParticlesDict, some from a file included through $FOAM_CASE
# (set by the application) with parameters of other dictionaries too, a
# switch written 1, and 'value uniform' in a field file of 0/. A
# misspelled keyword that no $name uses still stops, also from the
# included file.
. "$(dirname "$0")/testLib.sh"

# The same case written with literal values: the particles to expect.
reference="$scratch/reference"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$reference"
sed -i 's/openTop no;/openTop yes;/' "$reference/system/generateParticlesDict"
generateParticles -case "$reference" > "$scratch/log.reference" 2>&1
check "generateParticles on the literal case (exit 0)" [ $? -eq 0 ]

run="$scratch/case"
cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$run"
# The parameters of the whole case, some for other dictionaries (gateE,
# runEnd): let pass here.
printf 'L 0.8;\nH 0.5;\ngateE 1e6;\nrunEnd 2;\n' > "$run/system/caseParams"
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
expectIn "the other dictionaries' parameters: named in one warning" "$scratch/log.variables" \
    "Dictionary \".*generateParticlesDict\" does not read \(gateE runEnd\) of the file it #includes"
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

# An included entry that reads as a misspelling of a keyword here: the
# error names the included file and its line.
sed -i '/^colunmH/d' "$run/system/generateParticlesDict"
printf 'nDimension 2;\n' >> "$run/system/caseParams"
generateParticles -case "$run" > "$scratch/log.includedMisspelt" 2>&1
check "included misspelt keyword: exit 1" [ $? -eq 1 ]
expectIn "included misspelt keyword: named, with the keyword meant" "$scratch/log.includedMisspelt" \
    "Unknown keyword 'nDimension' .*Did you mean 'nDimensions'\?"
expectIn "included misspelt keyword: the included file's line" "$scratch/log.includedMisspelt" \
    "file: .*system/caseParams at line 5"
sed -i '/^nDimension /d' "$run/system/caseParams"

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
