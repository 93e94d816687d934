// SPDX-License-Identifier: MIT
// offset() as OpenSCAD 2021.01's offset.cc reads its arguments, and the warnings of 2D
// subtrees evaluated by Clipper (GeometryEvaluator::applyToChildren2D).
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/prism.h"
#include "core/math/bounds3.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

/// Bounds of every primitive's world points (boxes, polytopes and meshes).
Bounds3 sceneBounds(const ir::Scene &scene) {
    Bounds3 b;
    for (const auto &p : primitives(*scene.root)) {
        std::vector<Vec3> local;
        if (const auto *box = std::get_if<ir::BoxPrim>(&p.node->shape)) {
            local = {box->min, box->max};
        } else if (const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape)) {
            local = ir::prismPoints(*prism);
        } else if (const auto *mp = std::get_if<ir::MeshPrim>(&p.node->shape)) {
            local = scene.meshes[mp->mesh]->positions;
        }
        for (const Vec3 &v : local) b = unionBounds(b, p.worldFromObject.transformPoint(v));
    }
    return b;
}

double xMax(const std::string &src) {
    Imported r = importText(src);
    EXPECT_TRUE(r.warnings().empty()) << src << ": " << r.warnings().front();
    return sceneBounds(r.scene).max.x;
}

TEST(Offset, RadiusWinsOverDeltaAndChamferNeedsDelta) {
    // A 2 x 2 square offset by 1: mitred corners reach x = 3 like round ones; the chamfer and
    // a coarse round join tell the join types apart on the diagonal
    const double q = 1.0 / 65536;
    EXPECT_EQ(xMax("linear_extrude(1) offset(r=1) square(2);"), 3);
    EXPECT_EQ(xMax("linear_extrude(1) offset(delta=1) square(2);"), 3);
    EXPECT_EQ(xMax("linear_extrude(1) offset(2) square(2);"), 4);  // r is the first positional
    EXPECT_EQ(xMax("linear_extrude(1) offset(r=2, delta=3) square(2);"), 4);
    EXPECT_EQ(xMax("linear_extrude(1) offset(r=true, delta=3) square(2);"), 5);
    EXPECT_EQ(xMax("linear_extrude(1) offset() square(2);"), 3);  // r = 1
    EXPECT_EQ(xMax("linear_extrude(1) offset(delta=0.1) square(2);"), 2 + 6554 * q);
}

TEST(Offset, JoinTypesGiveTheirCorners) {
    auto points = [](const std::string &src) {
        Imported r = importText(src);
        EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
        auto p = primitives(*r.scene.root);
        EXPECT_EQ(p.size(), 1u);
        const auto *prism = p.empty() ? nullptr : std::get_if<ir::PrismPrim>(&p[0].node->shape);
        return prism && prism->mesh < 0 ? prism->outline.size() : 0;
    };
    EXPECT_EQ(points("linear_extrude(1) offset(delta=1) square(2);"), 4u);
    EXPECT_EQ(points("linear_extrude(1) offset(delta=1, chamfer=true) square(2);"), 8u);
    // chamfer=1 is not a boolean: mitred
    EXPECT_EQ(points("linear_extrude(1) offset(delta=1, chamfer=1) square(2);"), 4u);
    EXPECT_EQ(points("linear_extrude(1) offset(r=1, chamfer=true) square(2);"), 8u);
    EXPECT_EQ(points("linear_extrude(1) offset(r=1, $fn=16) square(2);"), 20u);
}

TEST(Offset, ThreeDChildrenAreIgnoredWithoutTheMixingWarning) {
    Imported r = importText("linear_extrude(1) offset(r=1) {\n  square(1);\n  cube(1);\n}");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{"Ignoring 3D child object for 2D operation"}));
    EXPECT_EQ(r.warning("Ignoring 3D").loc.line, 3);
    // Only 3D children: nothing
    r = importText("linear_extrude(1) offset(r=1) cube(1);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    // Inside a union the mixing warning comes first, as applyToChildren's isValidDim gives it
    r = importText("linear_extrude(1) offset(r=1) union() { square(1); cube(1); }");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{"Mixing 2D and 3D objects is not supported",
                                        "Ignoring 3D child object for 2D operation"}));
}

TEST(Offset, NegativeOffsetCanRemoveEverything) {
    Imported r = importText("linear_extrude(1) offset(r=-0.6) square(1);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_TRUE(primitives(*r.scene.root).empty());
}

TEST(Offset, ExtraUnnamedArgumentsAndNonFiniteAmountsWarn) {
    Imported r = importText("linear_extrude(1) offset(2, 3) square(1);");
    EXPECT_TRUE(r.hasWarning("Too many unnamed arguments supplied"));
    EXPECT_EQ(sceneBounds(r.scene).max.x, 3);
    r = importText("linear_extrude(1) offset(r=1/0) square(1);");
    EXPECT_TRUE(r.hasWarning("offset(): r = inf is not finite"));
    EXPECT_TRUE(primitives(*r.scene.root).empty());
}

TEST(Offset, TopLevelOffsetIsAPlateAndNestsInBooleans) {
    Imported r = importText("offset(delta=1) square(2);");
    EXPECT_TRUE(r.hasWarning("plates 1 unit thick"));
    Bounds3 b = sceneBounds(r.scene);
    EXPECT_EQ(b.min.x, -1);
    EXPECT_EQ(b.max.y, 3);
    r = importText("linear_extrude(1) difference() { offset(r=2) square(4); square(4); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_EQ(sceneBounds(r.scene).min.y, -2);
}

TEST(SelfIntersectingPolygon, IsFilledEvenOddWithoutAWarning) {
    // The bow tie: two triangles meeting at (2, 2), swept as two prisms
    Imported r = importText("linear_extrude(1) polygon([[0,0],[4,4],[4,0],[0,4]]);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_EQ(primitives(*r.scene.root).size(), 2u);
    // The pentagram: the middle has winding 2, so it is empty. Clipper gives two outlines
    // touching at the crossings (9 and 6 points, OffsetCrossCheck compares them with
    // OpenSCAD's); split strictly simple they are the five points, five exact prisms
    r = importText(
        "linear_extrude(1) polygon([for (i = [0:4]) 5 * [cos(90 + 144 * i), "
        "sin(90 + 144 * i)]]);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    auto prims = primitives(*r.scene.root);
    EXPECT_EQ(prims.size(), 5u);
    for (const auto &p : prims) {
        const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape);
        ASSERT_TRUE(prism);
        EXPECT_EQ(prism->outline.size(), 3u);
        EXPECT_LT(prism->mesh, 0);
    }
    // In CSG the pieces must be closed solids (an outline touching itself is split)
    r = importText(
        "union() { linear_extrude(1) polygon([for (i = [0:4]) 5 * [cos(90 + 144 * "
        "i), sin(90 + 144 * i)]]); cube(1); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
}

}  // namespace
}  // namespace rt::scad::test
