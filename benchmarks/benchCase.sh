# bench <tutorial> <endTime> <cellDivisor> [dp] [device]: one table row for
# a scratch copy of tutorials/sphVcpmFsi/<tutorial> run from its start to
# endTime without writes or function objects, with particle spacing dp
# (the tutorial's by default) on device cpu or cuda, and the time scheme
# $benchScheme when set (the tutorial's otherwise). Sourced by the
# run*Benchmarks scripts, which set $top and $scratch.
bench()
{
    local name="$1" endTime="$2" divisor="${3:-1}" dp="${4:-}" device="${5:-cpu}"
    local c="$scratch/$1.$3.$4.$device"
    cp -r "$top/tutorials/sphVcpmFsi/$1" "$c"
    (cd "$c" && ./Allclean > /dev/null 2>&1; rm -rf 0)
    [ -n "$dp" ] && sed -i "s/^dp .*/dp $dp;/" "$c/system/generateParticlesDict"
    sed -i "s/^endTime .*/endTime $endTime;/; s/^writeInterval .*/writeInterval 1000;/; s/^logInterval .*/logInterval 100000;/" \
        "$c/system/controlDict"
    # No function objects: the physics alone is timed.
    sed -i '/^functions/,$d' "$c/system/controlDict"
    sed -i '/^cellDivisor/d' "$c/system/sphSchemes"
    echo "cellDivisor $divisor;" >> "$c/system/sphSchemes"
    if [ -n "${benchScheme:-}" ]; then
        sed -i '/^timeScheme/d' "$c/system/sphSchemes"
        echo "timeScheme $benchScheme;" >> "$c/system/sphSchemes"
        name="$name ($benchScheme)"
    fi
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
