// SPDX-License-Identifier: MIT
// Benchmarks of the solids of revolution (not tests): all spans of random rays through a
// torus (ordinary, thin, a quarter turn) and through lathes of 4 to 256 profile edges, in
// rays per second (Mrays/s = items_per_second / 1e6), beside a sphere for scale.
// Run: build/tests/revolved_bench
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/geometry/revolved.h"
#include "core/math/rng.h"

namespace rt {
namespace {

/// Rays from a sphere around the bounds towards random points near the centre; most hit.
std::vector<Ray> rays(const Bounds3 &b) {
    Rng rng(1);
    std::vector<Ray> out;
    Vec3 c = b.centroid();
    double radius = length(b.diagonal());
    for (int i = 0; i < 4096; ++i) {
        double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
        double s = std::sqrt(1 - z * z);
        Vec3 o = c + Vec3(s * std::cos(phi), s * std::sin(phi), z) * (2 * radius);
        Vec3 target =
            c + Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * radius * 0.5;
        out.emplace_back(o, normalize(target - o));
    }
    return out;
}

void run(benchmark::State &state, const Primitive &p) {
    std::vector<Ray> rs = rays(p.objectBounds());
    std::vector<PrimitiveSpan> spans;
    size_t i = 0, found = 0;
    for (auto _ : state) {
        spans.clear();
        p.intersectAll(rs[i++ & 4095], spans);
        found += spans.size();
        benchmark::DoNotOptimize(spans.data());
    }
    state.counters["spans_per_ray"] = static_cast<double>(found) / state.iterations();
    state.SetItemsProcessed(state.iterations());
}

void BM_Sphere(benchmark::State &state) { run(state, Sphere(1)); }
BENCHMARK(BM_Sphere);

void BM_Torus(benchmark::State &state) {
    double minor = state.range(0) == 0 ? 0.3 : 1e-3;
    run(state, Torus(ir::TorusPrim{1, minor, 360, {}, 0}));
}
BENCHMARK(BM_Torus)->Arg(0)->Arg(1)->ArgName("thin");

void BM_TorusQuarter(benchmark::State &state) {
    run(state, Torus(ir::TorusPrim{1, 0.3, 90, {}, 0}));
}
BENCHMARK(BM_TorusQuarter);

/// A lathe of a circle of radius 0.3 at 1 from the axis as an n-gon (n profile edges).
void BM_Lathe(benchmark::State &state) {
    int n = static_cast<int>(state.range(0));
    ir::ProfileOutline o;
    for (int i = 0; i < n; ++i)
        o.push_back({1 + 0.3 * std::cos(2 * M_PI * i / n), 0.3 * std::sin(2 * M_PI * i / n)});
    run(state, Lathe(ir::LathePrim{{o}, 360, 0}));
}
BENCHMARK(BM_Lathe)->RangeMultiplier(4)->Range(4, 256);

}  // namespace
}  // namespace rt

BENCHMARK_MAIN();
