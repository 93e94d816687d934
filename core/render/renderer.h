// SPDX-License-Identifier: MIT
// Multi-threaded tile renderer: stratified box-filtered antialiasing with per-pixel seeded
// random streams, so an image is identical for any thread count.
#pragma once

#include <cstdint>
#include <functional>

#include "core/image/image.h"
#include "core/render/ray_stats.h"
#include "core/render/render_scene.h"

namespace rt {

struct RenderOptions {
    int width = 640;
    int height = 480;
    /// Samples per pixel; a perfect square k*k, stratified on a k x k grid. 1 means the pixel
    /// centre exactly, as POV-Ray without antialiasing.
    int samplesPerPixel = 1;
    uint64_t seed = 0;
    /// Worker threads; 0 = every hardware thread.
    int threads = 0;
    int tileSize = 16;
    /// Called from the calling thread about four times a second with the finished fraction.
    std::function<void(double)> progress;
};

struct RenderResult {
    Image image;
    RayStats stats;
    double seconds = 0;
    int threads = 0;
};

/// Largest accepted image side and sample count, so absurd sizes fail fast and clearly.
constexpr int kMaxImageSide = 32768;
constexpr int kMaxSamplesPerPixel = 65536;

/// Throws std::invalid_argument for bad options (sizes, non-square sample counts).
void validateRenderOptions(const RenderOptions &opts);

RenderResult renderImage(const RenderScene &scene, const RenderOptions &opts);

}  // namespace rt
