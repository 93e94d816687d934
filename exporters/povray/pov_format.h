// SPDX-License-Identifier: MIT
// Number and vector formatting for POV-Ray SDL: shortest text that reads back to the same double.
#pragma once

#include <string>

#include "core/math/mat4.h"
#include "core/math/rgb.h"
#include "core/math/vec3.h"

namespace rt::pov {

/// Shortest decimal that round-trips to `v` (std::to_chars); -0 is written as 0.
std::string num(double v);
/// <x, y, z>
std::string vec(const Vec3 &v);
/// rgb <r, g, b>
std::string rgb(const Rgb &c);
/// POV-Ray's `matrix <...>` for a column-vector affine matrix (povray-semantics.md 6.2): the
/// 12 numbers are the rows of its 4x3 transpose.
std::string matrix(const Mat4 &m);
/// The shortest exact POV-Ray transform for m: `translate <...>` for a pure translation,
/// `scale <...>` for a pure axis scale, otherwise `matrix <...>`.
std::string transform(const Mat4 &m);

}  // namespace rt::pov
