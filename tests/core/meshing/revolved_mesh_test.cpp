// SPDX-License-Identifier: MIT
// OpenSCAD's rotate_extrude mesh (closed, outward, OpenSCAD's vertices), the --facets rule for
// tori and lathes, and their dump, validation and bounds.
#include "core/meshing/revolved_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/ir_dump.h"
#include "core/ir/ir_validate.h"
#include "core/ir/scene_ir.h"
#include "core/meshing/facets.h"
#include "core/meshing/hull.h"

namespace rt::meshing {
using namespace ir;
namespace {

ProfileOutline rect(double r0, double r1, double z0, double z1) {
    return {{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
}

double volume(const Mesh &m) {
    double v = 0;
    for (const auto &t : m.triangles)
        v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]]));
    return v / 6;
}

/// Volume of a square [r0, r1] x [z0, z1] revolved as an n-gon over `angle` in n fragments:
/// each fragment is a wedge of the polygon whose corners sit at radius r.
double polygonVolume(double r0, double r1, double h, double angle, int n) {
    double step = angle / n * M_PI / 180;
    return n * 0.5 * std::sin(step) * (r1 * r1 - r0 * r0) * h;
}

void expectSolid(const Mesh &m, const char *what) {
    MeshTopology topo = analyzeMesh(m);
    EXPECT_TRUE(topo.oriented()) << what << ": boundary " << topo.boundaryEdges << " non-manifold "
                                 << topo.nonManifoldEdges << " misoriented "
                                 << topo.misorientedEdges;
    EXPECT_EQ(topo.degenerateTriangles, 0u) << what;
    EXPECT_GT(volume(m), 0) << what << " is inside out";
}

TEST(RevolvedMesh, FullTurnOfASquareHasOpenScadsRings) {
    Mesh m = openscadRevolve({rect(1, 2, 0, 1)}, 360, 4);
    expectSolid(m, "square, 4 fragments");
    EXPECT_EQ(m.positions.size(), 16u);
    EXPECT_EQ(m.triangles.size(), 32u);
    // Rings at a = -90, 0, 90, 180: (r sin a, r cos a)
    EXPECT_EQ(m.positions[0], Vec3(-1, 0, 0));
    EXPECT_EQ(m.positions[4], Vec3(0, 1, 0));
    EXPECT_EQ(m.positions[8], Vec3(1, 0, 0));
    EXPECT_EQ(m.positions[12], Vec3(0, -1, 0));
    EXPECT_NEAR(volume(m), polygonVolume(1, 2, 1, 360, 4), 1e-12);
}

TEST(RevolvedMesh, PartialTurnsAreClosedByTheProfile) {
    for (double angle : {90.0, 180.0, 270.0, 359.0}) {
        SCOPED_TRACE(angle);
        Mesh m = openscadRevolve({rect(1, 2, 0, 1)}, angle, 4);
        expectSolid(m, "square");
        EXPECT_EQ(m.positions.size(), 20u);
        EXPECT_NEAR(volume(m), polygonVolume(1, 2, 1, angle, 4), 1e-12);
        // Ring 0 at azimuth 0, the last at `angle`
        EXPECT_EQ(m.positions[0], Vec3(1, 0, 0));
        Mesh h = openscadRevolve({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)}, angle, 5);
        expectSolid(h, "square with a hole");
        double expect = polygonVolume(1, 3, 2, angle, 5) - polygonVolume(1.5, 2.5, 1, angle, 5);
        EXPECT_NEAR(volume(h), expect, 1e-9);
    }
}

TEST(RevolvedMesh, WindingOfTheOutlinesDoesNotMatter) {
    ProfileOutline outer = rect(1, 3, 0, 2), hole = rect(1.5, 2.5, 0.5, 1.5);
    std::reverse(outer.begin(), outer.end());
    for (double angle : {360.0, 120.0}) {
        Mesh a = openscadRevolve({outer, hole}, angle, 6);
        Mesh b = openscadRevolve({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)}, angle, 6);
        expectSolid(a, "mixed winding");
        EXPECT_NEAR(volume(a), volume(b), 1e-9);
    }
}

