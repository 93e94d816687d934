// SPDX-License-Identifier: MIT
// Benchmarks of the .scad evaluator (figures, not a timed test): a 100 000-primitive loop
// with 10 000 colours, parsed and evaluated into the IR, in primitives per second. Well under a
// second in RelWithDebInfo. Run: build/tests/scad_eval_bench
#include <benchmark/benchmark.h>

#include "importers/scad/scad_importer.h"

namespace rt {
namespace {

void BM_HundredThousandPrimitives(benchmark::State &state) {
    const std::string src =
        "for (i = [0:99], j = [0:99], k = [0:9]) translate([i, j, k]) color([i / 100, j / 100, "
        "0.5]) cube(0.5);";
    size_t primitives = 0;
    for (auto _ : state) {
        DiagnosticSink diag;
        ir::Scene scene = scad::importScadSource(src, "bench.scad", diag);
        primitives += scene.root->primitiveCount();
        benchmark::DoNotOptimize(scene);
    }
    state.SetItemsProcessed(static_cast<int64_t>(primitives));
}
BENCHMARK(BM_HundredThousandPrimitives)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rt

BENCHMARK_MAIN();
