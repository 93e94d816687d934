// SPDX-License-Identifier: MIT
// IR node tree: groups, CSG operations, transforms and analytic primitives, each with its SourceLoc.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/ir/source_loc.h"
#include "core/math/mat4.h"
#include "core/math/vec3.h"

namespace rt::ir {

/// Sphere of the given radius centred at the object-space origin.
struct SpherePrim {
    double radius = 1;
};

/// Axis-aligned box between two corners (min < max on every axis).
struct BoxPrim {
    Vec3 min{0, 0, 0}, max{1, 1, 1};
};

/// Truncated cone (OpenSCAD cylinder) along +Z from z0 to z1 with radius r1 at z0 and r2 at z1.
/// A cylinder has r1 == r2; a cone has one radius zero.
struct CylinderPrim {
    double z0 = 0, z1 = 1;
    double r1 = 1, r2 = 1;
};

/// A triangle mesh of Scene::meshes, placed by the node's transforms. Closed meshes are solids
/// (they can take part in CSG); open ones are surfaces only.
struct MeshPrim {
    int mesh = -1;
};

/// A convex polytope: the intersection of the half-spaces behind its faces. Faces are planar
/// vertex loops, counter-clockwise seen from outside; OpenSCAD's faceted spheres, cylinders
/// and cones (`--facets openscad`) and hulls are such solids.
struct PolytopePrim {
    std::vector<Vec3> vertices;
    std::vector<std::vector<int>> faces;
};

using PrimShape = std::variant<SpherePrim, BoxPrim, CylinderPrim, MeshPrim, PolytopePrim>;

/// OpenSCAD's $fn/$fa/$fs at the primitive, for the tessellated comparison mode.
struct Fragments {
    double fn = 0, fa = 12, fs = 2;
};

enum class NodeKind {
    Group,         ///< implicit union (module bodies, for, if, transforms' children); empty = no geometry
    Union,         ///< explicit union(): CSG union with internal surfaces removed
    Intersection,  ///< all children
    Difference,    ///< first child minus all others
    Transform,     ///< children under `matrix` (parent-from-child)
    Primitive,
};

struct Node {
    NodeKind kind = NodeKind::Group;
    SourceLoc loc;
    /// Optional human-readable origin ("module gear", "color(\"red\")"), used in export comments.
    std::string label;
    std::vector<std::unique_ptr<Node>> children;
    Mat4 matrix;                     ///< Transform only
    PrimShape shape;                 ///< Primitive only
    int material = -1;               ///< Primitive only: index into Scene::materials
    Fragments fragments;             ///< Primitive only
    bool highlight = false;          ///< OpenSCAD `#` modifier (rendered normally)
    /// Importer-internal: on an empty Group, the index of a 2D shape the importer keeps beside
    /// the tree until it is extruded or drawn as a plate. Never set in a finished scene.
    int shape2d = -1;

    static std::unique_ptr<Node> makeGroup(NodeKind kind, SourceLoc loc);
    static std::unique_ptr<Node> makeTransform(const Mat4 &m, SourceLoc loc);
    static std::unique_ptr<Node> makePrimitive(PrimShape shape, int material, SourceLoc loc);

    bool isCsg() const {
        return kind == NodeKind::Union || kind == NodeKind::Intersection ||
               kind == NodeKind::Difference;
    }
    /// Number of primitives in this subtree.
    size_t primitiveCount() const;
    std::unique_ptr<Node> clone() const;
};

using NodePtr = std::unique_ptr<Node>;

const char *nodeKindName(NodeKind k);

}  // namespace rt::ir
