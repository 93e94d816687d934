#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One scene of the cross-renderer suite: `scadray check` renders it with scadray and POV-Ray
# and compares the images statistically. Exit 77 (skipped) without the povray binary.
set -uo pipefail
scadray=$1 scene=$2 out=$3
if ! command -v povray >/dev/null 2>&1; then
    echo "SKIPPED: POV-Ray (povray) is not installed; scripts/setup.sh installs it"
    exit 77
fi
"$scadray" check "$scene" -o "$out"
