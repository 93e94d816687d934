#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test) of CSG with many operands: a 2 mm plate
# difference() { cube(...); for (...) translate(...) cylinder(...); } with N round holes on a
# 1 mm grid, N = 100, 1,000, 10,000 and 100,000, rendered whole at 640x480 by `scadray render`.
# Prints a Markdown table: the render time scadray reports (tracing), the whole run's wall time
# and peak memory (parse, evaluate, compile, BVH builds and start-up included) and, where POV-Ray
# is installed, POV-Ray's wall time on scadray's export of the same scene. POV-Ray is run only up
# to N = 1,000: its cost grows with N per ray (438 s at 10,000 holes on this machine).
# Then the Google Benchmark of the CSG nodes alone (build/tests/csg_bench): time per ray that
# hits and per ray that misses for plates, unions and intersections of N = 10 ... 100,000.
# Usage: scripts/bench_csg.sh [build-dir] [threads] [csg_bench options...]
#   threads: 1 by default (0 = all cores); e.g. --benchmark_filter=ray for csg_bench
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
threads=${2:-1}
BENCH_ARGS=("${@:3}")
povray_max=1000
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

plate() {  # N: writes $tmp/plate_N.scad, a side x side grid cut to N holes
    local n=$1 side
    side=$(awk -v n="$n" 'BEGIN { s = int(sqrt(n)); if (s * s < n) s++; print s }')
    cat >"$tmp/plate_$n.scad" <<EOF
// a plate with $n holes
n = $n;
side = $side;
difference() {
    cube([side, side, 2]);
    for (i = [0 : side - 1], j = [0 : side - 1])
        if (i * side + j < n) translate([i + 0.5, j + 0.5, -1]) cylinder(r=0.3, h=4);
}
EOF
}

# Wall seconds, CPU seconds (user + system) and peak KB of a command, its output kept in $tmp/out
timed() {
    /usr/bin/time -f "%e %U %S %M" -o "$tmp/time" "$@" >"$tmp/out" 2>&1 || {
        cat "$tmp/out" >&2
        return 1
    }
    awk '{ printf "%s %.2f %s\n", $1, $2 + $3, $4 }' "$tmp/time"
}

have_povray=0
command -v povray >/dev/null 2>&1 && have_povray=1
echo "Plate with N holes at 640x480, default (adaptive) sampling, $threads thread(s) (0 = all cores)"
echo
echo "| holes | scadray render time | scadray whole run: wall / CPU | peak memory | POV-Ray whole run (its export): wall / CPU |"
echo "|---:|---:|---:|---:|---:|"
for n in 100 1000 10000 100000; do
    plate "$n"
    read -r wall cpu kb < <(timed "$build/tools/scadray" render "$tmp/plate_$n.scad" -W 640 -H 480 \
        -t "$threads" -o "$tmp/plate_$n.png")
    render=$(sed -n 's/^scadray: .* \([0-9.]*\) s$/\1/p' "$tmp/out")
    prims=$(sed -n 's/^scadray: .*objects (\([0-9]*\) primitives.*/\1/p' "$tmp/out")
    if [ "$prims" != $((n + 1)) ]; then
        echo "plate_$n.scad: expected $((n + 1)) primitives, scadray says '$prims':" >&2
        cat "$tmp/out" >&2
        exit 1
    fi
    pov="not installed"
    if [ "$have_povray" = 1 ]; then
        if [ "$n" -le "$povray_max" ]; then
            "$build/tools/scadray" export "$tmp/plate_$n.scad" -W 640 -H 480 \
                -o "$tmp/plate_$n.pov" >/dev/null 2>&1
            read -r pwall pcpu _ < <(cd "$tmp" && timed povray "plate_$n.ini" "+WT$([ "$threads" = 0 ] && nproc || echo "$threads")")
            pov="$pwall s / $pcpu s"
        else
            pov="skipped (over $povray_max holes)"
        fi
    fi
    printf '| %s | %s s | %s s / %s s | %d MB | %s |\n' "$n" "$render" "$wall" "$cpu" $((kb / 1024)) "$pov"
done
echo
"$build/tests/csg_bench" "${BENCH_ARGS[@]}"
