#!/bin/bash
# sphVcpmFsi on bad input and bad runs: each a clear FATAL ERROR naming the
# file, line or keyword (or a warning), exit 1 and never a crash or a hang;
# particles leaving the domain are removed and counted while the run goes
# on; a blow-up stops with a diagnosis and writes the last good state.
. "$(dirname "$0")/testLib.sh"

source="$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D"
fresh()
{
    rm -rf "$scratch/c"
    cp -r "$source" "$scratch/c"
    sed -i 's/^endTime .*/endTime 0.01;/' "$scratch/c/system/controlDict"
    (cd "$scratch/c" && generateParticles > log.generateParticles 2>&1)
}
# expectFatal <what> <pattern>...: the solver exits 1 with each pattern
expectFatal()
{
    local what="$1"; shift
    (cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
    check "$what: exit status 1" [ $? -eq 1 ]
    local p
    for p in "$@"; do expectIn "$what: says /$p/" "$scratch/c/log.solver" "$p"; done
}

# The device: a bad name from the environment is an error naming where it
# may come from; cuda without a GPU (CI) says why and stops.
fresh
(cd "$scratch/c" && SPHVCPM_DEVICE=gpu timeout 60 sphVcpmFsi > log.solver 2>&1)
check "SPHVCPM_DEVICE=gpu: exit status 1" [ $? -eq 1 ]
expectIn "SPHVCPM_DEVICE=gpu: says what is expected" "$scratch/c/log.solver" \
    "device gpu: expected cpu, cuda or auto .*SPHVCPM_DEVICE"
if ! (cd "$scratch/c" && timeout 60 sphVcpmFsi -device cuda > log.solver 2>&1) \
   && grep -q "no GPU can be used" "$scratch/c/log.solver"; then
    pass "-device cuda without a GPU stops and says why"
    expectIn "-device cuda without a GPU: points to the CPU" "$scratch/c/log.solver" "-device cpu"
elif grep -q '^End' "$scratch/c/log.solver"; then
    pass "-device cuda ran on this machine's GPU"
else
    fail "-device cuda neither ran nor said why"; tail -5 "$scratch/c/log.solver"
fi
# device cuda; in controlDict without a GPU: the error names the file and line.
fresh; sed -i 's/^endTime .*/&\ndevice cuda;/' "$scratch/c/system/controlDict"
(cd "$scratch/c" && timeout 60 sphVcpmFsi > log.solver 2>&1)
if grep -q "no GPU can be used" "$scratch/c/log.solver"; then
    line=$(grep -n '^device' "$scratch/c/system/controlDict" | cut -d: -f1)
    expectIn "device cuda; in controlDict without a GPU: names controlDict's line" \
        "$scratch/c/log.solver" "system/controlDict.* at line $line"
else
    check "device cuda; in controlDict ran on this machine's GPU" grep -q '^End' "$scratch/c/log.solver"
fi
fresh
# auto: the GPU when there is one, else the CPU, and the run goes on.
(cd "$scratch/c" && rm -rf 0.* && timeout 60 sphVcpmFsi -device auto > log.solver 2>&1)
check "-device auto runs (on a GPU or falling back to the CPU)" grep -q '^End' "$scratch/c/log.solver"
expectIn "-device auto says where it runs" "$scratch/c/log.solver" "device auto: running on the (GPU|CPU)"

fresh; rm "$scratch/c/system/sphSchemes"
expectFatal "missing sphSchemes" "FATAL IO ERROR" "system/sphSchemes" \
    "an empty one takes every default"
fresh; rm "$scratch/c/constant/fluidProperties"
expectFatal "missing fluidProperties" "FATAL IO ERROR" \
    "constant/fluidProperties of the case \\(it needs rho0, and c0 or coefSound"

fresh; sed -i 's/^kernel /kernal /' "$scratch/c/system/sphSchemes"
line=$(grep -n '^kernal' "$scratch/c/system/sphSchemes" | cut -d: -f1)
expectFatal "misspelled kernel" "kernal" "sphSchemes.* at line $line" "'kernel'"

fresh; sed -i 's/^kernel .*/kernel quintic;/' "$scratch/c/system/sphSchemes"
expectFatal "unknown kernel" "quintic" "wendlandC2" "cubicSpline"

fresh; sed -i 's/^boundary .*/boundary { type adami; contact -1; }/' "$scratch/c/system/sphSchemes"
expectFatal "a negative contact push" "contact must be in \\[0, 10\\]" "sphSchemes"

fresh; sed -i 's/^boundary .*/boundary { type adami; contact 0; }/' "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
expectIn "contact 0: the log says the push is off" "$scratch/c/log.solver" "contact push off"

# The time scheme: an unknown one, a non-positive verletSteps, and Verlet
# with shifting (whose shift lives in the symplectic corrector).
# A keyword of one type under another would be silently unused; the
# dictionary form of artificial viscosity takes alpha's default as the word
# form does.
fresh; sed -i 's/^viscosity .*/viscosity { type laminar; alpha 0.1; }/' "$scratch/c/system/sphSchemes"
expectFatal "alpha under laminar" "'alpha' applies to type artificial only; with type laminar it would have no effect" "sphSchemes"
fresh; echo "timeScheme { type symplectic; verletSteps 20; }" >> "$scratch/c/system/sphSchemes"
expectFatal "verletSteps under symplectic" "'verletSteps' applies to type verlet only" "sphSchemes"
fresh; sed -i 's/^densityDiffusion .*/densityDiffusion { type none; delta 0.1; }/' "$scratch/c/system/sphSchemes"
expectFatal "delta under none" "'delta' applies to type fourtakas or molteniColagrossi only" "sphSchemes"
fresh; sed -i 's/^viscosity .*/viscosity { type artificial; }/' "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
expectIn "viscosity { type artificial; }: alpha 0.01 by default" "$scratch/c/log.solver" \
    "viscosity artificial \(alpha 0.01\)"

# A restart with a c0 changed since the run's start is weighed against the
# scene again (a still fluid as read would pass any c0).
fresh; sed -i 's/^stopAt .*/stopAt writeNow;/' "$scratch/c/system/controlDict"
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
sed -i 's/^coefSound .*/c0 1;/' "$scratch/c/constant/fluidProperties"
sed -i 's/^stopAt .*/stopAt endTime;/' "$scratch/c/system/controlDict"
expectFatal "a restart with c0 lowered to 1 m/s" "Reading time [0-9.e-]+" \
    "the speed of sound c0 = 1 m/s is far too low for this scene"

# A fixed step beyond the acoustic limit: a warning before the run, and a
# blow-up diagnosis that points to deltaT, not to maxCo.
fresh; sed -i 's/^deltaT .*/deltaT 2e-3;/; s/^adjustTimeStep .*/adjustTimeStep no;/' "$scratch/c/system/controlDict"
expectFatal "a fixed step 25 times the acoustic limit" \
    "adjustTimeStep no with deltaT 0.002 s, above the acoustic limit maxCo h/c0 = " \
    "lower deltaT, or set adjustTimeStep yes"

# deltaT longer than the run (minDeltaT, deltaT*1e-6 by default, would
# otherwise be blamed on writeInterval); a fixed step that would take more
# than 1e9 steps (a hang).
fresh; sed -i 's/^deltaT .*/deltaT 1e300;/' "$scratch/c/system/controlDict"
expectFatal "deltaT 1e300" "deltaT 1e\+300 s is longer than endTime 0.01 s" \
    "system/controlDict.* at line"
fresh; sed -i 's/^deltaT .*/deltaT 1e-300;/; s/^adjustTimeStep .*/adjustTimeStep no;/' "$scratch/c/system/controlDict"
expectFatal "adjustTimeStep no with deltaT 1e-300" \
    "adjustTimeStep no with deltaT 1e-300 s would take 1e\+298 steps to endTime 0.01 s"

# constant/g with dimensions that are not an acceleration.
fresh
printf 'FoamFile { class uniformDimensionedVectorField; object g; }\ndimensions [1 0 0 0 0 0 0];\nvalue (0 -5 0);\n' \
    > "$scratch/c/constant/g"
expectFatal "constant/g with dimensions of a mass" "Keyword 'dimensions': dimensions do not match: expected \[0 1 -2 0 0 0 0\], found \[1 0 0 0 0 0 0\]" \
    "constant/g at line 2"

# Probes and gauges outside the domain read 0: a warning names them.
fresh; sed -i '/^functions/,$d' "$scratch/c/system/controlDict"
cat >> "$scratch/c/system/controlDict" <<'DICT'
functions
{
    p { type probes; probeLocations ((3.45 0.01 0) (0.1 0.01 0)); }
    h { type freeSurfaceGauges; locations ((0.1 -5 0) (10 0 0)); }
}
DICT
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
check "probes and gauges outside the domain: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "a probe outside the domain: warned" "$scratch/c/log.solver" \
    "Function object 'p': probe 0 at \(3.45 0.01 0\) is outside the domain .* it reads 0"
expectIn "a gauge outside the domain: warned" "$scratch/c/log.solver" \
    "Function object 'h': gauge 1 at \(10 0 0\): its line up is outside the domain"
check "points inside the domain, or a gauge below it whose line up crosses it: no warning" bash -c "! grep -qE \"probe 1|gauge 0 \" '$scratch/c/log.solver'"

fresh; echo "timeScheme leapfrog;" >> "$scratch/c/system/sphSchemes"
expectFatal "unknown time scheme" "leapfrog" "symplectic" "verlet" "sphSchemes"
fresh; echo "timeScheme { type verlet; verletSteps 0; }" >> "$scratch/c/system/sphSchemes"
expectFatal "verletSteps 0" "verletSteps must be a positive number" "sphSchemes"
fresh; echo "timeScheme { type verlet; verletSteps 60; }" >> "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
expectIn "verletSteps 60: a warning naming the tested limits" "$scratch/c/log.solver" \
    "timeScheme verlet was found stable with verletSteps <= 40"
fresh; echo "timeScheme verlet;" >> "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "timeScheme verlet with the defaults: no warning" \
    bash -c "! grep -q 'Warning' '$scratch/c/log.solver'"
# A wall thinner than the kernel's support: a warning naming the wall, its
# thickness and the layers it needs; the run goes on.
fresh; sed -i 's/layers 3;/layers 2;/' "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "a wall of 2 layers: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "a wall of 2 layers: warned, with the layers it needs" "$scratch/c/log.solver" \
    "Wall 'box' has a member only 2 layers \(0.02 m\) thick .* support 2h = 0.03 m .* at least 3 layers"
fresh; sed -i 's/^hOverDp .*/hOverDp 2;/' "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
expectIn "hOverDp 2 with walls of 3 layers: warned" "$scratch/c/log.solver" \
    "Wall 'box' has a member only 3 layers .* support 2h = 0.04 m \(hOverDp 2\).* at least 4 layers"
fresh; sed -i 's/^hOverDp .*/hOverDp 1.3;/' "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "hOverDp 1.3 with walls of 3 layers: no warning about the walls" \
    bash -c "! grep -q 'has a member only' '$scratch/c/log.solver'"
# Walls that stay put are measured together: a wedge lying on the floor,
# thin at its toe, is no thin wall; a baffle one layer thick standing on
# the floor still is.
fresh; sed -i 's/^    water$/    ramp { type wall; shapes { w { shape polygon; points ((0.5 0) (0.8 0) (0.8 0.1)); } } }\n&/' \
    "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "a wedge wall on the floor: the run ends" grep -q '^End' "$scratch/c/log.solver"
check "a wedge wall on the floor: no warning about the walls" \
    bash -c "! grep -q 'has a member only' '$scratch/c/log.solver'"
fresh; sed -i 's/^    water$/    baffle { type wall; shapes { b { shape box; min (0.6 0 0); max (0.61 0.2 0); } } }\n&/' \
    "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
expectIn "a baffle of 1 layer on the floor: warned" "$scratch/c/log.solver" \
    "Wall 'baffle' has a member only 1 layers \\(0.01 m\\) thick"
# Two such baffles in the one group of static walls: each is named.
fresh; sed -i 's/^    water$/    baffle { type wall; shapes { b { shape box; min (0.6 0 0); max (0.61 0.2 0); } } }\n    baffle2 { type wall; shapes { b { shape box; min (0.7 0 0); max (0.71 0.2 0); } } }\n&/' \
    "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
expectIn "two baffles of 1 layer on the floor: the first warned" "$scratch/c/log.solver" \
    "Wall 'baffle' has a member only 1 layers"
expectIn "two baffles of 1 layer on the floor: the second warned" "$scratch/c/log.solver" \
    "Wall 'baffle2' has a member only 1 layers"
# A thick static wall on a shifted lattice (its own latticeOrigin) forms a
# group of its own: the wedge on the floor is still measured with the
# floor, no false warning.
fresh; sed -i 's/^    water$/    ramp { type wall; shapes { w { shape polygon; points ((0.5 0) (0.8 0) (0.8 0.1)); } } }\n    block { type wall; latticeOrigin (0.005 0.005 0); shapes { b { shape box; min (0.4 0.3 0); max (0.46 0.36 0); } } }\n&/' \
    "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "a wedge on the floor and a wall off its lattice: the run ends" grep -q '^End' "$scratch/c/log.solver"
check "a wedge on the floor and a wall off its lattice: no warning about the walls" \
    bash -c "! grep -q 'has a member only' '$scratch/c/log.solver'"

# Damping zones: logged when read; a bad one is an error naming the file.
fresh; echo "beach { start (0.5 0 0); end (0.8 0 0); rate 20; }" > "$scratch/c/constant/dampingZones"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "a damping zone: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "a damping zone: logged" "$scratch/c/log.solver" \
    "beach: from \(0.5 0 0\) to \(0.8 0 0\), rate 20 1/s"
echo "beach { start (0.5 0 0); end (0.5 0 0); rate 20; }" > "$scratch/c/constant/dampingZones"
expectFatal "a damping zone of no length" "constant/dampingZones" \
    "end \(0.5 0 0\) must differ from start"
echo "beach { start (0.5 0 0); end (0.8 0 0); rate 0; }" > "$scratch/c/constant/dampingZones"
expectFatal "a damping zone of rate 0" "constant/dampingZones" \
    "expected a relaxation rate > 0"

fresh; sed -i 's/^shifting .*/shifting { type fickian; }/' "$scratch/c/system/sphSchemes"
echo "timeScheme verlet;" >> "$scratch/c/system/sphSchemes"
expectFatal "Verlet with shifting" "use timeScheme symplectic with shifting" "sphSchemes"

fresh; sed -i 's/^rho0 .*/rho0 -1000;/' "$scratch/c/constant/fluidProperties"
expectFatal "negative rho0" "rho0" "fluidProperties"

# rho0 changed after generateParticles: the masses of 0/ carry the old
# density (walls would push as if denser): refused, naming the remedy.
fresh; sed -i 's/^rho0 .*/rho0 998;/' "$scratch/c/constant/fluidProperties"
expectFatal "rho0 changed since generateParticles" \
    "Body box of time 0: particle id [0-9]+ has mass .*, a density of 1000 kg/m\\^3 over dp\\^2, but rho0 of constant/fluidProperties is 998" \
    "Run generateParticles again after changing rho0"

fresh; sed -i 's/^coefSound .*/coefSound 20; c0 30;/' "$scratch/c/constant/fluidProperties"
expectFatal "both c0 and coefSound" "exactly one of c0" "fluidProperties"

fresh; sed -i 's/^coefSound .*/c0 5;/' "$scratch/c/constant/fluidProperties"
expectFatal "a speed of sound far too low" "far too low" "at least 10 times" "m/s"

fresh; sed -i 's/^maxCo .*/maxCo 3;/' "$scratch/c/system/controlDict"
expectFatal "maxCo out of range" "maxCo" "controlDict"

fresh; sed -i 's/^endTime .*/endTime -1;/' "$scratch/c/system/controlDict"
expectFatal "negative endTime" "endTime must be > 0"

fresh; rm -rf "$scratch/c/0"
expectFatal "no time directory" "generateParticles"

fresh; sed -i 's/^dp .*/dp 0.02;/' "$scratch/c/0/box/bodyProperties"
expectFatal "bodies of different dp" "must share one spacing"

fresh; sed -i 's/^coefSound .*/coefSound 7;/' "$scratch/c/constant/fluidProperties"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "a low speed of sound only warns: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "a low speed of sound: warning" "$scratch/c/log.solver" "Warning"

# A restart time with a body the initial time lacks (a directory copied
# in): an error naming it, not a body joining the run.
fresh; sed -i 's/^endTime .*/endTime 0.01; writeControl timeStep; writeInterval 5;/' \
    "$scratch/c/system/controlDict"
(cd "$scratch/c" && sphVcpmFsi > log.first 2>&1)
restartTime=$(cd "$scratch/c" && ls -d 0.* | sort -g | tail -1)
check "a run to restart from wrote $restartTime" [ -n "$restartTime" ]
cp -r "$scratch/c/$restartTime/water" "$scratch/c/$restartTime/water2"
expectFatal "a body not in 0/ at the restart time" \
    "Body water2 of the restart time .* is not in the initial time 0/"
rm -rf "$scratch/c/$restartTime/water2"
# uniform/time holds c0 of the run's start: a damaged or misspelt one is
# named, not passed over.
timeFile="$scratch/c/$restartTime/uniform/time"
cp "$timeFile" "$scratch/time.orig"
sed -i 's/^c0 .*/c0 -4;/' "$timeFile"
expectFatal "c0 -4 in uniform/time" "uniform/time" "Keyword 'c0' .* must be > 0"
cp "$scratch/time.orig" "$timeFile"; sed -i 's/^c0 /cO /' "$timeFile"
expectFatal "cO in uniform/time" "Unknown keyword 'cO' in .*uniform/time"
cp "$scratch/time.orig" "$timeFile"
# A 2D body's positions and velocities lie in z = 0: a z in a field file
# (ascii or binary) is an error naming the file and the value.
(cd "$scratch/c" && sed -i 's/^writeFormat .*/writeFormat ascii;/' system/controlDict \
    && rm -rf 0.* && sphVcpmFsi > log.first 2>&1)
restartTime=$(cd "$scratch/c" && ls -d 0.* | sort -g | tail -1)
sed -i '0,/^(\([-0-9.e]*\) \([-0-9.e]*\) 0)$/s//(\1 \2 0.01)/' \
    "$scratch/c/$restartTime/water/position"
expectFatal "z = 0.01 in a 2D position file" "$restartTime/water/position" \
    "Body 'water' is 2D .* value 0 of field 'position' has z = 0\.01"
# ... but a z at rounding level (older runs whose motion's origin was off
# the plane) is read as 0.
sed -i 's/^(\([-0-9.e]*\) \([-0-9.e]*\) 0\.01)$/(\1 \2 3.4e-16)/' \
    "$scratch/c/$restartTime/water/position"
(cd "$scratch/c" && sed -i 's/^endTime .*/endTime 0.012;/' system/controlDict \
    && sphVcpmFsi > log.solver 2>&1)
check "z = 3.4e-16 in a 2D position file: read as 0, the run goes on" \
    grep -q '^End' "$scratch/c/log.solver"

# A warning of controlDict is given once, after the banner (the solver's
# first look at controlDict, for the device, is quiet).
fresh; sed -i 's/^endTime .*/&\nwriteCompression on;/' "$scratch/c/system/controlDict"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "writeCompression on: the run ends" grep -q '^End' "$scratch/c/log.solver"
check "writeCompression on: one warning (got $(grep -c 'writeCompression' "$scratch/c/log.solver"))" \
    [ "$(grep -c 'writeCompression' "$scratch/c/log.solver")" = 1 ]
check "writeCompression on: the warning after the banner" \
    awk '/^Exec   :/ { banner = NR } /writeCompression/ { w = NR }
         END { exit !(banner && w > banner) }' "$scratch/c/log.solver"

# speedSystem: c0 = coefSound speedSystem, and the check of c0 expects that
# speed (the free fall over the column's height, 0.2 m, would be 2 m/s).
fresh; sed -i 's/^coefSound .*/coefSound 10; speedSystem [0 1 -1 0 0 0 0] 0.5;/' \
    "$scratch/c/constant/fluidProperties"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
check "speedSystem 0.5, coefSound 10: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "speedSystem 0.5, coefSound 10: c0 = 5 m/s" "$scratch/c/log.solver" "c0 = 5 m/s"
check "speedSystem 0.5, coefSound 10: no warning (c0 is 10 times it)" \
    bash -c "! grep -q 'Warning' '$scratch/c/log.solver'"
fresh; sed -i 's/^coefSound .*/c0 1; speedSystem 0.5;/' "$scratch/c/constant/fluidProperties"
expectFatal "c0 below 3 speedSystem" "far too low" "0.5 m/s \\(speedSystem\\)"
fresh; sed -i 's/^coefSound .*/coefSound 10; speedSystem -1;/' "$scratch/c/constant/fluidProperties"
expectFatal "a negative speedSystem" "speedSystem" "must be > 0" "fluidProperties"

# A time step below minDeltaT: diagnosis, last good state written.
fresh; sed -i 's/^adjustTimeStep .*/adjustTimeStep yes; minDeltaT 1e-3;/' "$scratch/c/system/controlDict"
expectFatal "a step below minDeltaT" "below minDeltaT" "particle id [0-9]+ of body water at \(" \
    "last good state is the start time, 0/"

# An initial speed above the scene's sets c0 with coefSound: the log says
# which particle (one damaged velocity would set every step).
fresh; sed -i 's/^\( *type  *fluid;\)/\1 U (30 0 0);/' "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
expectIn "c0 from an initial speed: the log names the particle" "$scratch/c/log.solver" \
    "c0 = coefSound x 30 m/s, the initial speed of id [0-9]+ of body water at"

# Dimensions written must be the quantity's: a density's on nu is a slip.
fresh; sed -i 's/^nu .*/nu [1 -3 0 0 0 0 0] 1e-06;/' "$scratch/c/constant/fluidProperties"
expectFatal "nu with a density's dimensions" "constant/fluidProperties" "nu" "\\[0 2 -1 0 0 0 0\\]"
# Values outside their ranges: an error naming the file and the keyword.
fresh; sed -i 's/^hOverDp .*/hOverDp 5;/' "$scratch/c/system/sphSchemes"
expectFatal "hOverDp 5" "system/sphSchemes" "hOverDp 5.* is outside the usable range \\[0.9, 3\\]"
fresh; echo "cellDivisor 7;" >> "$scratch/c/system/sphSchemes"
expectFatal "cellDivisor 7" "system/sphSchemes" "cellDivisor must be 1, 2, 3 or 4"
fresh; sed -i 's/delta 0.1;/delta 2;/' "$scratch/c/system/sphSchemes"
expectFatal "density diffusion delta 2" "system/sphSchemes" "delta must be in \\[0, 1\\]"
fresh; sed -i 's/^nu .*/nu -1e-6;/' "$scratch/c/constant/fluidProperties"
expectFatal "nu < 0" "constant/fluidProperties" "the kinematic viscosity nu must be >= 0"
fresh; sed -i 's/^gamma .*/gamma 0.5;/' "$scratch/c/constant/fluidProperties"
expectFatal "gamma 0.5" "constant/fluidProperties" "the Tait exponent gamma must be >= 1"
fresh; printf 'FoamFile { class uniformDimensionedVectorField; object g; }\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 1);\n' \
    > "$scratch/c/constant/g"
expectFatal "gravity out of a 2D case's plane" "constant/g" "gravity must have z = 0"
fresh; printf 'FoamFile { class uniformDimensionedVectorField; object g; }\nvalue [0 1 -1 0 0 0 0] (0 -9.81 0);\n' \
    > "$scratch/c/constant/g"
expectFatal "gravity of a speed's dimensions" "constant/g" "dimensions do not match: expected \\[0 1 -2 0 0 0 0\\]"
fresh; sed -i 's/^ *front .*/&\n    p0 { type probes; fields (); probeLocations ((0.1 0.1 0)); }/' \
    "$scratch/c/system/controlDict"
expectFatal "probes of no field" "system/controlDict" "Function object 'p0': fields is empty"
fresh; sed -i 's/^ *front .*/&\n    tip { type solidPoints; body gate; points ((0.5 0.1 0)); }/' \
    "$scratch/c/system/controlDict"
expectFatal "solidPoints of no solid" "system/controlDict" "there is no solid body 'gate'"
# The short form of a selection takes its defaults.
fresh; sed -i 's/^shifting .*/shifting fickian;/' "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
check "shifting fickian; (short form): the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "shifting fickian; (short form): the log says so" "$scratch/c/log.solver" "shifting fickian"

# A dictionary that is a FIFO is refused rather than waited on; a missing
# ';' after application no longer swallows the entry that follows.
fresh; rm "$scratch/c/system/sphSchemes"; mkfifo "$scratch/c/system/sphSchemes"
expectFatal "sphSchemes a FIFO" "system/sphSchemes" "not a regular file"
fresh; sed -i 's/^application .*/application sphVcpmFsi/' "$scratch/c/system/controlDict"
expectFatal "application without ';'" "system/controlDict" "Keyword 'application'.*expected ';'"

# A write interval below minDeltaT would make every step land below the
# floor: an input error naming writeInterval, before any step.
fresh; sed -i 's/^writeInterval .*/writeInterval 1e-300;/' "$scratch/c/system/controlDict"
expectFatal "writeInterval below minDeltaT" "system/controlDict" \
    "writeInterval 1e-300 s is below minDeltaT 1e-10 s"
# A number beyond double's range is an error, not infinity.
fresh; sed -i 's/^endTime .*/endTime 1e999;/' "$scratch/c/system/controlDict"
expectFatal "endTime 1e999" "system/controlDict" "Number '1e999' is too large"

# A fixed step far too large: the run blows up, says where, and writes the
# state at the start of the step that blew up (undoing the step: velocity
# and density kept, positions to round-off). A run that writes every step
# (writeControl timeStep: no step shortened to land on a write, so the
# same steps) has that state on disk already: its blow-up names that write
# rather than writing it again under a name of raised precision, and the
# two states agree. verletSteps 1 makes every Verlet step an Euler step, as
# the step after a write is, so that writes change no step there either.
. "$(dirname "$0")/fieldTools.sh"
blowUpPair()    # blowUpPair <timeScheme>
{
    local s=$1 every t tEvery body d
    fresh
    sed -i 's/^adjustTimeStep .*/adjustTimeStep no;/; s/^deltaT .*/deltaT 0.004;/; s/^endTime .*/endTime 0.4;/; s/^writeControl .*/writeControl timeStep;/; s/^writeInterval .*/writeInterval 1000;/; s/^writeFormat .*/writeFormat ascii;/; s/^writePrecision .*/writePrecision 17;/' \
        "$scratch/c/system/controlDict"
    if [ "$s" = verlet ]; then
        echo "timeScheme { type verlet; verletSteps 1; }" >> "$scratch/c/system/sphSchemes"
    else
        echo "timeScheme $s;" >> "$scratch/c/system/sphSchemes"
    fi
    every="$scratch/blowUp.$s.every"
    rm -rf "$every"; cp -r "$scratch/c" "$every"
    sed -i 's/^writeInterval .*/writeInterval 1;/' "$every/system/controlDict"
    expectFatal "$s: a blow-up" "blew up at time" "particle id [0-9]+ of body water" \
        "The state the failing step started from \\(time [0-9.e-]+\\) was written to [0-9.e-]+/ to look at; a restart from latestTime refuses it \\(blowUp in its uniform/time\\): remove it to go on from 0/"
    [ "$s" = verlet ] && expectIn "$s: a blow-up: the Verlet advice" \
        "$scratch/c/log.solver" "With timeScheme verlet"
    t=$(sed -n 's/.*was written to \([^/]*\)\/.*/\1/p' "$scratch/c/log.solver" | head -1)
    check "$s: the last good state ${t:-?}/ exists and is complete" \
        [ -n "$t" -a -f "$scratch/c/$t/water/position" -a -f "$scratch/c/$t/uniform/time" ]
    # The cause fixed, a restart does not go on from the blown-up state
    # unless controlDict names it.
    if [ "$s" = symplectic ]; then
        local r="$scratch/blowUp.restart"
        rm -rf "$r"; cp -r "$scratch/c" "$r"
        sed -i 's/^adjustTimeStep .*/adjustTimeStep yes;/; s/^deltaT .*/deltaT 1e-5;/; s/^endTime .*/endTime 0.03;/' \
            "$r/system/controlDict"
        (cd "$r" && timeout 120 sphVcpmFsi > log.solver 2>&1)
        check "$s: restart from the blown-up $t/: exit status 1" [ $? -eq 1 ]
        expectIn "$s: restart from the blown-up $t/: says what to do" "$r/log.solver" \
            "Time $t is the state a blown-up run stopped at \\(blowUp in .*$t/uniform/time\\).*remove $t/ to go on from the write before it"
        sed -i "s/^startFrom .*/startFrom startTime;/; s/^startTime .*/startTime $t;/" "$r/system/controlDict"
        (cd "$r" && timeout 120 sphVcpmFsi > log.solver 2>&1)
        expectIn "$s: startTime $t named: a warning, and it runs" "$r/log.solver" \
            "Time $t is the state a blown-up run stopped at.*started from it as system/controlDict asks"
    fi
    (cd "$every" && timeout 120 sphVcpmFsi > log.solver 2>&1)
    check "$s: a blow-up after a write: exit status 1" [ $? -eq 1 ]
    expectIn "$s: a blow-up after a write: names it" "$every/log.solver" \
        "The last good state \\(time [0-9.e-]+\\) is the last write, [0-9.e-]+/"
    tEvery=$(sed -n 's/.*is the last write, \([^/]*\)\/.*/\1/p' "$every/log.solver" | head -1)
    check "$s: both blow up in the same step (${t:-?} and ${tEvery:-?})" [ -n "$t" -a "$t" = "$tEvery" ]
    check "$s: a blow-up after a write: no precision raised" \
        bash -c "! grep -q 'Increased the timePrecision' '$every/log.solver'"
    [ -n "$t" -a "$t" = "$tEvery" ] || return
    bodyTable "$scratch/c/$t" water U rho > "$scratch/undone.state"
    bodyTable "$every/$t" water U rho > "$scratch/written.state"
    d=$(maxDifference "$scratch/undone.state" "$scratch/written.state")
    check "$s: the undone step's velocity and density are the state written before it ($d)" \
        isFinite "$d" 'v == 0'
    bodyTable "$scratch/c/$t" water position > "$scratch/undone.state"
    bodyTable "$every/$t" water position > "$scratch/written.state"
    d=$(maxDifference "$scratch/undone.state" "$scratch/written.state")
    check "$s: the undone step's positions are the ones written before it, to round-off ($d m)" \
        isFinite "$d" 'v < 1e-12'
}
blowUpPair symplectic
blowUpPair verlet

# A wall's U is a surface velocity it keeps in place (a belt; a cavity's
# lid): generateParticles notes it, and after 0.1 s the tank is where it
# was, every particle still at U, and the water in the floor's first three
# layers dragged along (+x) more than the water above.
rm -rf "$scratch/c"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D" "$scratch/c"
(cd "$scratch/c" && ./Allclean > /dev/null 2>&1)
sed -i 's/^dp .*/dp 0.02;/; s/^        type        wall;/        type        wall;\n        U           (0.2 0 0);/' \
    "$scratch/c/system/generateParticlesDict"
sed -i 's/^endTime .*/endTime 0.1;/; s/^writeInterval .*/writeInterval 0.1;/; s/^writeFormat .*/writeFormat ascii;/; /^functions/,$d' \
    "$scratch/c/system/controlDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "a wall with U: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "a wall with U: generateParticles notes its surface velocity" "$scratch/c/log.generateParticles" \
    "tank \(wall\): 408 particles.*surface velocity U \(0\.2 0 0\) m/s, in place"
bodyTable "$scratch/c/0" tank position > "$scratch/belt.0"
bodyTable "$scratch/c/0.1" tank position > "$scratch/belt.1"
check "a wall with U: in place after 0.1 s" [ -s "$scratch/belt.0" ]
check "a wall with U: in place after 0.1 s (positions by id)" cmp -s "$scratch/belt.0" "$scratch/belt.1"
fieldValues "$scratch/c/0.1/tank/U" > "$scratch/belt.wallU"
check "a wall with U: every particle keeps U" \
    awk '{ n++; if ($0 != "0.2 0 0") bad++ } END { exit !(n == 408 && !bad) }' "$scratch/belt.wallU"
fieldValues "$scratch/c/0.1/water/position" > "$scratch/belt.x"
fieldValues "$scratch/c/0.1/water/U" > "$scratch/belt.U"
check "a wall with U: the water on the floor dragged along, more than above" \
    awk 'FNR == NR { y[FNR] = $2; next }
         y[FNR] < 0.06 { n++; lo += $1 } y[FNR] > 0.3 { m++; hi += $1 }
         END { print "    mean u: floor " lo/n ", above " hi/m
               exit !(n > 0 && m > 0 && lo/n > 0.05 && lo/n > 2*hi/m) }' \
        "$scratch/belt.x" "$scratch/belt.U"

# A wavemaker's depth is the water's at the paddle (waveFlume2D: 0.25 m):
# one of 0.5 m (the stroke, and the waves, 32 % too low) is warned of.
rm -rf "$scratch/c"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/waveFlume2D" "$scratch/c"
(cd "$scratch/c" && ./Allclean > /dev/null 2>&1)
sed -i 's/^endTime .*/endTime 0.001;/; /^functions/,$d' "$scratch/c/system/controlDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "pistonWave depth 0.25 in 0.25 m of water: the run ends" grep -q '^End' "$scratch/c/log.solver"
check "pistonWave depth 0.25 in 0.25 m of water: no depth warning" \
    bash -c "! grep -q \"wavemaker's depth\" '$scratch/c/log.solver'"
rm -rf "$scratch/c/0.001"
sed -i 's/^\( *depth *\)0\.25;/\10.5;/' "$scratch/c/constant/motion"
(cd "$scratch/c" && sphVcpmFsi > log.solver 2>&1)
expectIn "pistonWave depth 0.5 in 0.25 m of water: warned with both" "$scratch/c/log.solver" \
    "Motion piston: its wavemaker's depth is 0\.5 m, but the water beside its bodies is 0\.25 m deep"
expectIn "pistonWave depth 0.5 in 0.25 m of water: names constant/motion" "$scratch/c/log.solver" \
    "constant/motion at line"

# Particles leaving the domain: water thrown up out of the open tank of
# hydrostaticTank2D past the domain's top is removed and counted, and the
# run goes on.
rm -rf "$scratch/c"
cp -r "$SPHVCPM_DIR/tutorials/sphVcpmFsi/hydrostaticTank2D" "$scratch/c"
(cd "$scratch/c" && ./Allclean > /dev/null 2>&1)
sed -i 's/^dp .*/dp 0.02;/; s/^        type        fluid;/        type        fluid;\n        U           (0 4 0);/' \
    "$scratch/c/system/generateParticlesDict"
sed -i 's/^endTime .*/endTime 0.3;/; /^functions/,$d' "$scratch/c/system/controlDict"
echo 'domain { min (-0.1 -0.1 0); max (1.1 1.0 0); }' >> "$scratch/c/system/sphSchemes"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1 && sphVcpmFsi > log.solver 2>&1)
check "fluid crossing the domain bounds: the run ends" grep -q '^End' "$scratch/c/log.solver"
expectIn "fluid crossing the domain bounds: removed and counted" "$scratch/c/log.solver" \
    "^Removed [0-9]+ particles? of water that left the domain"
