// SPDX-License-Identifier: MIT
// IR light sources (POV-Ray light_source semantics, povray-semantics.md 1.2-1.3).
#pragma once

#include "core/ir/source_loc.h"
#include "core/math/rgb.h"
#include "core/math/vec3.h"

namespace rt::ir {

struct Light {
    /// Point: light_source. Spot: POV-Ray `spotlight` (cone about `direction`). Directional:
    /// POV-Ray `parallel` light, rays along `direction` everywhere; `position` still places the
    /// plane the shadow rays end at (POV-Ray measures shadow distance from it).
    enum class Kind { Point, Spot, Directional };

    Kind kind = Kind::Point;
    Vec3 position;
    /// Spot and Directional: where the light shines (unit vector).
    Vec3 direction{0, 0, -1};
    /// Spot: full intensity inside `spotRadius`, falling to zero at `spotFalloff` (half-angles
    /// in degrees, as POV-Ray's radius and falloff), with POV-Ray's `tightness`.
    double spotRadius = 30;
    double spotFalloff = 45;
    double spotTightness = 0;
    Rgb color{1};
    /// POV-Ray fade: 2 / (1 + (d/fadeDistance)^fadePower); off unless both are positive.
    double fadeDistance = 0;
    double fadePower = 0;
    /// No shadow test and no highlights from this light (POV-Ray `shadowless`).
    bool shadowless = false;
    SourceLoc loc;
};

}  // namespace rt::ir
