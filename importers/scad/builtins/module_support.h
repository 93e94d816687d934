// SPDX-License-Identifier: MIT
// What several builtin families share: primitive leaves, argument helpers, materials, meshes.
#pragma once

#include <string>

#include "core/ir/scene_ir.h"
#include "importers/scad/lang/evaluator.h"

namespace rt::scad {

/// An argument as OpenSCAD's messages print it.
inline std::string argText(const Value &v) { return v.toEchoString(); }

/// OpenSCAD's lookup_radius: a numeric diameter wins over the radius (with a warning when
/// both are given); undef when neither is a number.
Value lookupRadius(Evaluator &ev, const Value &d, const Value &r, const char *dName,
                   const char *rName, const SourceLoc &loc);
/// OpenSCAD's warning for children given to a module that takes none.
void warnLeafChildren(Evaluator &ev, const ModuleInstantiation &inst);
/// An empty group for a primitive OpenSCAD makes empty, with a warning saying `why`.
ir::NodePtr emptyPrimitive(Evaluator &ev, const ModuleInstantiation &inst, const std::string &why);
/// A primitive leaf with the current fragments and material, charged to the budgets.
ir::NodePtr primitive(Evaluator &ev, ir::PrimShape shape, const ModuleInstantiation &inst,
                      const FramePtr &f);
/// sphere()/circle() radius from `r` and `d` (bound first and second): a numeric d wins,
/// with OpenSCAD's warning when r is given too; undef when neither is a number.
Value radiusArgument(Evaluator &ev, const BoundArgs &a, const ModuleInstantiation &inst);
/// An empty group for a feature not supported yet, with a warning (none inside `%`).
ir::NodePtr skipUnsupported(Evaluator &ev, const SourceLoc &loc, const std::string &what);
/// The children of hull() or minkowski(), a source of points only: a singular transform
/// inside still gives its flat points, as in OpenSCAD.
ir::NodePtr pointSourceChildren(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f);

/// The material of a primitive made at `primLoc` in the current color()/material() context
/// (builtins/metadata.cpp).
int resolveMaterial(Evaluator &ev, const SourceLoc &primLoc);

/// Adds a mesh to the scene; its index.
int addMesh(Evaluator &ev, ir::Mesh mesh);

/// Faces of OpenSCAD's tessellation of the primitives under `n` (as meshing::openscadPolyhedron
/// makes them), estimated from their parameters without building any: what the geometry
/// budget charges before projection(), minkowski(), hull() and resize() tessellate. The
/// points are of the same order.
double tessellatedFaces(const ir::Node &n, const ir::Scene &scene);

}  // namespace rt::scad
