// SPDX-License-Identifier: MIT
// hull() of 2D children: a convex polygon shape from the children's outline points, which
// extrudes or draws as a plate like any 2D shape; OpenSCAD's warnings for mixed dimensions,
// hulls without area and approximated CSG children.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/prism.h"
#include "importers/scad/geometry2d/shape2d.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

/// The faces of the one hull: a 3D hull's polytope, or an extruded 2D hull, a prism of a
/// convex outline (which has no mesh).
ir::PolytopePrim onlyPolytope(const Imported &r) {
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p.size(), 1u);
    if (const auto *poly = std::get_if<ir::PolytopePrim>(&p.at(0).node->shape)) return *poly;
    const auto &prism = std::get<ir::PrismPrim>(p.at(0).node->shape);
    EXPECT_LT(prism.mesh, 0);
    return ir::prismPolytope(prism);
}

Bounds3 boundsOf(const ir::PolytopePrim &p) {
    Bounds3 b;
    for (const Vec3 &v : p.vertices) b = unionBounds(b, v);
    return b;
}

void expectBounds(const ir::PolytopePrim &p, Vec3 min, Vec3 max) {
    Bounds3 b = boundsOf(p);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(b.min[k], min[k], 1e-12) << "axis " << k;
        EXPECT_NEAR(b.max[k], max[k], 1e-12) << "axis " << k;
    }
}

TEST(ScadHull2dGeometry, MonotoneChainDropsInnerDuplicateAndCollinearPoints) {
    Hull2d h = convexHull2d({{0, 0}, {2, 0}, {1, 0}, {2, 2}, {1, 1}, {0, 2}, {0, 2}, {0, 1}});
    EXPECT_EQ(h.kind, meshing::HullKind::Solid);
    EXPECT_EQ(h.ccw, (Outline{{0, 0}, {2, 0}, {2, 2}, {0, 2}}));
    EXPECT_GT(twiceSignedArea(h.ccw), 0);
    EXPECT_EQ(convexHull2d({}).kind, meshing::HullKind::Empty);
    EXPECT_EQ(convexHull2d({{1, 1}, {1, 1}}).kind, meshing::HullKind::Point);
    Hull2d line = convexHull2d({{0, 0}, {1, 1}, {3, 3}, {2, 2}});
    EXPECT_EQ(line.kind, meshing::HullKind::Line);
    EXPECT_TRUE(line.ccw.empty());
}

