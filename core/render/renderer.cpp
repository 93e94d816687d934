// SPDX-License-Identifier: MIT
// Tile scheduling across threads and per-pixel sampling.
#include "core/render/renderer.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <ctime>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/camera/camera.h"
#include "core/math/rng.h"
#include "core/render/whitted.h"
#include "core/system/large_stack.h"

namespace rt {

namespace {

/// Rounds of refinement up to `maxSamples`: the smallest k >= 1 with 4^k >= maxSamples, at most
/// kMaxAdaptiveLevel (validateRenderOptions requires 4^k == maxSamples).
int adaptiveLevels(int maxSamples) {
    int k = 1;
    while (k < kMaxAdaptiveLevel && (1 << (2 * k)) < maxSamples) ++k;
    return k;
}

}  // namespace

void validateRenderOptions(const RenderOptions &o) {
    if (o.width < 1 || o.height < 1 || o.width > kMaxImageSide || o.height > kMaxImageSide)
        throw std::invalid_argument("image size " + std::to_string(o.width) + "x" +
                                    std::to_string(o.height) + " is outside 1.." +
                                    std::to_string(kMaxImageSide));
    if (int64_t(o.width) * o.height > kMaxImagePixels)
        throw std::invalid_argument("image size " + std::to_string(o.width) + "x" +
                                    std::to_string(o.height) + " has more than " +
                                    std::to_string(kMaxImagePixels) +
                                    " pixels (16384 x 16384), the limit");
    if (o.samplesPerPixel < 1 || o.samplesPerPixel > kMaxSamplesPerPixel)
        throw std::invalid_argument("samples per pixel must be between 1 and " +
                                    std::to_string(kMaxSamplesPerPixel));
    if (o.batches < 1 || o.batches > kMaxBatches)
        throw std::invalid_argument("batches must be between 1 and " + std::to_string(kMaxBatches));
    if (!(o.sampleClamp >= 0)) throw std::invalid_argument("sample clamp must not be negative");
    if (o.threads < 0) throw std::invalid_argument("thread count must not be negative");
    if (o.tileSize < 1) throw std::invalid_argument("tile size must be positive");
    if (o.rowBegin < 0 || o.rowEnd < 0 || o.rowBegin >= (o.rowEnd > 0 ? o.rowEnd : o.height) ||
        o.rowEnd > o.height)
        throw std::invalid_argument("rows " + std::to_string(o.rowBegin) + ".." +
                                    std::to_string(o.rowEnd) + " are not a band of a picture " +
                                    std::to_string(o.height) + " rows high");
    if (o.adaptive) {
        if (o.adaptiveMax != 1 << (2 * adaptiveLevels(o.adaptiveMax)))
            throw std::invalid_argument(
                "adaptive antialiasing needs a maximum of 4, 16, 64, 256, "
                "1024 or 4096 samples per pixel, not " +
                std::to_string(o.adaptiveMax));
        if (!(o.adaptiveThreshold >= 0) || !(o.adaptiveTolerance >= 0))
            throw std::invalid_argument("adaptive threshold and tolerance must not be negative");
        if (o.batches != 1 || o.jitterSingleSample)
            throw std::invalid_argument("adaptive antialiasing renders one batch of samples");
    }
}

std::pair<int, int> tileRows(int tile, int tiles, int height) {
    if (tiles < 1 || tiles > height)
        throw std::invalid_argument("a picture " + std::to_string(height) +
                                    " rows high splits into 1 to " + std::to_string(height) +
                                    " tiles, not " + std::to_string(tiles));
    if (tile < 0 || tile >= tiles)
        throw std::invalid_argument("tile " + std::to_string(tile + 1) + " is not one of 1.." +
                                    std::to_string(tiles));
    auto begin = [&](int k) { return static_cast<int>(int64_t(k) * height / tiles); };
    return {begin(tile), begin(tile + 1)};
}

void strataGrid(int n, int &columns, int &rows) {
    rows = static_cast<int>(std::sqrt(double(n)));
    while (rows > 1 && n % rows != 0) --rows;
    rows = std::max(rows, 1);
    columns = n / rows;
}

namespace {

/// Runs job(0 .. jobs-1) on `threads` threads with a TraceContext each, adds their ray counts to
/// `stats` and reports progress from `from` to `to` of the whole render.
void runJobs(int threads, int jobs, const RenderOptions &opts, double from, double to,
             RayStats &stats, const std::function<void(int, TraceContext &)> &job) {
    if (jobs == 0) return;
    threads = std::min(threads, jobs);
    std::atomic<int> next{0}, done{0};
    std::mutex mutex;
    std::condition_variable finished;
    std::vector<RayStats> threadStats(threads);
    auto worker = [&](int id) {
        TraceContext ctx;
        for (int j; (j = next.fetch_add(1)) < jobs;) {
            job(j, ctx);
            done.fetch_add(1);
        }
        ctx.stats.spanOps = ctx.scratch.spanOps;
        ctx.stats.prunedSubtrees = ctx.scratch.prunedSubtrees;
        threadStats[id] = ctx.stats;
        std::lock_guard<std::mutex> lock(mutex);
        finished.notify_all();
    };
    std::vector<std::unique_ptr<StackThread>> pool;
    for (int i = 0; i < threads; ++i)
        pool.push_back(
            std::make_unique<StackThread>(kWorkerStackBytes, [&worker, i] { worker(i); }));
    {
        std::unique_lock<std::mutex> lock(mutex);
        while (done.load() < jobs) {
            finished.wait_for(lock, std::chrono::milliseconds(250));
            if (opts.progress) opts.progress(from + (to - from) * done.load() / jobs);
        }
    }
    for (auto &t : pool) t->join();
    for (const auto &s : threadStats) stats += s;
}

/// Last row (exclusive) of the rows the options ask for.
int endRow(const RenderOptions &o) { return o.rowEnd > 0 ? o.rowEnd : o.height; }

/// The thread tiles (tileSize squares) covering rows [rowBegin, rowEnd) of the picture.
struct Tiles {
    int x = 0, count = 0, rowBegin = 0, rowEnd = 0;
    Tiles(const RenderOptions &o, int rowBegin, int rowEnd)
        : x((o.width + o.tileSize - 1) / o.tileSize), rowBegin(rowBegin), rowEnd(rowEnd) {
        count = x * ((rowEnd - rowBegin + o.tileSize - 1) / o.tileSize);
    }
    explicit Tiles(const RenderOptions &o) : Tiles(o, o.rowBegin, endRow(o)) {}
    /// Calls f(x, y) for each pixel of tile `t` (picture coordinates).
    template <typename F>
    void forPixels(const RenderOptions &o, int t, F f) const {
        int x0 = (t % x) * o.tileSize, y0 = rowBegin + (t / x) * o.tileSize;
        int x1 = std::min(x0 + o.tileSize, o.width), y1 = std::min(y0 + o.tileSize, rowEnd);
        for (int y = y0; y < y1; ++y)
            for (int px = x0; px < x1; ++px) f(px, y);
    }
};

inline Rgb clampSample(Rgb c, const RenderOptions &opts) {
    if (opts.sampleClamp > 0)
        for (int ch = 0; ch < 3; ++ch) c[ch] = std::clamp(c[ch], 0.0, opts.sampleClamp);
    return c;
}

/// Camera rays made ahead of their traces, a few at a time: each waits on a square root and
/// three divisions (normalising its direction), which the processor overlaps when the rays are
/// made side by side, not each just before its trace (whose work depends on it). With each,
/// its sample's stream as the jitter left it, for the distributed rays of its path.
struct CameraRays {
    static constexpr int kSize = 16;
    Ray ray[kSize];
    Rng rng[kSize];
};

void renderUniform(const Camera &camera, const WhittedIntegrator &integrator,
                   const RenderOptions &opts, int threads, RenderResult &result) {
    Tiles tiles(opts);
    int columns, rows;
    strataGrid(opts.samplesPerPixel, columns, rows);
    bool jitter = opts.samplesPerPixel > 1 || opts.batches > 1 || opts.jitterSingleSample;
    double invSamples = 1.0 / opts.samplesPerPixel;
    int y0 = opts.rowBegin, bandRows = endRow(opts) - y0;
    if (opts.batches > 1) result.variance = Image(opts.width, bandRows);
    runJobs(threads, tiles.count, opts, 0, 1, result.stats, [&](int tile, TraceContext &ctx) {
        CameraRays prepared;
        tiles.forPixels(opts, tile, [&](int x, int y) {
            uint64_t pixelSeed = Rng::pixelSeed(uint64_t(y) * opts.width + x, opts.seed);
            // Welford's running mean and sum of squares over batch means
            Rgb mean(0), m2(0);
            int tiedSamples = 0;
            for (int b = 0; b < opts.batches; ++b) {
                Rgb sum(0);
                for (int s0 = 0; s0 < opts.samplesPerPixel; s0 += CameraRays::kSize) {
                    int n = std::min(CameraRays::kSize, opts.samplesPerPixel - s0);
                    for (int k = 0; k < n; ++k) {
                        int s = s0 + k;
                        // The sample's stream jitters its stratum of the pixel, then drives
                        // every distributed ray of its path
                        Rng rng =
                            Rng::forPixelSample(pixelSeed, uint64_t(b) * opts.samplesPerPixel + s);
                        double fx = 0.5, fy = 0.5;
                        if (jitter) {
                            fx = ((s % columns) + rng.uniform()) / columns;
                            fy = ((s / columns) + rng.uniform()) / rows;
                        }
                        prepared.rng[k] = rng;
                        prepared.ray[k] = camera.generateRay(x + fx, y + fy);
                    }
                    for (int k = 0; k < n; ++k) {
                        ctx.rng = prepared.rng[k];
                        ctx.tie = false;
                        Rgb c = integrator.li(prepared.ray[k], ctx);
                        tiedSamples += ctx.tie;
                        sum += clampSample(c, opts);
                    }
                }
                Rgb batchMean = sum * invSamples;
                Rgb delta = batchMean - mean;
                mean += delta / double(b + 1);
                m2 += delta * (batchMean - mean);
            }
            result.image.set(x, y - y0, mean);
            result.ties.set(x, y - y0,
                            Rgb(double(tiedSamples) / (opts.batches * opts.samplesPerPixel)));
            if (opts.batches > 1)
                result.variance.set(x, y - y0,
                                    m2 / double(opts.batches - 1) / double(opts.batches));
        });
    });
    result.samples = int64_t(opts.width) * bandRows * opts.samplesPerPixel * opts.batches;
}

/// Display value of a linear colour for the refinement decisions: the square root (close to
/// sRGB, and cheap) of the value clamped to [0, 1].
Rgb displayValue(const Rgb &c) {
    Rgb d;
    for (int ch = 0; ch < 3; ++ch) d[ch] = std::sqrt(std::clamp(c[ch], 0.0, 1.0));
    return d;
}

/// Display value in 1/255 steps, as the refinement decisions compare them.
std::array<uint8_t, 3> displayBytes(const Rgb &d) {
    return {displayStep(d[0]), displayStep(d[1]), displayStep(d[2])};
}

/// The primitive a camera ray hit: its index in the compiled scene, 0 for the background.
/// (A hash of its address differed between processes, and two primitives could share one.)
uint32_t hitKey(const LeafShape *hit) { return hit ? hit->sceneIndex : 0; }

/// The refinement threshold in the 1/255 steps of displayBytes.
int thresholdBytes(const RenderOptions &opts) {
    return static_cast<int>(std::floor(opts.adaptiveThreshold * 255));
}

/// Whether two samples saw different primitives or display values more than `threshold` apart.
bool samplesDiffer(uint32_t hitA, const std::array<uint8_t, 3> &a, uint32_t hitB,
                   const std::array<uint8_t, 3> &b, int threshold) {
    if (hitA != hitB) return true;
    for (int ch = 0; ch < 3; ++ch)
        if (std::abs(int(a[ch]) - int(b[ch])) > threshold) return true;
    return false;
}

/// What pass 1 leaves for pass 2: per pixel 8 bytes (the pages a pass touches are much of its
/// cost), the primitive hit and the display value of its centre sample, and the pixels to refine
/// (picture indices) in index order. Its per-pixel vectors start at row `firstRow`.
struct FirstPass {
    int firstRow = 0;
    std::vector<uint32_t> hits;
    std::vector<std::array<uint8_t, 3>> display;
    /// Per pixel, the sides (kLeft ...) of the neighbours that differ from it.
    std::vector<uint8_t> sides;
    std::vector<int> refine;
};

constexpr uint8_t kLeft = 1, kRight = 2, kAbove = 4, kBelow = 8;

/// A checked pixel's probe samples must see the centre's primitive and its display value within
/// this many 1/255 steps (the rounding of displayBytes). As loose as the refinement threshold,
/// the centres kept inside refracted and reflected detail biased whole 8x8 tiles of
/// default.scad past `compare`'s margin.
constexpr int kProbeAgreement = 1;

/// Bit q set for each quadrant q (column bit 0, row bit 1) of a pixel that faces one of the
/// differing neighbours `sides`.
int facingQuadrants(uint8_t sides) {
    int mask = 0;
    if (sides & kLeft) mask |= 1 << 0 | 1 << 2;
    if (sides & kRight) mask |= 1 << 1 | 1 << 3;
    if (sides & kAbove) mask |= 1 << 0 | 1 << 1;
    if (sides & kBelow) mask |= 1 << 2 | 1 << 3;
    return mask;
}

/// Pass 1: every pixel's centre; zeroes result.pixelLevels and finds the pixels to refine. A
/// band of the picture (rowBegin, rowEnd) also traces the centres of the rows bordering it: its
/// pixels' decisions read them, and must be those of the whole picture.
FirstPass adaptiveFirstPass(const Camera &camera, const WhittedIntegrator &integrator,
                            const RenderOptions &opts, int threads, RenderResult &result) {
    int y0 = opts.rowBegin, y1 = endRow(opts);
    int e0 = std::max(0, y0 - 1), e1 = std::min(opts.height, y1 + 1);
    Tiles tiles(opts, e0, e1);
    int w = opts.width, h = e1 - e0;
    FirstPass first;
    first.firstRow = e0;
    std::vector<uint32_t> &hits = first.hits;
    std::vector<std::array<uint8_t, 3>> &display = first.display;
    hits.resize(size_t(w) * h);
    display.resize(size_t(w) * h);
    runJobs(threads, tiles.count, opts, 0, 0.5, result.stats, [&](int tile, TraceContext &ctx) {
        tiles.forPixels(opts, tile, [&](int x, int y) {
            size_t pixel = size_t(y) * opts.width + x;
            // The centre sample has no jitter and no distributed ray: its stream is that of
            // uniform sampling's single sample
            ctx.rng = Rng::forSample(pixel, 0, opts.seed);
            ctx.tie = false;
            ctx.firstHit = nullptr;
            Rgb c = clampSample(integrator.li(camera.generateRay(x + 0.5, y + 0.5), ctx), opts);
            if (y >= y0 && y < y1) {
                result.image.set(x, y - y0, c);
                result.ties.set(x, y - y0, Rgb(ctx.tie ? 1.0 : 0.0));
            }
            hits[pixel - size_t(e0) * w] = hitKey(ctx.firstHit);
            display[pixel - size_t(e0) * w] = displayBytes(displayValue(c));
        });
    });
    // Mark both pixels of each neighbouring pair that differ in colour or primitive, each with
    // the side the other lies on
    std::vector<uint8_t> &sides = first.sides;
    sides.assign(size_t(w) * h, 0);
    result.pixelLevels.assign(size_t(w) * (y1 - y0), 0);
    int threshold = thresholdBytes(opts);
    auto pair = [&](size_t a, size_t b, uint8_t sideOfB, uint8_t sideOfA) {
        if (samplesDiffer(hits[a], display[a], hits[b], display[b], threshold)) {
            sides[a] |= sideOfB;
            sides[b] |= sideOfA;
        }
    };
    // Edge-sharing neighbours only: diagonal pairs added 7-9 % more samples on the example
    // scenes with no measurable change of the picture
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            size_t p = size_t(y) * w + x;
            if (x + 1 < w) pair(p, p + 1, kRight, kLeft);
            if (y + 1 < h) pair(p, p + w, kBelow, kAbove);
        }
    // The band's own rows: the bordering ones only lent their centres
    for (size_t p = size_t(y0 - e0) * w; p < size_t(y1 - e0) * w; ++p)
        if (sides[p]) first.refine.push_back(static_cast<int>(p + size_t(e0) * w));
    return first;
}

/// Cell (column, row) of a pixel's j-th adaptive sample in the 2^levels grid: base-4 digit l of
/// j picks the quadrant at depth l, scrambled by a random XOR per pixel and tree node, so the
/// first 4^k samples fill the 2^k grid, each uniformly placed within its cell.
void adaptiveCell(int j, int levels, uint64_t pixelKey, int &column, int &row) {
    column = row = 0;
    uint64_t node = 1;
    for (int l = 0; l < levels; ++l) {
        int q = ((j >> (2 * l)) & 3) ^ static_cast<int>(mixBits(pixelKey ^ mixBits(node)) & 3);
        column = column * 2 + (q & 1);
        row = row * 2 + (q >> 1);
        node = node * 4 + uint64_t(q);
    }
}

/// Standard error (display units, largest channel) of the mean of samples [0, 4^k), each group
/// {g + m 4^(k-1) : m = 0..3} being the four children of one cell of the 2^(k-1) grid: the
/// spread within a group estimates the variance of each of its strata (collapsed strata, an
/// overestimate where the picture is smooth within the group).
double adaptiveError(const std::vector<Rgb> &display, int k) {
    int groups = 1 << (2 * (k - 1));
    double worst = 0;
    for (int ch = 0; ch < 3; ++ch) {
        double var = 0;
        for (int g = 0; g < groups; ++g) {
            double m = 0;
            for (int i = 0; i < 4; ++i) m += display[g + i * groups][ch];
            m *= 0.25;
            for (int i = 0; i < 4; ++i) {
                double d = display[g + i * groups][ch] - m;
                var += d * d;
            }
        }
        // each group mean has variance ss / (3 * 4); the pixel mean is their average
        worst = std::max(worst, var / 12.0 / (double(groups) * groups));
    }
    return std::sqrt(worst);
}

void renderAdaptive(const Camera &camera, const WhittedIntegrator &integrator,
                    const RenderOptions &opts, int threads, RenderResult &result) {
    // Monte Carlo noise: every pixel from round 1 on, with no centre pass
    FirstPass first;
    int y0 = opts.rowBegin;
    if (opts.adaptiveNoise) {
        result.pixelLevels.assign(size_t(opts.width) * (endRow(opts) - y0), 0);
        first.refine.resize(result.pixelLevels.size());
        for (size_t p = 0; p < first.refine.size(); ++p)
            first.refine[p] = static_cast<int>(p + size_t(y0) * opts.width);
    } else {
        first = adaptiveFirstPass(camera, integrator, opts, threads, result);
    }
    const std::vector<int> &refine = first.refine;
    int levels = adaptiveLevels(opts.adaptiveMax);
    int side = 1 << levels;
    result.pixelChecked.assign(result.pixelLevels.size(), 0);
    constexpr int kChunk = 32;
    int chunks = static_cast<int>((refine.size() + kChunk - 1) / kChunk);
    runJobs(
        threads, chunks, opts, opts.adaptiveNoise ? 0 : 0.5, 1, result.stats,
        [&](int chunk, TraceContext &ctx) {
            std::vector<Rgb> values(opts.adaptiveMax), display(opts.adaptiveMax);
            std::vector<int> cells(opts.adaptiveMax);
            std::vector<uint32_t> hits(opts.adaptiveMax);
            std::vector<int> byCell(size_t(side) * side);
            size_t end = std::min(refine.size(), size_t(chunk + 1) * kChunk);
            for (size_t i = size_t(chunk) * kChunk; i < end; ++i) {
                int pixel = refine[i], x = pixel % opts.width, y = pixel / opts.width;
                // Its index into the result's vectors and into pass 1's
                size_t own = size_t(pixel) - size_t(y0) * opts.width;
                size_t firstOwn = size_t(pixel) - size_t(first.firstRow) * opts.width;
                uint64_t key = mixBits(uint64_t(pixel) ^ mixBits(opts.seed ^ 0x5ca1ab1e0ddba11ULL));
                uint64_t pixelSeed = Rng::pixelSeed(uint64_t(pixel), opts.seed);
                int tied = 0;
                // Sample j of the pixel: the cell's sample exactly as uniform sampling at
                // adaptiveMax draws it
                auto sample = [&](int j) {
                    int column, row;
                    adaptiveCell(j, levels, key, column, row);
                    int cell = row * side + column;
                    ctx.rng = Rng::forPixelSample(pixelSeed, uint64_t(cell));
                    double fx = (column + ctx.rng.uniform()) / side;
                    double fy = (row + ctx.rng.uniform()) / side;
                    ctx.tie = false;
                    ctx.firstHit = nullptr;
                    Rgb c =
                        clampSample(integrator.li(camera.generateRay(x + fx, y + fy), ctx), opts);
                    tied += ctx.tie;
                    values[j] = c;
                    display[j] = displayValue(c);
                    cells[j] = cell;
                    hits[j] = hitKey(ctx.firstHit);
                };
                // A pixel first takes the samples of round 1 in the quadrants facing its differing
                // neighbours (two, or three for neighbours on two adjacent sides). Where all saw
                // the centre's primitive and display value, the contrast lies in the neighbours'
                // boxes: the pixel keeps its centre (a checked pixel)
                int n = 0, k = 0;
                int facing = opts.adaptiveNoise ? 0xf : facingQuadrants(first.sides[firstOwn]);
                if (facing != 0xf) {
                    // quadrant q holds sample q ^ (round 1's scramble), as adaptiveCell places them
                    int scramble = static_cast<int>(mixBits(key ^ mixBits(1)) & 3);
                    bool flat = true;
                    int probes = 0;
                    for (int q = 0; q < 4; ++q)
                        if (facing >> q & 1) {
                            int j = q ^ scramble;
                            sample(j);
                            ++probes;
                            flat = flat && !samplesDiffer(hits[j], displayBytes(display[j]),
                                                          first.hits[firstOwn],
                                                          first.display[firstOwn], kProbeAgreement);
                        }
                    if (flat) {
                        result.pixelChecked[own] = static_cast<uint8_t>(probes);
                        continue;
                    }
                    for (int q = 0; q < 4; ++q)
                        if (!(facing >> q & 1)) sample(q ^ scramble);
                    n = 4;
                    k = 1;
                }
                if (k == 0 || (k < levels && adaptiveError(display, k) >= opts.adaptiveTolerance)) {
                    do {
                        ++k;
                        for (int count = 1 << (2 * k); n < count; ++n) sample(n);
                    } while (k < levels && adaptiveError(display, k) >= opts.adaptiveTolerance);
                }
                // Sum in cell order, as uniform sampling does
                std::fill(byCell.begin(), byCell.end(), -1);
                for (int j = 0; j < n; ++j) byCell[cells[j]] = j;
                Rgb sum(0);
                for (int j : byCell)
                    if (j >= 0) sum += values[j];
                result.image.set(x, y - y0, sum * (1.0 / n));
                result.ties.set(x, y - y0, Rgb(double(tied) / n));
                result.pixelLevels[own] = static_cast<uint8_t>(k);
            }
        });
    // Counted over the band's pixels (a band's bordering centres are not among its samples)
    int64_t pixels = int64_t(result.pixelLevels.size());
    result.pixelsBySamples.assign(levels + 1, 0);
    result.pixelsBySamples[0] = pixels - int64_t(refine.size());
    result.samples = opts.adaptiveNoise ? 0 : pixels;
    result.checkedPixels = 0;
    for (int pixel : refine) {
        size_t own = size_t(pixel) - size_t(y0) * opts.width;
        int k = result.pixelLevels[own];
        int probes = result.pixelChecked[own];
        ++result.pixelsBySamples[k];
        result.checkedPixels += probes > 0;
        result.samples += probes > 0 ? probes : int64_t(1) << (2 * k);
    }
}

}  // namespace

