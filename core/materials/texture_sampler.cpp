// SPDX-License-Identifier: MIT
// POV-Ray-compatible image-map lookup with glTF's sampler wrap modes and filters.
#include "core/materials/texture_sampler.h"

#include <algorithm>
#include <cmath>

namespace rt {

namespace {

using Wrap = ir::Texture::Wrap;

/// POV-Ray's EPSILON, added to image coordinates before wrapping (map_pos).
constexpr double kPovEpsilon = 1e-10;

double wrap(double x, double period) {
    double r = std::fmod(x, period);
    if (r < 0) r += period;
    return r >= period ? 0 : r;
}

const float *texel(const ir::Texture &tex, int x, int y) {
    x = wrapTexel(x, tex.width, tex.wrapU);
    y = wrapTexel(y, tex.height, tex.wrapV);
    return &tex.rgba[4 * (size_t(y) * tex.width + x)];
}

/// Continuous image coordinate along one axis, in texels from the left (top) edge, as POV-Ray's
/// map_pos computes it. Repeat follows map_pos literally (the exporter writes the image as
/// is); the other modes are the same value unwrapped (clamp: the exporter pads the image, so
/// POV-Ray's coordinate is this one plus the padding) or wrapped with period 2n (mirror: the
/// exporter writes the image and its mirror image side by side).
double imageCoordinate(double t, int n, Wrap mode, bool down) {
    // POV-Ray's planar image map over uv (gradient <1,-1,0>) puts v = 0 at the bottom row; the
    // exporter writes 1 - v, so here y counts down from the top exactly as glTF's v does
    if (mode == Wrap::Repeat) {
        if (!down) return wrap(std::fmod(t * n, double(n)) + kPovEpsilon, n);
        return wrap(-(std::fmod((1 - t) * n, double(n)) + kPovEpsilon), n);
    }
    double x = down ? t * n - kPovEpsilon : t * n + kPovEpsilon;
    return mode == Wrap::MirroredRepeat ? wrap(x, 2.0 * n) : x;
}

int floorInt(double x) {
    // Far outside the image every index reads the same texel as a nearer one (clamp) or a
    // periodic one; keep the conversion defined
    constexpr double kLimit = 1 << 30;
    return static_cast<int>(std::floor(std::max(-kLimit, std::min(kLimit, x))));
}

}  // namespace

int wrapTexel(int i, int n, ir::Texture::Wrap mode) {
    switch (mode) {
        case Wrap::ClampToEdge:
            return i < 0 ? 0 : i >= n ? n - 1 : i;
        case Wrap::MirroredRepeat: {
            int m = i % (2 * n);
            if (m < 0) m += 2 * n;
            return m < n ? m : 2 * n - 1 - m;
        }
        case Wrap::Repeat:
            break;
    }
    int m = i % n;
    return m < 0 ? m + n : m;
}

void sampleTexture(const ir::Texture &tex, double u, double v, float out[4]) {
    if (tex.width <= 0 || tex.height <= 0) {
        out[0] = out[1] = out[2] = out[3] = 1;
        return;
    }
    double x = imageCoordinate(u, tex.width, tex.wrapU, false);
    double y = imageCoordinate(v, tex.height, tex.wrapV, true);
    if (tex.nearest) {
        const float *t = texel(tex, floorInt(x), floorInt(y));
        for (int c = 0; c < 4; ++c) out[c] = t[c];
        return;
    }
    // Bilinear between the four texels around (x, y), pixel centres at half-integers
    x += 0.5;
    y += 0.5;
    int ix = floorInt(x), iy = floorInt(y);
    double p = x - ix, q = y - iy;
    const float *t11 = texel(tex, ix, iy), *t01 = texel(tex, ix - 1, iy),
                *t10 = texel(tex, ix, iy - 1), *t00 = texel(tex, ix - 1, iy - 1);
    for (int c = 0; c < 4; ++c)
        out[c] = float(t11[c] * (p * q) + t01[c] * ((1 - p) * q) + t10[c] * (p * (1 - q)) +
                       t00[c] * ((1 - p) * (1 - q)));
}

Rgb sampleTexture(const ir::Texture &tex, double u, double v) {
    float c[4];
    sampleTexture(tex, u, v, c);
    return {c[0], c[1], c[2]};
}

void transformTexCoord(const ir::TextureRef &ref, double *u, double *v) {
    if (!ref.hasTransform()) return;
    double su = *u * ref.scaleU, sv = *v * ref.scaleV;
    double c = std::cos(ref.rotation), s = std::sin(ref.rotation);
    *u = c * su + s * sv + ref.offsetU;
    *v = -s * su + c * sv + ref.offsetV;
}

bool textureCoordinates(const ir::TextureRef &ref, const SurfaceInteraction &si, double *u,
                        double *v) {
    if (ref.texCoord == 1 ? !si.hasUv1 : !si.hasUv) return false;
    *u = ref.texCoord == 1 ? si.u1 : si.u;
    *v = ref.texCoord == 1 ? si.v1 : si.v;
    transformTexCoord(ref, u, v);
    return true;
}

bool sampleTexture(const ir::Texture &tex, const ir::TextureRef &ref, const SurfaceInteraction &si,
                   float rgba[4]) {
    double u, v;
    if (!textureCoordinates(ref, si, &u, &v)) return false;
    sampleTexture(tex, u, v, rgba);
    return true;
}

}  // namespace rt
