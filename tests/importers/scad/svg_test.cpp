// SPDX-License-Identifier: MIT
// SVG reading as OpenSCAD 2021.01 reads it: page size at a dpi, viewBox, centring, shapes,
// path numbers, strokes of open paths, and the errors and warnings for bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/system/input_file.h"
#include "importers/scad/formats/svg.h"
#include "importers/scad/test_support.h"
#include "support/temp_dir_test.h"

namespace rt::scad::test {
namespace {

class Svg : public rt::test::TempDirTest {
  protected:
    Svg() : TempDirTest("scadray_svg") {}
    svg::Drawing read(const std::string &body, const svg::Options &opts = {},
                      const std::string &page = "width=\"72\" height=\"72\"") {
        std::string path = (dir / "t.svg").string();
        std::ofstream(path) << "<svg xmlns=\"http://www.w3.org/2000/svg\" " << page << ">" << body
                            << "</svg>";
        svg::Drawing d;
        std::string error;
        EXPECT_TRUE(svg::read(readInputFile(path, svg::kMaxFileBytes), path, opts, d, error))
            << error;
        return d;
    }
};

void bounds(const svg::Drawing &d, Vec2 &lo, Vec2 &hi) {
    lo = {INFINITY, INFINITY};
    hi = {-INFINITY, -INFINITY};
    for (const auto &shape : d.shapes)
        for (const Outline &o : shape)
            for (Vec2 p : o) {
                lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
                hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
            }
}

TEST_F(Svg, UnitlessSizesAreAtTheDpiAndYPointsUp) {
    // 72 units at 72 dpi: one inch; without a viewBox coordinates stay user units
    svg::Drawing d = read("<rect x=\"10\" y=\"2\" width=\"20\" height=\"8\"/>");
    ASSERT_EQ(d.shapes.size(), 1u);
    Vec2 lo, hi;
    bounds(d, lo, hi);
    EXPECT_DOUBLE_EQ(lo.x, 10);
    EXPECT_DOUBLE_EQ(hi.x, 30);
    EXPECT_DOUBLE_EQ(hi.y, 25.4 - 2);
    EXPECT_DOUBLE_EQ(lo.y, 25.4 - 10);
}

TEST_F(Svg, ViewBoxScalesIntoThePage) {
    svg::Drawing d = read("<rect x=\"0\" y=\"0\" width=\"100\" height=\"50\"/>", {},
                          "width=\"20mm\" height=\"10mm\" viewBox=\"0 0 100 50\"");
    Vec2 lo, hi;
    bounds(d, lo, hi);
    EXPECT_NEAR(lo.x, 0, 1e-12);
    EXPECT_NEAR(hi.x, 20, 1e-12);
    EXPECT_NEAR(lo.y, 0, 1e-12);
    EXPECT_NEAR(hi.y, 10, 1e-12);
    svg::Options centred;
    centred.center = true;
    bounds(read("<rect x=\"0\" y=\"0\" width=\"100\" height=\"50\"/>", centred,
                "width=\"20mm\" height=\"10mm\" viewBox=\"0 0 100 50\""),
           lo, hi);
    EXPECT_NEAR(lo.x, -10, 1e-12);
    EXPECT_NEAR(hi.y, 5, 1e-12);
}

TEST_F(Svg, CirclesHaveFortyPointsAndCurvesTwentySegments) {
    svg::Drawing d = read(
        "<circle cx=\"10\" cy=\"10\" r=\"5\"/>"
        "<path d=\"M0,0 C0,10 10,10 10,0 z\"/>");
    ASSERT_EQ(d.shapes.size(), 2u);
    EXPECT_EQ(d.shapes[0][0].size(), 40u);
    EXPECT_EQ(d.shapes[1][0].size(), 1u + 20u + 1u);
}

TEST_F(Svg, PathNumbersFollowSvgsGrammar) {
    // "4.5.5" is 4.5 then 0.5, "1e1-1" is 10 then -1, and a sign starts a number
    svg::Drawing d = read("<path d=\"M3-2 4.5.5 1e1-1z\"/>");
    ASSERT_EQ(d.shapes.size(), 1u);
    const Outline &o = d.shapes[0][0];
    ASSERT_EQ(o.size(), 4u);
    EXPECT_DOUBLE_EQ(o[1].x, 4.5);
    EXPECT_DOUBLE_EQ(o[1].y, 25.4 - 0.5);
    EXPECT_DOUBLE_EQ(o[2].x, 10);
    EXPECT_DOUBLE_EQ(o[2].y, 25.4 + 1);
}

TEST_F(Svg, OpenPathsAndLinesAreTheirStrokes) {
    svg::Drawing d = read(
        "<line x1=\"0\" y1=\"10\" x2=\"20\" y2=\"10\" stroke-width=\"4\" "
        "stroke-linecap=\"butt\"/>");
    Vec2 lo, hi;
    bounds(d, lo, hi);
    EXPECT_NEAR(lo.x, 0, 1e-9);
    EXPECT_NEAR(hi.x, 20, 1e-9);
    EXPECT_NEAR(hi.y - lo.y, 4, 1e-9);
    // The default cap is square, the default width 1
    bounds(read("<path d=\"M0,10 L20,10\"/>"), lo, hi);
    EXPECT_NEAR(lo.x, -0.5, 1e-9);
    EXPECT_NEAR(hi.y - lo.y, 1, 1e-9);
}

TEST_F(Svg, GroupTransformsCompose) {
    svg::Drawing d = read(
        "<g transform=\"translate(10,0)\"><rect transform=\"scale(2)\" "
        "x=\"1\" y=\"0\" width=\"1\" height=\"1\"/></g>");
    Vec2 lo, hi;
    bounds(d, lo, hi);
    EXPECT_DOUBLE_EQ(lo.x, 12);
    EXPECT_DOUBLE_EQ(hi.x, 14);
}

TEST_F(Svg, TextAndUseAreLeftOutAndNamed) {
    svg::Drawing d = read(
        "<text>hi</text><use href=\"#a\"/><defs><rect width=\"1\" "
        "height=\"1\"/></defs>");
    EXPECT_TRUE(d.shapes.empty());
    ASSERT_EQ(d.skipped.size(), 2u);
    EXPECT_EQ(d.skipped[0].first, "text");
    EXPECT_EQ(d.skipped[1].first, "use");
}

TEST_F(Svg, StrokesBeyondClipperRangeAreErrors) {
    // Scaled for Clipper's integers, 1e92 leaves their range: its conversion was undefined
    for (const char *body : {"<path d=\"M1e92,45 L100,45\" style=\"stroke-width:2\"/>",
                             "<path d=\"M0,0 L1,0\" style=\"stroke-width:1e300\"/>"}) {
        SCOPED_TRACE(body);
        svg::Drawing d;
        std::string error;
        std::string text = std::string(
                               "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"72\" "
                               "height=\"72\">") +
                           body + "</svg>";
        EXPECT_FALSE(svg::read(text, "big.svg", {}, d, error));
        EXPECT_NE(error.find("beyond the range of 2D geometry"), std::string::npos) << error;
    }
}

TEST_F(Svg, BrokenFilesAreErrors) {
    svg::Drawing d;
    std::string error;
    std::string broken = (dir / "broken.svg").string();
    EXPECT_FALSE(svg::read("<svg><rect", broken, {}, d, error));
    EXPECT_EQ(error, "Error parsing file '" + broken + "'");
}

TEST(SvgImport, ErrorsAndDpiWarningsAreLocated) {
    Imported missing = importText("linear_extrude(1) import(\"import2d/none.svg\");");
    bool located = false;
    for (const auto &d : missing.diag.all())
        if (d.severity == Severity::Error && d.message.find("Can't open file") == 0)
            located = d.loc.line == 1 && d.loc.col == 19;
    EXPECT_TRUE(located);
    Imported dpi = importText("import(\"import2d/basic.svg\", dpi=0);");
    EXPECT_TRUE(dpi.hasWarning("Invalid dpi value giving, using default of 72 dpi"));
}

}  // namespace
}  // namespace rt::scad::test
