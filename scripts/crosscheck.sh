#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs `scadray check` on every scene one after another (so timings are not disturbed by a
# parallel test) and prints a Markdown table of error against run time for the README.
# Usage: scripts/crosscheck.sh [build-dir] [extra check options...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
samples=tests/data/gltf/khronos
shopt -s nullglob
for scene in scenes/*.scad scenes/crosscheck/*.scad scenes/gltf/*.gltf \
             "$samples"/*.gltf "$samples"/*.glb "$samples"/*/*.gltf \
             tests/data/gltf/*.gltf tests/data/gltf/*.glb tests/data/gltf/assets/*.glb; do
    [ "$(basename "$scene")" = scadray.scad ] && continue
    name=$(basename "$scene"); name=${name%.*}
    "$build/tools/scadray" check "$scene" -o "$out/$name" -q --csv "$out/all.csv" "$@" || true
done
echo "| scene | verdict | RMSE | max error | masked | tiles failed / tested | POV-Ray wall (trace) | scadray wall |"
echo "|---|---|---|---|---|---|---|---|"
tail -n +2 "$out/all.csv" | while IFS=, read -r scene verdict rmse maxe masked tested failed det pw pt sw sr; do
    printf '| `%s` | %s | %s | %s | %s%% | %s / %s | %.2f s (%.2f s) | %.2f s |\n' \
        "$(echo "$scene" | sed -e "s|^scenes/||" -e "s|^tests/data/gltf/khronos/|khronos/|" -e "s|^tests/data/|data/|")" "$verdict" "$rmse" "$maxe" "$masked" "$failed" "$tested" "$pw" "$pt" "$sw"
done
