// SPDX-License-Identifier: MIT
// Base colour textures as POV-Ray pigments that sample exactly as scadray does.
//
// POV-Ray's image_map repeats its image over the unit square of uv space and reads it with
// the same arithmetic as rt::sampleTexture's REPEAT. The other glTF wrap modes become images:
//   CLAMP_TO_EDGE    the image padded with copies of its edge texels, as far as the mesh's
//                    texture coordinates reach (plus the filter's reach), so that POV-Ray's
//                    repeat never shows (`once` would not do: outside the image it is clear)
//   MIRRORED_REPEAT  the image and its mirror image side by side (period 2 in uv)
// and a pigment matrix maps the mesh's coordinates onto the baked image: the
// KHR_texture_transform, then the padding or doubling, conjugated by POV-Ray's v flip (the
// mesh2 uv_vectors hold 1 - v). NEAREST leaves out `interpolate`: POV-Ray then reads the
// texel under the point, as the sampler does.
//
// Alpha (glTF MASK and BLEND): an image_pattern over a grey image of alpha x factor, read with
// the same filter. BLEND ramps in a pigment_map between the colour image made clear (transmit
// all 1) and the colour image itself (transmit 1 - alpha, filtered colour and alpha as the
// sampler's straight RGBA). MASK steps at the cutoff (the filtered alpha compared with it, as
// glTF says) in a texture_map between nothing at all (no pigment colour, no finish: POV-Ray
// still adds the highlights of a pigment with transmit 1, and a cut-out texel is not there)
// and the colour image with the material's finish.
#include "exporters/povray/pov_texture.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/materials/texture_sampler.h"
#include "exporters/povray/pov_format.h"

namespace rt::pov {

void UvRange::add(double u, double v) {
    if (empty) {
        u0 = u1 = u;
        v0 = v1 = v;
        empty = false;
        return;
    }
    u0 = std::min(u0, u);
    u1 = std::max(u1, u);
    v0 = std::min(v0, v);
    v1 = std::max(v1, v);
}

namespace {

using Wrap = ir::Texture::Wrap;

/// How one axis of the texture is baked: `size` texels, texel k reading source texel
/// source(k); coordinate t of the sampler lands at s = scale t + offset of the baked image.
struct AxisBake {
    int n = 0, size = 0, pad0 = 0;
    Wrap wrap = Wrap::Repeat;
    double scale = 1, offset = 0;
    bool limited = false;  ///< clamp padding stopped at kMaxBakedTextureSide

