#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The fast unit suites under AddressSanitizer + UndefinedBehaviorSanitizer (clang, -O1 -g, with
# assertions) in build-asan/. Any sanitizer report (leaks included) fails the test that
# triggered it. Each suite runs as one process; SANITIZE_GTEST_FILTER replaces the default
# filter (which leaves out the OpenSCAD cross-checks).
#
#   ./scripts/sanitize.sh                 configure, build, run the unit suites (core, scad, gltf, ...)
#   ./scripts/sanitize.sh --build T...    only configure build-asan/ and build targets T (scripts/fuzz.sh)
#
# The same build holds the libFuzzer targets (SCADRAY_FUZZ instruments everything for coverage;
# the unit tests run unaffected), so the CI compiles the project once with clang, not twice.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
launcher=()
if command -v ccache >/dev/null; then
    launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
# Debug keeps assertions; -O1 keeps sanitized code quick
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug \
    -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DSCADRAY_SANITIZE=ON -DSCADRAY_FUZZ=ON \
    -DSCADRAY_WERROR="${SCADRAY_WERROR:-OFF}" "${launcher[@]}" >/dev/null

if [[ "${1:-}" == --build ]]; then
    shift
    cmake --build build-asan -j "$(nproc)" --target "$@"
    exit 0
fi

suites=(core_tests scad_tests gltf_tests meshio_tests cli_tests exporter_tests)
cmake --build build-asan -j "$(nproc)" --target scadray "${suites[@]}"
# Not detect_stack_use_after_return: its fake stack frames live on the heap, which the .scad
# evaluator's stack guard reads as an exhausted stack
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$(pwd)/tests/fuzz/lsan.supp:print_suppressions=0"
# Each suite runs as one process (ctest starts one per test, ~5 s each under ASan): two at a
# time, in the build's tests folder as ctest would. OpenSCAD cross-checks run OpenSCAD itself,
# unsanitized and slow, and test geometry, not memory safety: left to scripts/test.sh.
filter=${SANITIZE_GTEST_FILTER:-"-OpenScad*CrossCheck.*"}
mkdir -p build-asan/sanitize
run_suite() {
    local s=$1 start=$SECONDS rc=0 log=build-asan/sanitize/$1.log
    # Not --gtest_brief: a suite that aborts (an assertion, an uncaught exception, a sanitizer's
    # own fatal error) then names the test that was running in the log's last lines
    (cd build-asan/tests && "./$s" --gtest_filter="$filter") >"$log" 2>&1 || rc=$?
    # LeakSanitizer's tracer, which stops every thread at exit to scan their stacks, now and
    # then fails by itself when threads of a thread pool (OpenImageIO's, OpenEXR's) are alive
    # ("LeakSanitizer has encountered a fatal error", google/sanitizers#723, #1170): that is no
    # finding, and the suite runs once more; a leak report or a second failure fails it
    if [[ $rc -ne 0 ]] && grep -q 'LeakSanitizer has encountered a fatal error' "$log" &&
        ! grep -qE 'ERROR: (Address|Leak)Sanitizer|runtime error:|^\[  FAILED  \]' "$log"; then
        echo "sanitize: $s: LeakSanitizer's own tracer failed at exit (no finding); running it again"
        mv "$log" "$log.tracer-failure"
        rc=0
        (cd build-asan/tests && "./$s" --gtest_filter="$filter") >"$log" 2>&1 || rc=$?
    fi
    printf 'sanitize: %-15s %s in %d s (log build-asan/sanitize/%s.log)\n' "$s" \
        "$([[ $rc -eq 0 ]] && echo passed || echo "FAILED (exit $rc)")" $((SECONDS - start)) "$s"
    if [[ $rc -ne 0 ]]; then
        grep -E '^\[  FAILED  \]|ERROR: (Address|Leak)Sanitizer|runtime error:' \
            "$log" | sort -u | head -10 | sed 's/^/    /'
        echo "    last lines of the log:"
        tail -n 25 "$log" | sed 's/^/    | /'
    fi
    return $((rc == 0 ? 0 : 1))
}
export -f run_suite
export filter
if ! printf '%s\n' "${suites[@]}" | xargs -P 2 -I{} bash -c 'run_suite "$1"' _ {}; then
    echo "sanitize: a suite failed (see above)" >&2
    exit 1
fi
echo "sanitize: ${#suites[@]} suites passed under ASan + UBSan"
