// SPDX-License-Identifier: MIT
// 2D primitives and linear_extrude: lifted to exact 3D primitives, CSG and transforms.
#include <cmath>
#include <functional>

#include "core/ir/mesh.h"
#include "core/ir/prism.h"
#include "core/meshing/facets.h"
#include "importers/scad/geometry2d/extrude.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

/// Signed volume of a closed triangle mesh (divergence theorem).
double meshVolume(const ir::Mesh &m) {
    double v = 0;
    for (const auto &t : m.triangles)
        v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]]));
    return v / 6;
}

/// The mesh of a twisted or unevenly scaled extrusion, or of a non-convex prism.
const ir::Mesh &meshOf(const Imported &r, const ir::Node &n) {
    if (const auto *prism = std::get_if<ir::PrismPrim>(&n.shape))
        return *r.scene.meshes.at(prism->mesh);
    return *r.scene.meshes.at(std::get<ir::MeshPrim>(n.shape).mesh);
}

/// The planar faces of a prism of a convex outline (which has no mesh).
ir::PolytopePrim polytopeOf(const ir::Node &n) {
    const auto &prism = std::get<ir::PrismPrim>(n.shape);
    EXPECT_LT(prism.mesh, 0);
    return ir::prismPolytope(prism);
}

TEST(Extrude, SquareBecomesBox) {
    Imported r = importText("linear_extrude(3) square([2, 4]);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &box = std::get<ir::BoxPrim>(p[0].node->shape);
    EXPECT_EQ(box.min, Vec3(0, 0, 0));
    EXPECT_EQ(box.max, Vec3(2, 4, 3));
    EXPECT_TRUE(r.warnings().empty());
}

TEST(Extrude, CenteredAndPositionalRules) {
    Imported r = importText("linear_extrude(height=4, center=true) square(2, center=true);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(std::get<ir::BoxPrim>(p[0].node->shape).min, Vec3(-1, -1, -2));
    // The second positional argument is `layer`, not `center` (2021.01): z from 0 to 10
    r = importText("linear_extrude(10, true) square(2);");
    p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(std::get<ir::BoxPrim>(p[0].node->shape).max.z, 10);
    // Default height 100; center=1 is not a boolean
    r = importText("linear_extrude(center=1) square(1);");
    p = primitives(*r.scene.root);
    EXPECT_EQ(std::get<ir::BoxPrim>(p[0].node->shape).max.z, 100);
}

TEST(Extrude, CircleBecomesCylinderWithItsFragments) {
    Imported r = importText("linear_extrude(2) circle(r=3, $fn=7);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &c = std::get<ir::CylinderPrim>(p[0].node->shape);
    EXPECT_EQ(c.r1, 3);
    EXPECT_EQ(c.r2, 3);
    EXPECT_EQ(c.z1, 2);
    EXPECT_EQ(p[0].node->fragments.fn, 7);
    // Scaled: a truncated cone; the facets pass counts from the larger radius, which must
    // give the circle's 16 fragments (r=5), not the 30 of r=10
    r = importText("linear_extrude(height=2, scale=2) circle(d=10);");
    p = primitives(*r.scene.root);
    const auto &cone = std::get<ir::CylinderPrim>(p[0].node->shape);
    EXPECT_EQ(cone.r2, 10);
    EXPECT_EQ(p[0].node->fragments.fn, 0);
    EXPECT_EQ(meshing::openscadFragments(cone.r2, p[0].node->fragments), 16);
}

TEST(Extrude, ScaleZeroMakesPyramidAndCone) {
    Imported r = importText(
        "linear_extrude(height=3, scale=0) square(2, center=true);"
        "linear_extrude(height=3, scale=-1) circle(1);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    const auto &pyr = polytopeOf(*p[0].node);
    EXPECT_EQ(pyr.vertices.size(), 5u);
    EXPECT_EQ(pyr.faces.size(), 5u);
    EXPECT_EQ(std::get<ir::CylinderPrim>(p[1].node->shape).r2, 0);
}

TEST(Extrude, PolygonIsPrismConvexWithoutMeshNonConvexWithClosedMesh) {
    Imported r = importText(
        "linear_extrude(2) polygon([[0,0],[4,0],[4,3]]);"
        "linear_extrude(2) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_EQ(polytopeOf(*p[0].node).vertices.size(), 6u);
    const auto &prism = std::get<ir::PrismPrim>(p[1].node->shape);
    EXPECT_EQ(prism.outline.size(), 6u);
    EXPECT_EQ(prism.z0, 0);
    EXPECT_EQ(prism.z1, 2);
    EXPECT_EQ(prism.k0, 1);
    EXPECT_EQ(prism.k1, 1);
    const ir::Mesh &m = meshOf(r, *p[1].node);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_NEAR(meshVolume(m), 7 * 2, 1e-12);
}

TEST(Extrude, PrismMeshIsClosedAndOutwardWithPrismVolumes) {
    // An L of area 5: straight, narrowing, to an apex on top and from one below
    const std::vector<ir::Point2> ell{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    struct Case {
        double k0, k1, volume;
        size_t positions;
    };
    for (Case c : {Case{1, 1, 5 * 2, 12}, Case{2, 0.5, 2.0 / 3 * 5 * (4 + 0.25 + 1), 12},
                   Case{1, 0, 5 * 2.0 / 3, 7}, Case{0, 1, 5 * 2.0 / 3, 7}}) {
        ir::Mesh m;
        ASSERT_TRUE(prismMesh(ir::PrismPrim{ell, 0, 2, c.k0, c.k1, -1}, m));
        EXPECT_TRUE(ir::analyzeMesh(m).oriented()) << c.k0 << " " << c.k1;
        EXPECT_NEAR(meshVolume(m), c.volume, 1e-12) << c.k0 << " " << c.k1;
        EXPECT_EQ(m.positions.size(), c.positions);
    }
    // An outline of no area has no caps
    ir::Mesh m;
    EXPECT_FALSE(prismMesh(ir::PrismPrim{{{0, 0}, {1, 0}, {2, 0}}, 0, 1, 1, 1, -1}, m));
}

TEST(Extrude, PolygonHoleIsDifferenceWithPaddedSubtrahend) {
    for (const char *hole : {"[4,5,6,7]", "[4,7,6,5]"}) {
        Imported r = importText(std::string("linear_extrude(2) polygon([[0,0],[10,0],[10,10],"
                                            "[0,10],[2,2],[8,2],[8,8],[2,8]], [[0,1,2,3],") +
                                hole + "]);");
        auto p = primitives(*r.scene.root);
        ASSERT_EQ(p.size(), 2u) << hole;
        // The hole reaches beyond both caps, so no cap of it lies in a cap of the outline
        const auto &h = polytopeOf(*p[1].node);
        double zmin = 1e9, zmax = -1e9;
        for (const Vec3 &v : h.vertices) {
            zmin = std::min(zmin, v.z);
            zmax = std::max(zmax, v.z);
        }
        EXPECT_LT(zmin, 0);
        EXPECT_GT(zmax, 2);
        EXPECT_FALSE(anyPlaceholder(*r.scene.root));
    }
}

TEST(Extrude, TwoDBooleansAndTransformsLift) {
    Imported r = importText(
        "linear_extrude(2) difference() { square(4); translate([1,1]) rotate(45) circle(1); }");
    const ir::Node *diff = nullptr;
    std::function<void(const ir::Node &)> find = [&](const ir::Node &n) {
        if (n.kind == ir::NodeKind::Difference) diff = &n;
        for (const auto &c : n.children) find(*c);
    };
    find(*r.scene.root);
    ASSERT_NE(diff, nullptr);
    auto p = primitives(*diff);
    ASSERT_EQ(p.size(), 2u);
    // The circle's cylinder sits at (1, 1), turned 45 degrees about z
    Vec3 c = p[1].worldFromObject.transformPoint(Vec3(0, 0, 1));
    EXPECT_NEAR(c.x, 1, 1e-12);
    EXPECT_NEAR(c.y, 1, 1e-12);
    Vec3 e = p[1].worldFromObject.transformPoint(Vec3(1, 0, 1));
    EXPECT_NEAR(e.x, 1 + std::sqrt(0.5), 1e-12);
}

TEST(Extrude, ScaledTranslateLiftsToShear) {
    // The top of a square at x in [1, 2] scaled by 2 spans x in [2, 4]
    Imported r = importText("linear_extrude(height=2, scale=2) translate([1,0]) square(1);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &poly = polytopeOf(*p[0].node);
    double xmin = 1e9, xmax = -1e9;
    for (const Vec3 &v : poly.vertices) {
        Vec3 w = p[0].worldFromObject.transformPoint(v);
        if (w.z != 2) continue;
        xmin = std::min(xmin, w.x);
        xmax = std::max(xmax, w.x);
    }
    EXPECT_NEAR(xmin, 2, 1e-12);
    EXPECT_NEAR(xmax, 4, 1e-12);
}

TEST(Extrude, WarningsOfOpenScad) {
    Imported r = importText("linear_extrude(1) rotate([90,0,0]) square(1);");
    EXPECT_TRUE(r.hasWarning("Scaling a 2D object with 0 - removing object"));
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    r = importText("linear_extrude(1) { square(1); cube(1); }");
    EXPECT_TRUE(r.hasWarning("Ignoring 3D child object for 2D operation"));
    EXPECT_FALSE(r.hasWarning("Mixing"));
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
    r = importText("linear_extrude(1) union() { square(1); cube(1); }");
    EXPECT_TRUE(r.hasWarning("Mixing 2D and 3D objects is not supported"));
    r = importText("square([1,2,3]);");
    EXPECT_TRUE(r.hasWarning("Unable to convert square(size=[1, 2, 3], ...) parameter"));
    r = importText("circle(3, 5);");
    EXPECT_TRUE(r.hasWarning("Too many unnamed arguments supplied"));
    r = importText("polygon([[0,0],[1,0],[\"a\",1]]);");
    EXPECT_TRUE(r.hasWarning("Unable to convert points[2] = [\"a\", 1] to a vec2 of numbers"));
    r = importText("linear_extrude(1) polygon([[0,0],[1,0],[1,1]], [[0,1,7]]);");
    EXPECT_TRUE(r.hasWarning("Point index 7 is out of bounds (from paths[0][2])"));
    r = importText("linear_extrude(0) square(1);");
    EXPECT_TRUE(r.hasWarning("height 0 is not positive"));
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    // Outlines that cross themselves are sanitized even-odd, as OpenSCAD does: no warning
    r = importText("linear_extrude(1)\n  polygon([[0,0],[2,2],[2,0],[0,2]]);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
}

TEST(Extrude, TopLevelTwoDIsPreviewPlate) {
    Imported r = importText("translate([0,0,5]) square(2);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &box = std::get<ir::BoxPrim>(p[0].node->shape);
    EXPECT_EQ(box.min.z, -0.5);
    EXPECT_EQ(box.max.z, 0.5);
    EXPECT_NEAR(p[0].worldFromObject.transformPoint(Vec3(0, 0, 0)).z, 5, 1e-12);
    EXPECT_TRUE(r.hasWarning("plates 1 unit thick"));
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
    // Mixed with 3D: both shown, with OpenSCAD's warning
    r = importText("union() {\n  square(2);\n  cube(1);\n}");
    // At the first child of the other dimension, as OpenSCAD locates it
    EXPECT_EQ(r.warning("Mixing 2D and 3D objects is not supported").loc.line, 3);
    EXPECT_EQ(primitives(*r.scene.root).size(), 2u);
    // scale([1,1,0]) keeps a 2D object (its 2D part is regular)
    r = importText("scale([1,1,0]) circle(1);");
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
}

TEST(Extrude, TwistOfSeveralOutlinesSweepsTheirUnion) {
    // OpenSCAD combines the outlines (Clipper) before sweeping, and so do we: the frame
    // minus its hole is one swept outline minus one swept hole, no warning
    Imported r = importText(
        "linear_extrude(height=10, twist=90)\n"
        "    difference() { square(4, center=true); square(2, center=true); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    auto hasDifference = [](const ir::Node &n, auto &self) -> bool {
        if (n.kind == ir::NodeKind::Difference) return true;
        for (const auto &c : n.children)
            if (self(*c, self)) return true;
        return false;
    };
    EXPECT_TRUE(hasDifference(*r.scene.root, hasDifference));
    EXPECT_EQ(primitives(*r.scene.root).size(), 2u);
    // Overlapping squares become one outline
    r = importText(
        "linear_extrude(height=10, twist=90) { square(4); translate([2, 2]) "
        "square(4); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
}

TEST(Extrude, TwistMeshHasOpenScadSlices) {
    // $fn=8, twist 90: ceil(90 / 360 * 8) = 2 slices, 3 rings of 4
    Imported r = importText("linear_extrude(height=10, twist=90, $fn=8) square(2);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const ir::Mesh &m = meshOf(r, *p[0].node);
    EXPECT_EQ(m.positions.size(), 12u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_GT(meshVolume(m), 0);
    // The top is turned clockwise: (2, 0) goes to (0, -2)
    bool found = false;
    for (const Vec3 &v : m.positions)
        found |= std::abs(v.x) < 1e-12 && std::abs(v.y + 2) < 1e-12 && v.z == 10;
    EXPECT_TRUE(found);
    // Default $fa/$fs: helix slices; given slices win
    r = importText("linear_extrude(height=10, twist=360, slices=5) circle(1, $fn=6);");
    EXPECT_EQ(meshOf(r, *primitives(*r.scene.root)[0].node).positions.size(), 6u * 6);
    // Non-uniform scale without twist: the diagonal slices ($fn = 3 here)
    r = importText("linear_extrude(height=1, scale=[2,1], $fn=3) square(1);");
    EXPECT_EQ(meshOf(r, *primitives(*r.scene.root)[0].node).positions.size(), 4u * 4);
}

TEST(Extrude, PolygonTouchingItselfSweepsToClosedSolids) {
    // A corner visited twice (a bow-tie through a repeated point): on its own its sweep would
    // be a non-manifold mesh, which CSG cannot use; Clipper's strictly simple pieces are solids
    Imported r = importText(
        "difference() { cube([9, 9, 1]); translate([1, 1, -1]) linear_extrude(3) "
        "polygon([[0,0],[2,0],[1,1],[2,2],[0,2],[1,1]]); }");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 3u);
    for (size_t i = 1; i < p.size(); ++i) {
        int mesh = -1;
        if (const auto *mp = std::get_if<ir::MeshPrim>(&p[i].node->shape)) mesh = mp->mesh;
        if (const auto *pp = std::get_if<ir::PrismPrim>(&p[i].node->shape)) mesh = pp->mesh;
        if (mesh >= 0) {
            EXPECT_TRUE(ir::analyzeMesh(*r.scene.meshes[mesh]).closed());
        }
    }
    EXPECT_TRUE(r.warnings().empty());
}

TEST(Extrude, StiffCasesStayFinite) {
    // Collinear and repeated points are dropped: a convex quad
    Imported r = importText(
        "linear_extrude(1) polygon([[0,0],[1,0],[1,0],[2,0],[2,2],[1,2],[0,2],[0,1],[0,0]]);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(polytopeOf(*p[0].node).vertices.size(), 8u);
    // 10,000 points, non-convex (a wavy circle)
    r = importText(
        "n = 10000; linear_extrude(1) polygon([for (i = [0:n-1]) "
        "(10 + (i % 2)) * [cos(360 * i / n), sin(360 * i / n)]]);");
    p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const ir::Mesh &m = meshOf(r, *p[0].node);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_GT(meshVolume(m), M_PI * 100);
    // Tiny and huge
    for (const char *src : {"linear_extrude(1e-6) polygon([[0,0],[1e-6,0],[0,1e-6],[1e-7,1e-7]]);",
                            "linear_extrude(1e6, twist=30) square(1e6);",
                            "linear_extrude(1, scale=0, twist=90) "
                            "polygon([[0,0],[2,0],[1,1],[2,2],[0,2]]);"}) {
        r = importText(src);
        p = primitives(*r.scene.root);
        ASSERT_EQ(p.size(), 1u) << src;
        const auto *prism = std::get_if<ir::PrismPrim>(&p[0].node->shape);
        if (std::holds_alternative<ir::MeshPrim>(p[0].node->shape) || (prism && prism->mesh >= 0)) {
            const ir::Mesh &mm = meshOf(r, *p[0].node);
            for (const Vec3 &v : mm.positions)
                EXPECT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
            EXPECT_TRUE(ir::analyzeMesh(mm).oriented()) << src;
            EXPECT_GT(meshVolume(mm), 0) << src;
        }
    }
}

}  // namespace
}  // namespace rt::scad::test
