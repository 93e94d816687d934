#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test): hull() of 10,000 points (tests/bench/hull_10k.scad). Prints the wall
# time of scadray's parse + hull + render at 640x480 and of `openscad -o x.stl` on the same file.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scad=tests/bench/hull_10k.scad
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seconds() {
    local start end ms
    start=$(date +%s%N)
    "$@" >"$tmp/log" 2>&1 || { cat "$tmp/log"; return 1; }
    end=$(date +%s%N)
    ms=$(((end - start) / 1000000))
    printf '%d.%03d' $((ms / 1000)) $((ms % 1000))
}
echo "scadray render 640x480: $(seconds "$build/tools/scadray" render "$scad" -o "$tmp/hull.png" -W 640 -H 480) s"
if command -v openscad >/dev/null; then
    echo "openscad -o hull.stl:   $(seconds openscad -o "$tmp/hull.stl" "$scad") s"
else
    echo "openscad not installed; its time not measured"
fi
