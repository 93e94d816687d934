#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the libFuzzer targets of tests/fuzz (clang, ASan + UBSan, -O1 -g, in build-asan/ with
# the sanitized unit tests) and runs each for a fixed time, two at a time. Fails when any target
# finds a crash, a leak, a UBSan report, a timeout (-timeout=10 s per input) or an input using
# more than 2 GiB; the input is saved under build-asan/fuzz/artifacts/<target>/ and named in the
# summary. Minimize it with
#   build-asan/tests/fuzz/<target>_fuzz -minimize_crash=1 -runs=10000 <input>
# and keep it under tests/fuzz/regressions/<target>/, which every later run replays first.
#
#   ./scripts/fuzz.sh [seconds] [target...]    seconds per target (default 60); targets:
#                                            scad gltf glb stl off image pov dxf svg surface
#                                            report cli (default: all)
# The corpus grows in build-asan/fuzz/corpus/<target>/ between runs on one machine.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=60
if [[ $# -gt 0 && "$1" =~ ^[0-9]+$ ]]; then seconds=$1; shift; fi
all=(scad gltf glb stl off image pov dxf svg surface report cli)
targets=("$@")
if [[ ${#targets[@]} -eq 0 ]]; then targets=("${all[@]}"); fi
for t in "${targets[@]}"; do
    if [[ ! " ${all[*]} " =~ " $t " ]]; then echo "fuzz: unknown target '$t' (${all[*]})" >&2; exit 2; fi
done

./scripts/sanitize.sh --build "${targets[@]/%/_fuzz}"

work=$root/build-asan/fuzz
mkdir -p "$work"

# Seed files for a target: committed seeds, its regressions, and project files by pattern
# (copied into one folder, so libFuzzer does not read unrelated files in those trees)
seed() {  # seed TARGET PATTERN DIR...
    local t=$1 pattern=$2; shift 2
    local d
    for d in "$@"; do
        [[ -d "$d" ]] || continue
        find "$d" -type f -name "$pattern" -size -512k -print0 |
            while IFS= read -r -d '' f; do
                cp "$f" "$work/seeds/$t/$(echo "${f#"$root"/}" | tr '/' '_')"
            done
    done
}
run_one() {  # run_one TARGET
    local t=$1 max_len dict=()
    rm -rf "$work/seeds/$t" "$work/artifacts/$t"
    mkdir -p "$work/seeds/$t" "$work/corpus/$t" "$work/artifacts/$t" "$work/logs"
    case $t in
        scad) max_len=8192; dict=(-dict=tests/fuzz/scad.dict)
              # OpenSCAD's examples are GPL: read in place when installed, never copied into the repo
              seed scad '*.scad' scenes tests/importers tests/integration tests/bench /usr/share/openscad/examples ;;
        gltf) max_len=65536; dict=(-dict=tests/fuzz/gltf.dict)
              seed gltf '*.gltf' scenes tests/data/gltf ;;
        glb)  max_len=131072; dict=(-dict=tests/fuzz/gltf.dict)
              seed glb '*.glb' scenes tests/data/gltf ;;
        stl)  max_len=65536; seed stl '*.stl' scenes ;;
        off)  max_len=16384; seed off '*.off' scenes ;;
        image) max_len=16384 ;;
        pov)  max_len=2048 ;;
        dxf)  max_len=16384; seed dxf '*.dxf' tests/importers scenes /usr/share/openscad/examples ;;
        svg)  max_len=16384; seed svg '*.svg' tests/importers scenes /usr/share/openscad/examples ;;
        surface) max_len=16384; seed surface '*.dat' tests/importers scenes /usr/share/openscad/examples ;;
        report) max_len=8192 ;;
        cli)  max_len=1024 ;;
    esac
    local dirs=("$work/corpus/$t" "$work/seeds/$t")
    [[ -d tests/fuzz/seeds/$t ]] && dirs+=("tests/fuzz/seeds/$t")
    [[ -d tests/fuzz/regressions/$t ]] && dirs+=("tests/fuzz/regressions/$t")
    # The image reader's leak suppression (OpenImageIO) needs whole stacks through the library
    local unwind=1
    [[ $t == image ]] && unwind=0
    local rc=0
    ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0:fast_unwind_on_malloc=$unwind" \
    LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp:print_suppressions=0" \
    UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
        "$root/build-asan/tests/fuzz/${t}_fuzz" -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2048 -max_len="$max_len" "${dict[@]}" -print_final_stats=1 \
        -artifact_prefix="$work/artifacts/$t/" "${dirs[@]}" >"$work/logs/$t.log" 2>&1 || rc=$?
    local execs speed cov ft
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/logs/$t.log" | tail -1 || true)
    speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$work/logs/$t.log" | tail -1 || true)
    cov=$(grep -o 'cov: [0-9]*' "$work/logs/$t.log" | tail -1 | cut -d' ' -f2 || true)
    ft=$(grep -o 'ft: [0-9]*' "$work/logs/$t.log" | tail -1 | cut -d' ' -f2 || true)
    if [[ $rc -eq 0 ]]; then
        printf 'fuzz: %-6s ok      %8s runs %6s/s  cov %-6s ft %s\n' "$t" "${execs:-?}" "${speed:-?}" "${cov:-?}" "${ft:-?}"
    else
        printf 'fuzz: %-6s FAILED  (exit %d) after %s runs; log %s\n' "$t" "$rc" "${execs:-?}" "$work/logs/$t.log"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|scadray fuzz:|.*runtime error:|ALARM|==[0-9]+== ERROR)' \
            "$work/logs/$t.log" | head -5 | sed 's/^/    /' || true
        ls "$work/artifacts/$t"/* 2>/dev/null | sed 's/^/    input: /' || true
    fi
    return $((rc == 0 ? 0 : 1))
}

# Two at a time (2 cores); xargs fails when any target does
export -f seed run_one
export root work seconds
if ! printf '%s\n' "${targets[@]}" | xargs -P 2 -I{} bash -c 'run_one "$1"' _ {}; then
    echo "fuzz: a target failed (see above)" >&2
    exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds} s each without a finding"