TEST(RevolvedMesh, ProfilesOnTheAxisAreWelded) {
    // A square on the axis (a cylinder), a triangle with a vertex on it (a cone), and a
    // partial turn of both
    for (double angle : {360.0, 90.0, 270.0}) {
        SCOPED_TRACE(angle);
        Mesh cyl = openscadRevolve({rect(0, 1, 0, 1)}, angle, 6);
        expectSolid(cyl, "cylinder");
        Mesh cone = openscadRevolve({{{0, 0}, {1, 0}, {0, 2}}}, angle, 7);
        expectSolid(cone, "cone");
        Mesh tip = openscadRevolve({{{0, 1}, {1, 0}, {1, 2}}}, angle, 5);
        expectSolid(tip, "vertex on the axis");
    }
    EXPECT_EQ(openscadRevolve({rect(0, 1, 0, 1)}, 360, 6).positions.size(), 14u);
}

TEST(RevolvedMesh, ProfileTriangulationCoversTheEvenOddRegion) {
    // Two holes and an island in one of them
    std::vector<ProfileOutline> o = {rect(0, 10, 0, 10), rect(1, 4, 1, 9), rect(6, 9, 1, 9),
                                     rect(2, 3, 4, 6)};
    double area = 0;
    for (const auto &t : triangulateProfile(o)) {
        const ProfilePoint &a = o[t[0].first][t[0].second], &b = o[t[1].first][t[1].second],
                           &c = o[t[2].first][t[2].second];
        double twice = (b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r);
        EXPECT_GT(twice, 0);
        area += 0.5 * twice;
    }
    EXPECT_NEAR(area, 100 - 24 - 24 + 2, 1e-12);
    std::vector<int> parents = profileParents(o);
    EXPECT_EQ(parents, (std::vector<int>{-1, 0, 0, 1}));
    Mesh m = openscadRevolve(o, 200, 9);
    expectSolid(m, "nested outlines");
}

TEST(RevolvedMesh, FacetsModesForToriAndLathes) {
    auto make = [](double fn, int fragments) {
        Scene s;
        int mat = s.addMaterial(Material());
        LathePrim l;
        l.outlines = {rect(1, 2, 0, 1)};
        l.fragments = fragments;
        auto n = Node::makePrimitive(l, mat, {});
        n->fragments.fn = fn;
        s.root->children.push_back(std::move(n));
        TorusPrim t;
        t.major = 2;
        t.minor = 0.5;
        t.fragments = fragments;
        for (int i = 0; i < 8; ++i)
            t.facetOutline.push_back(
                {2 + 0.5 * std::cos(i * M_PI / 4), 0.5 * std::sin(i * M_PI / 4)});
        auto tn = Node::makePrimitive(t, mat, {});
        tn->fragments.fn = fn;
        s.root->children.push_back(std::move(tn));
        return s;
    };
    DiagnosticSink diag;
    Scene a = make(8, 8);
    applyFacets(a, FacetMode::Auto, diag);
    ASSERT_TRUE(std::holds_alternative<MeshPrim>(a.root->children[0]->shape));
    ASSERT_TRUE(std::holds_alternative<MeshPrim>(a.root->children[1]->shape));
    EXPECT_EQ(a.meshes.size(), 2u);
    EXPECT_EQ(a.stats.facets->faceted, 2);
    for (const auto &m : a.meshes) expectSolid(*m, "faceted");
    // No $fn at the rotate_extrude, or too many fragments: round under auto
    for (auto [fn, fragments] : {std::pair{0.0, 8}, std::pair{30.0, 30}}) {
        Scene s = make(fn, fragments);
        applyFacets(s, FacetMode::Auto, diag);
        EXPECT_TRUE(std::holds_alternative<LathePrim>(s.root->children[0]->shape));
        EXPECT_TRUE(std::holds_alternative<TorusPrim>(s.root->children[1]->shape));
        EXPECT_EQ(s.stats.facets->smooth, 2);
    }
    Scene o = make(0, 30);
    applyFacets(o, FacetMode::OpenScad, diag);
    EXPECT_EQ(o.stats.facets->faceted, 2);
    // Without a fragment count there is no OpenSCAD polygon: round
    Scene z = make(5, 0);
    applyFacets(z, FacetMode::OpenScad, diag);
    EXPECT_EQ(z.stats.facets->smooth, 2);
    EXPECT_TRUE(diag.all().empty());
}

