#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# scripts/slurm/ on a real Slurm cluster: brings up a private single-node cluster
# (cluster.sh), submits with scripts/slurm/submit.sh a 4-tile render, a 3-frame animation and a
# check of five scenes (three under awkward names), waits for them, and checks the merged picture and the frames against one
# process's bit for bit, and the check summary's lines. Stops every daemon it started, also on
# failure. Skipped (77) without Slurm, munge or root; the animation without ffmpeg and the check
# without povray are skipped with a note.
#   tests/slurm/slurm_test.sh SCADRAY SOURCE_DIR WORK_DIR
set -euo pipefail

[ $# -eq 3 ] || {
    echo "usage: $0 SCADRAY SOURCE_DIR WORK_DIR" >&2
    exit 2
}
scadray=$1 src=$2 work=$3
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
# shellcheck source=tests/slurm/cluster.sh
source "$here/cluster.sh"
require_cluster_tools

trap stop_cluster EXIT
trap 'exit 130' INT TERM
rm -rf "$work"
mkdir -p "$work"
start_cluster || exit 1
submit="$src/scripts/slurm/submit.sh"
# Seconds a submission may take before the test gives up on it (3 of them within ctest's 900)
limit=240
failures=0
fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

# --- A picture in 4 tiles: the default (adaptive) sampling of a sharp scene
scene="$src/scenes/default.scad"
size=(-W 72 -H 45)
"$scadray" render -q "$scene" "${size[@]}" -o "$work/single.png"
start=$(date +%s%N)
if timeout "$limit" "$submit" render --wait -n 4 --scadray "$scadray" -o "$work/tiled.png" "$scene" "${size[@]}"; then
    echo "tiled render: $((($(date +%s%N) - start) / 1000000)) ms through Slurm"
    cmp "$work/single.png" "$work/tiled.png" || fail "the merged picture differs from the single render's"
    tiles=("$work/tiled.png.tiles"/tile_*.exr)
    [ ${#tiles[@]} -eq 4 ] || fail "not 4 tiles in $work/tiled.png.tiles"
else
    fail "the tiled render did not finish (logs: $work/tiled.png.tiles/logs)"
    cat "$work/tiled.png.tiles/logs"/* 2>/dev/null | tail -n 20
fi

# --- An animation of 3 frames and its video
if [[ "$("$scadray" render --help)" != *--frames* ]]; then
    echo "NOTE: animation skipped: this scadray has no render --frames"
elif ! command -v ffmpeg >/dev/null; then
    echo "NOTE: animation skipped: ffmpeg not installed (Debian package ffmpeg)"
else
    cat >"$work/spin.scad" <<'EOF'
// A block turning once in 3 frames, and the camera turning half as fast
$vpr = [60, 0, 30 + 180 * $t];
$vpd = 12;
rotate([0, 0, 360 * $t]) cube([4, 2, 1], center = true);
EOF
    mkdir -p "$work/single"
    "$scadray" render -q "$work/spin.scad" -W 48 -H 36 --frames 3 -o "$work/single/spin.png"
    if timeout "$limit" "$submit" frames --wait --frames 3 --fps 3 --scadray "$scadray" \
        -o "$work/anim/spin.png" "$work/spin.scad" -W 48 -H 36; then
        for i in 0000 0001 0002; do
            cmp "$work/single/spin_$i.png" "$work/anim/spin_$i.png" || fail "frame $i differs from the single render's"
        done
        [ -s "$work/anim/spin.mp4" ] || fail "no video $work/anim/spin.mp4"
    else
        fail "the animation did not finish (logs: $work/anim/logs)"
        cat "$work/anim/logs"/* 2>/dev/null | tail -n 20
    fi
fi

# --- check over five scenes, the summary as the last step
if ! command -v povray >/dev/null; then
    echo "NOTE: check array skipped: povray not installed"
else
    # Two small scenes, and one of them under names that a shell, a list or POV-Ray could
    # misread: a space, a '#' and a leading '-'
    for name in "my part" "a#b" "-x"; do
        printf 'sphere(4, $fn=24);\ntranslate([7, 0, 0]) cube(5, center=true);\n' >"$work/$name.scad"
    done
    printf '%s\n' "# small scenes" "$src/scenes/crosscheck/primitives.scad" "" \
        "$src/scenes/crosscheck/csg_union.scad" "my part.scad" "  a#b.scad" "-x.scad" >"$work/scenes.txt"
    # The report exits 1 when a scene differs: the summary's lines are what is checked here
    timeout "$limit" "$submit" check --wait --scadray "$scadray" -o "$work/check" "$work/scenes.txt" \
        -- -W 32 -H 24 || true
    summary="$work/check/summary.txt"
    if [ ! -f "$summary" ]; then
        fail "no check summary $summary"
    else
        cat "$summary"
        [ "$(grep -c -E '^(PASS|DIFFERENT): ' "$summary")" -eq 5 ] || fail "the summary has not 5 verdicts"
        grep -q -E '^[0-9]+ of 5 scenes passed$' "$summary" || fail "the summary has no count"
        for name in "my part" "a#b" "-x"; do
            grep -q -F "$work/$name.scad at" "$summary" || fail "no verdict for '$name.scad'"
        done
        [ -s "$work/check/report.html" ] || fail "no HTML report $work/check/report.html"
    fi
fi

[ "$failures" -eq 0 ] || exit 1
echo "slurm: all passed"
