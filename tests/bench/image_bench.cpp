// SPDX-License-Identifier: MIT
// Benchmarks of writing a picture (not tests): the 8-bit sRGB code of a linear value by the
// table (srgbByte) and by the formula with its pow, and a whole 640x480 PNG through writeImage,
// of a picture like a render (sky gradient, a shaded checkered floor in perspective, a disc).
// Run: build/tests/image_bench
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "core/image/image_io.h"

namespace rt {
namespace {

std::vector<double> linearValues() {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> v(1 << 16);
    for (double &x : v) x = u(rng) * u(rng);  // more dark values, as in pictures
    return v;
}

void BM_SrgbByteTable(benchmark::State &state) {
    std::vector<double> v = linearValues();
    size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(srgbByte(v[i++ & 0xffff]));
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SrgbByteTable);

void BM_SrgbByteFormula(benchmark::State &state) {
    std::vector<double> v = linearValues();
    size_t i = 0;
    for (auto _ : state) {
        double x = std::clamp(v[i++ & 0xffff], 0.0, 1.0);
        benchmark::DoNotOptimize(std::floor(std::clamp(srgbEncode(x), 0.0, 1.0) * 255 + 0.5));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_SrgbByteFormula);

Image renderLike(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double sy = double(y) / h, sx = double(x) / w;
            Rgb c(0.45 + 0.2 * sy, 0.55 + 0.2 * sy, 0.8);  // sky
            if (sy > 0.45) {
                // floor: checks shrinking towards the horizon, lit from the left
                double depth = 1 / (sy - 0.4);
                int check = int(std::floor((sx - 0.5) * depth * 4)) + int(std::floor(depth * 2));
                double shade = 0.4 + 0.5 * (1 - sx) * (sy - 0.45);
                c = (check & 1) ? Rgb(0.9, 0.9, 0.85) * shade : Rgb(0.2, 0.25, 0.35) * shade;
            }
            double dx = sx - 0.6, dy = sy - 0.5;
            if (dx * dx + dy * dy < 0.03)
                c = Rgb(0.9, 0.7, 0.1) * (0.3 + 0.7 * std::max(0.0, -dx * 4 - dy * 3 + 0.5));
            img.set(x, y, c);
        }
    return img;
}

void BM_WritePng640x480(benchmark::State &state) {
    Image img = renderLike(640, 480);
    std::string path = (std::filesystem::temp_directory_path() /
                        ("image_bench_" + std::to_string(getpid()) + ".png"))
                           .string();
    for (auto _ : state) writeImage(img, path);
    state.counters["bytes"] = double(std::filesystem::file_size(path));
    std::filesystem::remove(path);
}
BENCHMARK(BM_WritePng640x480)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rt

BENCHMARK_MAIN();
