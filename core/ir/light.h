// SPDX-License-Identifier: MIT
// IR light sources (POV-Ray light_source semantics, povray-semantics.md 1.2-1.3).
#pragma once

#include "core/ir/source_loc.h"
#include "core/math/rgb.h"
#include "core/math/vec3.h"

namespace rt::ir {

struct Light {
    enum class Kind { Point };

    Kind kind = Kind::Point;
    Vec3 position;
    Rgb color{1};
    /// POV-Ray fade: 2 / (1 + (d/fadeDistance)^fadePower); off unless both are positive.
    double fadeDistance = 0;
    double fadePower = 0;
    /// No shadow test and no highlights from this light (POV-Ray `shadowless`).
    bool shadowless = false;
    SourceLoc loc;
};

}  // namespace rt::ir
