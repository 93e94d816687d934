#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Every scene in scenes/ must still open in OpenSCAD 2021.01 unchanged: export to .csg succeeds
# and OpenSCAD prints no WARNING or ERROR (our metadata modules are real modules to it).
# Exit 77 (skipped) when the openscad binary is absent.
set -uo pipefail
scenes_dir=$1
if ! command -v openscad >/dev/null 2>&1; then
    echo "SKIPPED: openscad is not installed (scripts/setup.sh installs it)"
    exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
count=0
for scene in "$scenes_dir"/*.scad "$scenes_dir"/*/*.scad; do
    [ -e "$scene" ] || continue
    count=$((count + 1))
    if ! OPENSCADPATH="$scenes_dir" openscad -o "$tmp/out.csg" "$scene" >"$tmp/log" 2>&1; then
        echo "FAIL: openscad could not export $scene"
        cat "$tmp/log"
        status=1
    # OpenSCAD always notes that $vp* variables override its automatic view; that is the
    # feature working, not a problem with the scene
    elif grep -E "WARNING|ERROR" "$tmp/log" | grep -v "Viewall and autocenter disabled in favor of \$vp\*"; then
        echo "FAIL: openscad warned about $scene"
        status=1
    fi
done
echo "$count scenes checked with $(openscad --version 2>&1)"
exit $status