TEST(ScadHull2dGeometry, ConvexClipKeepsTheCommonPart) {
    Outline a{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, b{{2, 2}, {6, 2}, {6, 6}, {2, 6}};
    Outline c = clipConvex(a, b);
    EXPECT_NEAR(twiceSignedArea(c), 8, 1e-12);
    EXPECT_TRUE(clipConvex(a, {{5, 5}, {6, 5}, {6, 6}}).empty());
}

TEST(ScadHull2d, CircleAndTranslatedSquareExtrudeToOnePrism) {
    Imported r = importText(
        "linear_extrude(2) hull() { circle(5); translate([10, 0]) "
        "square(3); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    const ir::PolytopePrim &p = onlyPolytope(r);
    // The default circle is a 16-gon, so its top and bottom points are vertices
    expectBounds(p, Vec3(-5, -5, 0), Vec3(13, 5, 2));
    // A prism: every vertex at the bottom has one above it
    EXPECT_EQ(p.vertices.size() % 2, 0u);
    for (const Vec3 &v : p.vertices) EXPECT_TRUE(v.z == 0 || v.z == 2) << v.toString();
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
}

TEST(ScadHull2d, TopLevelHullIsDrawnAsAPlate) {
    Imported r = importText("hull() { circle(5); translate([10, 0]) square(3); }");
    expectBounds(onlyPolytope(r), Vec3(-5, -5, -0.5), Vec3(13, 5, 0.5));
    EXPECT_TRUE(r.hasWarning("plates 1 unit thick"));
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
}

TEST(ScadHull2d, TransformsToEachLeafAndNestedHulls) {
    // rotate(90) puts the 2x1 square at x in [-1, 0], y in [0, 2]; the inner hull of the
    // scaled square spans [5, 7] x [0, 1]. The hull: (-1,0) (7,0) (7,1) (0,2) (-1,2).
    Imported r = importText(
        "linear_extrude(1) hull() { rotate(90) square([2, 1]); "
        "hull() { translate([5, 0]) scale([2, 1]) square(1); } }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    const ir::PolytopePrim &p = onlyPolytope(r);
    expectBounds(p, Vec3(-1, 0, 0), Vec3(7, 2, 1));
    EXPECT_EQ(p.vertices.size(), 10u);
}

TEST(ScadHull2d, HullWithoutAreaIsLeftOutWithALocatedWarning) {
    Imported r = importText("cube();\nlinear_extrude(1)\n  hull() polygon([[0,0],[1,1],[2,2]]);");
    Diagnostic d = r.warning("hull():");
    EXPECT_EQ(d.message,
              "hull(): the children's 3 2D points are collinear, so the hull has no "
              "area; left out");
    EXPECT_EQ(d.loc.line, 3);
    EXPECT_EQ(d.loc.col, 3);
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);  // the cube only
    // A child scaled to nothing is removed, as OpenSCAD does, and the rest is hulled
    r = importText("linear_extrude(1) hull() { square(1); scale([0, 1]) square(5); }");
    EXPECT_TRUE(r.hasWarning("Scaling a 2D object with 0 - removing object"));
    expectBounds(onlyPolytope(r), Vec3(0, 0, 0), Vec3(1, 1, 1));
}

TEST(ScadHull2d, FirstChildDecidesTheDimension) {
    // 2D first: the cube is ignored, with OpenSCAD's warnings at the cube's call
    Imported r = importText(
        "linear_extrude(1) hull() {\n  circle(1, $fn=4);\n  translate([10, 0])"
        "\n    cube(3);\n}");
    EXPECT_EQ(r.warning("Mixing 2D and 3D objects is not supported").loc.line, 3);
    EXPECT_EQ(r.warning("Ignoring 3D child object for 2D operation").loc.line, 3);
    expectBounds(onlyPolytope(r), Vec3(-1, -1, 0), Vec3(1, 1, 1));
    // 3D first: the circle is ignored, and the hull is the cube's
    r = importText("hull() {\n  cube(3);\n  translate([10, 0]) circle(1);\n}");
    EXPECT_EQ(r.warning("Mixing 2D and 3D objects is not supported").loc.line, 3);
    EXPECT_EQ(r.warning("Ignoring 2D child object for 3D operation").loc.line, 3);
    expectBounds(onlyPolytope(r), Vec3(0, 0, 0), Vec3(3, 3, 3));
}

TEST(ScadHull2d, ExactDifferencesAndIntersectionsNeedNoWarning) {
    // The hole misses the square's corners; the intersection of two squares is Clipper's
    Imported r = importText(
        "linear_extrude(1) hull() difference() { square(4); "
        "translate([2, 2]) circle(1); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    expectBounds(onlyPolytope(r), Vec3(0, 0, 0), Vec3(4, 4, 1));
    r = importText("linear_extrude(1) hull() intersection() { square(4); rotate(45) square(4); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    // Clipper's grid: OpenSCAD exports the corner at 2.82841, 185363 / 65536, not 2 sqrt 2
    expectBounds(onlyPolytope(r), Vec3(0, 0, 0), Vec3(185363.0 / 65536, 4, 1));
}

TEST(ScadHull2d, DifferencesAndIntersectionsAreEvaluatedExactly) {
    // The difference cuts a corner: the hull is that of the L left over (Clipper evaluates
    // it as OpenSCAD does), no warning
    Imported r = importText(
        "linear_extrude(1) hull() {\n  difference() { square(4); "
        "translate([-1, -1]) square(2); }\n}");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    const ir::PolytopePrim &p = onlyPolytope(r);
    EXPECT_EQ(p.vertices.size(), 10u);  // (1,0) (4,0) (4,4) (0,4) (0,1) at both ends
    // A non-convex operand: the hull of the true intersection, inside the square
    r = importText(
        "linear_extrude(1) hull() intersection() {\n  polygon([[0,0],[4,0],[4,4],"
        "[2,1],[0,4]]);\n  square(4);\n}");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    expectBounds(onlyPolytope(r), Vec3(0, 0, 0), Vec3(4, 4, 1));
    EXPECT_EQ(onlyPolytope(r).vertices.size(), 8u);  // the dent at (2, 1) is not a corner
}

}  // namespace
}  // namespace rt::scad::test
