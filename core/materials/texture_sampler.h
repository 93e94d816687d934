// SPDX-License-Identifier: MIT
// Texture lookup as POV-Ray 3.7 does it for `uv_mapping image_map { ... interpolate 2 }`
// (backend/support/imageutil.cpp: map_pos, Interp, bilinear), so textured surfaces render the
// same in both renderers.
#pragma once

#include "core/geometry/hit.h"
#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "core/math/rgb.h"

namespace rt {

/// Bilinearly interpolated RGB at texture coordinates (u, v), glTF convention (origin at the
/// top-left, v down). The image repeats outside [0,1].
Rgb sampleTexture(const ir::Texture &tex, double u, double v);

/// The texture coordinates a TextureRef reads at a hit: its coordinate set (false when the
/// surface has none) with KHR_texture_transform applied.
bool textureCoordinates(const ir::TextureRef &ref, const SurfaceInteraction &si, double *u,
                        double *v);

/// RGBA of the texture `ref` names at a hit (linear; alpha 1 for images without one), or
/// false when the surface has no coordinates for it.
bool sampleTexture(const ir::Texture &tex, const ir::TextureRef &ref, const SurfaceInteraction &si,
                   float rgba[4]);

}  // namespace rt
