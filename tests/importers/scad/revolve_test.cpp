// SPDX-License-Identifier: MIT
// rotate_extrude: lifted to tori and lathes under OpenSCAD 2021.01's rules (angle, sides of
// the axis, segment count, its error for profiles across the axis, the DXF form).
#include <cmath>

#include "core/ir/facet_mode.h"
#include "importers/scad/geometry2d/revolve.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

bool hasError(const Imported &r, const std::string &part) {
    for (const auto &d : r.diag.all())
        if (d.severity == Severity::Error && d.message.find(part) != std::string::npos) return true;
    return false;
}

TEST(Revolve, TranslatedCircleIsATorus) {
    Imported r = importText("rotate_extrude() translate([5, 2]) circle(r=1.5, $fn=6);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &t = std::get<ir::TorusPrim>(p[0].node->shape);
    EXPECT_EQ(t.major, 5);
    EXPECT_EQ(t.minor, 1.5);
    EXPECT_EQ(t.angle, 360);
    // The facet outline is the hexagon relative to the torus centre; z = 2 is a translation
    ASSERT_EQ(t.facetOutline.size(), 6u);
    EXPECT_DOUBLE_EQ(t.facetOutline[0].r, 6.5);
    EXPECT_DOUBLE_EQ(t.facetOutline[0].z, 0);
    EXPECT_EQ(p[0].worldFromObject.transformPoint(Vec3(0, 0, 0)), Vec3(0, 0, 2));
    // $fa = 12, $fs = 2 at max |x| = 6.5: ceil(max(min(30, 20.4), 5)) = 21 segments
    EXPECT_EQ(t.fragments, 21);
    EXPECT_TRUE(r.warnings().empty());
}

TEST(Revolve, PolygonIsALatheOfItsOutlines) {
    Imported r = importText(
        "rotate_extrude($fn=8) polygon([[1,0],[4,0],[4,3],[1,3],[2,1],[3,1],[3,2],[2,2]],"
        " [[0,1,2,3],[4,5,6,7]]);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &l = std::get<ir::LathePrim>(p[0].node->shape);
    ASSERT_EQ(l.outlines.size(), 2u);
    EXPECT_EQ(l.outlines[0][1].r, 4);
    EXPECT_EQ(l.outlines[0][2].z, 3);
    EXPECT_EQ(l.fragments, 8);
    EXPECT_EQ(p[0].node->fragments.fn, 8);
}

TEST(Revolve, SquareAndDifferenceLiftToCsg) {
    Imported r = importText(
        "rotate_extrude() difference() { translate([2, 0]) square([3, 2]);"
        " translate([3.5, 1]) circle(0.5); }");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<ir::LathePrim>(p[0].node->shape));
    EXPECT_TRUE(std::holds_alternative<ir::TorusPrim>(p[1].node->shape));
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
}

TEST(Revolve, AngleRules) {
    // 2021.01: outside (-360, 360] is a full turn
    EXPECT_EQ(revolveAngle(400), 360);
    EXPECT_EQ(revolveAngle(-360), 360);
    EXPECT_EQ(revolveAngle(360), 360);
    EXPECT_EQ(revolveAngle(-359), -359);
    EXPECT_EQ(revolveAngle(std::nan("")), 360);
    Imported r = importText("rotate_extrude(angle=90, $fn=8) translate([2, 0]) square(1);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &l = std::get<ir::LathePrim>(p[0].node->shape);
    EXPECT_EQ(l.angle, 90);
    EXPECT_EQ(l.fragments, 2);  // trunc(8 * 90 / 360)
    EXPECT_EQ(p[0].worldFromObject, Mat4());
    // A clockwise sweep is the counter-clockwise one turned back by the angle
    r = importText("rotate_extrude(angle=-90) translate([2, 0]) square(1);");
    p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    EXPECT_EQ(std::get<ir::LathePrim>(p[0].node->shape).angle, 90);
    Vec3 q = p[0].worldFromObject.transformPoint(Vec3(1, 0, 0));
    EXPECT_NEAR(q.x, 0, 1e-15);
    EXPECT_NEAR(q.y, -1, 1e-15);
    // angle = 0: empty, with a warning
    r = importText("rotate_extrude(angle=0) translate([2, 0]) square(1);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(r.hasWarning("angle 0"));
}

TEST(Revolve, NegativeSideIsMirroredAndTurned) {
    Imported r = importText("rotate_extrude(angle=90) translate([-3, 0]) square([1, 2]);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &l = std::get<ir::LathePrim>(p[0].node->shape);
    double rmin = 1e9, rmax = -1e9;
    for (const auto &q : l.outlines[0]) rmin = std::min(rmin, q.r), rmax = std::max(rmax, q.r);
    EXPECT_EQ(rmin, 2);
    EXPECT_EQ(rmax, 3);
    // Starts on -X, as OpenSCAD's rings do for a profile at x < 0
    Vec3 q = p[0].worldFromObject.transformPoint(Vec3(1, 0, 0));
    EXPECT_NEAR(q.x, -1, 1e-15);
    EXPECT_NEAR(q.y, 0, 1e-15);
}

TEST(Revolve, ProfileAcrossTheAxisIsOpenScadsError) {
    Imported r = importText("rotate_extrude() translate([-1, 0]) square([2, 1]);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(hasError(r,
                         "all points for rotate_extrude() must have the same X coordinate "
                         "sign (range is -1.00 -> 1.00)"));
    // A circle centred on the axis crosses it
    r = importText("rotate_extrude() circle(1);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(hasError(r, "same X coordinate sign"));
    // Touching the axis is allowed: a horn torus
    r = importText("rotate_extrude() translate([1, 0]) circle(1);");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    const auto &t = std::get<ir::TorusPrim>(p[0].node->shape);
    EXPECT_EQ(t.major, t.minor);
}

TEST(Revolve, SubtrahendAcrossTheAxisIsClipped) {
    // The first operand bounds the result: the subtracted square is cut at the axis
    Imported r = importText(
        "rotate_extrude(angle=90, $fn=4) difference() { square(2); translate([-1, -1]) "
        "square(1.5); }");
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 2u);
    const auto &cut = std::get<ir::LathePrim>(p[1].node->shape);
    for (const auto &q : cut.outlines[0]) EXPECT_GE(q.r, 0);
    // It reaches one segment beyond both end faces, on the same segment grid
    const auto &kept = std::get<ir::LathePrim>(p[0].node->shape);
    EXPECT_EQ(kept.fragments, 1);
    EXPECT_EQ(cut.angle, 270);
    EXPECT_EQ(cut.fragments, 3);
    Vec3 q = p[1].worldFromObject.transformPoint(Vec3(1, 0, 0));
    EXPECT_NEAR(q.x, 0, 1e-15);
    EXPECT_NEAR(q.y, -1, 1e-15);
}

TEST(Revolve, SidesAreThoseOfTheResultNotOfItsOperands) {
    // The first operand crosses the axis, the difference does not: OpenSCAD tests the
    // polygon set the children make, so there is no error
    Imported r = importText(
        "rotate_extrude() difference() { translate([-1, 0]) square([3, 1]);"
        " translate([-2, -1]) square([2, 3]); }");
    EXPECT_FALSE(hasError(r, "same X coordinate sign"));
    // The subtracted square lies at x <= 0, so nothing of it is left on the revolved side
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 1u);
    for (const auto &q : std::get<ir::LathePrim>(p[0].node->shape).outlines[0]) EXPECT_GE(q.r, 0);
    // Warnings of the children print once, though they are evaluated twice
    r = importText("rotate_extrude() { translate([2, 0]) square(1); cube(1); }");
    int ignoring = 0;
    for (const auto &w : r.warnings()) ignoring += w.find("Ignoring 3D child") != std::string::npos;
    EXPECT_EQ(ignoring, 1);
}

TEST(Revolve, ProfileBelowOpenScadsGridIsRevolvedWithAWarning) {
    // OpenSCAD sanitizes a polygon() on its grid (a square alone it takes as it is)
    Imported r = importText("rotate_extrude() polygon([[2e-6, 0], [3e-6, 0], [3e-6, 1e-6]]);");
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
    EXPECT_TRUE(r.hasWarning("smaller than OpenSCAD's 2D grid"));
    r = importText("rotate_extrude() translate([2e-6, 0]) square(1e-6);");
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
    EXPECT_TRUE(r.warnings().empty());
    // A profile with no area (one outline twice: even-odd) is empty, as in OpenSCAD, silently
    r = importText("rotate_extrude() polygon([[1,0],[2,0],[2,1],[1,1]], [[0,1,2,3],[0,1,2,3]]);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(r.warnings().empty());
}

TEST(Revolve, FirstPositionalArgumentIsTheDxfFile) {
    // 2021.01 binds rotate_extrude(180) to file = "180", reads no children and makes nothing
    Imported r = importText("rotate_extrude(180) translate([2, 0]) square(1);");
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    EXPECT_TRUE(r.hasWarning("Can't open DXF file '"));
    EXPECT_TRUE(r.hasWarning("DEPRECATED"));
}

TEST(Revolve, ThreeDChildrenAreIgnoredWithOpenScadsWarning) {
    Imported r = importText("rotate_extrude() { translate([2, 0]) square(1); cube(1); }");
    EXPECT_EQ(primitives(*r.scene.root).size(), 1u);
    EXPECT_TRUE(r.hasWarning("Ignoring 3D child object for 2D operation"));
}

TEST(Revolve, FragmentsFollowOpenScad) {
    XRange x;
    x.add(0);
    x.add(10);
    ir::Fragments f;  // $fa 12, $fs 2: min(30, 31.4) = 30
    EXPECT_EQ(revolveFragments(x, 360, f), 30);
    EXPECT_EQ(revolveFragments(x, 45, f), 3);  // trunc(3.75)
    EXPECT_EQ(revolveFragments(x, 1, f), 1);
    f.fn = 7;
    EXPECT_EQ(revolveFragments(x, -180, f), 3);
}

TEST(Revolve, ClipToPositiveXKeepsTheEvenOddFill) {
    Outline o{{-1, 0}, {2, 0}, {2, 2}, {-1, 2}};
    Outline c = clipToPositiveX(o);
    EXPECT_NEAR(std::abs(twiceSignedArea(c)), 8, 1e-12);
    for (Vec2 p : c) EXPECT_GE(p.x, 0);
    EXPECT_LT(clipToPositiveX(Outline{{-3, 0}, {-1, 0}, {-2, 1}}).size(), 3u);
}

}  // namespace
}  // namespace rt::scad::test
