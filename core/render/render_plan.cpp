// SPDX-License-Identifier: MIT
#include "core/render/render_plan.h"

#include <sstream>

namespace rt {

namespace {

std::string plural(size_t n, const std::string &one, const std::string &many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

struct MaterialUse {
    size_t used = 0, unused = 0, reflective = 0, transparent = 0, glossy = 0, frosted = 0;
};

MaterialUse materialUse(const RenderScene &scene) {
    MaterialUse u;
    for (size_t i = 0; i < scene.materials().size(); ++i) {
        if (!scene.materialUsed(static_cast<int>(i))) {
            ++u.unused;
            continue;
        }
        const ir::Material &m = scene.materials()[i];
        ++u.used;
        u.reflective += m.finish.hasReflection();
        u.transparent += m.isTransparent();
        u.glossy += m.finish.hasReflection() && m.finish.glossy > 0;
        u.frosted += m.isTransparent() && m.finish.frosted > 0;
    }
    return u;
}

}  // namespace

RenderPlan makePlan(const RenderScene &scene) {
    RenderPlan plan;
    MaterialUse u = materialUse(scene);
    size_t jittered = 0;
    for (const ir::Light &l : scene.lights())
        jittered += l.area && l.areaLight.jitter && !l.shadowless;
    plan.monteCarlo = u.glossy + u.frosted + jittered > 0;
    if (plan.monteCarlo) {
        plan.defaultSamples = 4;
        plan.samplesReason =
            "Monte Carlo effects: 4 samples average their noise (--aa-tolerance: "
            "more samples where the noise is larger)";
    } else {
        plan.defaultSamples = 1;
        plan.adaptive = true;
        plan.samplesReason =
            "every material is sharp and no light is jittered, so a pixel's centre is exact away "
            "from edges, shadow boundaries and textures, and only those get more samples "
            "(--no-aa: 1 per pixel; -s N: N everywhere)";
    }
    return plan;
}

std::string describePlan(const RenderScene &scene, const ir::ImportStats &imported,
                         const RenderPlan &plan, const RenderOptions &render, bool chosen) {
    const CompileStats &st = scene.stats();
    MaterialUse u = materialUse(scene);
    std::ostringstream os;
    os << "plan" << (scene.options().plan ? "" : " (disabled: nothing left out, CSG not pruned)")
       << ":\n";

    // Lights and shadow rays
    size_t shadowless = 0, area = 0;
    for (const ir::Light &l : scene.lights()) {
        shadowless += l.shadowless;
        area += l.area && !l.shadowless;
    }
    size_t casting = scene.lights().size() - shadowless;
    os << "  shadows: ";
    if (scene.lights().empty())
        os << "no lights, no shadow rays\n";
    else {
        os << "rays towards " << casting << " of "
           << plural(scene.lights().size(), "light", "lights");
        if (shadowless) os << " (" << shadowless << " shadowless: none)";
        if (area) os << ", " << plural(area, "area light", "area lights") << " with a grid of rays";
        os << "; none where a light is behind the surface\n";
    }
    os << "  reflection: ";
    if (u.reflective)
        os << u.reflective << " of " << plural(u.used, "material reflects", "materials reflect")
           << (u.glossy ? " (" + std::to_string(u.glossy) + " glossy)" : std::string()) << "\n";
    else
        os << "no material reflects: no reflection rays\n";
    os << "  refraction: ";
    if (u.transparent)
        os << u.transparent << " of " << plural(u.used, "material is", "materials are")
           << " transparent"
           << (u.frosted ? " (" + std::to_string(u.frosted) + " frosted)" : std::string()) << "\n";
    else
        os << "no material is transparent: no refraction or transmission rays\n";
    os << "  Monte Carlo: "
       << (plan.monteCarlo ? "glossy or frosted materials or jittered area lights: distributed rays"
                           : "every material sharp, no jittered light: no distributed rays")
       << "\n";

    // Objects
    os << "  objects: " << plural(st.objects, "solid", "solids") << " kept (" << st.csgObjects
       << " with CSG span merging, " << plural(st.primitives, "primitive", "primitives");
    if (st.triangles) os << ", " << st.triangles << " triangles";
    os << ")";
    if (st.unionsSplit)
        os << "; " << plural(st.unionsSplit, "union", "unions")
           << " of disjoint parts split into separate solids (no span merging)";
    os << "\n  dropped: " << st.behindCamera << " behind the camera";
    if (st.behindCamera)
        os << " (" << plural(st.behindCameraPrimitives, "primitive", "primitives") << ")";
    if (!st.behindCameraKept.empty())
        os << " (some are behind it but kept: " << st.behindCameraKept << ")";
    os << ", " << imported.backgroundParts << " % background parts, " << imported.disabledParts
       << " * disabled parts, " << plural(st.emptyDropped, "empty subtree", "empty subtrees")
       << ", " << plural(u.unused, "unused material", "unused materials") << " (of "
       << scene.materials().size() << ")\n";

    if (imported.facets) os << "  facets: " << imported.facets->describe() << "\n";

    // Acceleration
    os << "  acceleration: ";
    if (st.objects <= 1)
        os << "none (" << plural(st.objects, "solid", "solids") << ")\n";
    else if (st.bvhDepth <= 1)
        os << "one bounding box around " << st.objects
           << " solids, tested in turn (no hierarchy)\n";
    else
        os << "BVH over " << st.objects << " solids, depth " << st.bvhDepth << "\n";
    os << "  CSG pruning: "
       << (scene.options().plan ? "subtrees skipped by bounds and by the empty-operand rules"
                                : "off")
       << "\n";
    os << "  samples: ";
    if (render.adaptive && render.adaptiveNoise)
        os << "adaptive to Monte Carlo noise, every pixel 4, 16 ... up to " << render.adaptiveMax
           << " stratified samples until the standard error is below " << render.adaptiveTolerance;
    else if (render.adaptive)
        os << "adaptive, each pixel's centre; where a neighbour differs by more than "
           << render.adaptiveThreshold
           << " or saw another primitive, first the samples facing it (the centre is kept where"
              " they agree), then 4, 16 ... up to "
           << render.adaptiveMax << " stratified samples until the standard error is below "
           << render.adaptiveTolerance;
    else
        os << render.samplesPerPixel << " per pixel";
    os << (chosen ? " (chosen: " + plan.samplesReason + ")" : std::string(" (given)")) << "\n";
    return os.str();
}

void chooseSampling(const RenderPlan &plan, const SamplingRequest &request, RenderOptions &ro) {
    if (request.samplesGiven) return;
    ro.samplesPerPixel = plan.defaultSamples;
    ro.adaptive = (plan.adaptive || request.adaptiveGiven) && !request.noAdaptive;
    // Monte Carlo scenes: sampling adaptive to their noise, with a tolerance of its own
    ro.adaptiveNoise = ro.adaptive && plan.monteCarlo;
    if (ro.adaptiveNoise && !request.toleranceGiven) ro.adaptiveTolerance = kAdaptiveNoiseTolerance;
}

}  // namespace rt
