// SPDX-License-Identifier: MIT
// The render plan: what a compiled scene needs (which rays, which machinery) and what was left
// out, worked out once before rendering, with the reasons, for `scadray render --plan`.
#pragma once

#include <string>

#include "core/ir/scene_ir.h"
#include "core/render/render_scene.h"

namespace rt {

struct RenderPlan {
    /// Some effect needs random rays: glossy or frosted materials, jittered area lights.
    bool monteCarlo = false;
    /// Samples per pixel when the user gives none: 1 for a deterministic picture (more samples
    /// would only antialias edges), 4 where Monte Carlo effects average their noise.
    int defaultSamples = 1;
    std::string samplesReason;
};

RenderPlan makePlan(const RenderScene &scene);

/// The plan as text, a few lines: features in use and why, objects kept and dropped, the
/// acceleration structure, the samples per pixel (`samples`, chosen when `chosen`).
std::string describePlan(const RenderScene &scene, const ir::ImportStats &imported,
                         const RenderPlan &plan, int samples, bool chosen);

}  // namespace rt
