// SPDX-License-Identifier: MIT
// Cross-checks text() against the installed OpenSCAD 2021.01: the points of its OFF export of
// extruded, engraved, revolved and twisted text against ours, both ways, at OFF's 6 digits
// (Clipper's grid is finer than that only above 1 unit), and the point counts.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "core/meshing/facets.h"
#include "importers/scad/openscad_support.h"
#include "importers/scad/text_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

struct Case {
    const char *src;
    bool allPoints = false;  ///< compare 3D points (revolved, twisted), else the (x, y) plane
    bool warns = false;      ///< scadray warns (OpenSCAD is silent)
};

class TextCrossCheck : public ::testing::TestWithParam<Case> {};

TEST_P(TextCrossCheck, PointsMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const Case &c = GetParam();
    SCOPED_TRACE(c.src);
    fs::path dir = fs::temp_directory_path() / ("scadray_text_x_" + std::to_string(getpid()));
    fs::create_directories(dir);
    // A font file for use<> (Liberation Sans under a family name that is not installed)
    ASSERT_TRUE(writeRenamedFont("Scadraytst", dir / "renamed.ttf")) << kLiberationSans;
    ir::Mesh theirs = openscadOff(c.src, dir);
    Imported ours = importText(c.src, (dir / "case.scad").string());
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());

    EXPECT_EQ(ours.warnings().empty(), !c.warns) << (c.warns ? "" : ours.warnings().front());
    meshing::applyFacets(ours.scene, ir::FacetMode::OpenScad, ours.diag);
    std::vector<Vec3> mine = distinctPoints(worldPoints(ours.scene), !c.allPoints);
    std::vector<Vec3> ref = distinctPoints(theirs.positions, !c.allPoints);
    EXPECT_EQ(mine.size(), ref.size());
    expectPointsCovered(mine, ref, "our point missing from OpenSCAD's:");
    expectPointsCovered(ref, mine, "OpenSCAD's point missing from ours:");
}

INSTANTIATE_TEST_SUITE_P(
    Text, TextCrossCheck,
    ::testing::Values(
        // Outlines with holes, curve segments from $fa/$fs and from $fn
        Case{"linear_extrude(1) text(\"O\");"},
        Case{"linear_extrude(1) text(\"B8\", size=4, $fn=40);"},
        // $fn beyond int, and $fa = $fs = 0: 2 points a curve (x86's conversion of the count)
        Case{"linear_extrude(1) text(\"Se\", $fn=1e10);"},
        Case{"linear_extrude(1) text(\"Se\", $fa=0, $fs=0);"},
        // Alignment and spacing
        Case{"linear_extrude(1) text(\"Hello, World!\", halign=\"center\", valign=\"center\");"},
        Case{"linear_extrude(1) text(\"gyp\", valign=\"top\", halign=\"right\", spacing=1.3);"},
        Case{"linear_extrude(1) text(\"Qj\", valign=\"bottom\");"},
        // Directions, and a script HarfBuzz shapes right to left
        Case{"linear_extrude(1) text(\"Ab\", direction=\"ttb\");"},
        Case{"linear_extrude(1) text(\"Ab\", direction=\"btt\", halign=\"center\");"},
        Case{"linear_extrude(1) text(\"Ab\", direction=\"rtl\", halign=\"right\");"},
        Case{"linear_extrude(1) text(\"\\u0645\\u0631\\u062d\\u0628\\u0627\");"},
        // Small, large and negative sizes; fonts by fontconfig pattern, and a fallback
        Case{"linear_extrude(1) text(\"Ag\", size=0.5);"},
        Case{"linear_extrude(1) text(\"Ag\", size=250);"},
        Case{"linear_extrude(1) text(\"Ag\", size=-3);"},
        Case{"linear_extrude(1) text(\"Bold\", 6, \"Liberation Serif:style=Bold Italic\");"},
        Case{"linear_extrude(1) text(\"Mono\", font=\"Liberation Mono\");"},
        Case{"linear_extrude(1) text(\"Fb\", font=\"No Such Font 42\");", false, true},
        // A font file registered by use<>
        Case{"use <renamed.ttf>\nlinear_extrude(1) text(\"Reg\", font=\"Scadraytst Sans\");"},
        // Through the 2D machinery: engraved, mirrored, united, revolved, twisted
        Case{"linear_extrude(2) difference() { square([32, 12]); translate([1, 1]) "
             "text(\"TXT\"); }"},
        Case{"linear_extrude(1) mirror([1, 0]) text(\"R\");"},
        Case{"linear_extrude(1) offset(delta=0.25) union() { text(\"U\"); square(3); }"},
        Case{"linear_extrude(1) offset(r=0.4, $fn=8) text(\"rs\");"},
        Case{"linear_extrude(2) hull() text(\"ab\", size=6);"},
        Case{"rotate_extrude($fn=12) translate([12, 0]) text(\"S\", size=5);", true},
        Case{"linear_extrude(height=4, scale=0.5) text(\"sc\", size=7);", true},
        Case{"linear_extrude(height=3, twist=30, slices=3) text(\"Tw\", size=5);", true}));

}  // namespace
}  // namespace rt::scad::test
