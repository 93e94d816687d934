#!/bin/sh
# SPDX-License-Identifier: MIT
# Sampling adaptive to Monte Carlo noise against uniform sampling: renders each Monte
# Carlo scene at uniform 4, 16 and 64 spp and adaptive to noise (`--aa-max 64 --aa-tolerance T`)
# for each T of TOLS, and prints per render the mean samples per pixel, the render CPU seconds
# and the error against uniform REF spp: the RMSE over every pixel and the RMSE on the edge
# pixels `compare` masks (both in linear units, from `scadray compare`). Prints figures; it is
# not a test.
#
#   scripts/bench_aa_noise.sh [scadray] [scene.scad ...]
#   env: W=240 H=180 REF=256 THREADS=2 TOLS="0.05 0.02 0.01"
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/tools/scadray}
[ $# -gt 0 ] && shift
W=${W:-240} H=${H:-180} REF=${REF:-256} THREADS=${THREADS:-2} TOLS=${TOLS:-"0.05 0.02 0.01"}
[ $# -gt 0 ] || set -- "$here"/scenes/montecarlo/*.scad
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# render NAME OPTIONS...: the PNG and the summary (with --plan's ray line) of one render
render() {
    out=$1
    shift
    "$bin" render --plan -W "$W" -H "$H" -t "$THREADS" -o "$tmp/$out.png" "$@" 2>"$tmp/$out.log"
}

# row LABEL NAME: samples per pixel, CPU seconds, RMSE and masked RMSE against the reference
row() {
    spp=$(sed -n 's/^scadray: .*, \(adaptive \)\{0,1\}\([0-9.]*\) spp.*/\2/p' "$tmp/$2.log")
    cpu=$(sed -n "s/^  rays: .*, \([0-9.]*\) s CPU$/\1/p" "$tmp/$2.log")
    "$bin" compare "$tmp/$2.png" "$tmp/ref.png" >"$tmp/cmp.txt" 2>&1 || true
    rmse=$(sed -n 's/^error: RMSE \([0-9.e+-]*\),.*/\1/p' "$tmp/cmp.txt")
    edge=$(sed -n 's/.*RMSE there \([0-9.e+-]*\).*/\1/p' "$tmp/cmp.txt")
    printf '%-12s %-22s %7s %8s %10s %10s\n' "$scene_name" "$1" "$spp" "$cpu" "${rmse:-?}" "${edge:-?}"
}

echo "${W}x${H}, $THREADS threads; error against uniform $REF spp (linear units)"
printf '%-12s %-22s %7s %8s %10s %10s\n' scene sampling spp "CPU s" RMSE "edge RMSE"
for scene in "$@"; do
    scene_name=$(basename "$scene" .scad)
    render ref "$scene" -s "$REF"
    for s in 4 16 64; do
        render "u$s" "$scene" -s "$s"
        row "uniform $s" "u$s"
    done
    for t in $TOLS; do
        render "a$t" "$scene" --aa-max 64 --aa-tolerance "$t"
        row "noise-adaptive $t" "a$t"
    done
done
