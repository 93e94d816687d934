#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs what is missing, then configures and builds scadray in build/ (Release with debug info).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
# SCADRAY_WERROR=ON (as .ci/run sets) makes any compiler warning an error
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSCADRAY_WERROR="${SCADRAY_WERROR:-OFF}" >/dev/null
cmake --build build -j "$(nproc)"
