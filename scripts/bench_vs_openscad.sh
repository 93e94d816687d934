#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test): for each .scad file (default: tests/bench/*.scad), the wall time of
# scadray's parse + build + render at 640x480 and of `openscad -o x.stl` on the same file.
# Usage: scripts/bench_vs_openscad.sh [-b BUILD_DIR] [FILE.scad ...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
if [[ ${1:-} == -b ]]; then
    build=$2
    shift 2
fi
files=("$@")
[[ ${#files[@]} -gt 0 ]] || files=(tests/bench/*.scad)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seconds() {
    local start end ms
    start=$(date +%s%N)
    "$@" >"$tmp/log" 2>&1 || { cat "$tmp/log" >&2; echo "failed"; return 0; }
    end=$(date +%s%N)
    ms=$(((end - start) / 1000000))
    printf '%d.%03d s' $((ms / 1000)) $((ms % 1000))
}
printf '%-28s %-22s %s\n' file "scadray 640x480" "openscad -o .stl"
for scad in "${files[@]}"; do
    ours=$(seconds "$build/tools/scadray" render "$scad" -o "$tmp/x.png" -W 640 -H 480)
    if command -v openscad >/dev/null; then
        theirs=$(seconds openscad -o "$tmp/x.stl" "$scad")
    else
        theirs="openscad not installed"
    fi
    printf '%-28s %-22s %s\n' "$(basename "$scad")" "$ours" "$theirs"
done
