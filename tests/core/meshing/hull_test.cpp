// SPDX-License-Identifier: MIT
// Quickhull: invariants on random and degenerate point sets, and OpenSCAD's hull points of
// IR trees (transforms, tessellated round primitives, intersections, differences).
#include "core/meshing/hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "core/ir/scene_ir.h"
#include "core/math/rng.h"
#include "core/meshing/facets.h"

namespace rt::meshing {
using namespace ir;
namespace {

/// Volume by the divergence theorem over fan-triangulated faces, about the first vertex so
/// far-off solids keep their digits.
double volume(const PolytopePrim &p) {
    double v = 0;
    auto at = [&](int i) { return p.vertices[i] - p.vertices[0]; };
    for (const auto &f : p.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k) v += dot(at(f[0]), cross(at(f[k]), at(f[k + 1])));
    return v / 6;
}

/// Checks a solid hull of `points`: a closed, consistently oriented surface of sphere
/// topology (V - E + F = 2), vertices drawn from the input, every input point inside or on
/// it, every face convex towards the outside. Returns the hull.
PolytopePrim checkHull(const std::vector<Vec3> &points) {
    HullResult h = convexHull(points);
    EXPECT_EQ(h.kind, HullKind::Solid);
    EXPECT_EQ(h.unsettledPoints, 0);
    const PolytopePrim &p = h.polytope;
    std::set<std::tuple<double, double, double>> input;
    for (const Vec3 &v : points) input.insert({v.x, v.y, v.z});
    for (const Vec3 &v : p.vertices) EXPECT_TRUE(input.count({v.x, v.y, v.z})) << v.toString();
    // Every directed edge once, and its reverse once
    std::map<std::pair<int, int>, int> edges;
    for (const auto &f : p.faces) {
        EXPECT_GE(f.size(), 3u);
        for (size_t k = 0; k < f.size(); ++k) ++edges[{f[k], f[(k + 1) % f.size()]}];
    }
    for (const auto &[e, n] : edges) {
        EXPECT_EQ(n, 1);
        EXPECT_EQ(edges.count({e.second, e.first}), 1u);
    }
    long v = static_cast<long>(p.vertices.size()), e = static_cast<long>(edges.size() / 2),
         f = static_cast<long>(p.faces.size());
    EXPECT_EQ(v - e + f, 2);
    // Inside or on every face plane, within the hull's tolerance
    double tol = 4 * hullTolerance(points);
    std::vector<FacePlane> planes = polytopePlanes(p);
    EXPECT_EQ(planes.size(), p.faces.size());
    int outside = 0;
    for (const Vec3 &q : points)
        for (const FacePlane &pl : planes) outside += dot(pl.normal, q) - pl.offset > tol;
    EXPECT_EQ(outside, 0);
    // Faces wind counter-clockwise seen from outside: their Newell normal agrees with the
    // plane oriented away from the centroid
    for (size_t i = 0; i < p.faces.size(); ++i) {
        const auto &face = p.faces[i];
        Vec3 n(0);
        for (size_t k = 0; k < face.size(); ++k)
            n += cross(p.vertices[face[k]], p.vertices[face[(k + 1) % face.size()]]);
        EXPECT_GT(dot(n, planes[i].normal), 0);
    }
    EXPECT_GT(volume(p), 0);
    return p;
}

std::vector<Vec3> cubeCorners(double lo, double hi) {
    std::vector<Vec3> c;
    for (int i = 0; i < 8; ++i) c.push_back(Bounds3(Vec3(lo), Vec3(hi)).corner(i));
    return c;
}

TEST(Hull, CubeCornersWithInteriorAndDuplicates) {
    std::vector<Vec3> pts = cubeCorners(0, 1);
    // Every corner again, the centre, and a face centre: none adds a vertex
    std::vector<Vec3> again = pts;
    pts.insert(pts.end(), again.begin(), again.end());
    pts.push_back(Vec3(0.5));
    pts.push_back(Vec3(0.5, 0.5, 1));
    PolytopePrim p = checkHull(pts);
    EXPECT_EQ(p.vertices.size(), 8u);
    // Coplanar triangles merged: six quadrilaterals
    EXPECT_EQ(p.faces.size(), 6u);
    for (const auto &f : p.faces) EXPECT_EQ(f.size(), 4u);
    EXPECT_NEAR(volume(p), 1, 1e-12);
}

TEST(Hull, LatticeOfCoplanarPoints) {
    // 11^3 points of a grid: masses of coplanar and collinear points on every face and edge
    std::vector<Vec3> pts;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j)
            for (int k = 0; k <= 10; ++k) pts.emplace_back(i * 0.1, j * 0.3, k - 5.0);
    PolytopePrim p = checkHull(pts);
    EXPECT_EQ(p.vertices.size(), 8u);
    EXPECT_EQ(p.faces.size(), 6u);
    EXPECT_NEAR(volume(p), 1.0 * 3 * 10, 1e-9);
}

TEST(Hull, RandomPointsInABall) {
    Rng rng(7);
    std::vector<Vec3> pts;
    while (pts.size() < 20000) {
        Vec3 v(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
        if (lengthSquared(v) <= 1) pts.push_back(v * 10 + Vec3(100, -50, 3));
    }
    PolytopePrim p = checkHull(pts);
    EXPECT_GT(p.vertices.size(), 100u);
    EXPECT_LT(volume(p), 4.0 / 3 * M_PI * 1000);
    EXPECT_GT(volume(p), 0.9 * 4.0 / 3 * M_PI * 1000);
}

TEST(Hull, PointsOnASphereAreAllVertices) {
    Rng rng(11);
    std::vector<Vec3> pts;
    for (int i = 0; i < 3000; ++i) {
        double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
        double r = std::sqrt(1 - z * z);
        pts.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
    PolytopePrim p = checkHull(pts);
    EXPECT_EQ(p.vertices.size(), pts.size());
}

TEST(Hull, OpenScadSphereKeepsItsVerticesAndPlanarQuads) {
    // OpenSCAD's sphere is already convex: its hull has all its vertices, and the four
    // corners of each band trapezoid are coplanar
    PolytopePrim s = openscadSphere(3, 12);
    PolytopePrim p = checkHull(s.vertices);
    EXPECT_EQ(p.vertices.size(), s.vertices.size());
    EXPECT_NEAR(volume(p), volume(s), 1e-9);
}

TEST(Hull, DegenerateInputsAreNamed) {
    EXPECT_EQ(convexHull({}).kind, HullKind::Empty);
    EXPECT_EQ(convexHull({Vec3(1, 2, 3), Vec3(1, 2, 3)}).kind, HullKind::Point);
    EXPECT_EQ(convexHull({Vec3(0), Vec3(1), Vec3(2), Vec3(0.5)}).kind, HullKind::Line);
    std::vector<Vec3> flat;
    for (int i = 0; i < 50; ++i) flat.emplace_back(std::cos(i), std::sin(i), 0);
    EXPECT_EQ(convexHull(flat).kind, HullKind::Flat);
    // Tilted plane: coplanar up to rounding only
    std::vector<Vec3> tilted;
    Mat4 m = Mat4::rotateAxis(33, Vec3(1, 2, 3)) * Mat4::translate(Vec3(5, 6, 7));
    for (const Vec3 &v : flat) tilted.push_back(m.transformPoint(v));
    EXPECT_EQ(convexHull(tilted).kind, HullKind::Flat);
    // A tetrahedron is the smallest solid
    PolytopePrim t = checkHull({Vec3(0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)});
    EXPECT_EQ(t.faces.size(), 4u);
    EXPECT_NEAR(volume(t), 1.0 / 6, 1e-15);
}

TEST(Hull, RotatedAndFarOffInputs) {
    // A rotated cube far from the origin: the tolerance scales with the coordinates
    Mat4 m = Mat4::translate(Vec3(1e6, -2e6, 3e5)) * Mat4::rotateAxis(17, Vec3(1, 1, 0));
    std::vector<Vec3> pts;
    for (const Vec3 &c : cubeCorners(-1, 1)) pts.push_back(m.transformPoint(c));
    PolytopePrim p = checkHull(pts);
    EXPECT_EQ(p.vertices.size(), 8u);
    EXPECT_NEAR(volume(p), 8, 1e-8);
}

// Point gathering from IR trees

NodePtr box(Vec3 lo, Vec3 hi) { return Node::makePrimitive(BoxPrim{lo, hi}, -1, {}); }

NodePtr placed(const Mat4 &m, NodePtr child) {
    NodePtr t = Node::makeTransform(m, {});
    t->children.push_back(std::move(child));
    return t;
}

NodePtr csg(NodeKind kind, NodePtr a, NodePtr b) {
    NodePtr n = Node::makeGroup(kind, {});
    n->children.push_back(std::move(a));
    n->children.push_back(std::move(b));
    return n;
}

HullResult hullOf(const Node &n, DiagnosticSink &diag) {
    Scene scene;
    std::vector<Vec3> pts;
    EXPECT_TRUE(gatherHullPoints(n, scene, diag, pts));
    return convexHull(pts);
}

TEST(HullPoints, TransformsAndTessellatedRoundPrimitives) {
    // cube(1) and translate([5,0,0]) sphere(1, $fn=8): 8 corners and 8 x 4 sphere points
    NodePtr s = Node::makePrimitive(SpherePrim{1}, -1, {});
    s->fragments.fn = 8;
    NodePtr g = csg(NodeKind::Group, box(Vec3(0), Vec3(1)),
                    placed(Mat4::translate(Vec3(5, 0, 0)), std::move(s)));
    DiagnosticSink diag;
    HullResult h = hullOf(*g, diag);
    ASSERT_EQ(h.kind, HullKind::Solid);
    Bounds3 b;
    for (const Vec3 &v : h.polytope.vertices) b = unionBounds(b, v);
    // Four rings at 22.5, 67.5, 112.5 and 157.5 degrees from +Z: no equator, no poles
    EXPECT_DOUBLE_EQ(b.max.x, 5 + std::cos(M_PI / 8));
    EXPECT_NEAR(b.max.z, 1, 1e-12);  // from the cube
    EXPECT_NEAR(b.min.z, -std::cos(M_PI / 8), 1e-12);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
}

TEST(HullPoints, IntersectionOfConvexOperandsIsClipped) {
    // cube 2 centred, intersected with a cube shifted by 1 in x: a 1 x 2 x 2 box
    NodePtr n = csg(NodeKind::Intersection, box(Vec3(-1), Vec3(1)),
                    placed(Mat4::translate(Vec3(1, 0, 0)), box(Vec3(-1), Vec3(1))));
    DiagnosticSink diag;
    HullResult h = hullOf(*n, diag);
    ASSERT_EQ(h.kind, HullKind::Solid);
    EXPECT_NEAR(volume(h.polytope), 4, 1e-12);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
    // Disjoint operands: nothing
    NodePtr apart = csg(NodeKind::Intersection, box(Vec3(0), Vec3(1)), box(Vec3(2), Vec3(3)));
    EXPECT_EQ(hullOf(*apart, diag).kind, HullKind::Empty);
}

TEST(HullPoints, DifferenceIsExactOnlyWhenCornersSurvive) {
    DiagnosticSink diag;
    // A hole through the middle keeps every corner: exact, no warning
    NodePtr hole =
        csg(NodeKind::Difference, box(Vec3(0), Vec3(4)), box(Vec3(1, 1, -1), Vec3(3, 3, 5)));
    HullResult h = hullOf(*hole, diag);
    EXPECT_NEAR(volume(h.polytope), 64, 1e-9);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
    // Cutting a corner off cannot be hulled exactly here: a warning names the approximation
    NodePtr corner = csg(NodeKind::Difference, box(Vec3(0), Vec3(4)), box(Vec3(3), Vec3(5)));
    hullOf(*corner, diag);
    EXPECT_EQ(diag.countContaining("hull() of a difference() that cuts corners"), 1);
}

}  // namespace
}  // namespace rt::meshing
