// SPDX-License-Identifier: MIT
// resize(), minkowski() and projection(): the IR they make and the located warnings for what
// they leave out (the cross-checks against OpenSCAD are in openscad_ops_crosscheck_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/facet_mode.h"
#include "core/ir/material.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

Bounds3 worldBounds(const Imported &r) {
    Bounds3 b;
    for (const auto &p : primitives(*r.scene.root)) {
        if (const auto *box = std::get_if<ir::BoxPrim>(&p.node->shape)) {
            for (int i = 0; i < 8; ++i)
                b = unionBounds(
                    b, p.worldFromObject.transformPoint(Bounds3(box->min, box->max).corner(i)));
        } else if (const auto *poly = std::get_if<ir::PolytopePrim>(&p.node->shape)) {
            for (const Vec3 &v : poly->vertices)
                b = unionBounds(b, p.worldFromObject.transformPoint(v));
        } else if (const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape)) {
            for (const auto &q : prism->outline)
                b = unionBounds(b, p.worldFromObject.transformPoint(Vec3(q.x, q.y, 0)));
        }
    }
    return b;
}

TEST(ScadResize, ScalesAboutTheOriginToTheNewSize) {
    Imported r = importText("resize([3, 5, 0], auto=true) translate([1, 1, 1]) cube([2, 4, 6]);");
    EXPECT_TRUE(r.warnings().empty());
    Bounds3 b = worldBounds(r);
    // x: 3 / 2; y: 5 / 4; z takes the scale of the largest new size (y)
    EXPECT_NEAR(b.min.x, 1.5, 1e-12);
    EXPECT_NEAR(b.max.x, 4.5, 1e-12);
    EXPECT_NEAR(b.max.y, 6.25, 1e-12);
    EXPECT_NEAR(b.max.z, 8.75, 1e-12);
}

TEST(ScadResize, UsesTheTessellatedBox) {
    // sphere(1, $fn=8) has no ring at the equator: its box is 2 sin(67.5 deg) wide, not 2
    Imported r = importText("resize([10, 0, 0], auto=true) sphere(1, $fn=8);");
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    const Mat4 &m = prims[0].worldFromObject;
    EXPECT_NEAR(m.transformVector(Vec3(1, 0, 0)).x, 10 / (2 * std::sin(67.5 * M_PI / 180)), 1e-12);
}

