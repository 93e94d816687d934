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

const float *texel(const ir::Texture &tex, int x, int y) {
    x = static_cast<int>(wrap(x, tex.width));
    y = static_cast<int>(wrap(y, tex.height));
    return &tex.rgba[4 * (size_t(y) * tex.width + x)];
}

/// Bilinear RGBA at (u, v), as POV-Ray's image_map interpolate 2.
void bilinear(const ir::Texture &tex, double u, double v, float out[4]) {
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
    const float *t11 = texel(tex, ix, iy), *t01 = texel(tex, ix - 1, iy),
                *t10 = texel(tex, ix, iy - 1), *t00 = texel(tex, ix - 1, iy - 1);
    for (int c = 0; c < 4; ++c)
        out[c] = float(t11[c] * (p * q) + t01[c] * ((1 - p) * q) + t10[c] * (p * (1 - q)) +
                       t00[c] * ((1 - p) * (1 - q)));
}

}  // namespace

Rgb sampleTexture(const ir::Texture &tex, double u, double v) {
    if (tex.width <= 0 || tex.height <= 0) return Rgb(1);
    float c[4];
    bilinear(tex, u, v, c);
    return {c[0], c[1], c[2]};
}

bool textureCoordinates(const ir::TextureRef &ref, const SurfaceInteraction &si, double *u,
                        double *v) {
    if (ref.texCoord == 1 ? !si.hasUv1 : !si.hasUv) return false;
    double s = ref.texCoord == 1 ? si.u1 : si.u, t = ref.texCoord == 1 ? si.v1 : si.v;
    if (ref.hasTransform()) {
        // KHR_texture_transform: scale, then rotate, then offset (the extension's matrix
        // translation * rotation * scale, its rotation matrix with columns (cos, sin) and
        // (-sin, cos))
        double su = s * ref.scaleU, sv = t * ref.scaleV;
        double c = std::cos(ref.rotation), n = std::sin(ref.rotation);
        s = c * su - n * sv + ref.offsetU;
        t = n * su + c * sv + ref.offsetV;
    }
    *u = s;
    *v = t;
    return true;
}

bool sampleTexture(const ir::Texture &tex, const ir::TextureRef &ref, const SurfaceInteraction &si,
                   float rgba[4]) {
    double u, v;
    if (!textureCoordinates(ref, si, &u, &v)) return false;
    if (tex.width <= 0 || tex.height <= 0) {
        rgba[0] = rgba[1] = rgba[2] = rgba[3] = 1;
        return true;
    }
    bilinear(tex, u, v, rgba);
    return true;
}

}  // namespace rt
