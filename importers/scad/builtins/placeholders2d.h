// SPDX-License-Identifier: MIT
// 2D shapes in the node tree: placeholder nodes, their Clipper evaluation and their lifting
// into 3D solids by the extrusions (and by the preview's plates for top-level 2D objects).
#pragma once

#include <optional>
#include <vector>

#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/revolve.h"
#include "importers/scad/geometry2d/shape2d.h"
#include "importers/scad/lang/evaluator.h"

namespace rt::scad {

/// A resolved linear_extrude (or the plate OpenSCAD's preview draws for a top-level 2D object).
struct ExtrudeSpec {
    double z0 = 0, z1 = 1;
    Vec2 scale{1, 1};
    double twist = 0;
    int slices = 1;                  ///< the mesh path's slice count, once known
    int sliceArg = 0;                ///< `slices` as given (0: computed)
    ir::Fragments fragments;         ///< $fn/$fa/$fs at the call, for the slice count
    int material = -1;               ///< -1: each 2D primitive keeps its own material
    bool previewTransforms = false;  ///< plates: transforms act in 3D, as in the preview
    bool meshPath = false;           ///< twist or non-uniform scale: swept triangle meshes
    /// linear_extrude's group of children: OpenSCAD unions them without its mixing warning
    /// (applyToChildren2D), only ignoring 3D ones
    const ir::Node *silentUnion = nullptr;
    SourceLoc loc;
};

/// A resolved rotate_extrude: the sweep every lifted leaf takes.
struct RevolveSpec {
    double angle = 360;                     ///< |angle| in (0, 360], counter-clockwise from +X
    int segments = 1;                       ///< OpenSCAD's segment count over the angle
    ir::Fragments fragments;                ///< $fn/$fa/$fs at the call
    int material = -1;                      ///< -1: each 2D primitive keeps its own material
    const ir::Node *silentUnion = nullptr;  ///< the call's group of children
    SourceLoc loc;
};

/// OpenSCAD's Value::getVec2: exactly two numbers.
bool getVec2(const Value &v, double &x, double &y);

/// Runs a Clipper operation; a coordinate beyond Clipper's range is a located error.
template <typename F>
auto withClipper(const SourceLoc &loc, F &&f) -> decltype(f()) {
    try {
        return f();
    } catch (const clipper2d::RangeError &e) {
        throw EvalError(loc, e.what());
    }
}

// Placeholders
/// An empty group standing for a 2D shape in the node tree until an extrusion lifts it.
ir::NodePtr shape2dNode(Evaluator &ev, Shape2d shape, const ModuleInstantiation &inst);
const Shape2d *shape2dOf(Evaluator &ev, const ir::Node &n);
/// A 2D shape node holding an evaluated polygon set (offset(), minkowski(), projection(),
/// ...); an empty group when the set is empty.
ir::NodePtr polygonSetNode(Evaluator &ev, clipper2d::PolygonSet set,
                           const ModuleInstantiation &inst);
/// Bit 1: the subtree holds 2D shapes; bit 2: it holds 3D primitives.
int contentsOf(Evaluator &ev, const ir::Node &n);
/// OpenSCAD's dimension of a node: that of its first child with geometry (0: none).
int dimensionOf(Evaluator &ev, const ir::Node &n);
/// n's 2D children; 3D ones are left out, with OpenSCAD's warnings when warnIgnored (and
/// its mixing warning when warnMixing too).
std::vector<const ir::Node *> children2d(Evaluator &ev, const ir::Node &n, bool warnMixing,
                                         bool warnIgnored = true);
/// OpenSCAD's warnings for the 2D parts of a 3D subtree, which 3D operations ignore.
void warnIgnored2d(Evaluator &ev, const ir::Node &n);
/// Number of 2D outlines under `n` (a circle or square is one).
size_t outlineCount(Evaluator &ev, const ir::Node &n);
/// Outline points of the 2D shapes under `n` (a circle's fragments), for the geometry
/// budget.
double pointCount2d(Evaluator &ev, const ir::Node &n);
void extentOf2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed, Vec2 scale, double &rSqr,
                double &deltaSqr);
/// The x range of every outline point of the 2D subtree n placed by `placed`.
XRange pointRange2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed);

// Clipper evaluation
/// OpenSCAD's polygon set for the 2D children of `n` (the placeholder tree under a module
/// call, such as the group of an extrusion's children): GeometryEvaluator's
/// applyToChildren2D(UNION) in 2021.01, so one child is taken as it is and several are
/// united by Clipper, 3D children are ignored (with OpenSCAD's warnings), each polygon()
/// is sanitized even-odd and results are quantised as clipper2d.h says. Empty when
/// nothing 2D is left.
clipper2d::PolygonSet evaluate2d(Evaluator &ev, const ir::Node &n);
/// The polygon set of the 2D subtree n; nullopt for OpenSCAD's null geometry. The
/// children of `silent` are combined without the mixing warning (applyToChildren2D
/// called directly).
std::optional<clipper2d::PolygonSet> polygons2d(Evaluator &ev, const ir::Node &n,
                                                const ir::Node *silent);
/// hull() of 2D children (the first child with geometry is 2D): a convex polygon shape.
ir::NodePtr hull2d(Evaluator &ev, const ir::Node &children, const ModuleInstantiation &inst);
/// The points whose convex hull is OpenSCAD's hull of the 2D subtree n placed by
/// `placed`; false (after a warning) when there are more than meshing::kMaxHullPoints.
bool hullPoints2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed, std::vector<Vec2> &out);

// Lifting into 3D
/// The 3D solid of a 2D subtree swept as `spec` says; null when nothing is left.
ir::NodePtr lift2d(Evaluator &ev, const ir::Node &n, const ExtrudeSpec &spec, const Affine2 &placed,
                   double pad);
ir::NodePtr liftShape(Evaluator &ev, const Shape2d &s, const ExtrudeSpec &spec,
                      const Affine2 &placed, double pad);
ir::NodePtr sweptSolid(Evaluator &ev, const Outline &ccw, const ExtrudeSpec &spec, double pad,
                       int material, const SourceLoc &loc);
/// A polygon set's regions swept as `spec` says (see liftShape).
ir::NodePtr liftRegions(Evaluator &ev, const std::vector<Region> &regions, const ExtrudeSpec &spec,
                        double pad, int material, const SourceLoc &loc);
ir::NodePtr makeLifted(Evaluator &ev, ir::PrimShape shape, int material, const SourceLoc &loc);
/// The 3D solid of a 2D subtree revolved as `spec` says (the subtree's profile is on the
/// +X side once placed); `subtracted` inside what a difference subtracts.
ir::NodePtr liftRevolve(Evaluator &ev, const ir::Node &n, const RevolveSpec &spec,
                        const Affine2 &placed, bool subtracted);
ir::NodePtr revolveShape(Evaluator &ev, const Shape2d &s, const RevolveSpec &spec,
                         const Affine2 &placed, bool subtracted);
/// Draws the 2D subtrees left outside any extrusion as OpenSCAD's preview does.
int finish2d(Evaluator &ev, ir::Node &n, bool top);

}  // namespace rt::scad
