#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test): scadray against POV-Ray 3.7 at equal quality. Each scene is rendered
# by scadray with N stratified samples per pixel and by POV-Ray from scadray's own export,
# supersampled k x k by size (the way `check` compares them: N = k*k), on one thread and on two.
# Whole processes are timed (parse, build, trace, write): CPU seconds (user + system) and wall
# seconds, best of RUNS. Prints a Markdown table with POV-Ray's time over scadray's: CPU time
# for one thread, wall time for two.
# Usage: scripts/bench_povray.sh [-b BUILD_DIR] [-r RUNS] [-k "3 4"] [-t "1 2"] [SCENE ...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build runs=1 ks="3 4" threads="1 2"
while getopts "b:r:k:t:" opt; do
    case $opt in
    b) build=$OPTARG ;;
    r) runs=$OPTARG ;;
    k) ks=$OPTARG ;;
    t) threads=$OPTARG ;;
    *) exit 2 ;;
    esac
done
shift $((OPTIND - 1))
scenes=("$@")
[[ ${#scenes[@]} -gt 0 ]] ||
    scenes=(scenes/default.scad scenes/lecture_csg.scad scenes/csg_part.scad scenes/print_plate.scad
        scenes/mirrors.scad scenes/glass.scad scenes/crosscheck/meshes.scad)
bin=$build/tools/scadray
[[ -x $bin ]] || { echo "bench_povray: $bin is not built (scripts/build.sh)" >&2; exit 1; }
if ! command -v povray >/dev/null; then
    echo "bench_povray: povray is not installed (scripts/setup.sh installs it); nothing to compare" >&2
    exit 0
fi
width=640 height=480
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Runs a command RUNS times; prints "cpu wall" of the run with the least CPU time.
best_of() {
    local best="" line
    for ((i = 0; i < runs; ++i)); do
        /usr/bin/time -f "%U %S %e" -o "$tmp/time" "$@" >"$tmp/log" 2>&1 ||
            { cat "$tmp/log" >&2; echo "bench_povray: failed: $*" >&2; exit 1; }
        line=$(awk '{ printf "%.2f %.2f", $1 + $2, $3 }' "$tmp/time")
        if [[ -z $best ]] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
            best=$line
        fi
    done
    echo "$best"
}

echo "scadray vs POV-Ray $(povray --version 2>&1 | awk '/^POV-Ray/ { print $2; exit }'): ${width}x${height}," \
    "whole processes, best of $runs, $(nproc) cores, $(date -u +%Y-%m-%d)"
echo
echo "| scene | spp | threads | scadray CPU / wall | POV-Ray CPU / wall | POV-Ray / scadray |"
echo "|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
    name=${scene#scenes/}
    for k in $ks; do
        spp=$((k * k))
        "$bin" export "$scene" -q -o "$tmp/scene.pov" -W $width -H $height --supersample "$k"
        for t in $threads; do
            read -r sc sw < <(best_of "$bin" render "$scene" -q -o "$tmp/ours.png" -W $width -H $height \
                -s "$spp" -t "$t")
            read -r pc pw < <(cd "$tmp" && best_of povray scene.ini "+WT$t" -GA)
            if [[ $t == 1 ]]; then
                ratio=$(awk -v a="$pc" -v b="$sc" 'BEGIN { printf "%.2fx CPU", a / b }')
            else
                ratio=$(awk -v a="$pw" -v b="$sw" 'BEGIN { printf "%.2fx wall", a / b }')
            fi
            echo "| $name | $spp | $t | $sc s / $sw s | $pc s / $pw s | $ratio |"
        done
    done
done
