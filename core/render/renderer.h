// SPDX-License-Identifier: MIT
// Multi-threaded tile renderer: stratified box-filtered antialiasing with per-pixel seeded
// random streams, so an image is identical for any thread count.
#pragma once

#include <cstdint>
#include <functional>

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
    /// Called from the calling thread about four times a second with the finished fraction.
    std::function<void(double)> progress;
};

struct RenderResult {
    Image image;
    /// Variance of each pixel's mean when batches > 1, else empty.
    Image variance;
    /// Fraction of each pixel's samples whose path met coincident surfaces (a tie), in all
    /// three channels.
    Image ties;
    RayStats stats;
    double seconds = 0;
    int threads = 0;
};

/// Largest accepted image side and sample count, so absurd sizes fail fast and clearly.
constexpr int kMaxImageSide = 32768;
/// Most pixels a render may have (16384 x 16384, about 9 GiB for its three float images): the
/// same limit as for images read back (compare, check), so every render can be compared.
constexpr int64_t kMaxImagePixels = static_cast<int64_t>(kMaxReadImagePixels);
constexpr int kMaxSamplesPerPixel = 65536;
constexpr int kMaxBatches = 1024;

/// Columns and rows of the stratification grid of n samples: rows is the largest divisor of n
/// not above its square root.
void strataGrid(int n, int &columns, int &rows);

/// Throws std::invalid_argument for bad options (sizes, sample counts).
void validateRenderOptions(const RenderOptions &opts);

RenderResult renderImage(const RenderScene &scene, const RenderOptions &opts);

}  // namespace rt
