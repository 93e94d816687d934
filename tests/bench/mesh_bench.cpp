// SPDX-License-Identifier: MIT
// Benchmarks of triangle meshes (not tests): BVH build time, bytes per triangle and closest-hit
// rays per second, for icospheres of 20 * 4^k triangles, so scaling with size is visible.
// Run: build/tests/mesh_bench
#include <benchmark/benchmark.h>

#include "core/geometry/triangle_mesh.h"
#include "core/math/rng.h"
#include "support/mesh_builder.h"

namespace rt {
namespace {

void BM_MeshBuild(benchmark::State &state) {
    auto mesh = test::icosphere(static_cast<int>(state.range(0)), 1);
    size_t bytes = 0;
    for (auto _ : state) {
        TriangleMesh tm(mesh);
        bytes = tm.extraBytes();
        benchmark::DoNotOptimize(tm.bounds());
    }
    double tris = static_cast<double>(mesh->triangles.size());
    state.counters["triangles"] = tris;
    state.counters["bvh_bytes_per_tri"] = bytes / tris;
    state.counters["mesh_bytes_per_tri"] =
        (mesh->positions.size() * sizeof(Vec3) + mesh->triangles.size() * 12) / tris;
    state.SetItemsProcessed(state.iterations() * mesh->triangles.size());
}
BENCHMARK(BM_MeshBuild)->DenseRange(4, 8, 2)->Unit(benchmark::kMillisecond);

void BM_MeshClosestHit(benchmark::State &state) {
    auto mesh =
        std::make_shared<TriangleMesh>(test::icosphere(static_cast<int>(state.range(0)), 1));
    Rng rng(1);
    std::vector<Ray> rays;
    for (int i = 0; i < 4096; ++i) {
        Vec3 o(rng.uniform() * 6 - 3, rng.uniform() * 6 - 3, 5);
        rays.emplace_back(o, normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, 0) - o));
    }
    size_t i = 0;
    for (auto _ : state) {
        TriangleMesh::Hit hit;
        benchmark::DoNotOptimize(mesh->closest(rays[i++ & 4095], 0, kInfinity, &hit));
    }
    state.counters["triangles"] = static_cast<double>(mesh->triangleCount());
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_MeshClosestHit)->DenseRange(4, 8, 2);

}  // namespace
}  // namespace rt

BENCHMARK_MAIN();
