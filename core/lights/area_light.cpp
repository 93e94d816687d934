// SPDX-License-Identifier: MIT
// Area light grid and its recursive average.
#include "core/lights/area_light.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

/// POV-Ray's threshold on |dr| + |dg| + |db| between neighbouring corners that forces a split
/// below the adaptive level.
constexpr double kAdaptiveColourDistance = 0.1;

/// An `orient` light whose direction is within this of vertical builds its grid about the y
/// axis instead of z (POV-Ray's TraceAreaLightShadowRay).
constexpr double kOrientVerticalTolerance = 0.01;

/// POV-Ray's circular mapping nudges grid coordinates by this so the centre point of an odd
/// grid is not 0/0.
constexpr double kCircularNudge = 0.001;

double colourDistance(const Rgb &a, const Rgb &b) {
    return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

}  // namespace

AreaLightSampler::AreaLightSampler(const ir::Light &light, const Vec3 &shadedPoint, Rng &rng)
    : light_(light), rng_(rng), axis1_(light.areaLight.axis1), axis2_(light.areaLight.axis2) {
    const ir::Light::Area &a = light.areaLight;
    if (a.orient) {
        // Face the shaded point: both axes square to the direction towards the light and as
        // long as axis1
        Vec3 d = light.position - shadedPoint;
        double len = length(d);
        if (len > 0) {
            d = d / len;
            Vec3 up = std::abs(std::abs(d.z) - 1) < kOrientVerticalTolerance ? Vec3(0, 1, 0)
                                                                             : Vec3(0, 0, 1);
            double size = length(a.axis1);
            axis1_ = normalize(cross(d, up));
            axis2_ = normalize(cross(d, axis1_)) * size;
            axis1_ = axis1_ * size;
        }
    }
}

Vec3 AreaLightSampler::gridTarget(int u, int v) {
    const ir::Light::Area &a = light_.areaLight;
    double ju = u, jv = v;
    if (a.jitter) {
        ju += rng_.uniform() - 0.5;
        jv += rng_.uniform() - 0.5;
    }
    double s1 = 0, s2 = 0;
    if (a.circular || a.orient) {
        // Square onto disc: scale by the max-norm over the 2-norm (needs n >= 2 on both axes)
        s1 = ju / (a.n1 - 1) - 0.5 + kCircularNudge;
        s2 = jv / (a.n2 - 1) - 0.5 + kCircularNudge;
        double scale = std::max(std::abs(s1), std::abs(s2)) / std::hypot(s1, s2);
        s1 *= scale;
        s2 *= scale;
    } else {
        if (a.n1 > 1) s1 = ju / (a.n1 - 1) - 0.5;
        if (a.n2 > 1) s2 = jv / (a.n2 - 1) - 0.5;
    }
    return light_.position + axis1_ * s1 + axis2_ * s2;
}

Rgb AreaLightSampler::corner(int u, int v, const std::function<Rgb(const Vec3 &)> &sample) {
    size_t i = size_t(u) * light_.areaLight.n2 + v;
    if (!done_[i]) {
        grid_[i] = sample(gridTarget(u, v));
        done_[i] = 1;
        ++evaluated_;
    }
    return grid_[i];
}

Rgb AreaLightSampler::region(int u1, int v1, int u2, int v2, int level,
                             const std::function<Rgb(const Vec3 &)> &sample) {
    Rgb c00 = corner(u1, v1, sample), c10 = corner(u2, v1, sample);
    Rgb c01 = corner(u1, v2, sample), c11 = corner(u2, v2, sample);
    if ((u2 - u1 > 1 || v2 - v1 > 1) &&
        (level < light_.areaLight.adaptive || colourDistance(c00, c10) > kAdaptiveColourDistance ||
         colourDistance(c10, c11) > kAdaptiveColourDistance ||
         colourDistance(c11, c01) > kAdaptiveColourDistance ||
         colourDistance(c01, c00) > kAdaptiveColourDistance)) {
        // Quadrants share the middle row or column when the region spans an even count
        int uLo = (u1 + u2) / 2, uHi = (u1 + u2 + 1) / 2;
        int vLo = (v1 + v2) / 2, vHi = (v1 + v2 + 1) / 2;
        return (region(u1, v1, uLo, vLo, level + 1, sample) +
                region(uHi, v1, u2, vLo, level + 1, sample) +
                region(u1, vHi, uLo, v2, level + 1, sample) +
                region(uHi, vHi, u2, v2, level + 1, sample)) *
               0.25;
    }
    return (c00 + c10 + c01 + c11) * 0.25;
}

Rgb AreaLightSampler::average(const std::function<Rgb(const Vec3 &)> &sample) {
    const ir::Light::Area &a = light_.areaLight;
    // The cache of grid samples is needed only here (a one-ray shadow uses gridTarget alone)
    grid_.resize(size_t(a.n1) * a.n2);
    done_.assign(grid_.size(), 0);
    evaluated_ = 0;
    return region(0, 0, a.n1 - 1, a.n2 - 1, 0, sample);
}

AreaLightWeights::AreaLightWeights(const ir::Light::Area &area)
    : n1_(area.n1), n2_(area.n2), adaptive_(area.adaptive) {
    weights_.assign(size_t(n1_) * n2_, 0);
    region(0, 0, n1_ - 1, n2_ - 1, 0, 1);
    if (adapts_) {
        weights_.clear();
        return;
    }
    cdf_.resize(weights_.size());
    double sum = 0;
    for (size_t i = 0; i < weights_.size(); ++i) cdf_[i] = sum += weights_[i];
    for (double &c : cdf_) c /= sum;  // sum is 1 up to rounding
}

void AreaLightWeights::region(int u1, int v1, int u2, int v2, int level, double w) {
    if (u2 - u1 > 1 || v2 - v1 > 1) {
        // Beyond the adaptive level the split depends on the sample values
        if (level >= adaptive_) {
            adapts_ = true;
            return;
        }
        int uLo = (u1 + u2) / 2, uHi = (u1 + u2 + 1) / 2;
        int vLo = (v1 + v2) / 2, vHi = (v1 + v2 + 1) / 2;
        region(u1, v1, uLo, vLo, level + 1, w / 4);
        region(uHi, v1, u2, vLo, level + 1, w / 4);
        region(u1, vHi, uLo, v2, level + 1, w / 4);
        region(uHi, vHi, u2, v2, level + 1, w / 4);
        return;
    }
    for (auto [u, v] : {std::pair{u1, v1}, {u2, v1}, {u1, v2}, {u2, v2}})
        weights_[size_t(u) * n2_ + v] += w / 4;
}

double AreaLightWeights::weight(int u, int v) const {
    return weights_.empty() ? 0 : weights_[size_t(u) * n2_ + v];
}

void AreaLightWeights::pick(double u, int &gu, int &gv) const {
    size_t i = std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin();
    i = std::min(i, cdf_.size() - 1);
    // Skip zero-weight points a rounding tie might land on
    while (weights_[i] == 0 && i + 1 < cdf_.size()) ++i;
    gu = static_cast<int>(i / n2_);
    gv = static_cast<int>(i % n2_);
}

}  // namespace rt
