#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The cross-renderer comparison must be able to fail: the same scene with one material 2%
# brighter is compared with the unchanged scene's POV-Ray reference and must be DIFFERENT,
# while each variant on its own passes its check. Exit 77 (skipped) without povray.
set -uo pipefail
scadray=$1 scene=$2 out=$3
if ! command -v povray >/dev/null 2>&1; then
    echo "SKIPPED: POV-Ray (povray) is not installed; scripts/setup.sh installs it"
    exit 77
fi
name=$(basename "$scene" .scad)
"$scadray" check "$scene" -o "$out/base" -q || { echo "FAIL: base check failed"; exit 1; }
"$scadray" check "$scene" -D 'c=[0.918, 0.357, 0.204]' -o "$out/brighter" -q ||
    { echo "FAIL: variant check failed"; exit 1; }
"$scadray" compare "$out/brighter/${name}_scadray.exr" "$out/base/${name}_reference.exr"
rc=$?
if [ $rc -ne 1 ]; then
    echo "FAIL: a 2% brighter material was not detected (compare exit $rc)"
    exit 1
fi
echo "PASS: the 2% change was detected"