expectIn "the run summary counts the removed particles" "$scratch/c/log.solver" \
    "water: [0-9]+ particles removed for leaving the domain"
check "the run summary: the largest speed at least the initial 4 m/s, its Mach number speed/c0, Ma^2 in %" \
    awk '/largest fluid speed/ { u = $4
             for (i = 1; i < NF; ++i) {
                 if ($i == "Mach") ma = $(i + 1)
                 if ($i == "c0" && $(i + 1) == "=") c0 = $(i + 2)
                 if ($i == "Ma^2" && $(i + 1) == "=") pc = $(i + 2)
             }
             found = 1 }
         END { exit !(found && u >= 4 && ma > 0 && (ma - u/c0)^2 < (1e-2*ma)^2 \
                      && (pc - 100*ma*ma)^2 < (2e-2*pc)^2) }' \
        "$scratch/c/log.solver"
check "removals reported with the log lines, not one line each" \
    [ "$(grep -c '^Removed ' "$scratch/c/log.solver")" -le "$(grep -c '^Time = ' "$scratch/c/log.solver")" ]
check "the removals reported add up to the summary's count" \
    awk '/^Removed / { n += $2 } /particles removed for leaving the domain/ { total = $2 }
         END { exit !(n > 0 && n == total) }' "$scratch/c/log.solver"

