// SPDX-License-Identifier: MIT
// ir::Environment: what a ray sees when it leaves the scene (POV-Ray's sky_sphere). None keeps
// the flat background colour; a gradient is a piecewise-linear function of the direction's
// height (its z component, -1 straight down to +1 straight up); an image is an equirectangular
// (latitude-longitude) picture around the scene. Mirror and glass surfaces reflect and refract
// it, glossy and frosted ones sample it; it lights nothing else (no image-based lighting).
#pragma once

#include <string>
#include <vector>

#include "core/ir/mesh.h"
#include "core/math/rgb.h"

namespace rt::ir {

enum class EnvironmentKind { None, Gradient, Image };

/// One colour of a gradient environment at direction height z in [-1, 1].
struct GradientStop {
    double z = 0;
    Rgb color{0};
    bool operator==(const GradientStop &) const = default;
};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::None;
    /// Gradient: stops with strictly increasing z, the first at -1 and the last at +1;
    /// linear in RGB between them (as POV-Ray's colour_map).
    std::vector<GradientStop> gradient;
    /// Image: linear RGB, the top row looking straight up (+Z), the bottom row straight down;
    /// u (left to right) runs once round the horizon from +X through -Y, -X and +Y, so the
    /// picture is seen unmirrored from inside. `imagePath` is the file it came from.
    TexturePtr image;
    std::string imagePath;
    /// Turns the environment about +Z by this many degrees (counterclockwise seen from above).
    double rotateDegrees = 0;
};

/// The studio sky glTF models get when rendered on their own: white overhead, a neutral grey
/// horizon and a darker ground, linear RGB at z = -1, 0, 0.5 and 1 (documented in the README).
Environment studioEnvironment();

}  // namespace rt::ir
