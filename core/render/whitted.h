// SPDX-License-Identifier: MIT
// Whitted-style recursive ray tracer with POV-Ray 3.7's classic shading, shadows through
// transparent solids, reflection, refraction and total internal reflection, exactly as
// docs/design/povray-semantics.md sets them out (sections 3 to 6).
#pragma once

#include <vector>

#include "core/geometry/shape.h"
#include "core/lights/area_light.h"
#include "core/math/rng.h"
#include "core/render/interior_stack.h"
#include "core/render/ray_stats.h"
#include "core/render/render_scene.h"

namespace rt {

/// Per-thread state of a trace.
struct TraceContext {
    RayStats stats;
    SpanScratch scratch;
    /// Set when the current sample's path met a tie (coincident surfaces); the renderer clears
    /// it per sample and reports the fraction of such samples per pixel.
    bool tie = false;
    /// Primitive (or mesh) the current sample's camera ray hit, null for the background: the
    /// adaptive renderer refines pixels whose neighbours saw another primitive.
    const LeafShape *firstHit = nullptr;
    /// The current sample's random stream (pixel jitter, then every distributed ray of its
    /// path), seeded by pixel, sample and user seed so a render is the same on any thread count.
    Rng rng;
};

class WhittedIntegrator {
  public:
    /// `cameraPosition` decides which solids a camera ray starts inside.
    WhittedIntegrator(const RenderScene &scene, const Vec3 &cameraPosition);

    /// Radiance along a camera ray.
    Rgb li(const Ray &cameraRay, TraceContext &ctx) const;

  private:
    /// POV-Ray's TraceRay: `level` is the trace level of the ray's parent hit; rays beyond
    /// max_trace_level or below adc_bailout weight return black. Continued rays (through a
    /// surface with no change of ior) do not count a level.
    /// `blurred` is set below a glossy or frosted split: later blurred surfaces of the path
    /// send one distributed ray each instead of a fan.
    Rgb trace(const Ray &ray, int level, double weight, const InteriorStack &stack, bool continued,
              bool blurred, TraceContext &ctx) const;
    Rgb shade(const Ray &ray, const SurfaceInteraction &si, int level, double weight,
              const InteriorStack &stack, bool blurred, TraceContext &ctx) const;
    /// Mean of `traceOne(direction)` over a fan of directions spread by `lobe` about `centre`
    /// and kept on the side `side` points to: blurSamples rays (a randomly shifted rank-1
    /// lattice, stratified in both dimensions) at a path's first blurred surface, one after it.
    template <typename TraceOne>
    Rgb distribute(const ir::Finish &f, double spreadDegrees, const Vec3 &centre, const Vec3 &side,
                   bool blurred, TraceContext &ctx, TraceOne traceOne) const;
    /// Ambient, emission and the sum over lights of diffuse, phong and specular; `c` is the
    /// pigment colour at the hit.
    Rgb localColour(const Ray &ray, const SurfaceInteraction &si, const Vec3 &N,
                    const ir::Material &m, const Rgb &c, const InteriorStack &stack, bool blurred,
                    TraceContext &ctx) const;
    /// Pigment colour at a hit: the material's colour times its texture, if any.
    Rgb surfaceColour(const ir::Material &m, const SurfaceInteraction &si) const;
    /// Spotlight cone and fade of light `index` seen in direction L at shadow distance dist.
    double lightAttenuation(size_t index, const Vec3 &L, double dist) const;
    /// shade() with the material, shading normal and colour at the hit resolved (a glTF
    /// material's at its texel).
    Rgb shadeWith(const Ray &ray, const SurfaceInteraction &si, const ir::Material &m,
                  const Vec3 &ns, const Rgb &c, int level, double weight,
                  const InteriorStack &stack, bool blurred, TraceContext &ctx) const;
    /// Filtered light reaching si from the direction L over distance dist (1 = unoccluded),
    /// docs/design/povray-semantics.md section 4. `stack` is the interior list of the ray that
    /// hit si.
    Rgb shadowFilter(const SurfaceInteraction &si, const Vec3 &L, double dist,
                     const InteriorStack &stack, TraceContext &ctx) const;
    /// Light colour `lc` arriving at si from area light `index`: POV-Ray's averaged grid of
    /// shadow rays (docs/design/povray-semantics.md section 5). Below a blurred split, where
    /// the path is one of a fan whose mean is taken, a light with fixed grid weights sends one
    /// shadow ray to a grid point drawn by weight instead: the same expectation for a fraction
    /// of the rays.
    Rgb areaShadow(const SurfaceInteraction &si, size_t index, const Rgb &lc,
                   const InteriorStack &stack, bool blurred, TraceContext &ctx) const;
    /// Whether light `index`'s shadow rays at a hit take random numbers from the pixel's
    /// stream (a jittered area light, or one-ray area shadows below a blurred split).
    bool drawsRandomNumbers(size_t index, bool blurred) const;
    /// n_transmitted / n_incident at a surface of `object`, as POV-Ray's ComputeRelativeIOR.
    double relativeIor(const Shape *object, const InteriorStack &stack) const;
    const ir::Interior &interiorOf(const Shape *object) const {
        return scene_.material(object->interiorMaterial).interior;
    }

    const RenderScene &scene_;
    InteriorStack cameraStack_;
    /// POV-Ray's grid weights of each light (trivial for point lights), for one-ray shadows
    std::vector<AreaLightWeights> areaWeights_;
    /// What every hit would otherwise recompute per light
    struct LightConstants {
        Vec3 axis;  ///< unit direction the light shines in (parallel and spot lights)
        double cosRadius = 1, cosFalloff = 1;  ///< spot cones
    };
    std::vector<LightConstants> lightConstants_;
};

}  // namespace rt