uint8_t displayStep(double d) {
    // std::lround was a libm call per channel, 2 % of pass 1's instructions. d * 255 is in
    // [0, 255] or NaN, and x - i is exact there.
    double x = d * 255;
    int i = x >= 0 ? static_cast<int>(x) : 0;
    return static_cast<uint8_t>(i + (x - i >= 0.5));
}

double meanSamplesPerPixel(const RenderResult &r) {
    double pixels = double(r.image.width()) * r.image.height();
    return pixels > 0 ? r.samples / pixels : 0;
}

std::string describeSampling(const RenderResult &r) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f per pixel", meanSamplesPerPixel(r));
    if (r.pixelsBySamples.empty()) return buf;
    double pixels = double(r.image.width()) * r.image.height();
    // Sampling adaptive to noise has no centre-only pixels: it starts at 4
    bool noise = r.pixelsBySamples[0] == 0;
    std::string s = "adaptive, pixels by samples:";
    for (size_t k = noise ? 1 : 0; k < r.pixelsBySamples.size(); ++k) {
        char part[96];
        if (k == 0)
            std::snprintf(part, sizeof part, " 1: %.1f %%, checked: %.1f %%",
                          100.0 * (r.pixelsBySamples[0] - r.checkedPixels) / pixels,
                          100.0 * r.checkedPixels / pixels);
        else
            std::snprintf(part, sizeof part, "%s %d: %.1f %%", noise && k == 1 ? "" : ",",
                          1 << (2 * k), 100.0 * r.pixelsBySamples[k] / pixels);
        s += part;
    }
    return s + "; " + buf;
}

RenderResult renderImage(const RenderScene &scene, const RenderOptions &opts) {
    validateRenderOptions(opts);
    auto start = std::chrono::steady_clock::now();
    std::clock_t cpuStart = std::clock();
    Camera camera(scene.camera(), opts.width, opts.height);
    WhittedIntegrator integrator(scene, camera.position());
    int threads =
        opts.threads > 0 ? opts.threads : std::max(1u, std::thread::hardware_concurrency());
    RenderResult result;
    result.image = Image(opts.width, endRow(opts) - opts.rowBegin);
    result.ties = Image(opts.width, endRow(opts) - opts.rowBegin);
    result.threads = std::min(threads, Tiles(opts).count);
    if (opts.adaptive)
        renderAdaptive(camera, integrator, opts, threads, result);
    else
        renderUniform(camera, integrator, opts, threads, result);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.cpuSeconds = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    return result;
}

}  // namespace rt
