#!/bin/sh
# SPDX-License-Identifier: MIT
# Adaptive antialiasing against uniform sampling: renders every scene at today's old
# default (-s 1), the adaptive default and uniform -s REF, and prints per scene the render time
# (CPU seconds of the render, all threads, without start-up, the best of REPEAT runs; CPU time
# because other processes inflate wall time), the ratio of adaptive to 1 spp,
# the mean samples per pixel, where the samples went (checked: pixels that kept
# their centre after 2 or 3 probe samples), and `scadray compare` of adaptive and of
# 1 spp against uniform REF spp (PASS/FAIL and the RMSE on the edge pixels compare masks, where
# antialiasing shows). Prints figures; it is not a test.
#
#   scripts/bench_aa.sh [scadray] [scene.scad ...]
#   env: W=640 H=480 REF=64 THREADS=2 REPEAT=3 AA="--aa-max 64" (extra options of the adaptive run)
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/tools/scadray}
[ $# -gt 0 ] && shift
W=${W:-640} H=${H:-480} REF=${REF:-64} THREADS=${THREADS:-2} REPEAT=${REPEAT:-3} AA=${AA:-}
if [ $# -eq 0 ]; then
    set --
    for f in "$here"/scenes/*.scad; do
        [ "$(basename "$f")" = scadray.scad ] || set -- "$@" "$f"
    done
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# render NAME OPTIONS...: best render CPU seconds of REPEAT runs -> $tmp/NAME.time, summary -> $tmp/NAME.log
render() {
    out=$1
    shift
    best=
    i=0
    while [ $i -lt "$REPEAT" ]; do
        "$bin" render --plan -W "$W" -H "$H" -t "$THREADS" -o "$tmp/$out.exr" "$@" 2>"$tmp/$out.log"
        t=$(sed -n "s/^  rays: .*, \([0-9.]*\) s CPU$/\1/p" "$tmp/$out.log")
        best=$(echo "$best $t" | awk '{ print (NF == 1 || $2 + 0 < $1 + 0) ? $NF : $1 }')
        i=$((i + 1))
    done
    echo "$best" >"$tmp/$out.time"
}

# compare TEST: "PASS 0.0123" (verdict and masked RMSE against the reference)
compare() {
    "$bin" compare "$tmp/$1.exr" "$tmp/ref.exr" >"$tmp/cmp.txt" 2>&1 || true
    verdict=$(head -c 4 "$tmp/cmp.txt")
    edge=$(sed -n 's/.*RMSE there \([0-9.e+-]*\).*/\1/p' "$tmp/cmp.txt")
    echo "$verdict ${edge:-0}"
}

echo "${W}x${H}, $THREADS threads, render CPU seconds, best of $REPEAT; adaptive options: ${AA:-defaults}"
printf '%-22s %8s %8s %6s %6s %-40s %8s %-18s %-18s\n' scene "1spp s" "adapt s" ratio spp \
    "pixels with 1 / checked / 4 / 16 / 64 samples" "$REF spp s" "adaptive vs $REF" "1 spp vs $REF"
for scene in "$@"; do
    name=$(basename "$scene" .scad)
    render one "$scene" -s 1
    # shellcheck disable=SC2086
    render adaptive "$scene" $AA
    saved=$REPEAT
    REPEAT=1
    render ref "$scene" -s "$REF"
    REPEAT=$saved
    spp=$(sed -n 's/^scadray: .*, adaptive \([0-9.]*\) spp.*/\1/p' "$tmp/adaptive.log")
    spread=$(sed -n 's/^plan: samples: adaptive, pixels by samples: \([^;]*\);.*/\1/p' "$tmp/adaptive.log" |
        sed 's/[0-9a-z]*: //g; s/ %//g; s/,/ \//g')
    [ -n "$spp" ] || spp="uniform"
    t1=$(cat "$tmp/one.time") ta=$(cat "$tmp/adaptive.time")
    ratio=$(awk -v a="$ta" -v b="$t1" 'BEGIN { printf "%.2f", a / b }')
    printf '%-22s %8s %8s %6s %6s %-40s %8s %-18s %-18s\n' "$name" "$t1" "$ta" "$ratio" "$spp" \
        "${spread:--}" "$(cat "$tmp/ref.time")" "$(compare adaptive)" "$(compare one)"
done