    int source(int k) const {
        return wrap == Wrap::ClampToEdge ? wrapTexel(k - pad0, n, wrap) : wrapTexel(k, n, wrap);
    }
    /// The coordinates over which a clamped axis reads as the sampler does.
    double exactFrom() const { return (1.0 - pad0) / n; }
    double exactTo() const { return double(size - pad0 - 1) / n; }
};

AxisBake bakeAxis(int n, Wrap wrap, double lo, double hi) {
    AxisBake a;
    a.n = n;
    a.wrap = wrap;
    a.size = n;
    if (wrap == Wrap::MirroredRepeat) {
        a.size = 2 * n;
        a.scale = 0.5;
    } else if (wrap == Wrap::ClampToEdge) {
        // Two texels beyond the farthest coordinate: one for the bilinear neighbour, one spare
        auto reach = [&](double beyond) {
            return std::min(std::max(0.0, std::ceil(beyond * n)), double(kMaxBakedTextureSide)) + 2;
        };
        double p0 = reach(-lo), p1 = reach(hi - 1);
        double room = std::max(0, kMaxBakedTextureSide - n);
        if (p0 + p1 > room) {
            a.limited = true;
            double k = room / (p0 + p1);
            p0 = std::max(2.0, std::floor(p0 * k));
            p1 = std::max(2.0, std::floor(p1 * k));
        }
        a.pad0 = int(p0);
        a.size = n + int(p0) + int(p1);
        a.scale = double(n) / a.size;
        a.offset = p0 / a.size;
    }
    return a;
}

std::string imageSpec(const std::string &kind, const std::string &file, bool nearest) {
    return kind + " { png \"" + file + "\" gamma 1.0" + (nearest ? "" : " interpolate 2");
}

}  // namespace

TexturePigment texturePigment(const ir::Texture &tex, const ir::TextureRef &ref, const Rgb &factor,
                              const TextureAlpha &alpha, const UvRange &range, double filter,
                              double transmit, const std::string &fileStem) {
    TexturePigment out;
    UvRange r = range;
    if (r.empty) r.add(0, 0), r.add(1, 1);
    AxisBake ax = bakeAxis(tex.width, tex.wrapU, r.u0, r.u1);
    AxisBake ay = bakeAxis(tex.height, tex.wrapV, r.v0, r.v1);

    // The images: colour x factor, and alpha x factor where the alpha decides anything
    bool withAlpha = alpha.mode != TextureAlpha::Mode::Opaque;
    Image colour(ax.size, ay.size), grey;
    if (withAlpha) grey = Image(ax.size, ay.size);
    for (int y = 0; y < ay.size; ++y)
        for (int x = 0; x < ax.size; ++x) {
            const float *p =
                &tex.rgba[4 * (size_t(ay.source(y)) * size_t(tex.width) + size_t(ax.source(x)))];
            colour.set(x, y, Rgb(p[0], p[1], p[2]) * factor);
            if (withAlpha) grey.set(x, y, Rgb(std::clamp(p[3] * alpha.factor, 0.0, 1.0)));
        }
    std::string file = fileStem + ".png", alphaFile = fileStem + "_alpha.png";
    out.files.push_back({file, std::move(colour)});
    if (withAlpha) out.files.push_back({alphaFile, std::move(grey)});

    // The lookup in POV-Ray's uv space (v up): p -> F(D(M(F^-1 p))), F(u, v) = (u, 1 - v);
    // the pigment's matrix is its inverse
    auto lookup = [&](double px, double py, double *qx, double *qy) {
        double u = px, v = 1 - py;
        transformTexCoord(ref, &u, &v);
        *qx = ax.scale * u + ax.offset;
        *qy = 1 - (ay.scale * v + ay.offset);
    };
    double ox, oy, ex, ey, fx, fy;
    lookup(0, 0, &ox, &oy);
    lookup(1, 0, &ex, &ey);
    lookup(0, 1, &fx, &fy);
    double a = ex - ox, c = ey - oy, b = fx - ox, d = fy - oy;  // G = [a b; c d] p + o
    double det = a * d - b * c;
    std::string matrixLine, note;
    bool identity = a == 1 && b == 0 && c == 0 && d == 1 && ox == 0 && oy == 0;
    if (!identity && std::abs(det) > 1e-12) {
        // T = G^-1: p -> [d -b; -c a] / det (p - o)
        double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
        double tx = -(ia * ox + ib * oy), ty = -(ic * ox + id * oy);
        // POV-Ray's matrix: p' = x row0 + y row1 + z row2 + row3
        matrixLine = "        matrix <" + num(ia) + ", " + num(ic) + ", 0, " + num(ib) + ", " +
                     num(id) + ", 0, 0, 0, 1, " + num(tx) + ", " + num(ty) + ", 0>\n";
    } else if (!identity) {
        note +=
            "    // scadray: the texture transform collapses the texture to a line or a "
            "point, which a POV-Ray matrix cannot express; written untransformed\n";
    }
    for (const AxisBake *axis : {&ax, &ay})
        if (axis->limited)
            note += "    // scadray: clamp to edge along " + std::string(axis == &ax ? "u" : "v") +
                    " holds for texture coordinates " + num(axis->exactFrom()) + " to " +
                    num(axis->exactTo()) + " (the padded image stops at " +
                    std::to_string(kMaxBakedTextureSide) + " texels); beyond, POV-Ray repeats\n";

    std::string map = imageSpec("image_map", file, tex.nearest);
    std::ostringstream os;
    os << note << "    pigment {\n";
    if (alpha.mode == TextureAlpha::Mode::Mask) {
        // The texels that are there; the cut-out ones are body()'s texture_map entry
        os << "        " << map << " filter all " << num(filter) << " transmit all "
           << num(transmit) << " }\n    }\n";
        out.sdl = os.str();
        out.cutOutPattern = "    " + imageSpec("image_pattern", alphaFile, tex.nearest) + " }\n";
        out.matrix = matrixLine;
        out.cutoff = alpha.cutoff;
        return out;
    }
    if (!withAlpha) {
        os << "        " << map << " filter all " << num(filter) << " transmit all "
           << num(transmit) << " }\n";
    } else {
        os << "        " << imageSpec("image_pattern", alphaFile, tex.nearest) << " }\n"
           << "        pigment_map {\n"
           << "            [0 " << map << " transmit all 1 }]\n"
           << "            [1 " << map << " filter all " << num(filter) << " transmit all "
           << num(transmit) << " }]\n"
           << "        }\n";
    }
    os << matrixLine << "    }\n";
    out.sdl = os.str();
    return out;
}

std::string TexturePigment::body(const std::string &finish) const {
    if (cutOutPattern.empty()) return sdl + finish;
    return cutOutPattern + "    texture_map {\n" + "        [" + num(cutoff) +
           " pigment { rgbt 1 } finish { ambient 0 diffuse 0 }]\n" + "        [" + num(cutoff) +
           "\n" + sdl + finish + "        ]\n    }\n" + matrix;
}

}  // namespace rt::pov
