// SPDX-License-Identifier: MIT
#include "core/ir/facet_mode.h"

#include <cstdio>

namespace rt::ir {

const char *facetModeName(FacetMode mode) {
    switch (mode) {
        case FacetMode::Smooth:
            return "smooth";
        case FacetMode::OpenScad:
            return "openscad";
        case FacetMode::Auto:
            return "auto";
    }
    return "?";
}

std::optional<FacetMode> parseFacetMode(std::string_view text) {
    for (FacetMode m : {FacetMode::Smooth, FacetMode::OpenScad, FacetMode::Auto})
        if (text == facetModeName(m)) return m;
    return std::nullopt;
}

std::string FacetStats::describe() const {
    std::string s = std::string(facetModeName(mode)) + ": ";
    switch (mode) {
        case FacetMode::Smooth:
            s += "every round solid exactly round";
            break;
        case FacetMode::OpenScad:
            s += "round solids as OpenSCAD tessellates them";
            break;
        case FacetMode::Auto:
            s += "OpenSCAD's polygons where $fn gives at most " +
                 std::to_string(kAutoFacetMaxFragments) + " fragments, round otherwise";
            break;
    }
    return s + " (" + std::to_string(faceted) + " faceted, " + std::to_string(smooth) + " round)";
}

}  // namespace rt::ir
