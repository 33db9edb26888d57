# Sourced by the benchmark scripts, which set $top (and $scratch for
# bench).

# benchCase <tutorial> <dir> <endTime> [dp] [timeScheme]: a clean copy of
# tutorials/sphVcpmFsi/<tutorial> in <dir>, to run from its start to
# endTime without writes or function objects (the physics alone is
# timed), with particle spacing dp and the time scheme when given (the
# tutorial's otherwise).
benchCase()
{
    local c="$2"
    cp -r "$top/tutorials/sphVcpmFsi/$1/." "$c"
    (cd "$c" && ./Allclean > /dev/null 2>&1; rm -rf 0)
    [ -n "${4:-}" ] && sed -i "s/^dp .*/dp $4;/" "$c/system/generateParticlesDict"
    sed -i "s/^endTime .*/endTime $3;/; s/^writeInterval .*/writeInterval 1000;/; /^functions/,\$d" \
        "$c/system/controlDict"
    if [ -n "${5:-}" ]; then
        sed -i '/^timeScheme/d' "$c/system/sphSchemes"
        echo "timeScheme $5;" >> "$c/system/sphSchemes"
    fi
}

# bench <tutorial> <endTime> <cellDivisor> [dp] [device]: one table row for
# a benchCase copy run on device cpu or cuda with cells of 2h/cellDivisor
# and the time scheme $benchScheme when set.
bench()
{
    local name="$1" endTime="$2" divisor="${3:-1}" dp="${4:-}" device="${5:-cpu}"
    local c="$scratch/$1.$3.$4.$device"
    mkdir -p "$c"
    benchCase "$1" "$c" "$endTime" "$dp" "${benchScheme:-}"
    sed -i "s/^logInterval .*/logInterval 100000;/" "$c/system/controlDict"
    sed -i '/^cellDivisor/d' "$c/system/sphSchemes"
    echo "cellDivisor $divisor;" >> "$c/system/sphSchemes"
    [ -n "${benchScheme:-}" ] && name="$name ($benchScheme)"
    (cd "$c" && generateParticles > log.generateParticles 2>&1 \
             && sphVcpmFsi -device "$device" > log.sphVcpmFsi 2>&1) \
        || { echo "$name failed"; tail "$c/log.sphVcpmFsi"; return; }
    awk -v name="$name" -v div="$divisor" '
        / bytes per particle/ { bytes = $1 }
        /^Run summary:/ { steps = $3; n = $6; wall = $9 }
        /particle-steps\/s/ { ps = $1; ips = $4; nb = $7; gsub(/\(/, "", nb) }
        END { printf "| %s | %d | %d | 2h/%d | %s | %.3g | %.3g M | %.3g G | %s |\n",
                     name, n, steps, div, nb, wall, ps, ips, bytes }' "$c/log.sphVcpmFsi"
}
