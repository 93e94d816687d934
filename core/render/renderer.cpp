// SPDX-License-Identifier: MIT
// Tile scheduling across threads and per-pixel sampling.
#include "core/render/renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "core/camera/camera.h"
#include "core/math/rng.h"
#include "core/render/whitted.h"
#include "core/system/large_stack.h"

namespace rt {

void validateRenderOptions(const RenderOptions &o) {
    if (o.width < 1 || o.height < 1 || o.width > kMaxImageSide || o.height > kMaxImageSide)
        throw std::invalid_argument("image size " + std::to_string(o.width) + "x" +
                                    std::to_string(o.height) + " is outside 1.." +
                                    std::to_string(kMaxImageSide));
    if (int64_t(o.width) * o.height > kMaxImagePixels)
        throw std::invalid_argument("image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                                    " has more than " + std::to_string(kMaxImagePixels) +
                                    " pixels (16384 x 16384), the limit");
    if (o.samplesPerPixel < 1 || o.samplesPerPixel > kMaxSamplesPerPixel)
        throw std::invalid_argument("samples per pixel must be between 1 and " +
                                    std::to_string(kMaxSamplesPerPixel));
    if (o.batches < 1 || o.batches > kMaxBatches)
        throw std::invalid_argument("batches must be between 1 and " + std::to_string(kMaxBatches));
    if (!(o.sampleClamp >= 0)) throw std::invalid_argument("sample clamp must not be negative");
    if (o.threads < 0) throw std::invalid_argument("thread count must not be negative");
    if (o.tileSize < 1) throw std::invalid_argument("tile size must be positive");
}

void strataGrid(int n, int &columns, int &rows) {
    rows = static_cast<int>(std::sqrt(double(n)));
    while (rows > 1 && n % rows != 0) --rows;
    rows = std::max(rows, 1);
    columns = n / rows;
}

RenderResult renderImage(const RenderScene &scene, const RenderOptions &opts) {
    validateRenderOptions(opts);
    auto start = std::chrono::steady_clock::now();
    Camera camera(scene.camera(), opts.width, opts.height);
    WhittedIntegrator integrator(scene, camera.position());

    int tilesX = (opts.width + opts.tileSize - 1) / opts.tileSize;
    int tilesY = (opts.height + opts.tileSize - 1) / opts.tileSize;
    int tileCount = tilesX * tilesY;
    int threads = opts.threads > 0 ? opts.threads
                                   : std::max(1u, std::thread::hardware_concurrency());
    threads = std::min(threads, tileCount);
    int columns, rows;
    strataGrid(opts.samplesPerPixel, columns, rows);
    bool jitter = opts.samplesPerPixel > 1 || opts.batches > 1 || opts.jitterSingleSample;
    double invSamples = 1.0 / opts.samplesPerPixel;

    RenderResult result;
    result.image = Image(opts.width, opts.height);
    if (opts.batches > 1) result.variance = Image(opts.width, opts.height);
    result.ties = Image(opts.width, opts.height);
    result.threads = threads;
    std::atomic<int> nextTile{0}, doneTiles{0};
    std::mutex mutex;
    std::condition_variable finished;
    std::vector<RayStats> threadStats(threads);

    auto worker = [&](int id) {
        TraceContext ctx;
        for (int tile; (tile = nextTile.fetch_add(1)) < tileCount;) {
            int x0 = (tile % tilesX) * opts.tileSize, y0 = (tile / tilesX) * opts.tileSize;
            int x1 = std::min(x0 + opts.tileSize, opts.width);
            int y1 = std::min(y0 + opts.tileSize, opts.height);
            for (int y = y0; y < y1; ++y)
                for (int x = x0; x < x1; ++x) {
                    uint64_t pixel = uint64_t(y) * opts.width + x;
                    // Welford's running mean and sum of squares over batch means
                    Rgb mean(0), m2(0);
                    int tiedSamples = 0;
                    for (int b = 0; b < opts.batches; ++b) {
                        Rgb sum(0);
                        for (int s = 0; s < opts.samplesPerPixel; ++s) {
                            // The sample's stream jitters its stratum of the pixel, then
                            // drives every distributed ray of its path
                            ctx.rng = Rng::forSample(
                                pixel, uint64_t(b) * opts.samplesPerPixel + s, opts.seed);
                            double fx = 0.5, fy = 0.5;
                            if (jitter) {
                                fx = ((s % columns) + ctx.rng.uniform()) / columns;
                                fy = ((s / columns) + ctx.rng.uniform()) / rows;
                            }
                            ctx.tie = false;
                            Rgb c = integrator.li(camera.generateRay(x + fx, y + fy), ctx);
                            tiedSamples += ctx.tie;
                            if (opts.sampleClamp > 0)
                                for (int ch = 0; ch < 3; ++ch)
                                    c[ch] = std::clamp(c[ch], 0.0, opts.sampleClamp);
                            sum += c;
                        }
                        Rgb batchMean = sum * invSamples;
                        Rgb delta = batchMean - mean;
                        mean += delta / double(b + 1);
                        m2 += delta * (batchMean - mean);
                    }
                    result.image.set(x, y, mean);
                    result.ties.set(x, y, Rgb(double(tiedSamples) / (opts.batches * opts.samplesPerPixel)));
                    if (opts.batches > 1)
                        result.variance.set(x, y, m2 / double(opts.batches - 1) / double(opts.batches));
                }
            doneTiles.fetch_add(1);
        }
        ctx.stats.spanOps = ctx.scratch.spanOps;
        ctx.stats.prunedSubtrees = ctx.scratch.prunedSubtrees;
        threadStats[id] = ctx.stats;
        std::lock_guard<std::mutex> lock(mutex);
        finished.notify_all();
    };

    std::vector<std::unique_ptr<StackThread>> pool;
    for (int i = 0; i < threads; ++i)
        pool.push_back(std::make_unique<StackThread>(kWorkerStackBytes, [&worker, i] { worker(i); }));
    {
        std::unique_lock<std::mutex> lock(mutex);
        while (doneTiles.load() < tileCount) {
            finished.wait_for(lock, std::chrono::milliseconds(250));
            if (opts.progress) opts.progress(double(doneTiles.load()) / tileCount);
        }
    }
    for (auto &t : pool) t->join();
    for (const auto &s : threadStats) result.stats += s;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rt
