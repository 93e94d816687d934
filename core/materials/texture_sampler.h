// SPDX-License-Identifier: MIT
// Texture lookup as POV-Ray 3.7 does it for `uv_mapping image_map { ... interpolate 2 }`
// (backend/support/imageutil.cpp: map_pos, Interp, bilinear), so textured surfaces render the
// same in both renderers.
#pragma once

#include "core/ir/mesh.h"
#include "core/math/rgb.h"

namespace rt {

/// Bilinearly interpolated RGB at texture coordinates (u, v), glTF convention (origin at the
/// top-left, v down). The image repeats outside [0,1].
Rgb sampleTexture(const ir::Texture &tex, double u, double v);

}  // namespace rt
