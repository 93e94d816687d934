#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test) of rendering across machines: one scene rendered by one process on
# every core, then in TILES tiles through Slurm (scripts/slurm/submit.sh, one core a tile) on the
# private single-node cluster of tests/slurm/cluster.sh; prints both wall times, the tiles'
# CPU seconds, and whether the two pictures are the same bit for bit. On one machine the cluster
# cannot be faster than one multi-threaded process: the figure is the cost of the scheduling,
# the scene read once per tile and the bordering rows each tile traces again.
# Needs root, slurm-wlm and munge (as the test). Usage:
#   scripts/bench_slurm.sh [build-dir] [scene] [width] [height] [tiles] [render options...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scene=$(realpath "${2:-scenes/default.scad}")
width=${3:-640} height=${4:-480} tiles=${5:-4}
shift $(($# < 5 ? $# : 5))
options=("$@")
scadray=$(realpath "$build/tools/scadray")
[ -x "$scadray" ] || {
    echo "bench_slurm: $scadray not found; build the target scadray first" >&2
    exit 2
}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

now() { date +%s%N; }
ms() { echo "$((($2 - $1) / 1000000))"; }

start=$(now)
"$scadray" render -q "$scene" -W "$width" -H "$height" "${options[@]}" -o "$tmp/single.png"
single=$(ms "$start" "$(now)")

# Inside the cluster: the submission, waited for, and the tiles' CPU time from their logs
cat >"$tmp/in_cluster.sh" <<EOF
set -e
start=\$(date +%s%N)
scripts/slurm/submit.sh render --wait -n $tiles --scadray "$scadray" -o "$tmp/tiled.png" "$scene" \
    -W $width -H $height ${options[*]} >/dev/null
echo "\$(((\$(date +%s%N) - start) / 1000000))" >"$tmp/tiled_ms"
EOF
tests/slurm/cluster.sh run -- bash "$tmp/in_cluster.sh"
tiled=$(cat "$tmp/tiled_ms")
cpu=$(grep -h -o '[0-9.]* s CPU' "$tmp/tiled.png.tiles/logs/"scadray-tile-* | awk '{s += $1} END {printf "%.2f", s}')
same=no
cmp -s "$tmp/single.png" "$tmp/tiled.png" && same=yes
echo "scene $(basename "$scene") ${width}x${height} ${options[*]}, $(nproc) cores"
echo "  one process (all cores):         $single ms"
echo "  $tiles tiles through Slurm (1 core each): $tiled ms wall, $cpu s CPU in the renders"
echo "  same picture bit for bit: $same"
