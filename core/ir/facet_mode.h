// SPDX-License-Identifier: MIT
// How round primitives are drawn (`--facets`), and what the facet pass did: plain data the
// scene carries; the tessellation itself is in core/meshing/facets.h.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace rt::ir {

/// How round primitives are drawn.
enum class FacetMode {
    Smooth,    ///< exactly round (analytic sphere, cylinder, cone)
    OpenScad,  ///< as OpenSCAD 2021.01 tessellates them, from $fn/$fa/$fs
    Auto,      ///< OpenSCAD's polygon where a small $fn was given, else smooth
};

/// `auto` draws a primitive faceted when `$fn` was set (it is 0 unless the file sets it) and
/// gives at most this many fragments: hexagonal nut traps, square and octagonal holes and the
/// like are meant as polygons, while `$fn=32` and above, or the $fa/$fs defaults (5 fragments
/// for a sphere of radius 1), only approximate a round shape.
constexpr int kAutoFacetMaxFragments = 12;

const char *facetModeName(FacetMode mode);
std::optional<FacetMode> parseFacetMode(std::string_view text);

/// What the pass did, for the render plan.
struct FacetStats {
    FacetMode mode = FacetMode::Auto;
    int faceted = 0;  ///< spheres, cylinders, tori and lathes drawn as OpenSCAD's polygons
    int smooth = 0;   ///< the same drawn round
    std::string describe() const;
};

}  // namespace rt::ir
