#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One command from a fresh Debian 12 machine to a picture: sets up, builds, and renders the
# default scene to out/default.png (pass another scene and output to render those instead).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
scene=${1:-scenes/default.scad}
output=${2:-out/default.png}
mkdir -p "$(dirname "$output")"
./build/tools/scadray render "$scene" -o "$output" -W 960 -H 720 -s 4
echo "wrote $output"
