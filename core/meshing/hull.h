// SPDX-License-Identifier: MIT
// Convex hulls (quickhull) of point sets, and the points OpenSCAD 2021.01 hulls for a node tree.
#pragma once

#include <functional>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/node.h"

namespace rt::ir {
struct Scene;
}

namespace rt::meshing {

using ir::Node;
using ir::PolytopePrim;
using ir::Scene;

/// Points closer than this many units in the last place of the input's coordinate scale
/// (max|x| + max|y| + max|z|, as in Barber et al.'s qhull and Lloyd's quickhull3d) count as
/// lying on a plane: a distance to a plane through input points is computed with a few roundings
/// of that scale, so anything closer is within the noise of the arithmetic, not outside.
constexpr double kHullToleranceUlps = 8;

/// What the points span.
enum class HullKind {
    Empty,  ///< no points
    Point,  ///< all points coincide (within tolerance)
    Line,   ///< collinear
    Flat,   ///< coplanar: a polygon without volume
    Solid,  ///< a polytope with volume
};

const char *hullKindName(HullKind kind);

struct HullResult {
    HullKind kind = HullKind::Empty;
    /// Solid only: vertices (each an input point) and faces, counter-clockwise seen from
    /// outside; coplanar triangles are merged into one polygon face.
    PolytopePrim polytope;
    /// Points whose position relative to the hull the arithmetic could not settle (they
    /// would have made the hull's horizon inconsistent); each is within a few tolerances of
    /// the hull. Zero on all but pathological inputs.
    int unsettledPoints = 0;
};

/// The convex hull of `points` (non-finite points must not be given).
HullResult convexHull(const std::vector<Vec3> &points);

/// The tolerance convexHull uses for these points.
double hullTolerance(const std::vector<Vec3> &points);

/// More points than this for one hull are refused (a sphere with `$fn=100000` would give
/// 5e9): the hull is left out with a warning.
constexpr size_t kMaxHullPoints = 20'000'000;

/// The points whose convex hull is OpenSCAD's hull() of the subtree `node`, in the
/// coordinates of node's parent: cube corners; spheres, cylinders and cones as OpenSCAD
/// tessellates them (from the node's $fn/$fa/$fs, whatever the --facets mode); tori and
/// lathes as OpenSCAD's rotate_extrude mesh (from their `fragments`); polyhedron and
/// mesh vertices; polytope vertices. Unions are exact. An intersection of convex operands is
/// clipped exactly; a difference is exact when the subtracted parts miss every vertex of the
/// first operand's hull. Other cases are approximated with a warning at the CSG node. Returns
/// false (after a warning) when there are more than kMaxHullPoints. `op` names the operation
/// in warnings (resize() takes its bounding box from the same points).
bool gatherHullPoints(const Node &node, const Scene &scene, DiagnosticSink &diag,
                      std::vector<Vec3> &out, const char *op = "hull()");

/// A primitive as OpenSCAD 2021.01 tessellates it, in its own coordinates: box corners; spheres,
/// cylinders and cones from the node's $fn/$fa/$fs; tori and lathes as its rotate_extrude
/// mesh; meshes and non-convex prisms as their triangles; polytopes and convex prisms as their
/// faces. Each face is planar; their orientation is not specified.
PolytopePrim openscadPolyhedron(const Node &primitive, const Scene &scene);

/// Convex parts whose union is OpenSCAD's geometry of the subtree `node`, each as the points
/// whose hull it is (in the coordinates of node's parent), for minkowski(), which distributes
/// over unions: boxes, spheres, cylinders, polytopes and convex prisms as gatherHullPoints
/// takes them, convex polyhedra and meshes, intersections of convex operands, all under
/// transforms and unions. Every other subtree (a difference, a non-convex intersection, mesh or
/// extrusion, a solid of revolution) is passed to `solid` with its placement instead. Returns
/// false (after a warning) when there are more than kMaxHullPoints.
bool gatherConvexParts(const Node &node, const Scene &scene, DiagnosticSink &diag,
                       std::vector<std::vector<Vec3>> &out,
                       const std::function<void(const Node &, const Mat4 &)> &solid,
                       const char *op = "minkowski()");

}  // namespace rt::meshing
