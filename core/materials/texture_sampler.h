// SPDX-License-Identifier: MIT
// Texture lookup as POV-Ray 3.7 does it for `uv_mapping image_map { ... }` (backend/support/
// imageutil.cpp: map_pos, no_interpolation, Interp, bilinear), extended by glTF's sampler wrap
// modes and filters in a way the POV-Ray exporter reproduces exactly with baked images.
#pragma once

#include "core/geometry/hit.h"
#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "core/math/rgb.h"

namespace rt {

/// The texel an index `i` along an axis of `n` texels reads under `wrap`: modulo n (repeat),
/// clamped to [0, n-1] (clamp to edge) or reflected with period 2n (mirrored repeat).
int wrapTexel(int i, int n, ir::Texture::Wrap wrap);

/// RGBA at texture coordinates (u, v), glTF convention (origin at the top-left, v down), with
/// the texture's wrap modes and filter: bilinear between the four texels around the point
/// (texel centres at half-integers, as POV-Ray's `interpolate 2`) or, with `nearest`, the
/// texel under it (as POV-Ray's image_map without interpolation). No mipmaps: minification
/// filters the same way.
void sampleTexture(const ir::Texture &tex, double u, double v, float rgba[4]);

/// RGB of sampleTexture above (white for an empty texture).
Rgb sampleTexture(const ir::Texture &tex, double u, double v);

/// KHR_texture_transform of `ref` applied to (u, v): scale, then rotate, then offset. The
/// rotation turns counter-clockwise as seen in uv space with v pointing down, as the extension
/// describes, the glTF-Sample-Viewer renders it and the TextureTransformTest sample checks it:
/// u' = cos r u + sin r v, v' = -sin r u + cos r v. The GLSL listing in the extension text turns
/// the other way (github.com/KhronosGroup/glTF/issues/1563).
void transformTexCoord(const ir::TextureRef &ref, double *u, double *v);

/// The texture coordinates a TextureRef reads at a hit: its coordinate set (false when the
/// surface has none) with KHR_texture_transform applied.
bool textureCoordinates(const ir::TextureRef &ref, const SurfaceInteraction &si, double *u,
                        double *v);

/// RGBA of the texture `ref` names at a hit (linear; alpha 1 for images without one), or
/// false when the surface has no coordinates for it.
bool sampleTexture(const ir::Texture &tex, const ir::TextureRef &ref, const SurfaceInteraction &si,
                   float rgba[4]);

}  // namespace rt