TEST(RevolvedMesh, DumpValidateAndBounds) {
    Scene s;
    int mat = s.addMaterial(Material());
    LathePrim l;
    l.outlines = {rect(1, 2, 0, 1)};
    l.angle = 90;
    l.fragments = 3;
    s.root->children.push_back(Node::makePrimitive(l, mat, {}));
    TorusPrim t{3, 1, 360, {}, 0};
    s.root->children.push_back(Node::makePrimitive(t, mat, {}));
    std::string d = dump(*s.root);
    EXPECT_NE(d.find("lathe angle 90 fragments 3 outlines [[[1, 0] [2, 0] [2, 1] [1, 1]]]"),
              std::string::npos)
        << d;
    EXPECT_NE(d.find("torus major 3 minor 1 angle 360"), std::string::npos) << d;
    DiagnosticSink diag;
    EXPECT_NO_THROW(validateScene(s, diag));
    Bounds3 b = primitiveBounds(t);
    EXPECT_EQ(b.min, Vec3(-4, -4, -1));
    EXPECT_EQ(b.max, Vec3(4, 4, 1));
    EXPECT_EQ(primitiveBounds(l).max, Vec3(2, 2, 1));

    auto bad = [&](PrimShape shape) {
        Scene e;
        e.root->children.push_back(Node::makePrimitive(shape, e.addMaterial(Material()), {}));
        EXPECT_THROW(validateScene(e, diag), SceneError);
    };
    bad(TorusPrim{1, 0, 360, {}, 0});
    bad(TorusPrim{1, 2, 360, {}, 0});
    bad(TorusPrim{NAN, 0.5, 360, {}, 0});
    bad(TorusPrim{1, 0.5, 0, {}, 0});
    bad(TorusPrim{1, 0.5, 361, {}, 0});
    bad(LathePrim{{{{1, 0}, {2, 0}}}, 360, 0});
    bad(LathePrim{{{{-1, 0}, {2, 0}, {2, 1}}}, 360, 0});
    bad(LathePrim{{{{1, 0}, {2, INFINITY}, {2, 1}}}, 360, 0});
    bad(LathePrim{{rect(1, 2, 0, 1)}, -90, 0});
}

TEST(RevolvedMesh, HullUsesTheFacetedVertices) {
    // hull() of a lathe: OpenSCAD hulls its rotate_extrude mesh
    Scene s;
    int mat = s.addMaterial(Material());
    auto h = Node::makeGroup(NodeKind::Group, {});
    LathePrim l;
    l.outlines = {rect(1, 2, 0, 1)};
    l.fragments = 4;
    h->children.push_back(Node::makePrimitive(l, mat, {}));
    DiagnosticSink diag;
    std::vector<Vec3> pts;
    ASSERT_TRUE(gatherHullPoints(*h, s, diag, pts));
    EXPECT_EQ(pts.size(), 16u);
    HullResult r = convexHull(pts);
    ASSERT_FALSE(r.polytope.vertices.empty());
    EXPECT_EQ(r.polytope.vertices.size(), 8u);
}

}  // namespace
}  // namespace rt::meshing
