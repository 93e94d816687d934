// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's projection() of a 3D node tree onto the XY plane, as Clipper polygon sets:
// the slice at z = 0 (cut = true) and the shadow (cut = false), both computed from the
// primitives as OpenSCAD tessellates them, without building the CSG result's mesh.
#pragma once

#include <unordered_map>
#include <vector>

#include "core/ir/node.h"
#include "core/math/bounds3.h"
#include "importers/scad/geometry2d/clipper2d.h"

namespace rt::ir {
struct Scene;
}

namespace rt::scad {

/// A primitive of a tree with its faces as OpenSCAD tessellates them, in the tree's root
/// coordinates.
struct TessellatedLeaf {
    const ir::Node *node = nullptr;
    ir::PolytopePrim mesh;
    Bounds3 bounds;
};

/// The primitives of a node tree tessellated once, placed in the root's coordinates: the
/// projections and minkowski()'s boundary read them, and faces() measures their work before
/// any of it is done.
class Tessellation {
  public:
    Tessellation(const ir::Node &root, const Mat4 &rootFromNode, const ir::Scene &scene);

    /// Faces of all primitives (a shadow examines each face against every primitive's faces).
    size_t faces() const { return faces_; }
    /// The leaf of a primitive node of the tree.
    const TessellatedLeaf &leaf(const ir::Node &primitive) const {
        return leaves_[index_.at(&primitive)];
    }
    /// The leaves under `subtree` (a node of the tree), in tree order.
    std::vector<const TessellatedLeaf *> leavesUnder(const ir::Node &subtree) const;

  private:
    void add(const ir::Node &n, const Mat4 &rootFromNode, const ir::Scene &scene);

    std::vector<TessellatedLeaf> leaves_;
    std::unordered_map<const ir::Node *, size_t> index_;
    size_t faces_ = 0;
};

/// The cross-section of the solid `root` (its own coordinates) with the plane z = 0. Each
/// primitive is sliced as a closed solid (a face lying in the plane belongs to the section, as
/// in OpenSCAD, whose CGAL slice of cube(1) at its bottom face is the unit square), and the
/// sections are combined by the tree's unions, intersections and differences in Clipper.
/// `tess` is the tessellation of `root` with the identity placement.
clipper2d::PolygonSet projectCut(const Tessellation &tess, const ir::Node &root);

/// The shadow of the solid `root` on z = 0 (OpenSCAD: the union of the projections of every face
/// of the evaluated mesh). Unions are the union of their operands' shadows; a primitive is the
/// union of its faces; a difference or intersection is the union, over every face of its
/// primitives that is not vertical, of the part of that face on the result's boundary: where
/// the tree evaluated with the face's primitive present differs from the tree evaluated
/// without it, every other primitive being its section in the face's plane. Exact for solids
/// in general position; faces of different primitives in one plane count as touching.
clipper2d::PolygonSet projectShadow(const Tessellation &tess, const ir::Node &root);

/// Convex polygons (root coordinates: `tess` is the tessellation of `node` in its placement)
/// that lie in the solid
/// `node` and cover its boundary, for minkowski(): every face of its primitives (a face inside
/// a union is still inside the solid), or for a difference or an intersection the parts of its
/// primitives' faces on the result's boundary, computed as for the shadow in each face's own
/// plane (scaled to Clipper's full range) and triangulated.
std::vector<std::vector<Vec3>> solidBoundary(const Tessellation &tess, const ir::Node &node);

}  // namespace rt::scad
