// SPDX-License-Identifier: MIT
// The geometry budget: each expensive operation charges its estimated points and faces before
// doing the work, so a model that would run for minutes or exhaust memory ends in a located
// error naming --max-geometry, while realistic models stay far below the default.
#include <gtest/gtest.h>

#include <string>

#include "core/ir/diagnostics.h"
#include "importers/scad/scad_importer.h"
#include "test_support.h"

namespace rt::scad {
namespace {

using test::Imported;
using test::importText;

/// The CLI's options: the default budget from the constant `scadray` uses.
ImportOptions cliDefaults() {
    ImportOptions opts;
    opts.maxGeometry = kDefaultMaxGeometry;
    return opts;
}

/// The EvalError of importing `src` with `opts` (fails the test when there is none).
std::string budgetError(const std::string &src, const ImportOptions &opts, std::string *loc) {
    try {
        importText(src, "budget.scad", opts);
    } catch (const EvalError &e) {
        if (loc) *loc = e.loc().toString();
        return e.what();
    }
    ADD_FAILURE() << "expected an EvalError from " << src;
    return "";
}

TEST(GeometryBudget, HugeOffsetEndsInALocatedError) {
    // r = 1e9 with $fn = 1e6: a million points on one outline, which Clipper's strictly simple
    // pass compares pairwise (hours); the error points at the offset() that made them
    std::string loc;
    std::string err =
        budgetError("linear_extrude(1) offset(r=1e9, $fn=1e6) square(1);\n", cliDefaults(), &loc);
    EXPECT_EQ(loc, "budget.scad:1:19");
    EXPECT_NE(err.find("geometry budget of " + std::to_string(kDefaultMaxGeometry)),
              std::string::npos)
        << err;
    EXPECT_NE(err.find("--max-geometry"), std::string::npos) << err;
}

TEST(GeometryBudget, OffsetPointsAreChargedBeforeClipperMakesThem) {
    // Fragments too fine for the arc tolerance to resolve: Clipper would step 2e17 times
    // round each corner. Refused at the offset() itself, before any point exists
    std::string loc;
    std::string err = budgetError("offset(r=1e12, $fn=1e9) square(1);\n", cliDefaults(), &loc);
    EXPECT_EQ(loc, "budget.scad:1:1");
    EXPECT_EQ(err.rfind("offset(): about ", 0), 0u) << err;
    EXPECT_NE(err.find("points"), std::string::npos) << err;
}

TEST(GeometryBudget, ProjectionOfAFineSphereEndsInALocatedError) {
    // 2,000 x 1,000 fragments: two million faces whose shadows Clipper would unite
    std::string loc;
    std::string err = budgetError("projection() sphere(10, $fn=2000);\n", cliDefaults(), &loc);
    EXPECT_EQ(loc, "budget.scad:1:1");
    EXPECT_EQ(err.rfind("projection(): about 4e+12 face pairs", 0), 0u) << err;
    EXPECT_NE(err.find("--max-geometry"), std::string::npos) << err;
}

TEST(GeometryBudget, ZeroMeansNoCapAndTheBudgetIsCumulative) {
    // Each projection of a sphere of 20 x 10 fragments: 202 faces, about 41,000 face pairs
    const std::string one = "linear_extrude(1) projection() sphere(5, $fn=20);\n";
    ImportOptions opts;
    opts.maxGeometry = 60'000;
    EXPECT_NO_THROW(importText(one, "budget.scad", opts));
    std::string loc;
    std::string err = budgetError(one + "translate([20, 0, 0])" + one, opts, &loc);
    EXPECT_EQ(loc, "budget.scad:2:40");
    EXPECT_NE(err.find("left of the geometry budget of 60000"), std::string::npos) << err;
    opts.maxGeometry = 0;
    EXPECT_NO_THROW(importText(one + "translate([20, 0, 0])" + one, "budget.scad", opts));
}

TEST(GeometryBudget, EachExpensiveOperationCharges) {
    ImportOptions opts;
    opts.maxGeometry = 10'000;
    struct Case {
        std::string src, what;
    };
    for (const Case &c : std::vector<Case>{
             {"circle(1, $fn=20000);", "circle()"},
             {"sphere(1, $fn=20000);", "sphere()"},
             {"cylinder(1, 1, 1, $fn=20000);", "cylinder()"},
             {"linear_extrude(1, twist=90, slices=5000) square(10);", "linear_extrude()"},
             {"rotate_extrude($fn=10000) translate([2, 0]) square(1);", "rotate_extrude()"},
             {"hull() sphere(1, $fn=200);", "hull()"},
             {"minkowski() { cube(1); sphere(1, $fn=200); }", "minkowski()"},
             {"resize([2, 2, 2]) sphere(1, $fn=200);", "resize()"},
             {"projection(cut=true) sphere(1, $fn=200);", "projection(cut = true)"},
             {"polyhedron([[0,0,0],[1,0,0],[0,1,0],[0,0,1]], [for (i = [1:3000]) "
              "each [[0,1,2],[0,3,1],[0,2,3],[1,3,2]]]);",
              "polyhedron()"}}) {
        SCOPED_TRACE(c.src);
        std::string err = budgetError(c.src, opts, nullptr);
        EXPECT_EQ(err.rfind(c.what + ": about ", 0), 0u) << err;
        EXPECT_NE(err.find("--max-geometry"), std::string::npos) << err;
    }
}

TEST(GeometryBudget, RepeatedPolyhedronFacesAreDrawnOnce) {
    // 130 bytes naming a tetrahedron's four faces 100,000 times (rotated copies count as the
    // same face): OpenSCAD's CGAL operations take it as the tetrahedron, and so does the
    // trace, with one warning giving the count
    Imported r = importText(
        "polyhedron([[0,0,0],[1,0,0],[0,1,0],[0,0,1]],\n"
        "  [for (i = [1:100000]) each [[0,1,2],[0,3,1],[2,3,0],[1,3,2]]]);\n",
        "", cliDefaults());
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.meshes[0]->triangles.size(), 4u);
    int warnings = 0;
    for (const std::string &w : r.warnings())
        if (w.find("repeat") != std::string::npos) ++warnings;
    EXPECT_EQ(warnings, 1);
    Diagnostic d = r.warning("399996 triangles repeat earlier faces");
    EXPECT_EQ(d.loc.line, 2) << d.message;
    // A face listed the other way round is another face (its back), kept
    Imported both = importText(
        "polyhedron([[0,0,0],[1,0,0],[0,1,0],[0,0,1]],\n"
        "  [[0,1,2],[0,3,1],[0,2,3],[1,3,2],[2,1,0]]);\n");
    EXPECT_EQ(both.scene.meshes[0]->triangles.size(), 5u);
    EXPECT_FALSE(both.hasWarning("repeat"));
}

TEST(GeometryBudget, RealisticModelsStayFarBelowTheDefault) {
    // Fine round parts, extrusions, hulls, offsets and a projection, as printer parts use them
    ImportOptions opts = cliDefaults();
    EXPECT_NO_THROW(importText(R"(
$fn = 360;
difference() {
    hull() for (x = [0, 80]) translate([x, 0, 0]) cylinder(r=10, h=5);
    for (x = [0, 80]) translate([x, 0, -1]) cylinder(r=3, h=7);
}
linear_extrude(20, twist=360, slices=200) offset(r=2) square(10, center=true);
rotate_extrude() translate([30, 0]) circle(4);
translate([0, 50, 0]) linear_extrude(1) projection() sphere(10, $fn=48);
minkowski() { cube([40, 20, 2]); sphere(2, $fn=32); }
for (i = [0:99]) translate([i * 3, 100, 0]) sphere(1);
)",
                               "budget.scad", opts));
}

}  // namespace
}  // namespace rt::scad