# A domain that leaves out wall particles: an error naming the particle
# and the domain (a wall is never removed, as fluid leaving is).
fresh
echo 'domain { min (0.05 -0.1 0); max (1 1 0); }' >> "$scratch/c/system/sphSchemes"
expectFatal "a domain without some walls" \
    "Wall particle id [0-9]+ of body box at .* lies outside the domain bounds" \
    "enlarge the domain of system/sphSchemes"

# A 3D case reads every vector with 3 components: a 2-component one (a
# slip from a 2D case, read as z = 0) is an error naming the file.
fresh3D()
{
    rm -rf "$scratch/c"
    cp -r "$source" "$scratch/c"
    sed -i 's/^nDimensions .*/nDimensions 3;/; s/^dp .*/dp 0.05;/; s/max (0.8 0.5 0)/max (0.8 0.5 0.2)/; s/max (0.2 0.4 0)/max (0.2 0.4 0.2)/' \
        "$scratch/c/system/generateParticlesDict"
    sed -i 's/^endTime .*/endTime 0.001;/' "$scratch/c/system/controlDict"
    (cd "$scratch/c" && generateParticles > log.generateParticles 2>&1)
}
fresh3D
check "3D: the case generates" [ -f "$scratch/c/0/water/position" ]
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
check "3D: the case runs" grep -q '^End' "$scratch/c/log.solver"
# Built with y up, as in 2D: the log says that g is the default, along -z.
expectIn "3D without constant/g: the log says which way is up" "$scratch/c/log.solver" \
    "g = \\(0 0 -9.81\\) \\(no constant/g: the 3D default, up is \\+z\\)"
