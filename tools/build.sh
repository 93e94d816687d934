#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, then configures and builds scadray in build/ (Release with debug info).
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/setup.sh
# The glTF sample models the tests use: ../shared by default, or $SCADRAY_SHARED_DIR
shared=()
if [[ -n "${SCADRAY_SHARED_DIR:-}" ]]; then shared=(-DSCADRAY_SHARED_DIR="$SCADRAY_SHARED_DIR"); fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "${shared[@]}" >/dev/null
cmake --build build -j "$(nproc)"
