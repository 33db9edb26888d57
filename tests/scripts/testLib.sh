# Shared helpers of the script tests (sourced). Each test counts its checks
# and ends with "N passed, N failed".
set -u
nPassed=0
nFailed=0

# Whether the run that wrote log was a single-precision build (its banner
# says so): comparisons to round-off then use float's, documented where
# used (docs/solver.md, "Precision").
singleBuild() { grep -q "(single precision)" "$1"; }

pass() { nPassed=$((nPassed + 1)); echo "PASS: $*"; }
fail() { nFailed=$((nFailed + 1)); echo "FAIL: $*"; }

# isFinite <value> [<awk condition on v>]: value is a finite number (an
# empty, nan or inf one is not; awkFinite of bin/tools/RunFunctions, sourced
# below) and the condition holds, e.g.
#     check "small" isFinite "$d" 'v < 1e-9'
isFinite()
{
    awk -v v="$1" "$awkFinite"'BEGIN { exit !(finite(v) && ('"${2:-1}"')) }'
}

# check "what" command...: passes when the command succeeds
check()
{
    local what="$1"; shift
    if "$@"; then pass "$what"; else fail "$what"; fi
}

# expectIn "what" file pattern: grep -E pattern in file
expectIn()
{
    if grep -qE -- "$3" "$2"; then pass "$1"; else
        fail "$1: /$3/ not found in $2"; sed 's/^/    | /' "$2" | tail -n 15
    fi
}

# expectFatalOf "what" pattern command...: the command exits 1 with the
# FATAL ERROR block and pattern (grep -E) in its output, which stays in
# $scratch/log.error for further checks.
expectFatalOf()
{
    local what="$1" pattern="$2"; shift 2
    local out="$scratch/log.error"
    "$@" > "$out" 2>&1
    check "$what: exit 1" [ $? -eq 1 ]
    expectIn "$what: FATAL ERROR" "$out" "SPHVCPM FATAL ERROR"
    expectIn "$what: message" "$out" "$pattern"
}

finish()
{
    echo "$nPassed passed, $nFailed failed"
    [ "$nFailed" -eq 0 ]
}

# A scratch directory removed on exit (kept when SPHVCPM_KEEP_SCRATCH is
# set, for debugging).
scratch=$(mktemp -d "${TMPDIR:-/tmp}/sphvcpmTest.XXXXXX")
[ -n "${SPHVCPM_KEEP_SCRATCH:-}" ] || trap 'rm -rf "$scratch"' EXIT

: "${SPHVCPM_DIR:=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}"
export SPHVCPM_DIR
# SPHVCPM_APPBIN: the build's applications (platforms/bin-single for a
# single-precision build, set by CTest).
export PATH="${SPHVCPM_APPBIN:-$SPHVCPM_DIR/platforms/bin}:$SPHVCPM_DIR/bin:$PATH"
# awkFinite, the finite-number test in awk that the tutorials' checks use
# too, with the rest of the Allruns' functions.
. "$SPHVCPM_DIR/bin/tools/RunFunctions"

# skipWithoutGpu <what>: exits 77 (skipped) when sphVcpmFsi cannot use a
# GPU here, saying why (a short run of the coarse dam break asks for one).
skipWithoutGpu()
{
    local probe="$scratch/gpuProbe"
    cp -r "$SPHVCPM_DIR/tests/data/cases/damBreakSmall2D" "$probe"
    (cd "$probe" && generateParticles > log.generateParticles 2>&1 \
        && sed -i "s/^endTime .*/endTime 0.001;/" system/controlDict \
        && sphVcpmFsi -device cuda > log.cuda 2>&1)
    if grep -q "no GPU can be used" "$probe/log.cuda"; then
        echo "No GPU: $(grep -o 'no GPU can be used.*' "$probe/log.cuda" | head -1)"
        echo "Skipped: $1 needs a GPU"
        exit 77
    fi
}

# Case dictionaries the solver tests share.
# writeGravity <case> "<vector>": constant/g
writeGravity()
{
    mkdir -p "$1/constant"
    printf 'dimensions [0 1 -2 0 0 0 0];\nvalue      %s;\n' "$2" > "$1/constant/g"
}

# writeFsiControl <case> <endTime> <deltaT> <writeInterval> <logInterval>
# [lines...]: system/controlDict of a coupled run (adaptive step at maxCo
# 0.2, ascii at 17 digits), the lines appended (functions, say).
writeFsiControl()
{
    mkdir -p "$1/system"
    {
        printf '%s\n' "application     sphVcpmFsi;" "startFrom       latestTime;" \
            "startTime       0;" "stopAt          endTime;" "endTime         $2;" \
            "deltaT          $3;" "adjustTimeStep  yes;" "maxCo           0.2;" \
            "maxDeltaT       1e-3;" "writeControl    adjustableRunTime;" \
            "writeInterval   $4;" "writeFormat     ascii;" "writePrecision  17;" \
            "logInterval     $5;"
        shift 5
        [ $# -eq 0 ] || printf '%s\n' "$@"
    } > "$1/system/controlDict"
}

# writeWaterModel <case> "<c0 or coefSound entry>": water in
# constant/fluidProperties and the default schemes (Wendland C2, h = 1.5
# dp, Fourtakas diffusion, laminar viscosity, Adami walls) in
# system/sphSchemes.
writeWaterModel()
{
    mkdir -p "$1/constant" "$1/system"
    echo "rho0 1000; nu 1e-6; $2 gamma 7; turbulence off;" > "$1/constant/fluidProperties"
    cat > "$1/system/sphSchemes" <<'DICT'
kernel wendlandC2; hOverDp 1.5;
densityDiffusion { type fourtakas; delta 0.1; }
viscosity { type laminar; }
shifting { type none; }
boundary adami;
DICT
}
