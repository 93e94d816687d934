// SPDX-License-Identifier: MIT
// Solids swept from 2D outlines for linear_extrude (OpenSCAD 2021.01 GeometryEvaluator.cc
// extrudePolygon/add_slice, calc.cc slice counts).
#pragma once

#include "core/ir/mesh.h"
#include "core/ir/node.h"
#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad {

/// An outline swept from z0 to z1: at z0 it is scaled by scale0 about the origin and turned
/// clockwise by rot0 degrees, at z1 by scale1 and rot1; in between each quantity is linear in
/// z, sampled at `slices` + 1 rings.
struct Sweep {
    double z0 = 0, z1 = 1;
    Vec2 scale0{1, 1}, scale1{1, 1};
    double rot0 = 0, rot1 = 0;
    int slices = 1;
};

/// A simple counter-clockwise outline swept straight (no twist, uniform scales k0 at z0 and
/// k1 at z1): a prism, a frustum, a pyramid where a scale is 0. Its `mesh` is left -1.
ir::PrismPrim straightPrism(const Outline &ccw, double z0, double z1, double k0, double k1);

/// A simple counter-clockwise outline swept as a closed triangle mesh: OpenSCAD's rings, its
/// choice of diagonal for each side quad, and ear-clipped caps (none where a ring is a point).
/// Returns false when a cap cannot be triangulated (no area).
bool sweepMesh(const Outline &ccw, const Sweep &s, ir::Mesh &out);

/// The closed triangle mesh of a prism, as sweepMesh builds it (what OpenSCAD renders of a
/// straight linear_extrude). Returns false when a cap cannot be triangulated (no area).
bool prismMesh(const ir::PrismPrim &p, ir::Mesh &out);

/// OpenSCAD 2021.01's slice count for linear_extrude (has_slices wins; twist: helix or conical
/// helix length; non-uniform scale: the longest diagonal path; else 1). rSqr is the largest
/// squared distance of an outline point from the origin, deltaSqr the largest squared shift
/// of a point between bottom and top scale.
int extrudeSlices(int slices, double height, double twist, Vec2 scale, double rSqr, double deltaSqr,
                  const ir::Fragments &f);

}  // namespace rt::scad
