// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's tessellation of rotate_extrude (solids of revolution) as a closed mesh.
#pragma once

#include <vector>

#include "core/ir/mesh.h"
#include "core/ir/node.h"

namespace rt::meshing {

using ir::Mesh;
using ir::ProfileOutline;

/// OpenSCAD 2021.01's rotate_extrude of profile outlines (GeometryEvaluator.cc rotatePolygon):
/// each outline's vertices form rings, a point (r, z) at ring angle a going to
/// (r sin a, r cos a, z) with a = -90 + j 360 / fragments for a full turn and
/// a = 90 - j angle / fragments otherwise (j = 0..fragments), and each outline edge gives two
/// triangles between consecutive rings. A partial turn is closed by the profile (even-odd,
/// holes bridged) in the planes at azimuth 0 and `angle`. Points on the axis are welded, so the
/// mesh is closed; triangles face outwards whatever the outlines' winding.
Mesh openscadRevolve(const std::vector<ProfileOutline> &outlines, double angle, int fragments);

/// The vertices openscadRevolve makes (for hull() of a solid of revolution).
std::vector<Vec3> openscadRevolvePoints(const std::vector<ProfileOutline> &outlines, double angle,
                                        int fragments);

/// For each outline, the index of the innermost other outline around it, or -1: the
/// even-odd region is the outlines at even depth less their children.
std::vector<int> profileParents(const std::vector<ProfileOutline> &outlines);

/// Triangulates the even-odd region of `outlines` in the (r, z) plane: triangles of
/// (outline, vertex) pairs, counter-clockwise. Holes are joined to the outline around them
/// by bridges, then ears are clipped.
std::vector<std::array<std::pair<int, int>, 3>> triangulateProfile(
    const std::vector<ProfileOutline> &outlines);

}  // namespace rt::meshing
