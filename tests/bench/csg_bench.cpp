// SPDX-License-Identifier: MIT
// Benchmarks of CSG nodes with many operands (not tests): build time and time per ray against
// the number of operands N = 10 ... 100,000, for a plate with N holes (a difference), a union of
// N separate spheres and two intersections of N operands (N large spheres whose common part is a
// ball, and N slabs turned about z whose common part is a prism). The shapes are built through
// the core API (no parsing). Rays are those of a 64 x 48 camera framing the solid, split into
// those that hit it and those that miss, each timed on its own.
// Run: build/tests/csg_bench [--benchmark_filter=ray]
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/csg/csg_shape.h"

namespace rt {
namespace {

enum class Kind { Plate, Union, SphereIntersection, SlabIntersection };

const char *kindName(Kind k) {
    switch (k) {
        case Kind::Plate:
            return "plate";
        case Kind::Union:
            return "union";
        case Kind::SphereIntersection:
            return "isect_spheres";
        case Kind::SlabIntersection:
            return "isect_slabs";
    }
    return "";
}

int addPrimitive(CsgShape &s, std::unique_ptr<Primitive> p, const Mat4 &m, int material) {
    return s.addLeaf(
        std::make_unique<PrimitiveInstance>(std::move(p), *Transform::fromMatrix(m), material));
}

/// The shape of kind `k` with `n` operands (beside a plate's minuend).
std::unique_ptr<CsgShape> build(Kind k, int n) {
    auto s = std::make_unique<CsgShape>();
    int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    std::vector<int> ops;
    ops.reserve(n + 1);
    switch (k) {
        case Kind::Plate:
            // A side x side x 2 plate with n holes of radius 0.3 on a 1 mm grid
            ops.push_back(addPrimitive(
                *s, std::make_unique<Box>(Vec3(0, 0, 0), Vec3(side, side, 2)), Mat4(), 0));
            for (int i = 0; i < n; ++i)
                ops.push_back(addPrimitive(*s, std::make_unique<Cone>(-1, 3, 0.3, 0.3),
                                           Mat4::translate({i % side + 0.5, i / side + 0.5, 0}),
                                           1));
            s->addOp(CsgShape::Op::Difference, std::move(ops));
            break;
        case Kind::Union:
            // n spheres of radius 0.4 on a 1 mm grid, none touching
            for (int i = 0; i < n; ++i)
                ops.push_back(addPrimitive(*s, std::make_unique<Sphere>(0.4),
                                           Mat4::translate({i % side + 0.5, i / side + 0.5, 0.5}),
                                           0));
            s->addOp(CsgShape::Op::Union, std::move(ops));
            break;
        case Kind::SphereIntersection: {
            // n spheres of radius 2 centred on a Fibonacci lattice of the unit sphere: their common
            // part is nearly the ball of radius 1 about the origin
            const double golden = M_PI * (3 - std::sqrt(5.0));
            for (int i = 0; i < n; ++i) {
                double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z);
                Vec3 c(r * std::cos(golden * i), r * std::sin(golden * i), z);
                ops.push_back(addPrimitive(*s, std::make_unique<Sphere>(2), Mat4::translate(c), 0));
            }
            s->addOp(CsgShape::Op::Intersection, std::move(ops));
            break;
        }
        case Kind::SlabIntersection:
            // n slabs |x| <= 1 (6 long, 2 high) turned about z by 180 i / n degrees: a prism
            // with a 2n-gon of inradius 1 as its section
            for (int i = 0; i < n; ++i)
                ops.push_back(addPrimitive(*s,
                                           std::make_unique<Box>(Vec3(-1, -3, -1), Vec3(1, 3, 1)),
                                           Mat4::rotateZ(180.0 * i / n), 0));
            s->addOp(CsgShape::Op::Intersection, std::move(ops));
            break;
    }
    return s;
}

struct Setup {
    std::unique_ptr<CsgShape> shape;
    std::vector<Ray> hits, misses;
};

/// Rays of a 64 x 48 pinhole camera looking down at the solid from the front left, framing its
/// bounds, sorted into those that hit and those that miss.
Setup &setup(Kind k, int n) {
    static std::map<std::pair<Kind, int>, Setup> cache;
    Setup &s = cache[{k, n}];
    if (s.shape) return s;
    s.shape = build(k, n);
    Bounds3 b = s.shape->worldBounds();
    Vec3 centre = (b.min + b.max) * 0.5;
    double radius = length(b.max - b.min) * 0.5;
    Vec3 eye = centre + normalize(Vec3(-0.5, -0.8, 0.9)) * (3 * radius);
    Vec3 forward = normalize(centre - eye);
    Vec3 right = normalize(cross(forward, Vec3(0, 0, 1)));
    Vec3 up = cross(right, forward);
    double half = std::tan(std::asin(1 / 3.0));  // the bounding sphere fills the height
    SpanScratch scratch;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) {
            double u = (2 * (x + 0.5) / 64 - 1) * half * 64 / 48,
                   v = (1 - 2 * (y + 0.5) / 48) * half;
            Ray r(eye, normalize(forward + right * u + up * v));
            Crossing c;
            (s.shape->firstCrossing(r, 0, kInfinity, &c, scratch) ? s.hits : s.misses).push_back(r);
        }
    return s;
}

void BM_Build(benchmark::State &state, Kind k) {
    int n = static_cast<int>(state.range(0));
    for (auto _ : state) benchmark::DoNotOptimize(build(k, n));
    state.counters["operands"] = n;
    state.counters["time_per_operand"] =
        benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                       benchmark::Counter::kInvert);
}

/// Closest crossing (what camera and shadow rays ask for) of one ray per iteration.
void BM_Ray(benchmark::State &state, Kind k, bool hit) {
    int n = static_cast<int>(state.range(0));
    Setup &s = setup(k, n);
    const std::vector<Ray> &rays = hit ? s.hits : s.misses;
    if (rays.empty()) {
        state.SkipWithError("no such rays");
        return;
    }
    SpanScratch scratch;
    size_t i = 0;
    for (auto _ : state) {
        Crossing c;
        benchmark::DoNotOptimize(s.shape->firstCrossing(rays[i], 0, kInfinity, &c, scratch));
        if (++i == rays.size()) i = 0;
    }
    state.counters["operands"] = n;
    state.counters["rays"] = static_cast<double>(rays.size());
    state.counters["merges_per_ray"] = benchmark::Counter(static_cast<double>(scratch.spanOps),
                                                          benchmark::Counter::kAvgIterations);
    state.SetItemsProcessed(state.iterations());
}

}  // namespace
}  // namespace rt

int main(int argc, char **argv) {
    using namespace rt;
    for (Kind k : {Kind::Plate, Kind::Union, Kind::SphereIntersection, Kind::SlabIntersection}) {
        std::string name = kindName(k);
        for (bool hit : {true, false})
            benchmark::RegisterBenchmark((name + (hit ? "/ray_hit" : "/ray_miss")).c_str(),
                                         [k, hit](benchmark::State &st) { BM_Ray(st, k, hit); })
                ->RangeMultiplier(10)
                ->Range(10, 100000);
        benchmark::RegisterBenchmark((name + "/build").c_str(),
                                     [k](benchmark::State &st) { BM_Build(st, k); })
            ->RangeMultiplier(10)
            ->Range(10, 100000)
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
