#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Submits a scadray job array and the job that finishes it, with one command:
#
#   submit.sh render [-n TILES] [-o OUT.png] [common options] SCENE [render options]
#       TILES array tasks (render_tile.sbatch, tile K/N) and a merge (merge.sbatch) into OUT
#       (default <scene>.png), bit for bit the picture of one `scadray render`. The tiles go to
#       OUT's folder, in <OUT name>.tiles/ (earlier tiles there are removed first).
#   submit.sh frames --frames N [--fps F] [--video FILE] [-o NAME.png] [common options] SCENE
#           [render options]
#       N array tasks (frame.sbatch, frame I of N) and the video (encode.sbatch).
#   submit.sh check [-o DIR] [common options] SCENE... [-- check options]
#       one array task per scene (check_scene.sbatch; a .txt or .list argument is a list of scenes,
#       one a line) and the summary (report.sbatch) in DIR (default check_results).
#
# Common options: --scadray PATH (the binary; default scadray on PATH, else the build beside
# this script), --sbatch 'ARGS' (more sbatch options for every job: partition, time limit,
# --cpus-per-task ...), --wait (return when the last job has ended: 0 when it completed). Prints the
# array's and the last job's ids. Every path must be on a filesystem the nodes share.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

usage() {
    sed -n '3,21p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//' >&2
    exit 2
}
die() {
    echo "submit.sh: $*" >&2
    exit 2
}
absolute() { case $1 in /*) echo "$1" ;; *) echo "$PWD/$1" ;; esac; }

[ $# -ge 1 ] || usage
mode=$1
shift
case $mode in render | frames | check) ;; -h | --help) usage ;; *) die "unknown mode '$mode' (render, frames or check)" ;; esac

tiles=4 output="" frames="" fps="" video="" scadray="" sbatch_extra="" wait=0
while [ $# -gt 0 ]; do
    case $1 in
    -n | --tiles) tiles=${2:?}; shift 2 ;;
    -o | --output) output=${2:?}; shift 2 ;;
    --frames) frames=${2:?}; shift 2 ;;
    --fps) fps=${2:?}; shift 2 ;;
    --video) video=${2:?}; shift 2 ;;
    --scadray) scadray=${2:?}; shift 2 ;;
    --sbatch) sbatch_extra=${2:?}; shift 2 ;;
    --wait) wait=1; shift ;;
    -h | --help) usage ;;
    -*) die "unknown option '$1' before the scene (scadray's own options follow the scene)" ;;
    *) break ;;
    esac
done
[ $# -ge 1 ] || die "no scene given"

# The binary, as an absolute path the jobs can run
if [ -z "$scadray" ]; then
    scadray=$(command -v scadray || true)
    [ -n "$scadray" ] || scadray="$here/../../build/tools/scadray"
fi
[ -x "$scadray" ] || die "no scadray binary at '$scadray' (give --scadray PATH)"
export SCADRAY
SCADRAY=$(absolute "$scadray")
command -v sbatch >/dev/null || die "sbatch not found (is this a Slurm login node?)"

# shellcheck disable=SC2206 # --sbatch takes several words
extra=($sbatch_extra)
submit() { sbatch --parsable "${extra[@]}" "$@" | cut -d ';' -f 1; }
# Waits for job `id` to end and returns 0 when it completed. Polls squeue every second at first,
# less often as the wait grows (at most every 10 s): sbatch --wait polls at doubling intervals
# and can add half a minute to a job of seconds.
wait_for() {
    local id=$1 start=$SECONDS state
    while [ -n "$(squeue -h -j "$id" -o %i 2>/dev/null)" ]; do
        sleep $((1 + (SECONDS - start) / 30 > 10 ? 10 : 1 + (SECONDS - start) / 30))
    done
    state=$(scontrol show job -o "$id" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | cut -d= -f2 || true)
    echo "$mode: job $id ended: ${state:-state unknown}" >&2
    [ "$state" = COMPLETED ]
}
finish() {
    local array=$1
    shift
    local last
    last=$(submit "$@")
    echo "$mode: array job $array, then job $last"
    [ "$wait" -eq 0 ] || wait_for "$last"
}

case $mode in
render)
    scene=$(absolute "$1")
    shift
    [ -n "$output" ] || output="$(basename "${scene%.*}").png"
    output=$(absolute "$output")
    [[ $tiles =~ ^[1-9][0-9]*$ ]] || die "-n takes a number of tiles, not '$tiles'"
    dir="$output.tiles"
    mkdir -p "$dir/logs"
    rm -f "$dir"/tile_*.exr
    array=$(submit --array="1-$tiles" --output="$dir/logs/%x-%A_%a.out" \
        "$here/render_tile.sbatch" "$dir" "$scene" "$@")
    finish "$array" --dependency="afterok:$array" --kill-on-invalid-dep=yes \
        --output="$dir/logs/%x-%j.out" "$here/merge.sbatch" "$dir" "$output"
    ;;
frames)
    [[ $frames =~ ^[1-9][0-9]*$ ]] || die "frames needs --frames N"
    scene=$(absolute "$1")
    shift
    [ -n "$output" ] || output="$(basename "${scene%.*}").png"
    output=$(absolute "$output")
    logs="$(dirname "$output")/logs"
    mkdir -p "$logs"
    video_args=()
    [ -z "$fps" ] || video_args+=(--fps "$fps")
    [ -z "$video" ] || video_args+=(--video "$(absolute "$video")")
    array=$(submit --array="0-$((frames - 1))" --output="$logs/%x-%A_%a.out" \
        "$here/frame.sbatch" "$scene" "$output" "$@")
    finish "$array" --dependency="afterok:$array" --kill-on-invalid-dep=yes \
        --output="$logs/%x-%j.out" "$here/encode.sbatch" "$output" "$frames" "${video_args[@]}"
    ;;
check)
    dir=$(absolute "${output:-check_results}")
    mkdir -p "$dir/logs"
    list="$dir/scenes.txt"
    : >"$list"
    while [ $# -gt 0 ] && [ "$1" != "--" ]; do
        case $1 in
        *.txt | *.list)
            # A list: one scene a line, relative to the list; blank lines and lines starting
            # with # skipped (a '#' inside a name, a.scad#1, is part of it, as in `report`)
            [ -f "$1" ] || die "$1: no such list of scenes"
            base=$(cd "$(dirname "$1")" && pwd)
            number=0
            while IFS= read -r line || [ -n "$line" ]; do
                number=$((number + 1))
                line=$(printf '%s' "$line" | sed 's/^[[:space:]]*//; s/[[:space:]]*$//')
                case $line in '' | '#'*) continue ;; esac
                case $line in /*) scene=$line ;; *) scene="$base/$line" ;; esac
                # Checked before any job is submitted: a wrong line is this error, not a task
                # that fails later
                [ -f "$scene" ] || die "$1:$number: no such scene file: $line"
                printf '%s\n' "$scene" >>"$list"
            done <"$1"
            ;;
        *)
            [ -f "$1" ] || die "no such scene file: $1"
            absolute "$1" >>"$list"
            ;;
        esac
        shift
    done
    [ "${1:-}" != "--" ] || shift
    count=$(wc -l <"$list")
    [ "$count" -ge 1 ] || die "no scenes to check"
    array=$(submit --array="1-$count" --output="$dir/logs/%x-%A_%a.out" \
        "$here/check_scene.sbatch" "$list" "$dir" "$@")
    finish "$array" --dependency="afterany:$array" --output="$dir/logs/%x-%j.out" \
        "$here/report.sbatch" "$list" "$dir"
    ;;
esac
