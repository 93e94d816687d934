#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test) of start-up cost: whole processes that do almost nothing, so what they
# cost is what every run pays before its first ray. Prints the best of N runs (default 5) of wall
# time, CPU time (user + system) and peak resident memory for
#   scadray --version
#   scadray render of a one-cube scene at 1x1 to PNG (libpng, no OpenImageIO)
#   the same to EXR (loads the OpenImageIO module, scadray_oiio.so)
#   POV-Ray rendering scadray's export of the same scene at 1x1 (skipped where povray is absent)
# Usage: scripts/bench_startup.sh [build-dir] [runs]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
runs=${2:-5}
scadray="$build/tools/scadray"
if [ ! -x "$scadray" ]; then
    echo "bench_startup: $scadray not found; build the target scadray first" >&2
    exit 2
fi
if ! command -v python3 >/dev/null || [ ! -x /usr/bin/time ]; then
    echo "bench_startup: needs python3 and /usr/bin/time (Debian packages python3, time)" >&2
    exit 2
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo 'cube(1);' >"$tmp/cube.scad"

# best LABEL COMMAND...: runs COMMAND 2 x $runs times (output discarded) and prints the smallest
# wall time, CPU time (user + system) and peak RSS seen, each minimised on its own. Wall and CPU
# time come from wait4() on the command itself, at microsecond resolution (/usr/bin/time prints
# centiseconds, too coarse for a 10 ms process); peak RSS from /usr/bin/time's %M on separate
# runs, since a child forked by python3 would count python's own pages up to its exec.
best() {
    python3 - "$runs" "$tmp/rss" "$@" <<'PY'
import os, subprocess, sys, time
runs, rssFile, label, cmd = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4:]
def run(argv):
    start = time.perf_counter()
    child = subprocess.Popen(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    elapsed = time.perf_counter() - start
    err = child.stderr.read().decode(errors="replace")
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        sys.exit(f"bench_startup: {' '.join(argv)} failed (exit {code}):\n{err}")
    return elapsed, usage.ru_utime + usage.ru_stime
wall = cpu = rss = float("inf")
for _ in range(runs):
    w, c = run(cmd)
    wall, cpu = min(wall, w), min(cpu, c)
    run(["/usr/bin/time", "-f", "%M", "-o", rssFile] + cmd)
    rss = min(rss, int(open(rssFile).read().split()[-1]))
print(f"{label:<36} {wall * 1000:8.1f} ms {cpu * 1000:8.1f} ms {rss / 1024:8.1f} MB")
PY
}

echo "start-up, best of $runs runs ($(nproc) CPUs, load average $(cut -d' ' -f1-3 /proc/loadavg)):"
printf "%-36s %11s %11s %11s\n" "" "wall" "CPU" "peak RSS"
best "scadray --version" "$scadray" --version
best "scadray render 1x1 -> PNG" "$scadray" render "$tmp/cube.scad" -W 1 -H 1 -o "$tmp/cube.png"
best "scadray render 1x1 -> EXR (module)" "$scadray" render "$tmp/cube.scad" -W 1 -H 1 \
    -o "$tmp/cube.exr"
if command -v povray >/dev/null 2>&1; then
    "$scadray" export "$tmp/cube.scad" -W 1 -H 1 -o "$tmp/cube.pov" >/dev/null 2>&1
    # POV-Ray as `scadray check` runs it: in the scene's folder, HOME there (no user povray.conf)
    best "povray 1x1 (scadray's export)" env -C "$tmp" HOME="$tmp" povray cube.ini -D -V +WT1
else
    echo "povray is not installed: POV-Ray's start-up skipped (scripts/setup.sh installs it)"
fi
