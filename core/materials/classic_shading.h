// SPDX-License-Identifier: MIT
// POV-Ray 3.7's classic finish formulas (docs/design/povray-semantics.md sections 3.2, 3.3,
// 6.2 and 6.6), shared by the tracer and its tests: reflectivity with falloff or Fresnel,
// highlight colour, light fade, interior fade.
#pragma once

#include "core/ir/light.h"
#include "core/ir/material.h"
#include "core/math/rgb.h"

namespace rt {

/// POV-Ray's generic zero test (configbackend.h EPSILON).
constexpr double kPovEpsilon = 1e-10;

/// Luminance weights POV-Ray uses for `greyscale()` (colour.h).
inline double povGreyscale(const Rgb &c) { return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b; }

struct Reflectivity {
    Rgb value;           ///< multiplies the reflected colour
    double weightScale;  ///< the reflected ray's weight is the parent's times this
};

/// Reflectivity at incidence cosine cosI. `relativeIor` is n_transmitted / n_incident as
/// POV-Ray's ComputeRelativeIOR gives it; used only with fresnel.
Reflectivity reflectivity(const ir::Finish &f, double cosI, double relativeIor);

/// Colour of phong/specular highlights: the light colour, tinted towards the pigment by
/// `metallic` except at grazing angles (POV-Ray's empirical Fresnel curve).
Rgb highlightColour(const ir::Finish &f, const Rgb &lightColour, const Rgb &pigment, double cosNL);

/// POV-Ray light fade: 2 / (1 + (d / fadeDistance)^fadePower), or 1 when fade is off.
double lightFade(const ir::Light &light, double distance);

/// Interior fade of light that travelled `depth` inside a medium
/// (docs/design/povray-semantics.md section 6.6); the shadow path requires fadePower > 0, the
/// trace path does not.
Rgb interiorFade(const ir::Interior &in, double depth, bool shadowPath);

}  // namespace rt
