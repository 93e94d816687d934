// SPDX-License-Identifier: MIT
// POV-Ray-compatible bilinear image-map lookup.
#include "core/materials/texture_sampler.h"

#include <cmath>

namespace rt {

namespace {

/// POV-Ray's EPSILON, added to image coordinates before wrapping (map_pos).
constexpr double kPovEpsilon = 1e-10;

double wrap(double x, double period) {
    double r = std::fmod(x, period);
    if (r < 0) r += period;
    return r >= period ? 0 : r;
}

Rgb texel(const ir::Texture &tex, int x, int y) {
    x = static_cast<int>(wrap(x, tex.width));
    y = static_cast<int>(wrap(y, tex.height));
    const float *p = &tex.rgba[4 * (size_t(y) * tex.width + x)];
    return {p[0], p[1], p[2]};
}

}  // namespace

Rgb sampleTexture(const ir::Texture &tex, double u, double v) {
    if (tex.width <= 0 || tex.height <= 0) return Rgb(1);
    // POV-Ray's planar image map over uv (gradient <1,-1,0>) puts v = 0 at the bottom row; the
    // exporter writes 1 - v, so here y counts down from the top exactly as glTF's v does
    double vPov = 1 - v;
    double x = std::fmod(u * tex.width, double(tex.width)) + kPovEpsilon;
    double y = std::fmod(vPov * tex.height, double(tex.height)) + kPovEpsilon;
    x = wrap(x, tex.width);
    y = wrap(-y, tex.height);
    // Bilinear between the four texels around (x, y), pixel centres at half-integers
    x += 0.5;
    y += 0.5;
    int ix = static_cast<int>(x), iy = static_cast<int>(y);
    double p = x - ix, q = y - iy;
    return texel(tex, ix, iy) * (p * q) + texel(tex, ix - 1, iy) * ((1 - p) * q) +
           texel(tex, ix, iy - 1) * (p * (1 - q)) + texel(tex, ix - 1, iy - 1) * ((1 - p) * (1 - q));
}

}  // namespace rt