TEST(ScadResize, InfiniteSizeLeavesNothingWithAWarning) {
    Imported r = importText("resize([1/0, 0, 0]) cube(2);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    Diagnostic w = r.warning("leaves no finite volume");
    EXPECT_EQ(w.loc.line, 1);
    EXPECT_EQ(w.loc.col, 1);
}

TEST(ScadResize, TwoDimensionalChildrenAreResizedIn2D) {
    Imported r = importText("linear_extrude(1) resize([10, 0], auto=true) square([2, 1]);");
    Bounds3 b = worldBounds(r);
    EXPECT_NEAR(b.max.x, 10, 1e-9);
    EXPECT_NEAR(b.max.y, 5, 1e-9);
}

TEST(ScadMinkowski, ConvexOperandsGiveOnePolytope) {
    Imported r = importText("minkowski() { cube(1); translate([5, 0, 0]) cube(2); }");
    EXPECT_TRUE(r.warnings().empty());
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    const auto &p = std::get<ir::PolytopePrim>(prims[0].node->shape);
    EXPECT_EQ(p.vertices.size(), 8u);
    Bounds3 b = worldBounds(r);
    EXPECT_EQ(b.min, Vec3(5, 0, 0));
    EXPECT_EQ(b.max, Vec3(8, 3, 3));
}

TEST(ScadMinkowski, DistributesOverUnions) {
    Imported r = importText(
        "minkowski() { union() { cube(1); translate([4, 0, 0]) cube(1); } sphere(0.5, $fn=8); }");
    EXPECT_EQ(primitives(*r.scene.root).size(), 2u);
    EXPECT_EQ(r.scene.root->children.at(0)->kind, ir::NodeKind::Union);
}

TEST(ScadMinkowski, NonConvexOperandIsMovedAndItsBoundarySwept) {
    // A cube with a bore plus a small cube: the drilled cube moved by a corner of the small
    // one, and one hull per convex piece of its boundary (its faces, cut by the bore)
    Imported r = importText(
        "color(\"red\") minkowski() {\n  color(\"blue\") difference() { cube(4); "
        "translate([2, 2, -1]) cylinder(r=1, h=6, $fn=8); }\n  cube(0.5);\n}");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    const ir::Node &u = *r.scene.root->children.at(0)->children.at(0);  // under color()
    ASSERT_EQ(u.kind, ir::NodeKind::Union);
    size_t polytopes = 0, moved = 0;
    for (const auto &c : u.children) {
        if (c->kind == ir::NodeKind::Transform) {
            ++moved;
            EXPECT_EQ(c->children.at(0)->kind, ir::NodeKind::Difference);
        } else if (std::holds_alternative<ir::PolytopePrim>(c->shape)) {
            ++polytopes;
        }
    }
    EXPECT_EQ(moved, 1u);
    // 6 cube faces (4 sides whole, top and bottom triangulated around the bore) and 8 bore walls
    EXPECT_GT(polytopes, 14u);
    // The moved copy is drawn in the minkowski()'s colour, not its child's
    for (const auto &p : primitives(u))
        EXPECT_EQ(r.scene.materials.at(p.node->material).color, Rgb(1, 0, 0));
    Bounds3 b = worldBounds(r);
    EXPECT_NEAR(b.max.x, 4.5, 1e-12);
    EXPECT_NEAR(b.min.x, 0, 1e-12);
}

TEST(ScadMinkowski, ConvexMeshIsOnePolytopeAndAConcaveOneIsSwept) {
    // A cube as a polyhedron with two triangles per face (every corner a hull vertex): convex,
    // one hull of sums
    const char *cube =
        "polyhedron([[0,0,0],[2,0,0],[2,2,0],[0,2,0],[0,0,2],[2,0,2],[2,2,2],[0,2,2]], "
        "[[0,1,2],[0,2,3],[4,6,5],[4,7,6],[0,4,5],[0,5,1],[1,5,6],[1,6,2],[2,6,7],[2,7,3],"
        "[3,7,4],[3,4,0]])";
    Imported convex = importText(std::string("minkowski() { ") + cube + "; cube(1); }");
    auto prims = primitives(*convex.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    EXPECT_EQ(std::get<ir::PolytopePrim>(prims[0].node->shape).vertices.size(), 8u);
    // The same cube with a notch pressed into its top (a vertex below the top face): not
    // convex, so it is moved and its boundary swept, giving more than one part
    const char *notched =
        "polyhedron([[0,0,0],[2,0,0],[2,2,0],[0,2,0],[0,0,2],[2,0,2],[2,2,2],[0,2,2],[1,1,1]], "
        "[[0,1,2],[0,2,3],[4,8,5],[5,8,6],[6,8,7],[7,8,4],[0,4,5],[0,5,1],[1,5,6],[1,6,2],"
        "[2,6,7],[2,7,3],[3,7,4],[3,4,0]])";
    Imported concave = importText(std::string("minkowski() { ") + notched + "; cube(1); }");
    EXPECT_GT(primitives(*concave.scene.root).size(), 1u);
}

TEST(ScadMinkowski, TwoDimensionalSumIsAPolygon) {
    Imported r = importText("linear_extrude(1) minkowski() { square(2); circle(1, $fn=4); }");
    EXPECT_TRUE(r.warnings().empty());
    Bounds3 b = worldBounds(r);
    EXPECT_NEAR(b.min.x, -1, 1e-4);
    EXPECT_NEAR(b.max.x, 3, 1e-4);
}

TEST(ScadProjection, CutOfACubeAtItsFaceIsTheFace) {
    Imported r = importText("linear_extrude(1) projection(cut=true) cube([2, 3, 1]);");
    EXPECT_TRUE(r.warnings().empty());
    Bounds3 b = worldBounds(r);
    EXPECT_NEAR(b.max.x, 2, 1e-4);
    EXPECT_NEAR(b.max.y, 3, 1e-4);
}

TEST(ScadProjection, CutThatMissesWarns) {
    Imported r = importText("projection(cut=true) translate([0, 0, 5]) cube(1);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(r.hasWarning("do not meet the plane z = 0"));
}

TEST(ScadProjection, ShadowOfADifferenceKeepsTheHole) {
    // A tube seen from above: a ring, whose hole makes the extrusion a difference of prisms
    Imported r = importText(
        "linear_extrude(1) projection() difference() { cylinder(r=2, h=1, $fn=8); "
        "cylinder(r=1, h=3, center=true, $fn=8); }");
    EXPECT_TRUE(r.warnings().empty());
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 2u);
    const auto &hole = std::get<ir::PrismPrim>(prims[1].node->shape);
    EXPECT_NEAR(hole.outline.at(2).x, 1, 1e-4);
}

TEST(ScadProjection, ShadowOfAnIntersectionIsItsOverlap) {
    // Two boxes overlapping in [1, 2] x [0, 1]: the shadow is that square only
    Imported r = importText(
        "linear_extrude(1) projection() intersection() { cube([2, 1, 1]); translate([1, 0, 0.5]) "
        "cube([2, 1, 1]); }");
    Bounds3 b = worldBounds(r);
    EXPECT_NEAR(b.min.x, 1, 1e-4);
    EXPECT_NEAR(b.max.x, 2, 1e-4);
}

TEST(ScadProjection, TwoDimensionalChildrenAreIgnoredWithAWarning) {
    Imported r = importText("projection() { square(2); cube(1); }");
    EXPECT_TRUE(r.hasWarning("2D children are ignored"));
}

}  // namespace
}  // namespace rt::scad::test
