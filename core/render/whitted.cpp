// SPDX-License-Identifier: MIT
// POV-Ray-compatible Whitted integrator.
#include "core/render/whitted.h"

#include <cmath>

#include "core/lights/area_light.h"
#include "core/materials/classic_shading.h"
#include "core/materials/lobe_sampling.h"
#include "core/materials/pbr_material.h"
#include "core/materials/texture_sampler.h"
#include "core/render/environment.h"

namespace rt {

namespace {

/// Shadow rays stop this fraction of the light distance short of the light, so a light placed
/// on a surface does not shadow itself (scale-free form of POV-Ray's SHADOW_TOLERANCE).
constexpr double kShadowEpsilon = 1e-9;

Rgb powRgb(const Rgb &c, double e) {
    return {std::pow(c.r, e), std::pow(c.g, e), std::pow(c.b, e)};
}

/// POV-Ray's cubic_spline (lighting/point.cpp): 0 below low, 1 above high, smooth between.
double cubicSpline(double low, double high, double x) {
    if (x < low) return 0;
    if (x >= high) return 1;
    double p = (x - low) / (high - low);
    return (3 - 2 * p) * p * p;
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const RenderScene &scene, const Vec3 &cameraPosition)
    : scene_(scene) {
    // POV-Ray's InitRayContainerState: camera rays start inside every solid holding the camera
    for (const auto &o : scene.objects())
        if (o->inside(cameraPosition)) cameraStack_.push(o.get());
    for (const ir::Light &l : scene.lights()) {
        areaWeights_.emplace_back(l.areaLight);
        LightConstants k;
        k.axis = normalize(l.direction);
        k.cosRadius = std::cos(radians(l.spotRadius));
        k.cosFalloff = std::cos(radians(l.spotFalloff));
        lightConstants_.push_back(k);
    }
}

Rgb WhittedIntegrator::li(const Ray &cameraRay, TraceContext &ctx) const {
    ++ctx.stats.camera;
    Rgb c = trace(cameraRay, 0, 1.0, cameraStack_, false, false, ctx);
    if (!c.isFinite()) {
        ++ctx.stats.nonFinite;
        return Rgb(0);
    }
    return c;
}

Rgb WhittedIntegrator::trace(const Ray &ray, int level, double weight, const InteriorStack &stack,
                             bool continued, bool blurred, TraceContext &ctx) const {
    const ir::Settings &s = scene_.settings();
    if (level >= s.maxTraceLevel || weight < s.adcBailout) return Rgb(0);
    // A camera ray looks up the leaves it can meet (VistaLists::find checks that it is one).
    // The hit first, its surface only where there is one: RenderScene::intersect's
    // SurfaceInteraction would be zeroed (232 bytes, a `rep stos`) on every ray, hit or not
    RenderScene::Hit hit;
    bool found = scene_.closestHit(ray, 0, kInfinity, &hit, ctx.scratch,
                                   level == 0 ? scene_.vista() : nullptr);
    ctx.tie = ctx.tie || hit.tie;
    if (level == 0) ctx.firstHit = found ? hit.crossing.leaf : nullptr;  // the camera ray
    if (!found) return missRadiance(s, ray.d);  // the background or the environment
    return shade(ray, scene_.surfaceAt(ray, hit), continued ? level : level + 1, weight, stack,
                 blurred, ctx);
}

double WhittedIntegrator::relativeIor(const Shape *object, const InteriorStack &stack) const {
    double iorX = interiorOf(object).ior;
    if (stack.empty()) return iorX;
    if (stack.contains(object)) {
        if (stack.size() == 1) return 1 / iorX;
        return interiorOf(stack.top()).ior / iorX;
    }
    return iorX / interiorOf(stack.top()).ior;
}

Rgb WhittedIntegrator::shade(const Ray &ray, const SurfaceInteraction &si, int level, double weight,
                             const InteriorStack &stack, bool blurred, TraceContext &ctx) const {
    int materialIndex = si.leaf->material();
    const ir::Material &stored = scene_.material(materialIndex);
    // A glTF material with per-texel textures: its classic material and normal at this texel
    // (in a branch of its own: an empty std::optional of it would be zeroed, 400 bytes, on
    // every shade)
    if (stored.texel.pbr) {
        TexelShading texel = shadeTexel(stored, scene_.texelImages(materialIndex), si, ray.d);
        // Cut out (alpha MASK): the ray goes on as if the surface were not there
        if (texel.cutOut)
            return trace(spawnRay(si, ray.d), level, weight, stack, true, blurred, ctx);
        // A texel's colour has its textures in
        return shadeWith(ray, si, texel.material, texel.normal, texel.material.color, level, weight,
                         stack, blurred, ctx);
    }
    return shadeWith(ray, si, stored, si.ns, surfaceColour(stored, si), level, weight, stack,
                     blurred, ctx);
}

Rgb WhittedIntegrator::shadeWith(const Ray &ray, const SurfaceInteraction &si,
                                 const ir::Material &m, const Vec3 &ns, const Rgb &c, int level,
                                 double weight, const InteriorStack &stack, bool blurred,
                                 TraceContext &ctx) const {
    const ir::Finish &f = m.finish;
    const ir::Settings &settings = scene_.settings();
    // Shading normal (a smooth mesh's interpolated one, or the normal map's) faces the ray
    Vec3 N = dot(ns, ray.d) > 0 ? -ns : ns;
    double cosI = -dot(ray.d, N);

    Rgb colour = localColour(ray, si, N, m, c, stack, blurred, ctx);

    Reflectivity refl = reflectivity(f, cosI, f.fresnel ? relativeIor(si.object, stack) : 1);
    Rgb filCol = c * m.filter + Rgb(m.transmit);
    if (f.conserveEnergy)
        for (int i = 0; i < 3; ++i) filCol[i] *= std::min(1.0, 1 - refl.value[i]);
    double trans = std::min(1.0, std::abs(povGreyscale(filCol)));

    // The mirror direction only where a ray takes it (its square root and divisions would
    // hold up every opaque, non-reflecting hit's return)
    auto reflectDirection = [&] { return normalize(ray.d + N * (2 * cosI)); };
    bool tir = false;
    if (trans > settings.adcBailout) {
        double w = weight * std::max({std::abs(filCol.r), std::abs(filCol.g), std::abs(filCol.b)});
        const Shape *x = si.object;
        // Relative ior and the interior list beyond the surface (POV-Ray ComputeRefraction)
        InteriorStack next = stack;
        double eta;
        if (stack.empty()) {
            if (!next.push(x)) ++ctx.stats.interiorOverflow;
            eta = 1 / interiorOf(x).ior;
        } else if (stack.top() == x) {
            next.remove(x);
            eta = interiorOf(x).ior / (next.empty() ? 1.0 : interiorOf(next.top()).ior);
        } else if (next.remove(x)) {
            eta = 1;  // leaving the overlap of two solids
        } else {
            eta = interiorOf(stack.top()).ior / interiorOf(x).ior;
            if (!next.push(x)) ++ctx.stats.interiorOverflow;
        }
        Rgb transmitted;
        if (std::abs(eta - 1) < kPovEpsilon) {
            // Same medium on both sides: continue straight on without using a trace level
            ++ctx.stats.transmission;
            transmitted = trace(spawnRay(si, ray.d), level, w, next, true, blurred, ctx);
        } else {
            // Heckbert's refraction; N faces the ray so n = cos of incidence
            double n = cosI;
            double t = 1 + eta * eta * (n * n - 1);
            // A frosted surface spreads the refracted (or totally reflected) ray over its lobe,
            // keeping each ray on the side the sharp one goes to
            Vec3 dir = ray.d * eta + N * (eta * n - std::sqrt(std::max(t, 0.0)));
            tir = t < 0;
            const InteriorStack &beyond = tir ? stack : next;
            Vec3 centre = tir ? reflectDirection() : dir, side = tir ? N : -N;
            auto traceOne = [&](const Vec3 &d) {
                return trace(spawnRay(si, d), level, w, beyond, false, true, ctx);
            };
            if (f.frosted > 0) {
                transmitted = distribute(f, f.frosted, centre, side, blurred, ctx, traceOne);
            } else {
                ++(tir ? ctx.stats.internalReflection : ctx.stats.refraction);
                transmitted = trace(spawnRay(si, centre), level, w, beyond, false, blurred, ctx);
            }
        }
        // Light leaving a medium the ray was inside fades with the distance travelled
        Rgb att(1);
        if (stack.contains(x)) att = interiorFade(interiorOf(x), si.t, false);
        colour += tir ? att * transmitted : att * transmitted * filCol;
    }
    if (!tir && !refl.value.isBlack()) {
        double w = weight * refl.weightScale;
        auto traceOne = [&](const Vec3 &d) {
            Rgb r = trace(spawnRay(si, d), level, w, stack, false, true, ctx);
            return f.reflectionExponent != 1 ? powRgb(r, 1 / f.reflectionExponent) : r;
        };
        Rgb r;
        Vec3 reflectDir = reflectDirection();
        if (f.glossy > 0) {
            r = distribute(f, f.glossy, reflectDir, N, blurred, ctx, traceOne);
        } else {
            ++ctx.stats.reflection;
            r = trace(spawnRay(si, reflectDir), level, w, stack, false, blurred, ctx);
            if (f.reflectionExponent != 1) r = powRgb(r, 1 / f.reflectionExponent);
        }
        colour += refl.value * r;
    }
    return colour;
}

template <typename TraceOne>
Rgb WhittedIntegrator::distribute(const ir::Finish &f, double spreadDegrees, const Vec3 &centre,
                                  const Vec3 &side, bool blurred, TraceContext &ctx,
                                  TraceOne traceOne) const {
    Lobe lobe(f.blurLobe == ir::Finish::Lobe::Phong ? LobeShape::Phong : LobeShape::Normal,
              radians(spreadDegrees));
    int n = blurred ? 1 : f.blurSamples;
    // Rank-1 lattice with a Fibonacci-like generator, shifted by a random vector (Cranley-
    // Patterson rotation): every point is uniform on its own, so the mean is unbiased, and
    // the n points are stratified in both dimensions
    int g = latticeGenerator(n);
    double shift1 = ctx.rng.uniform(), shift2 = ctx.rng.uniform();
    Rgb sum(0);
    for (int i = 0; i < n; ++i) {
        double u1 = double(i) / n + shift1, u2 = double((int64_t(i) * g) % n) / n + shift2;
        u1 -= std::floor(u1);
        u2 -= std::floor(u2);
        ++ctx.stats.distributed;
        sum += traceOne(sampleLobeAbout(lobe, centre, side, u1, u2));
    }
    return sum * (1.0 / n);
}

Rgb WhittedIntegrator::surfaceColour(const ir::Material &m, const SurfaceInteraction &si) const {
    Rgb c = m.color;
    // glTF COLOR_0 multiplies the base colour (and its texture)
    if (si.hasVertexColor) c *= Rgb(si.vertexColor[0], si.vertexColor[1], si.vertexColor[2]);
    const ir::Texture *tex = scene_.texture(m.baseColorTexture.texture);
    float t[4];
    if (!tex || !sampleTexture(*tex, m.baseColorTexture, si, t)) return c;
    return c * Rgb(t[0], t[1], t[2]);
}

Rgb WhittedIntegrator::localColour(const Ray &ray, const SurfaceInteraction &si, const Vec3 &N,
                                   const ir::Material &m, const Rgb &c, const InteriorStack &stack,
                                   bool blurred, TraceContext &ctx) const {
    const ir::Finish &f = m.finish;
    double a = 1 - m.filter - m.transmit;  // opacity
    Rgb colour = c * a * (scene_.settings().ambientLight * f.ambient + f.emission);
    if (f.diffuse == 0 && f.phong == 0 && f.specular == 0) return colour;

    for (size_t li = 0; li < scene_.lights().size(); ++li) {
        const ir::Light &light = scene_.lights()[li];
        // Direction to the light and the distance a shadow ray covers (POV-Ray measures a
        // parallel light's distance along the beam, to the plane through its position)
        Vec3 L;
        double dist;
        if (light.kind == ir::Light::Kind::Directional) {
            L = -lightConstants_[li].axis;
            dist = dot(light.position - si.p, L);
        } else {
            Vec3 toLight = light.position - si.p;
            dist = length(toLight);
            if (!(dist > 0)) continue;
            L = toLight / dist;
        }
        // A light behind the surface, as seen from the viewer, does nothing. Nor does one
        // whose highlight POV-Ray's test leaves out on a surface with no diffuse or specular
        // term (clear glass with a phong highlight): the phong cosine is known before the
        // shadow ray. Neither gets a shadow ray from the plan, nor does a shadowless light;
        // but a shadow ray that would draw from the pixel's random numbers (a jittered area
        // light, or a blurred split's one-ray shadow) is cast, so that they stay the same.
        // Without the plan (--no-plan, to measure what it saves) a shadow ray goes to every
        // light, as in a naive ray tracer, and its answer is thrown away.
        double cosNL = dot(N, L);
        bool shows = cosNL >= kPovEpsilon;
        bool phongLit = false;
        double phongK = 0;
        if (shows && f.phong > 0) {
            Vec3 r = ray.d - N * (2 * dot(ray.d, N));
            phongK = dot(r, L);
            // POV-Ray skips tiny phong terms of tight highlights
            phongLit = phongK > 0 && !(f.phongSize >= 60 && phongK <= 0.0008);
        }
        if (shows && f.diffuse == 0 && f.specular == 0 && !phongLit)
            shows = drawsRandomNumbers(li, blurred);
        if (!scene_.options().plan && (!shows || light.shadowless) && dist > 0) {
            bool tie = ctx.tie;  // nor may it mark the pixel
            (void)shadowFilter(si, L, dist, stack, ctx);
            ctx.tie = tie;
        }
        if (!shows) continue;
        Rgb lc = light.color * lightAttenuation(li, L, dist);
        if (!light.shadowless && dist > 0)
            lc = light.area ? areaShadow(si, li, lc, stack, blurred, ctx)
                            : lc * shadowFilter(si, L, dist, stack, ctx);
        if (!(std::abs(lc.r) > kPovEpsilon || std::abs(lc.g) > kPovEpsilon ||
              std::abs(lc.b) > kPovEpsilon))
            continue;
        if (f.diffuse != 0) {
            double intensity = f.brilliance != 1 ? std::pow(cosNL, f.brilliance) : cosNL;
            colour += c * lc * (f.diffuse * a * intensity);
        }
        if (light.shadowless) continue;  // fill lights give no highlights
        Rgb hc = highlightColour(f, lc, c, cosNL);
        if (phongLit) colour += hc * (f.phong * std::pow(phongK, f.phongSize));
        if (f.specular > 0) {
            Vec3 h = (L - ray.d) * 0.5;
            double hl = length(h);
            double k = hl > 0 ? dot(h, N) / hl : 0;
            if (k > 0) colour += hc * (f.specular * std::pow(k, 1 / f.roughness));
        }
    }
    return colour;
}

double WhittedIntegrator::lightAttenuation(size_t index, const Vec3 &L, double dist) const {
    const ir::Light &light = scene_.lights()[index];
    const LightConstants &k = lightConstants_[index];
    double att = 1;
    if (light.kind == ir::Light::Kind::Spot) {
        // POV-Ray Attenuate_Light: cos^tightness, then a cubic spline from the falloff cone
        // (0) to the radius cone (1)
        double cosTheta = dot(-L, k.axis);
        if (!(cosTheta > 0)) return 0;
        att = std::pow(cosTheta, light.spotTightness);
        if (k.cosRadius > 0 && cosTheta < k.cosRadius)
            att *= cubicSpline(k.cosFalloff, k.cosRadius, cosTheta);
    }
    return att * lightFade(light, dist);
}

bool WhittedIntegrator::drawsRandomNumbers(size_t index, bool blurred) const {
    const ir::Light &light = scene_.lights()[index];
    return light.area && (light.areaLight.jitter || (blurred && areaWeights_[index].fixed()));
}

Rgb WhittedIntegrator::areaShadow(const SurfaceInteraction &si, size_t index, const Rgb &lc,
                                  const InteriorStack &stack, bool blurred,
                                  TraceContext &ctx) const {
    const ir::Light &light = scene_.lights()[index];
    AreaLightSampler grid(light, si.p, ctx.rng);
    auto arriving = [&](const Vec3 &target) {
        Vec3 toTarget = target - si.p;
        double d = length(toTarget);
        if (!(d > 0)) return lc;
        return lc * shadowFilter(si, toTarget / d, d, stack, ctx);
    };
    const AreaLightWeights &weights = areaWeights_[index];
    if (blurred && weights.fixed()) {
        int u, v;
        weights.pick(ctx.rng.uniform(), u, v);
        return arriving(grid.gridTarget(u, v));
    }
    return grid.average(arriving);
}

Rgb WhittedIntegrator::shadowFilter(const SurfaceInteraction &si, const Vec3 &L, double dist,
                                    const InteriorStack &stack, TraceContext &ctx) const {
    Rgb filter(1);
    // The interior list is copied only at the first transparent crossing: most shadow rays
    // end at an opaque blocker or reach the light (and an empty std::optional of it would be
    // zeroed, 272 bytes, on every shadow ray)
    InteriorStack inside;
    bool copied = false;
    Ray ray = spawnRay(si, L);
    double remaining = (dist - dot(ray.o - si.p, L)) * (1 - kShadowEpsilon);
    // March from surface to surface towards the light, filtering at each crossing
    while (true) {
        ++ctx.stats.shadow;
        RenderScene::Hit blocker;
        bool blocked = scene_.closestHit(ray, 0, remaining, &blocker, ctx.scratch);
        ctx.tie = ctx.tie || blocker.tie;
        if (!blocked) return filter;
        // An opaque blocker settles it; only a transparent one needs its surface
        int materialIndex = blocker.crossing.leaf->material();
        const ir::Material &m = scene_.material(materialIndex);
        if (blocker.object->opaque || !m.isTransparent()) return Rgb(0);
        SurfaceInteraction hit = scene_.surfaceAt(ray, blocker);
        bool cutOut = false;
        if (m.texel.pbr) {
            TexelShading t = shadeTexel(m, scene_.texelImages(materialIndex), hit, ray.d, false);
            cutOut = t.cutOut;  // alpha MASK: passes untouched, entering or leaving nothing
            if (!cutOut) filter *= t.material.color * t.material.filter + Rgb(t.material.transmit);
        } else {
            filter *= surfaceColour(m, hit) * m.filter + Rgb(m.transmit);
        }
        // The shadow ray starts with the interior list of the ray that hit the shaded point; at
        // each crossing light fades over the segment inside that solid, then the crossing
        // enters or leaves it (POV-Ray ComputeShadowTexture, ComputeShadowMedia)
        if (!copied) {
            inside = stack;
            copied = true;
        }
        if (cutOut) {
        } else if (inside.contains(hit.object)) {
            filter *= interiorFade(interiorOf(hit.object), hit.t, true);
            inside.remove(hit.object);
        } else if (!inside.push(hit.object)) {
            ++ctx.stats.interiorOverflow;
        }
        if (filter.isBlack()) return filter;
        remaining -= hit.t;
        ray = spawnRay(hit, ray.d);
        remaining -= length(ray.o - hit.p);
        if (!(remaining > 0)) return filter;
    }
}

}  // namespace rt
