// SPDX-License-Identifier: MIT
// Planar faces and points of a PrismPrim (a straight, uniformly scaled sweep of an outline).
#pragma once

#include <vector>

#include "core/ir/node.h"

namespace rt::ir {

/// The prism's corners: the outline scaled by k0 at z0, then by k1 at z1; an end whose scale
/// is 0 contributes one apex point on the Z axis instead.
std::vector<Vec3> prismPoints(const PrismPrim &p);

/// The prism as a polytope of planar faces, counter-clockwise seen from outside: the bottom
/// cap, the top cap (none at an apex) and one quadrilateral per outline edge (a triangle
/// where it meets an apex). It bounds the prism's solid only when the outline is convex.
PolytopePrim prismPolytope(const PrismPrim &p);

}  // namespace rt::ir