rm -rf "$scratch/c"/0.*
printf 'FoamFile { class uniformDimensionedVectorField; object g; }\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81 0);\n' \
    > "$scratch/c/constant/g"
(cd "$scratch/c" && timeout 120 sphVcpmFsi > log.solver 2>&1)
expectIn "3D with constant/g: its g, without the note" "$scratch/c/log.solver" "g = \\(0 -9.81 0\\)$"
rm "$scratch/c/constant/g"
rm -rf "$scratch/c"/0.*
sed -i 's/max (0.2 0.4 0.2)/max (0.2 0.4)/' "$scratch/c/system/generateParticlesDict"
(cd "$scratch/c" && generateParticles > log.generateParticles 2>&1)
check "3D: a 2-component vector in generateParticlesDict: exit status 1" [ $? -eq 1 ]
expectIn "3D: a 2-component vector in generateParticlesDict: says so" \
    "$scratch/c/log.generateParticles" "vector of 3 components \\(x y z\\) in a 3D case"
expectIn "3D: a 2-component vector in generateParticlesDict: names the file" \
    "$scratch/c/log.generateParticles" "system/generateParticlesDict"
fresh3D
printf 'FoamFile { class uniformDimensionedVectorField; object g; }\ndimensions [0 1 -2 0 0 0 0];\nvalue (0 -9.81);\n' \
    > "$scratch/c/constant/g"
expectFatal "3D: gravity of 2 components" "vector of 3 components \\(x y z\\) in a 3D case" "constant/g"
rm "$scratch/c/constant/g"
echo 'domain { min (-0.1 -0.1); max (1 1 1); }' >> "$scratch/c/system/sphSchemes"
expectFatal "3D: a domain corner of 2 components" "vector of 3 components \\(x y z\\) in a 3D case" "system/sphSchemes"
fresh3D
sed -i 's/direction (1 0 0);/direction (1 0);/' "$scratch/c/system/controlDict"
expectFatal "3D: a function object's direction of 2 components" \
    "vector of 3 components \\(x y z\\) in a 3D case" "system/controlDict"

finish
