# Reading ascii particle fields in script tests (sourced after testLib.sh,
# which provides $scratch).

# fieldValues <file>: the values of an ascii field, one per line (a vector
# as "x y z"), in file order.
fieldValues()
{
    awk '
        /^value/ { seen = 1; next }
        seen && !inList && /^\($/ { inList = 1; next }
        inList && /^\)/ { exit }
        inList { gsub(/[()]/, ""); print }' "$1"
}

# withFirstValue <file> <value>: the ascii field with its first value
# replaced (a damaged field for the error tests), on stdout.
withFirstValue()
{
    awk -v value="$2" '
        /^\($/ { inList = 1; print; next }
        inList && !done { print value; done = 1; next }
        { print }' "$1"
}

# bodyTable <timeDir> <body> <field>...: "id value..." per particle, sorted
# by id, for comparing runs whose particle order may differ.
bodyTable()
{
    local dir="$1/$2"; shift 2
    local tmp="$scratch/.bodyTable.$$"
    local args=("$tmp.id") f
    fieldValues "$dir/id" > "$tmp.id"
    for f in "$@"; do
        fieldValues "$dir/$f" > "$tmp.$f"
        args+=("$tmp.$f")
    done
    paste -d ' ' "${args[@]}" | sort -n -k1,1
    rm -f "$tmp".*
}

# maxDifference <tableA> <tableB>: the largest absolute difference of the
# value columns of two bodyTables (ids must match row by row; "ids differ"
# otherwise). nan when a value is not a finite number or no row was read
# (two missing or empty tables do not agree), so that a check of the result
# with isFinite (testLib.sh) fails.
maxDifference()
{
    paste -d ' ' "$1" "$2" | awk "$awkFinite"'
        { n = NF/2; if (NF % 2 || $1 != $(n+1)) { differ = 1; exit 1 }
          rows++
          for (i = 2; i <= n; i++) {
              if (!finite($i) || !finite($(n+i))) { bad = 1; continue }
              d = $i - $(n+i); if (d < 0) d = -d; if (d > m) m = d } }
        END { if (differ) { print "ids differ"; exit 1 }
              if (!rows || bad) print "nan"; else printf "%.3g\n", m + 0 }'
}
