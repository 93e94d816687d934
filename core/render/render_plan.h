// SPDX-License-Identifier: MIT
// The render plan: what a compiled scene needs (which rays, which machinery) and what was left
// out, worked out once before rendering, with the reasons, for `scadray render --plan`.
#pragma once

#include <string>

#include "core/ir/scene_ir.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"

namespace rt {

struct RenderPlan {
    /// Some effect needs random rays: glossy or frosted materials, jittered area lights.
    bool monteCarlo = false;
    /// Samples per pixel when the user gives none: 1 for a deterministic picture (more samples
    /// would only antialias edges), 4 where Monte Carlo effects average their noise.
    int defaultSamples = 1;
    /// Adaptive antialiasing when the user gives no sample count (sharp scenes): the centre of
    /// each pixel, more samples only where neighbours differ. Monte Carlo scenes keep
    /// defaultSamples everywhere: their noise differs between all neighbours, and sampling
    /// adaptive to noise (RenderOptions::adaptiveNoise, what `--aa-*` options ask for there)
    /// measured no better than uniform sampling at the same mean count (README).
    bool adaptive = false;
    std::string samplesReason;
};

RenderPlan makePlan(const RenderScene &scene);

/// The sampling a caller asked for; whatever it leaves open, the plan decides (chooseSampling).
struct SamplingRequest {
    bool samplesGiven = false;    ///< a uniform count (RenderOptions::samplesPerPixel) was given
    bool adaptiveGiven = false;   ///< an adaptive setting was given: adaptive even where the
                                  ///< plan would sample uniformly
    bool toleranceGiven = false;  ///< RenderOptions::adaptiveTolerance was given
    bool noAdaptive = false;      ///< adaptive antialiasing refused
    /// Whether the plan chose the sampling (for describePlan): nothing about it was given.
    bool planChooses() const { return !samplesGiven && !adaptiveGiven; }
};

/// Fills in the samples per pixel and the adaptive settings of `ro` that `request` leaves
/// open, as the plan says: sharp scenes adaptive from one sample, Monte Carlo scenes a few
/// samples everywhere, or adaptive to their noise with its own tolerance when asked.
void chooseSampling(const RenderPlan &plan, const SamplingRequest &request, RenderOptions &ro);

/// The plan as text, a few lines: features in use and why, objects kept and dropped, the
/// acceleration structure, the sampling of `render` (uniform or adaptive, chosen by the plan
/// when `chosen`).
std::string describePlan(const RenderScene &scene, const ir::ImportStats &imported,
                         const RenderPlan &plan, const RenderOptions &render, bool chosen);

}  // namespace rt
