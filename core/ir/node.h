// SPDX-License-Identifier: MIT
// IR node tree: groups, CSG operations, transforms and analytic primitives, each with its
// SourceLoc.
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

/// A point of a profile in the half-plane of a solid of revolution: r is the distance from
/// the +Z axis (r >= 0), z the height.
struct ProfilePoint {
    double r = 0, z = 0;
};
using ProfileOutline = std::vector<ProfilePoint>;

/// A solid of revolution about +Z (OpenSCAD's rotate_extrude of polygons): the region inside
/// `outlines` (even-odd rule, r >= 0) revolved from the +X axis counter-clockwise by `angle`
/// degrees (0 < angle <= 360; 360 is a full turn with no end faces). Each outline edge sweeps
/// a piece of a cone, a cylinder or an annulus. `fragments` is OpenSCAD's segment count over
/// `angle` (rotatePolygon), used when the solid is drawn faceted; 0 when unknown.
struct LathePrim {
    std::vector<ProfileOutline> outlines;
    double angle = 360;
    int fragments = 0;
};

/// A torus about +Z centred at the origin: the disc of radius `minor` whose centre is `major`
/// from the axis, revolved from +X counter-clockwise by `angle` degrees (0 < angle <= 360).
/// major >= minor > 0 (major == minor is the horn torus OpenSCAD makes of a circle touching
/// the axis). For the faceted form: `facetOutline` is OpenSCAD's polygon of the circle as
/// placed in the profile plane, and `fragments` its segment count over `angle`.
struct TorusPrim {
    double major = 1, minor = 0.25;
    double angle = 360;
    ProfileOutline facetOutline;
    int fragments = 0;
};

/// A point of a plane outline.
struct Point2 {
    double x = 0, y = 0;
};

/// A prism, frustum or pyramid (OpenSCAD's linear_extrude without twist and with a uniform
/// scale): the simple counter-clockwise `outline` swept along +Z from z0 to z1, scaled about
/// the Z axis by k0 at z0 and by k1 at z1, linearly in between (k0, k1 >= 0, not both 0; a
/// scale of 0 is an apex). A convex outline has `mesh` -1 and is drawn as the convex polytope
/// of its planar faces; a non-convex one names its closed triangle mesh in Scene::meshes (the
/// importer's sweep, with OpenSCAD's triangles), which the renderer draws. The POV-Ray writer
/// writes the outline itself as a `prism`.
struct PrismPrim {
    std::vector<Point2> outline;
    double z0 = 0, z1 = 1;
    double k0 = 1, k1 = 1;
    int mesh = -1;
};

using PrimShape = std::variant<SpherePrim, BoxPrim, CylinderPrim, MeshPrim, PolytopePrim, LathePrim,
                               TorusPrim, PrismPrim>;

/// OpenSCAD's $fn/$fa/$fs at the primitive, for the tessellated comparison mode.
struct Fragments {
    double fn = 0, fa = 12, fs = 2;
};

enum class NodeKind {
    Group,  ///< implicit union (module bodies, for, if, transforms' children); empty = no geometry
    Union,  ///< explicit union(): CSG union with internal surfaces removed
    Intersection,  ///< all children
    Difference,    ///< first child minus all others
    Transform,     ///< children under `matrix` (parent-from-child)
    Primitive,
};

/// Deepest nesting of nodes a scene may have (modules, transforms, colours and CSG operations
/// each add a level). OpenSCAD 2021.01 stops recursive modules near 2,500 calls (7,500 levels
/// here); the walks over the tree recurse, on stacks sized for this depth
/// (core/system/large_stack.h).
constexpr int kMaxTreeDepth = 20000;

struct Node {
    NodeKind kind = NodeKind::Group;
    SourceLoc loc;
    /// Optional human-readable origin ("module gear", "color(\"red\")"), used in export comments.
    std::string label;
    std::vector<std::unique_ptr<Node>> children;
    Mat4 matrix;             ///< Transform only
    PrimShape shape;         ///< Primitive only
    int material = -1;       ///< Primitive only: index into Scene::materials
    Fragments fragments;     ///< Primitive only
    bool highlight = false;  ///< OpenSCAD `#` modifier (rendered normally)
    /// Importer-internal: on an empty Group, the index of a 2D shape the importer keeps beside
    /// the tree until it is extruded or drawn as a plate. Never set in a finished scene.
    int shape2d = -1;

    Node() = default;
    Node(Node &&) = default;
    Node &operator=(Node &&) = default;
    /// Frees the subtree without recursion, so even a tree deeper than kMaxTreeDepth (one an
    /// importer is still refusing) cannot overflow the stack on its way out.
    ~Node();

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
