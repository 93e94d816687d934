// SPDX-License-Identifier: MIT
// IR light sources (POV-Ray light_source semantics, docs/design/povray-semantics.md sections
// 3.2-3.3).
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
    /// POV-Ray area_light (point and spot lights): shadows are the average visibility of an
    /// n1 x n2 grid spanning axis1 x axis2 about `position`, averaged recursively as POV-Ray
    /// does (docs/design/povray-semantics.md section 5); light colour, fade and highlights
    /// still come from the centre. With jitter each grid point moves by up to half a cell,
    /// drawn from the sample's seeded stream, so soft shadows converge with samples per pixel.
    struct Area {
        Vec3 axis1{1, 0, 0}, axis2{0, 1, 0};
        int n1 = 1, n2 = 1;
        int adaptive = 100;  ///< POV-Ray's default: in practice full subdivision
        bool jitter = false;
        bool circular = false;
        bool orient = false;  ///< turn the grid to face each shaded point (forces circular)
        bool operator==(const Area &) const = default;
    };
    bool area = false;
    Area areaLight;
    SourceLoc loc;
};

}  // namespace rt::ir
