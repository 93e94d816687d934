// SPDX-License-Identifier: MIT
// hull() of 2D children against the installed OpenSCAD 2021.01: the vertices (6 significant
// digits) and the volume of OpenSCAD's OFF export of `linear_extrude(2) hull() {...}` are those
// of our extruded hull, one convex prism.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "importers/scad/openscad_support.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

TEST(OpenScadHull2dCrossCheck, ExtrudedHullVerticesAndVolumeMatch) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; 2D hull cross-check skipped";
    const char *const bodies[] = {
        // A circle (the $fa/$fs defaults) and a translated square
        "circle(5); translate([10, 0]) square(3);",
        // Two circles with $fn
        "circle(2, $fn=12); translate([6, 1]) circle(1, $fn=12);",
        // Rotated and scaled children
        "rotate(30) square([3, 1]); translate([5, 2]) scale([2, 0.5]) circle(1.5, $fn=10); "
        "mirror([1, 1]) translate([1, 3]) square(1);",
        // A nested hull under transforms
        "hull() { square(1); translate([3, 0]) circle(0.5, $fn=8); } "
        "translate([0, 4]) rotate(15) square(2, center=true);",
        // A polygon with a hole
        "polygon([[0,0],[6,0],[6,6],[0,6],[2,2],[4,2],[4,4],[2,4]], [[0,1,2,3],[4,5,6,7]]); "
        "translate([8, 3]) circle(1, $fn=6);",
        // Exact CSG children: a convex intersection, a difference that keeps the corners
        "intersection() { circle(3, $fn=10); square(4); } translate([-3, 0]) square(1);",
        "difference() { square(4); translate([2, 2]) circle(1, $fn=8); }",
        // Differences and intersections that change the hull, evaluated by Clipper
        "difference() { square(4); translate([-1, -1]) square(2); }",
        "difference() { circle(3, $fn=12); translate([1, -4]) square(8); }",
        "intersection() { polygon([[0,0],[4,0],[4,4],[2,1],[0,4]]); square([4, 3]); }",
    };
    fs::path tmp = fs::temp_directory_path() / ("scadray_hull2d_" + std::to_string(getpid()));
    fs::create_directories(tmp);
    for (const char *body : bodies) {
        std::string src = std::string("linear_extrude(2) hull() { ") + body + " }";
        SCOPED_TRACE(src);
        expectSamePolytope(src, tmp);
    }
    fs::remove_all(tmp);
}

}  // namespace
}  // namespace rt::scad::test
