#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Benchmark (not a test): renders a 1.3-million-triangle mesh (an icosphere written as binary
# STL) and the 1.04-million instanced triangles of MetalRoughSpheresNoTextures at 640x480, and
# prints wall time and peak memory of each whole run. Then scadray's mesh BVH side by side with
# Embree 3 where installed (build on 1 and 2 threads, camera and random rays, bytes per
# triangle; with the positions in floats, as STL and glTF give them, and in double), and the
# Google Benchmark of BVH build and closest-hit rays at growing sizes.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/tests/icosphere_stl" "$tmp/icosphere.stl" 8
run() {
    /usr/bin/time -f "  whole run: %e s wall, %M KB peak resident" "$build/tools/scadray" render "$@" 2>&1 |
        grep -E "scadray:|whole run"
}
echo "1.31 M distinct triangles:"
run "$tmp/icosphere.stl" -o "$tmp/icosphere.png" -W 640 -H 480
samples=tests/data/gltf/khronos/MetalRoughSpheresNoTextures.glb
if [ -f "$samples" ]; then
    echo "1.04 M instanced triangles (MetalRoughSpheresNoTextures.glb):"
    run "$samples" -o "$tmp/spheres.png" -W 640 -H 480
fi
echo "scadray and Embree 3 on the same 1.31 M-triangle icosphere (positions in floats) and the same rays:"
"$build/tests/mesh_vs_embree" 8
echo "the same with scadray's positions in double (leaves keep vertex indices; Embree traces them rounded):"
"$build/tests/mesh_vs_embree" 8 --double
"$build/tests/mesh_bench"
