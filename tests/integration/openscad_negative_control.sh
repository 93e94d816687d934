#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The geometry referee must be able to fail: a scene with skew faces first passes
# `check --openscad`; then OpenSCAD alone is handed `-D nudge=1` (one corner 1 unit higher,
# through an `openscad` wrapper first on PATH) and the check must report DIFFERENT (exit 1).
# Exit 77 (skipped) without openscad.
set -uo pipefail
scadray=$1 scene=$2 out=$3
real=$(command -v openscad) || { echo "SKIPPED: openscad is not installed"; exit 77; }
mkdir -p "$out/bin"
"$scadray" check --openscad "$scene" -W 160 -H 120 -o "$out/same" ||
    { echo "FAIL: the unchanged scene does not agree with OpenSCAD"; exit 1; }
printf '#!/bin/sh\nexec "%s" -D nudge=1 "$@"\n' "$real" >"$out/bin/openscad"
chmod +x "$out/bin/openscad"
PATH="$out/bin:$PATH" "$scadray" check --openscad "$scene" -W 160 -H 120 -o "$out/nudged"
rc=$?
if [ $rc -ne 1 ]; then
    echo "FAIL: a corner moved by 1 unit in OpenSCAD's mesh was not detected (exit $rc)"
    exit 1
fi
echo "PASS: the moved corner was detected"
