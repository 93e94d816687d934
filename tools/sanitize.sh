#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The fast unit suites under AddressSanitizer + UndefinedBehaviorSanitizer (clang, -O1 -g, with
# assertions) in build-asan/. Any sanitizer report (leaks included) fails the test that
# triggered it. Extra arguments go to ctest (e.g. -R Csg).
#
#   ./tools/sanitize.sh                 configure, build and run core/scad/gltf/meshio/cli/exporter tests
#   ./tools/sanitize.sh --build T...    only configure build-asan/ and build targets T (tools/fuzz.sh)
#
# The same build holds the libFuzzer targets (SCADRAY_FUZZ instruments everything for coverage;
# the unit tests run unaffected), so the CI compiles the project once with clang, not twice.
set -euo pipefail
cd "$(dirname "$0")/.."
./tools/setup.sh
shared=()
if [[ -n "${SCADRAY_SHARED_DIR:-}" ]]; then shared=(-DSCADRAY_SHARED_DIR="$SCADRAY_SHARED_DIR"); fi
launcher=()
if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# Debug keeps assertions; -O1 keeps sanitized code quick
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DSCADRAY_SANITIZE=ON -DSCADRAY_FUZZ=ON \
    "${launcher[@]}" "${shared[@]}" >/dev/null

if [[ "${1:-}" == --build ]]; then
    shift
    cmake --build build-asan -j "$(nproc)" --target "$@"
    exit 0
fi

suites=(core_tests scad_tests gltf_tests meshio_tests cli_tests exporter_tests)
cmake --build build-asan -j "$(nproc)" --target scadray "${suites[@]}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$(pwd)/tests/fuzz/lsan.supp:print_suppressions=0"
labels=$(IFS='|'; echo "${suites[*]}")
ctest --test-dir build-asan --output-on-failure -j "$(nproc)" -L "^(${labels})\$" "$@"
