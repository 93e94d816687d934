// SPDX-License-Identifier: MIT
// Cross-checks what goes through Clipper (offset(), self-intersecting polygons, 2D booleans
// under twist) against the installed OpenSCAD 2021.01: the outline points of its OFF export
// (or all its points, for twisted sweeps) against ours, both ways, at OFF's 6 digits.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/ir/prism.h"
#include "core/meshing/facets.h"
#include "importers/scad/openscad_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

struct Case {
    const char *src;
    bool allPoints;  ///< compare 3D points (mesh sweeps), else the points' (x, y)
};

class OffsetCrossCheck : public ::testing::TestWithParam<Case> {};

TEST_P(OffsetCrossCheck, PointsMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const Case &c = GetParam();
    SCOPED_TRACE(c.src);
    fs::path dir = fs::temp_directory_path() / ("scadray_offset_" + std::to_string(getpid()));
    fs::create_directories(dir);
    ir::Mesh theirs = openscadOff(c.src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());

    Imported ours = importText(c.src);
    EXPECT_TRUE(ours.warnings().empty()) << ours.warnings().front();
    meshing::applyFacets(ours.scene, ir::FacetMode::OpenScad, ours.diag);
    std::vector<Vec3> mine = worldPoints(ours.scene), ref = theirs.positions;
    if (!c.allPoints) {
        // Subtrahends reach beyond the caps: compare where the points stand in the plane
        for (Vec3 &v : mine) v.z = 0;
        for (Vec3 &v : ref) v.z = 0;
    }
    expectPointsCovered(mine, ref, "our point missing from OpenSCAD's:");
    expectPointsCovered(ref, mine, "OpenSCAD's point missing from ours:");
}

INSTANTIATE_TEST_SUITE_P(
    Clipper, OffsetCrossCheck,
    ::testing::Values(
        // offset(r): round joins with the arc tolerance of r's fragments
        Case{"linear_extrude(1) offset(r=1) square(2);", false},
        Case{"linear_extrude(1) offset(r=1, $fn=16) square(2);", false},
        Case{"linear_extrude(1) offset(0.3, $fn=7) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]);",
             false},
        Case{"linear_extrude(1) offset(r=-0.4, $fn=12) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],"
             "[0,4]]);",
             false},
        // offset(delta): mitred, or chamfered
        Case{"linear_extrude(1) offset(delta=0.7) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]);",
             false},
        Case{"linear_extrude(1) offset(delta=0.7, chamfer=true) polygon([[0,0],[4,0],[4,1],[1,1],"
             "[1,4],[0,4]]);",
             false},
        // Small coordinates show Clipper's grid and its truncation
        Case{"linear_extrude(1) offset(delta=0.1) polygon([[0,0],[0.7,0.1],[0.3,0.9]]);", false},
        // Holes: one grows, one closes; a negative offset removes a thin part
        Case{"linear_extrude(1) offset(delta=-0.5) difference() { square(6); "
             "translate([2, 2]) square(2); }",
             false},
        Case{"linear_extrude(1) offset(r=1.2) difference() { square(6); "
             "translate([2.5, 2.5]) square(1); }",
             false},
        Case{"linear_extrude(1) offset(delta=-0.6) union() { square(4); square([10, 1]); }", false},
        // Closing a gap: offset in, then out, of a union
        Case{"linear_extrude(1) offset(r=-1, $fn=20) offset(r=1, $fn=20) { square(3); "
             "translate([3.5, 0]) square(3); }",
             false},
        // A mirrored offset is sanitized again
        Case{"linear_extrude(1) mirror([1, 0]) offset(delta=0.3) polygon([[0,0],[3,0.2],[1,2]]);",
             false},
        // Self-intersecting polygons, filled even-odd
        Case{"linear_extrude(2) polygon([[0,0],[4,4],[4,0],[0,4]]);", false},
        Case{"linear_extrude(2) polygon([for (i = [0:4]) 5 * [cos(90 + 144 * i), "
             "sin(90 + 144 * i)]]);",
             false},
        Case{"linear_extrude(2) polygon([[0,0],[0.9,0.9],[0.9,0.1],[0.1,0.7]]);", false},
        // Twist and non-uniform scale sweep OpenSCAD's union of the outlines
        Case{"linear_extrude(height=10, twist=90) { square(4, center=true); "
             "translate([2, 0]) square(2, center=true); }",
             true},
        Case{"linear_extrude(height=10, twist=90) difference() { square(4, center=true); "
             "square(2, center=true); }",
             true},
        Case{"linear_extrude(height=5, scale=[1.5, 0.5]) offset(r=1, $fn=8) square(2);", true},
        Case{"linear_extrude(height=6, twist=-60, $fn=12) polygon([[0,0],[4,4],[4,0],[0,4]]);",
             true}));

}  // namespace
}  // namespace rt::scad::test
