// SPDX-License-Identifier: MIT
// A glTF base colour texture as a POV-Ray uv_mapping pigment that reads the same texel values
// as scadray's sampler (core/materials/texture_sampler.h): the colour factor, the sampler's
// wrap modes and the KHR_texture_transform are baked into the written image and a pigment
// matrix; per-texel alpha becomes per-texel transmit.
#pragma once

#include <string>
#include <vector>

#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "exporters/povray/pov_writer.h"

namespace rt::pov {

/// How the texture's alpha makes the surface see-through (glTF alphaMode): not at all
/// (OPAQUE), transmit 1 where the filtered alpha x factor is below the cutoff and 0 elsewhere
/// (MASK), or transmit 1 - alpha x factor (BLEND).
struct TextureAlpha {
    enum class Mode { Opaque, Mask, Blend };
    Mode mode = Mode::Opaque;
    double factor = 1;    ///< baseColorFactor.a
    double cutoff = 0.5;  ///< alphaCutoff
};

/// The texture coordinates, after KHR_texture_transform, a texture is read at (the bounds of
/// the vertices' coordinates: the transform is affine, so the triangles stay inside).
struct UvRange {
    double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
    bool empty = true;
    void add(double u, double v);
};

/// Largest side, in texels, of an image the exporter bakes; clamp padding stops there (and the
/// pigment says over which coordinates clamping is then exact).
constexpr int kMaxBakedTextureSide = 8192;

struct TexturePigment {
    std::vector<TextureFile> files;  ///< images to write beside the scene
    /// `pigment { ... }` lines, each indented by 4; for MASK the pigment of the texels that
    /// are there (body() adds the rest)
    std::string sdl;
    /// MASK only: the image_pattern over the alpha image, the cutoff and the pigment matrix,
    /// which body() puts on the whole texture
    std::string cutOutPattern, matrix;
    double cutoff = 0.5;

    /// The texture body after `uv_mapping`, given the material's `finish { ... }` lines: the
    /// pigment then the finish; for MASK a texture_map whose cut-out entry has no pigment and
    /// no finish, since POV-Ray adds the highlights of a pigment with transmit 1 and a glTF
    /// cut-out texel is not there at all.
    std::string body(const std::string &finish) const;
};

/// The pigment for `tex` read through `ref` (its RGB multiplied by `factor`), with `filter`
/// and `transmit` for every texel on top of what the alpha says. Image files are named
/// fileStem + ".png" (+ "_alpha.png").
TexturePigment texturePigment(const ir::Texture &tex, const ir::TextureRef &ref, const Rgb &factor,
                              const TextureAlpha &alpha, const UvRange &range, double filter,
                              double transmit, const std::string &fileStem);

}  // namespace rt::pov
