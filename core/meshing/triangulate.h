// SPDX-License-Identifier: MIT
// Triangulation of planar polygons in 3D: the faces of OFF files and polyhedra, the caps of
// extrusions.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/math/vec3.h"

namespace rt::meshing {

/// Triangulates a planar (or nearly planar) simple polygon given by vertex indices into
/// `positions`, keeping its orientation; ear clipping in the plane of its Newell normal.
/// Returns false (and leaves `out` unchanged) for degenerate polygons.
bool triangulatePolygon(const std::vector<Vec3> &positions, const std::vector<uint32_t> &polygon,
                        std::vector<std::array<uint32_t, 3>> &out);

}  // namespace rt::meshing
