#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# What the render plan saves: every scene in scenes/ (and scenes/montecarlo/) rendered with the
# plan and with --no-plan (nothing left out, no CSG pruning, shadow rays to every light as a
# naive ray tracer casts them), best of N runs each, at the same size and sample count. Prints
# a Markdown table: time, rays, shadow rays, span merges, pruned subtrees, solids, and whether
# the two pictures are identical. A benchmark, not a test.
# Usage: scripts/bench_plan.sh [WIDTH HEIGHT RUNS]   (default 640 480 3)
set -euo pipefail
cd "$(dirname "$0")/.."
width=${1:-640} height=${2:-480} runs=${3:-3}
bin=./build/tools/scadray
[[ -x $bin ]] || ./scripts/build.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# One render; prints "seconds rays spanops pruned objects spp shadow"
measure() {
    local scene=$1 out=$2; shift 2
    local best="" line
    for ((i = 0; i < runs; ++i)); do
        "$bin" render "$scene" -o "$out" -W "$width" -H "$height" "$@" 2>"$tmp/log" >/dev/null
        line=$(awk '
            /^scadray: .* spp, / { for (i = 1; i <= NF; ++i) { if ($i == "spp,") spp = $(i-1);
                                     if ($i == "objects") obj = $(i-1); }
                                   t = $(NF-1) }
            /^  rays: / { rays = $2; shadow = $6 }
            /^  csg: / { ops = $2; pruned = $5 }
            END { print t, rays, ops, pruned, obj, spp, shadow }' "$tmp/log")
        if [[ -z $best ]] || awk -v a="${line%% *}" -v b="${best%% *}" 'BEGIN { exit !(a < b) }'; then
            best=$line
        fi
    done
    echo "$best"
}

echo "Render plan benchmark: ${width}x${height}, best of $runs runs, $(nproc) threads, $(date -u +%Y-%m-%d)"
echo
echo "| scene | spp | plan: time | no plan: time | speed-up | rays: plan / no plan | shadow rays: plan / no plan | span merges: plan / no plan | pruned subtrees | solids: plan / no plan | same picture |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for scene in scenes/*.scad scenes/montecarlo/*.scad; do
    [[ $(basename "$scene") == scadray.scad ]] && continue
    # Uniform sampling at the count the plan chooses (--no-aa), so both runs trace the same pixels
    read -r t1 r1 o1 p1 n1 s1 h1 < <(measure "$scene" "$tmp/plan.png" --no-aa)
    # The same sample count as the plan chose, so only the plan's savings differ
    read -r t2 r2 o2 p2 n2 s2 h2 < <(measure "$scene" "$tmp/naive.png" --no-plan -s "$s1")
    same=no
    cmp -s "$tmp/plan.png" "$tmp/naive.png" && same=yes
    speed=$(awk -v a="$t1" -v b="$t2" 'BEGIN { printf "%.2fx", b / a }')
    echo "| ${scene#scenes/} | $s1 | $t1 s | $t2 s | $speed | $r1 / $r2 | $h1 / $h2 | $o1 / $o2 | $p1 | $n1 / $n2 | $same |"
done
