// SPDX-License-Identifier: MIT
// Multi-threaded tile renderer: stratified box-filtered antialiasing with per-pixel seeded
// random streams, so an image is identical for any thread count; uniform (the same samples in
// every pixel) or adaptive (more samples only where the picture needs them).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/image/image.h"
#include "core/image/image_limits.h"
#include "core/render/ray_stats.h"
#include "core/render/render_scene.h"

namespace rt {

struct RenderOptions {
    int width = 640;
    int height = 480;
    /// Samples per pixel, stratified on the squarest grid of that many cells (k x k for a
    /// square, 4 x 2 for 8). One sample is the pixel centre exactly, as POV-Ray without
    /// antialiasing, unless `jitterSingleSample`.
    int samplesPerPixel = 1;
    /// Jitter even a single sample over its pixel, so that every sample count estimates the
    /// same box-filtered image (convergence measurements need this).
    bool jitterSingleSample = false;
    uint64_t seed = 0;
    /// Independent batches of samplesPerPixel samples each; with more than one, the result
    /// carries the variance of each pixel's mean, estimated from the batch means.
    int batches = 1;
    /// Clamp each sample's radiance to [0, sampleClamp] before averaging (0 = off), as an image
    /// file that clips at 1 does to each of its pixels: used when comparing with POV-Ray's
    /// supersampled PNG references.
    double sampleClamp = 0;
    /// Worker threads; 0 = every hardware thread.
    int threads = 0;
    int tileSize = 16;
    /// Adaptive antialiasing instead of samplesPerPixel samples everywhere (batches 1 only).
    /// Pass 1 traces each pixel's centre. A pixel is refined when its display value (square
    /// root of the linear one, close to sRGB) differs from that of a pixel sharing an edge
    /// with it by more than adaptiveThreshold in some channel, or its camera ray hit another
    /// primitive than that neighbour's. Pass 2 gives each such pixel rounds of 4, 16, 64 ...
    /// stratified samples, the first 4^k of which are the cells of a 2^k x 2^k grid, up to
    /// adaptiveMax, stopping when the standard error of its mean (estimated from the spread within
    /// groups of sibling cells, in display units) is below adaptiveTolerance (0: always
    /// adaptiveMax). A refined pixel first traces the samples of round 1 in the quadrants facing
    /// its differing neighbours (2, or 3 for neighbours on two adjacent sides; not where they lie
    /// on opposite sides); where all see the centre's primitive and display value (within
    /// 1/255), the contrast lies in the neighbours' boxes and the pixel keeps its centre (a
    /// "checked" pixel), else the rest of round 1 follows.
    /// A refined pixel is the mean of its stratified samples only; every sample sits in a cell
    /// of the adaptiveMax grid with the position and random stream uniform sampling gives that
    /// cell, so a pixel refined to adaptiveMax is exactly the pixel of `samplesPerPixel =
    /// adaptiveMax`, and the picture converges to uniform sampling's as the threshold and the
    /// tolerance go to 0. Unrefined pixels are exactly those of 1 sample per pixel.
    bool adaptive = false;
    /// Adaptive sampling of Monte Carlo noise rather than of edges (with adaptive): no centre
    /// pass and no probes; every pixel takes the 4 cells of round 1, then rounds of 16, 64 ...
    /// while the standard error of its mean is at or above adaptiveTolerance, with the samples
    /// and the error estimate described above (a pixel refined to adaptiveMax is again the
    /// pixel of `samplesPerPixel = adaptiveMax`). adaptiveThreshold is not used; `render`
    /// takes kAdaptiveNoiseTolerance as the tolerance unless one is given.
    bool adaptiveNoise = false;
    int adaptiveMax = 64;
    double adaptiveThreshold = 0.02;
    /// 0.15: at 0.1, 2.5 % of glass.scad's pixels took 16 samples (against 0.8 %), for a
    /// picture that passed `compare` against uniform 64 either way.
    double adaptiveTolerance = 0.15;
    /// Rows [rowBegin, rowEnd) of the picture only (rowEnd 0: to its last row), as one tile of
    /// a picture rendered in horizontal bands (`render --tile`, tileRows): the result's images
    /// and per-pixel vectors hold those rows (their row 0 is row rowBegin), and every pixel is
    /// bit for bit the pixel the whole picture has. Edge-adaptive sampling also traces the
    /// centres of the rows just above and below the band, which its refinement decisions read.
    int rowBegin = 0;
    int rowEnd = 0;
    /// Called from the calling thread about four times a second with the finished fraction.
    std::function<void(double)> progress;
};

/// Rows [begin, end) of tile `tile` (0-based) of `tiles` horizontal bands of a picture
/// `height` rows high: begin = floor(tile * height / tiles), so bands differ by at most one
/// row and the later ones are the taller. Throws std::invalid_argument unless
/// 0 <= tile < tiles <= height.
std::pair<int, int> tileRows(int tile, int tiles, int height);

struct RenderResult {
    Image image;
    /// Variance of each pixel's mean when batches > 1, else empty.
    Image variance;
    /// Fraction of each pixel's samples whose path met coincident surfaces (a tie), in all
    /// three channels.
    Image ties;
    RayStats stats;
    /// Camera samples traced (adaptive: pass 1 centres plus the refined pixels' samples).
    int64_t samples = 0;
    /// Adaptive renders: pixels by samples, index k = pixels whose value is the mean of
    /// 4^k samples (k = 0: the centre sample only); empty for uniform renders.
    std::vector<int64_t> pixelsBySamples;
    /// Adaptive renders: pixels of pixelsBySamples[0] that were marked for refinement but kept
    /// their centre after the 2 or 3 probe samples they took agreed with it.
    int64_t checkedPixels = 0;
    /// Adaptive renders: each pixel's probe samples where it is a checked pixel, else 0.
    std::vector<uint8_t> pixelChecked;
    /// Adaptive renders: each pixel's k (row by row): the mean of 4^k samples, 0 = its centre.
    std::vector<uint8_t> pixelLevels;
    double seconds = 0;
    /// CPU time of the whole process during the render (all threads): a measure of the work
    /// that other processes on the machine do not inflate as they do `seconds`.
    double cpuSeconds = 0;
    int threads = 0;
};

/// Largest accepted image side and sample count, so absurd sizes fail fast and clearly.
constexpr int kMaxImageSide = 32768;
/// Most pixels a render may have (16384 x 16384, about 9 GiB for its three float images): the
/// same limit as for images read back (compare, check), so every render can be compared.
constexpr int64_t kMaxImagePixels = static_cast<int64_t>(kMaxReadImagePixels);
constexpr int kMaxSamplesPerPixel = 65536;
constexpr int kMaxBatches = 1024;
/// The default adaptiveTolerance of sampling adaptive to Monte Carlo noise: a standard error of
/// 0.02 display units (about 5/255); the edge default (0.15) would leave nearly every pixel at
/// 4 samples.
constexpr double kAdaptiveNoiseTolerance = 0.02;
/// Adaptive refinement goes up to 4^kMaxAdaptiveLevel samples per pixel.
constexpr int kMaxAdaptiveLevel = 6;
constexpr int kMaxAdaptiveSamples = 1 << (2 * kMaxAdaptiveLevel);

/// The mean samples per pixel of a render (camera samples over pixels).
double meanSamplesPerPixel(const RenderResult &r);

/// "adaptive, pixels by samples: 1: 93.1 %, checked: 2.1 %, 4: 3.1 %, 16: 1.5 %, 64: 0.2 %; 1.38
/// per pixel" for an adaptive render (checked: pixels that kept their centre after 2 or 3 probe
/// samples), "16.00 per pixel" for a uniform one.
std::string describeSampling(const RenderResult &r);

/// The 1/255 step of a display value d in [0, 1] as adaptive antialiasing compares them: d * 255
/// rounded half away from zero (as std::lround), 0 for NaN.
uint8_t displayStep(double d);

/// Columns and rows of the stratification grid of n samples: rows is the largest divisor of n
/// not above its square root.
void strataGrid(int n, int &columns, int &rows);

/// Throws std::invalid_argument for bad options (sizes, sample counts).
void validateRenderOptions(const RenderOptions &opts);

RenderResult renderImage(const RenderScene &scene, const RenderOptions &opts);

}  // namespace rt
