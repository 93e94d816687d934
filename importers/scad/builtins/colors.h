// SPDX-License-Identifier: MIT
// Colour arguments as color() reads them: CSS names, hex strings, and [r,g,b(,a)] vectors.
#pragma once

#include <optional>
#include <string>

#include "importers/scad/lang/value.h"

namespace rt::scad {

struct Rgba {
    double r = 0, g = 0, b = 0, a = 1;
};

/// One of the 148 CSS Color Level 4 names or "transparent" (case-insensitive), or a hex
/// string `#rgb`, `#rgba`, `#rrggbb`, `#rrggbbaa`; empty when unrecognised.
std::optional<Rgba> parseColorString(const std::string &s);

/// A colour value: a string as above, or a vector whose missing components are 1 (extra ones
/// are ignored, non-numbers read as 0). Empty when the value is neither.
std::optional<Rgba> colorFromValue(const Value &v);

}  // namespace rt::scad
