#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# One command from a fresh Debian 12 machine to a tested build: sets up, builds, runs every test.
# Extra arguments go to ctest (e.g. -L povray, -R Csg).
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/build.sh
ctest --test-dir build --output-on-failure -j "$(nproc)" "$@"
