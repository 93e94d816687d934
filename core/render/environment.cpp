// SPDX-License-Identifier: MIT
// Environment lookup for rays that leave the scene.
#include "core/render/environment.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/materials/texture_sampler.h"
#include "core/math/float_util.h"

namespace rt {

namespace {

Rgb gradientAt(const std::vector<ir::GradientStop> &stops, double z) {
    if (stops.empty()) return Rgb(0);
    if (z <= stops.front().z) return stops.front().color;
    for (size_t i = 1; i < stops.size(); ++i) {
        if (z <= stops[i].z) {
            const ir::GradientStop &a = stops[i - 1], &b = stops[i];
            double t = (z - a.z) / (b.z - a.z);
            return a.color * (1 - t) + b.color * t;
        }
    }
    return stops.back().color;
}

}  // namespace

void environmentUv(double rotateDegrees, const Vec3 &d, double *u, double *v) {
    double len = length(d);
    Vec3 n = len > 0 ? d / len : Vec3(0, 0, 1);
    if (rotateDegrees != 0) {
        double a = radians(-rotateDegrees), c = std::cos(a), s = std::sin(a);
        n = Vec3(c * n.x - s * n.y, s * n.x + c * n.y, n.z);
    }
    // POV-Ray's spherical map (map_type 1) with its pole turned from +y to +Z: the angle round
    // the pole runs from +X towards -Y, the height is asin(z)
    double h = std::sqrt(n.x * n.x + n.y * n.y);
    double theta = 0;
    if (h > 0) {
        theta = std::acos(std::clamp(n.x / h, -1.0, 1.0));
        if (n.y > 0) theta = 2 * kPi - theta;
    }
    *u = theta / (2 * kPi);
    *v = 0.5 - std::asin(std::clamp(n.z, -1.0, 1.0)) / kPi;
}

Rgb environmentRadiance(const ir::Environment &env, const Vec3 &d) {
    switch (env.kind) {
        case ir::EnvironmentKind::None:
            return Rgb(0);
        case ir::EnvironmentKind::Gradient: {
            double len = length(d);
            return gradientAt(env.gradient, len > 0 ? d.z / len : 1);
        }
        case ir::EnvironmentKind::Image: {
            if (!env.image) return Rgb(0);
            double u, v;
            environmentUv(env.rotateDegrees, d, &u, &v);
            return sampleTexture(*env.image, u, v);
        }
    }
    return Rgb(0);
}

Rgb environmentMean(const ir::Environment &env) {
    switch (env.kind) {
        case ir::EnvironmentKind::None:
            return Rgb(0);
        case ir::EnvironmentKind::Gradient: {
            // Directions are uniform in z over the sphere (Archimedes), so the mean is the
            // integral of the piecewise-linear gradient over [-1, 1], halved
            Rgb sum(0);
            const auto &g = env.gradient;
            for (size_t i = 1; i < g.size(); ++i)
                sum += (g[i - 1].color + g[i].color) * (0.5 * (g[i].z - g[i - 1].z));
            return sum * 0.5;
        }
        case ir::EnvironmentKind::Image: {
            if (!env.image || env.image->width <= 0) return Rgb(0);
            const ir::Texture &t = *env.image;
            Rgb sum(0);
            double weight = 0;
            for (int y = 0; y < t.height; ++y) {
                double w = std::sin(kPi * (y + 0.5) / t.height);  // the row's solid angle
                for (int x = 0; x < t.width; ++x) {
                    const float *p = &t.rgba[4 * (size_t(y) * t.width + x)];
                    sum += Rgb(p[0], p[1], p[2]) * w;
                }
                weight += w * t.width;
            }
            return sum * (1 / weight);
        }
    }
    return Rgb(0);
}

}  // namespace rt
