// SPDX-License-Identifier: MIT
// hull(): one polytope primitive from the children's OpenSCAD points, placed and coloured
// like any primitive; located warnings for flat hulls, approximations and 2D children.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/material.h"
#include "core/meshing/facets.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

const ir::PolytopePrim &onlyPolytope(const Imported &r, Mat4 *worldFromObject = nullptr) {
    auto p = primitives(*r.scene.root);
    EXPECT_EQ(p.size(), 1u);
    if (worldFromObject) *worldFromObject = p.at(0).worldFromObject;
    return std::get<ir::PolytopePrim>(p.at(0).node->shape);
}

Bounds3 boundsOf(const ir::PolytopePrim &p) {
    Bounds3 b;
    for (const Vec3 &v : p.vertices) b = unionBounds(b, v);
    return b;
}

TEST(ScadHull, TwoCubesGiveOnePolytopeOfTheirOuterCorners) {
    Imported r = importText("hull() { cube(1); translate([3, 0, 0]) cube(1); }");
    const ir::PolytopePrim &p = onlyPolytope(r);
    EXPECT_EQ(p.vertices.size(), 8u);
    EXPECT_EQ(p.faces.size(), 6u);
    EXPECT_EQ(boundsOf(p).max, Vec3(4, 1, 1));
    EXPECT_TRUE(r.warnings().empty());
}

TEST(ScadHull, PlacedUnderItsOwnTransformAndColouredByItsContext) {
    // The transform above hull() stays a transform; colours inside do not matter
    Imported r = importText(
        "color(\"red\") translate([10, 0, 0]) hull() { color(\"blue\") cube(2); sphere(1); }");
    Mat4 worldFromObject;
    const ir::PolytopePrim &p = onlyPolytope(r, &worldFromObject);
    EXPECT_EQ(worldFromObject, Mat4::translate(Vec3(10, 0, 0)));
    EXPECT_EQ(boundsOf(p).max, Vec3(2, 2, 2));
    // sphere(1) with the defaults: 5 fragments, 3 rings, the lowest at -cos(30 deg)
    EXPECT_NEAR(boundsOf(p).min.z, -std::cos(M_PI / 6), 1e-12);
    const ir::Node &n = *primitives(*r.scene.root).at(0).node;
    EXPECT_EQ(r.scene.materials.at(n.material).color, Rgb(1, 0, 0));
}

TEST(ScadHull, NestedHullsAndTessellationFromDollarVariables) {
    Imported r = importText(
        "hull($fn = 6) { hull() { sphere(2); } translate([0, 0, 5]) "
        "cylinder(r = 1, h = 1); }");
    const ir::PolytopePrim &p = onlyPolytope(r);
    // The $fn of hull() reaches its children: a hexagonal sphere (3 rings of 6) and cylinder.
    // The cylinder's lower ring lies on the sides between the sphere's top ring and its top
    // ring (same radius, same angles), so 18 corners remain, as in OpenSCAD's OFF export
    EXPECT_EQ(p.vertices.size(), 18u);
    EXPECT_DOUBLE_EQ(boundsOf(p).max.x, 2);
    EXPECT_DOUBLE_EQ(boundsOf(p).max.z, 6);
}

TEST(ScadHull, FacetsModeLeavesHullsAlone) {
    Imported r = importText("hull() sphere(5, $fn = 40);");
    ir::PolytopePrim before = onlyPolytope(r);
    for (ir::FacetMode mode : {ir::FacetMode::Smooth, ir::FacetMode::OpenScad}) {
        meshing::applyFacets(r.scene, mode, r.diag);
        EXPECT_EQ(onlyPolytope(r).vertices, before.vertices);
        EXPECT_EQ(r.scene.stats.facets->faceted + r.scene.stats.facets->smooth, 0);
    }
}

TEST(ScadHull, FlatHullsAreLeftOutWithALocatedWarning) {
    Imported r = importText(
        "cube();\n  hull() { translate([0, 0, 1]) cube([1, 1, 0]); "
        "polyhedron([[0,0,0],[1,0,0],[0,1,0]], [[0,1,2]]); }");
    Diagnostic w = r.warning("hull()");
    EXPECT_EQ(w.loc.line, 2);
    EXPECT_EQ(w.loc.col, 3);
    // cube([1,1,0]) is empty already; the triangle alone is flat
    EXPECT_TRUE(
        r.hasWarning("hull(): the children's 3 points are coplanar, so the hull has no "
                     "volume; left out"));
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
}

TEST(ScadHull, FlattenedChildrenStillGivePoints) {
    // scale([1, 1, 0]) flattens the cube to a square, whose corners join the hull (a pyramid)
    Imported r = importText(
        "hull() { scale([1, 1, 0]) cube(2, center = true); "
        "translate([0, 0, 3]) cube(0.001, center = true); }");
    const ir::PolytopePrim &p = onlyPolytope(r);
    EXPECT_EQ(boundsOf(p).min, Vec3(-1, -1, 0));
    EXPECT_FALSE(r.hasWarning("singular"));
}

TEST(ScadHull, ApproximatedDifferencesAndTwoDimensionalChildrenAreNamed) {
    Imported r = importText("hull() {\n  difference() { cube(4); cube(3); }\n  square(1);\n}");
    Diagnostic d = r.warning("hull() of a difference()");
    EXPECT_EQ(d.loc.line, 2);
    EXPECT_EQ(d.loc.col, 3);
    // The first child is 3D, so the hull is: OpenSCAD ignores the square with its warnings
    Diagnostic s = r.warning("Ignoring 2D child object for 3D operation");
    EXPECT_EQ(s.loc.line, 3);
    EXPECT_EQ(r.warning("Mixing 2D and 3D objects is not supported").loc.line, 3);
    EXPECT_EQ(boundsOf(onlyPolytope(r)).max, Vec3(4, 4, 4));
}

TEST(ScadHull, ExactDifferencesAndIntersectionsNeedNoWarning) {
    Imported r = importText(
        "hull() { difference() { cube(4); translate([1, 1, -1]) "
        "cylinder(r = 1, h = 6); } intersection() { sphere(3, $fn = 8); "
        "cube(2); } }");
    onlyPolytope(r);
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
}

TEST(ScadHull, BackgroundHullsAndEmptyHullsAreSilent) {
    Imported r = importText("%hull() cube(); hull(); hull() { cube(0); }");
    EXPECT_EQ(primitives(*r.scene.root).size(), 0u);
    EXPECT_EQ(r.warnings(), (std::vector<std::string>{
                                "cube(): size [0, 0, 0] is not positive and finite; OpenSCAD "
                                "makes empty geometry"}));
}

}  // namespace
}  // namespace rt::scad::test
