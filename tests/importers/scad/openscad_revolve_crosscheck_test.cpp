// SPDX-License-Identifier: MIT
// rotate_extrude's faceted form against the installed OpenSCAD 2021.01: the IR is built by
// hand (the importer's rotate_extrude lands separately) and the vertices and volume of our
// mesh are compared with OpenSCAD's OFF export of the same profile.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "core/meshing/revolved_mesh.h"
#include "importers/scad/openscad_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

struct RevolveCase {
    const char *src;
    std::vector<ir::ProfileOutline> outlines;
    double angle;
    int fragments;
};

TEST(OpenScadRevolveCrossCheck, VerticesAndVolumeMatch) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    ir::ProfileOutline square = {{1, 0}, {2, 0}, {2, 1}, {1, 1}};
    ir::ProfileOutline onAxis = {{0, 0}, {1.5, 0}, {0.5, 2}, {0, 2}};
    ir::ProfileOutline big = {{1, 0}, {3, 0}, {3, 2}, {1, 2}};
    ir::ProfileOutline hole = {{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}};
    const RevolveCase cases[] = {
        {"rotate_extrude($fn=4) translate([1,0]) square(1);", {square}, 360, 4},
        {"rotate_extrude(angle=90, $fn=4) translate([1,0]) square(1);", {square}, 90, 1},
        {"rotate_extrude(angle=270, $fn=8) translate([1,0]) square(1);", {square}, 270, 6},
        {"rotate_extrude($fn=7) polygon([[0,0],[1.5,0],[0.5,2],[0,2]]);", {onAxis}, 360, 7},
        {"rotate_extrude(angle=200, $fn=9) difference() { translate([1,0]) square(2); "
         "translate([1.5,0.5]) square(1); }",
         {big, hole},
         200,
         5},
    };
    // A torus' facet outline: OpenSCAD's 8-gon of the circle (radians, from +X), translated
    ir::ProfileOutline circle;
    for (int i = 0; i < 8; ++i) {
        double phi = (M_PI * 2 * i) / 8;
        circle.push_back({0.5 * std::cos(phi) + 2, 0.5 * std::sin(phi)});
    }
    const RevolveCase tori[] = {
        {"rotate_extrude($fn=8) translate([2,0]) circle(0.5, $fn=8);", {circle}, 360, 8},
        {"rotate_extrude(angle=135, $fn=8) translate([2,0]) circle(0.5, $fn=8);", {circle}, 135, 3},
    };
    fs::path tmp = fs::temp_directory_path() / ("scadray_revolve_" + std::to_string(getpid()));
    fs::create_directories(tmp);
    std::vector<RevolveCase> all(std::begin(cases), std::end(cases));
    all.insert(all.end(), std::begin(tori), std::end(tori));
    for (const RevolveCase &c : all) {
        SCOPED_TRACE(c.src);
        ir::Mesh ours = meshing::openscadRevolve(c.outlines, c.angle, c.fragments);
        ir::Mesh theirs = openscadOff(c.src, tmp);
        ASSERT_FALSE(theirs.positions.empty());
        expectCovered(ours.positions, theirs.positions, "ours");
        expectCovered(theirs.positions, ours.positions, "OpenSCAD's");
        EXPECT_NEAR(meshVolume(ours), meshVolume(theirs), 1e-4 * std::abs(meshVolume(theirs)));
    }
    fs::remove_all(tmp);
}

}  // namespace
}  // namespace rt::scad::test
