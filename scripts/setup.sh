#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 packages scadray needs to build, test and compare renders; installs only what is missing.
# clang and libclang-rt-14-dev (libFuzzer and the sanitizer runtimes) serve scripts/sanitize.sh and scripts/fuzz.sh.
# openscad-mcad is OpenSCAD's MCAD library (LGPL, read in place), which examples/Old/example023.scad uses.
set -euo pipefail

packages=(
    g++ cmake ninja-build pkg-config
    libopenimageio-dev libpng-dev libcli11-dev
    libgtest-dev libgmock-dev libbenchmark-dev
    libtinygltf-dev libdraco-dev libmeshoptimizer-dev nlohmann-json3-dev libpolyclipping-dev libxml2-dev
    libfreetype-dev libharfbuzz-dev libfontconfig-dev fonts-liberation
    povray openscad
    openscad-mcad
    # render --frames encodes the video with ffmpeg; its tests count the frames with ffprobe (same package)
    ffmpeg
    clang libclang-rt-14-dev
    clang-format  # scripts/check_format.sh: the code stays as .clang-format says (CI)
    python3  # scripts/check_docs.py: the documentation test
    libembree-dev
    libjs-chart.js  # Chart.js, embedded into `scadray report` pages for the converge plots
    chromium  # the headless browser of the report's test (tests/integration/report_browser.sh)
    slurm-wlm munge  # the private Slurm cluster of the tests of scripts/slurm/ (tests/slurm/cluster.sh)
)

missing=()
for p in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
        missing+=("$p")
    fi
done

if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
    sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
