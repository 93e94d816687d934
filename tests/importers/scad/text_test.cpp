// SPDX-License-Identifier: MIT
// text() as OpenSCAD 2021.01 reads its arguments (text.cc) and renders them (FreetypeRenderer,
// DrawingCallback): glyph outlines and holes, alignment, spacing, direction, the curve
// segments $fn/$fa/$fs give, fonts registered with use<>, and the warnings of bad input.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/ir/diagnostics.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/text_render.h"
#include "importers/scad/openscad_support.h"
#include "importers/scad/text_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

/// One step of Clipper's grid, the precision every text outline ends on.
constexpr double kQuantum = 1.0 / 65536;

/// The regions OpenSCAD's text node has: the glyph polygons united by Clipper.
std::vector<Region> regionsOf(const std::string &s, const std::string &font = "") {
    text::TextParams p;
    p.text = s;
    p.font = font;
    text::detectProperties(p);
    text::TextResult r = text::renderText(p, {});
    std::vector<clipper2d::PolygonSet> glyphs;
    for (auto &g : r.glyphs) glyphs.push_back({g, true});
    if (glyphs.empty()) return {};
    return clipper2d::regions(clipper2d::apply(glyphs, clipper2d::BoolOp::Union));
}

size_t holes(const std::vector<Region> &regions) {
    size_t n = 0;
    for (const Region &r : regions) n += r.holes.size();
    return n;
}

/// A scene's points in the plane, with their bounds.
struct Points2d {
    std::vector<Vec3> points;
    double x0 = kInfinity, y0 = kInfinity, x1 = -kInfinity, y1 = -kInfinity;
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
};

/// The points of `linear_extrude(1) <shape>` (outlines and holes), which must import
/// without warnings.
Points2d pointsOf(const std::string &shape) {
    Imported r = importText("linear_extrude(1) " + shape);
    EXPECT_TRUE(r.warnings().empty()) << shape << ": " << r.warnings().front();
    Points2d out;
    for (Vec3 v : distinctPoints(worldPoints(r.scene), true)) {
        out.points.push_back(v);
        out.x0 = std::min(out.x0, v.x);
        out.x1 = std::max(out.x1, v.x);
        out.y0 = std::min(out.y0, v.y);
        out.y1 = std::max(out.y1, v.y);
    }
    return out;
}

TEST(TextRender, GlyphsHaveTheirHoles) {
    // An O is one region with a hole, a B two holes, an i two regions, a space nothing
    std::vector<Region> o = regionsOf("O");
    EXPECT_EQ(o.size(), 1u);
    EXPECT_EQ(holes(o), 1u);
    std::vector<Region> b = regionsOf("B");
    EXPECT_EQ(b.size(), 1u);
    EXPECT_EQ(holes(b), 2u);
    std::vector<Region> i = regionsOf("i");
    EXPECT_EQ(i.size(), 2u);
    EXPECT_EQ(holes(i), 0u);
    EXPECT_TRUE(regionsOf(" ").empty());
    // Glyphs that do not touch stay apart: 8 is one region with two holes, "OO" two regions
    EXPECT_EQ(holes(regionsOf("8")), 2u);
    EXPECT_EQ(regionsOf("OO").size(), 2u);
    // Each glyph is one polygon set of its own: an O gives two outlines, kept for Clipper
    text::TextParams p;
    p.text = "Oi";
    text::detectProperties(p);
    text::TextResult r = text::renderText(p, {});
    ASSERT_EQ(r.glyphs.size(), 2u);
    EXPECT_EQ(r.glyphs[0].size(), 2u);
    EXPECT_EQ(r.glyphs[1].size(), 2u);
    EXPECT_EQ(r.fontUsed, "Liberation Sans:style=Regular");
    EXPECT_TRUE(r.messages.empty());
}

TEST(TextRender, DetectsScriptAndDirection) {
    auto detect = [](const std::string &s, const std::string &direction = "",
                     const std::string &script = "") {
        text::TextParams p;
        p.text = s;
        p.direction = direction;
        p.script = script;
        text::detectProperties(p);
        return p.script + " " + p.direction;
    };
    EXPECT_EQ(detect("abc"), "Latn ltr");
    EXPECT_EQ(detect("\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7"), "Arab rtl");  // Arabic
    EXPECT_EQ(detect("123"), " ltr");  // digits have no script of their own
    EXPECT_EQ(detect("abc", "ttb"), "Latn ttb");
    EXPECT_EQ(detect("abc", "BTT"), "Latn btt");
    // HarfBuzz reads the first letter only; an unknown one falls back to the script's
    EXPECT_EQ(detect("abc", "rubbish"), "Latn rtl");
    EXPECT_EQ(detect("abc", "sideways"), "Latn ltr");
    EXPECT_EQ(detect("abc", "", "Grek"), "Grek ltr");
}

TEST(Text, SegmentsFollowDollarFn) {
    // Each curve gets floor(fragments / 8) + 1 points, at least 2: $fn = 1, 3 and 8 give 2,
    // as do a $fn beyond int (converted as x86 does) and $fa = $fs = 0 (an infinite count)
    size_t two = pointsOf("text(\"O\", $fn=8);").points.size();
    EXPECT_EQ(pointsOf("text(\"O\", $fn=1);").points.size(), two);
    EXPECT_EQ(pointsOf("text(\"O\", $fn=3);").points.size(), two);
    EXPECT_EQ(pointsOf("text(\"O\", $fn=1e10);").points.size(), two);
    EXPECT_EQ(pointsOf("text(\"O\", $fa=0, $fs=0);").points.size(), two);
    // Size 10 by $fa = 12 and $fs = 2: 30 fragments, 4 points a curve, as $fn = 24
    size_t four = pointsOf("text(\"O\");").points.size();
    EXPECT_EQ(pointsOf("text(\"O\", $fn=24);").points.size(), four);
    EXPECT_EQ(pointsOf("text(\"O\", size=1, $fn=24);").points.size(), four);
    // Size 1: 5 fragments by $fs, so 2 points a curve
    EXPECT_EQ(pointsOf("text(\"O\", size=1);").points.size(), two);
    size_t many = pointsOf("text(\"O\", $fn=200);").points.size();  // 26 a curve
    EXPECT_GT(four, two);
    EXPECT_GT(many, 5 * four);
}

TEST(Text, HalignAndValignShiftByTheTextExtent) {
    Points2d left = pointsOf("text(\"II\");");
    Points2d right = pointsOf("text(\"II\", halign=\"right\");");
    Points2d center = pointsOf("text(\"II\", halign=\"center\");");
    double width = left.x0 - right.x0;  // the advances
    EXPECT_GT(width, left.width());
    EXPECT_NEAR(left.x0 - center.x0, width / 2, 2 * kQuantum);
    EXPECT_NEAR(left.y0, right.y0, kQuantum);
    // An I sits on the baseline and has no descent: bottom is the baseline
    Points2d top = pointsOf("text(\"II\", valign=\"top\");");
    Points2d bottom = pointsOf("text(\"II\", valign=\"bottom\");");
    Points2d middle = pointsOf("text(\"II\", valign=\"center\");");
    EXPECT_NEAR(left.y0, 0, kQuantum);
    EXPECT_NEAR(bottom.y0, 0, kQuantum);
    double ascend = left.y1 - top.y1;
    EXPECT_GT(ascend, 0.9 * left.height());
    EXPECT_NEAR(left.y1 - middle.y1, ascend / 2, 2 * kQuantum);
    // A descender lifts bottom-aligned text by its depth
    Points2d g = pointsOf("text(\"g\");");
    Points2d gBottom = pointsOf("text(\"g\", valign=\"bottom\");");
    EXPECT_LT(g.y0, -1);
    EXPECT_GT(gBottom.y0, -0.2);
    EXPECT_GE(gBottom.y0, g.y0 + 1);
}

TEST(Text, SpacingScalesTheAdvances) {
    Points2d one = pointsOf("text(\"I\");");
    Points2d two = pointsOf("text(\"II\");");
    Points2d three = pointsOf("text(\"III\");");
    double advance = two.x1 - one.x1;
    EXPECT_NEAR(three.x1 - two.x1, advance, 2 * kQuantum);
    EXPECT_NEAR(pointsOf("text(\"III\", spacing=2);").x1 - three.x1, 2 * advance, 4 * kQuantum);
    // spacing = 0 puts every glyph on the first
    Points2d stacked = pointsOf("text(\"III\", spacing=0);");
    EXPECT_NEAR(stacked.x1, one.x1, kQuantum);
    EXPECT_NEAR(stacked.x0, one.x0, kQuantum);
}

TEST(Text, DirectionOrdersTheGlyphs) {
    // Right to left lays "ab" out as "ba" is laid out left to right
    Points2d rtl = pointsOf("text(\"ab\", direction=\"rtl\");");
    Points2d ba = pointsOf("text(\"ba\");");
    ASSERT_EQ(rtl.points.size(), ba.points.size());
    expectPointsCovered(rtl.points, ba.points, "rtl point missing from \"ba\":");
    // Top to bottom stacks the glyphs below the origin
    Points2d ttb = pointsOf("text(\"abc\", direction=\"ttb\");");
    EXPECT_GT(ttb.height(), 2 * ttb.width());
    EXPECT_LT(ttb.y1, 0);
    Points2d btt = pointsOf("text(\"abc\", direction=\"btt\");");
    EXPECT_NEAR(btt.height(), ttb.height(), 1e-3);
}

TEST(Text, SizeMultipliesEveryPoint) {
    // Sizes 10 and 20 have the same segment count (30 fragments by $fa)
    Points2d ten = pointsOf("text(\"Ag\");");
    Points2d twenty = pointsOf("text(\"Ag\", size=20);");
    EXPECT_NEAR(twenty.x1, 2 * ten.x1, 2 * kQuantum);
    EXPECT_NEAR(twenty.y0, 2 * ten.y0, 2 * kQuantum);
    // A negative size turns the text half round (both with 2 points a curve)
    Points2d turned = pointsOf("text(\"Ag\", size=-10);");
    Points2d plain = pointsOf("text(\"Ag\", $fn=8);");
    EXPECT_NEAR(turned.x0, -plain.x1, kQuantum);
    EXPECT_NEAR(turned.y1, -plain.y0, kQuantum);
    // Positional arguments: text, size, font
    Points2d positional = pointsOf("text(\"Ag\", 20, \"Liberation Sans\");");
    EXPECT_EQ(positional.points.size(), twenty.points.size());
    EXPECT_NEAR(positional.x1, twenty.x1, kQuantum);
}

TEST(Text, WorksThroughThe2dMachinery) {
    // Engraved: a plate minus text, one region with the letters as holes
    Imported r = importText(
        "linear_extrude(2) difference() { translate([-1, -1]) square([30, 12]); text(\"AB\"); }");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_FALSE(primitives(*r.scene.root).empty());
    // Revolved text off the axis, and text at the top level (a preview plate)
    r = importText("rotate_extrude($fn=24) translate([20, 0]) text(\"L\");");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_FALSE(primitives(*r.scene.root).empty());
    r = importText("text(\"top\");");
    EXPECT_TRUE(r.hasWarning("2D objects outside linear_extrude()"));
    EXPECT_FALSE(primitives(*r.scene.root).empty());
    EXPECT_FALSE(anyPlaceholder(*r.scene.root));
    // Text crossing the revolve axis is OpenSCAD's error, as for any 2D shape
    r = importText("rotate_extrude() text(\"A\", halign=\"center\");");
    ASSERT_FALSE(r.diag.all().empty());
    EXPECT_EQ(r.diag.all().front().severity, Severity::Error);
    EXPECT_NE(r.diag.all().front().message.find("same X coordinate sign"), std::string::npos);
    EXPECT_TRUE(primitives(*r.scene.root).empty());
}

TEST(Text, BadInputWarnsWhereOpenScadIsSilentOrWarns) {
    // Values of other types are the defaults (lookup_variable_with_default)
    Imported r = importText("text(123);");
    EXPECT_EQ(r.warnings().front(),
              "text(): text = 123 is not a string; OpenSCAD 2021.01 draws nothing for it");
    EXPECT_EQ(r.warning("text = 123").loc.col, 6);
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    r = importText("linear_extrude(1) text(\"A\", size=\"x\");");
    EXPECT_EQ(r.warnings(), (std::vector<std::string>{"text(): size = \"x\" is not a number; "
                                                      "OpenSCAD 2021.01 uses 10"}));
    EXPECT_EQ(worldPoints(r.scene).size(),
              worldPoints(importText("linear_extrude(1) text(\"A\");").scene).size());
    r = importText("linear_extrude(1) text(\"A\", valign=3, halign=true);");
    EXPECT_TRUE(r.hasWarning("valign = 3 is not a string; OpenSCAD 2021.01 uses \"baseline\""));
    EXPECT_TRUE(r.hasWarning("halign = true is not a string; OpenSCAD 2021.01 uses \"left\""));
    // A direction HarfBuzz reads by its first letter, or not at all
    r = importText("linear_extrude(1) text(\"A\", direction=\"rubbish\");");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{
                  "text(): direction = \"rubbish\" is not \"ltr\", \"rtl\", \"ttb\" or "
                  "\"btt\"; OpenSCAD 2021.01 lays the text out rtl"}));
    r = importText("linear_extrude(1) text(\"A\", direction=\"foo\");");
    EXPECT_TRUE(r.hasWarning("OpenSCAD 2021.01 lays the text out ltr"));
    r = importText("linear_extrude(1) text(\"A\", direction=\"TTB\");");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    // undef is the default without a word
    r = importText("linear_extrude(1) text(\"A\", size=undef, font=undef);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();

    // OpenSCAD's own warnings for unknown alignments, located at the argument
    r = importText("linear_extrude(1)\n  text(\"A\", halign=\"foo\", valign=\"bar\");");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{
                  "Unknown value for the halign parameter (use \"left\", \"right\" or "
                  "\"center\"): 'foo'",
                  "Unknown value for the valign parameter (use \"baseline\", \"bottom\", \"top\" "
                  "or \"center\"): 'bar'"}));
    EXPECT_EQ(r.warning("halign").loc.line, 2);
    EXPECT_EQ(r.warning("halign").loc.col, 13);

    // Sizes that make nothing, and a spacing that is not finite
    for (const char *src : {"text(\"A\", size=0/0);", "text(\"A\", size=1/0);",
                            "text(\"A\", size=0);", "text(\"A\", spacing=-1/0);"}) {
        r = importText(src);
        EXPECT_TRUE(r.hasWarning("OpenSCAD makes no 2D object of it")) << src;
        EXPECT_TRUE(primitives(*r.scene.root).empty()) << src;
    }
    // Empty text is nothing, silently (OpenSCAD too)
    r = importText("linear_extrude(1) text(\"\"); linear_extrude(1) text();");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    // Children are left out; a fourth positional argument is OpenSCAD's warning
    r = importText("linear_extrude(1) text(\"A\") cube(1);");
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{"module text() does not support child modules"}));
    r = importText("linear_extrude(1) text(\"A\", 5, \"Liberation Sans\", \"center\");");
    EXPECT_EQ(r.warnings(), (std::vector<std::string>{"Too many unnamed arguments supplied"}));

    // A font that is not installed: fontconfig's best match, as OpenSCAD takes it silently;
    // generic names are not warned about
    r = importText("linear_extrude(1) text(\"A\", font=\"No Such Font 42\");");
    EXPECT_TRUE(
        r.hasWarning("text(): font 'No Such Font 42' is not installed; fontconfig's best "
                     "match, "));
    EXPECT_EQ(r.warning("No Such Font").loc.col, 29);
    EXPECT_FALSE(primitives(*r.scene.root).empty());
    r = importText("text(\"A\", font=\":size=abc\");");
    EXPECT_TRUE(r.hasWarning("text(): font ':size=abc' is not a fontconfig pattern"));
    EXPECT_TRUE(primitives(*r.scene.root).empty());
    r = importText(
        "linear_extrude(1) text(\"A\", font=\"sans-serif\"); "
        "linear_extrude(1) text(\"A\", font=\"Liberation Serif:style=Bold\");");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();

    // A huge $fn is refused before the points are made
    try {
        importText("text(\"OO\", $fn=1e8);");
        ADD_FAILURE() << "no error";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("outline points, more than 20000000"),
                  std::string::npos)
            << e.what();
    }
    // A size beyond Clipper's range is a located error (OpenSCAD 2021.01 aborts)
    EXPECT_THROW(importText("text(\"A\", size=1e15);"), EvalError);
}

TEST(Text, UsedFontFileIsFound) {
    fs::path dir = fs::temp_directory_path() / ("scadray_text_" + std::to_string(getpid()));
    fs::create_directories(dir);
    if (!writeRenamedFont("Scadraytsu", dir / "renamed.ttf")) {
        fs::remove_all(dir);
        GTEST_SKIP() << kLiberationSans
                     << " is missing (scripts/setup.sh installs fonts-liberation)";
    }
    // Without use<> the family is not installed; with it the text is Liberation Sans' shape
    std::string scene = "linear_extrude(1) text(\"Ag\", font=\"Scadraytsu Sans\");";
    std::ofstream(dir / "plain.scad") << scene;
    DiagnosticSink diag;
    importScad((dir / "plain.scad").string(), diag);
    EXPECT_EQ(diag.all().size(), 1u);
    EXPECT_NE(diag.all().front().message.find("is not installed"), std::string::npos);
    std::ofstream(dir / "used.scad") << "use <renamed.ttf>\n" << scene;
    Imported used;
    used.scene = importScad((dir / "used.scad").string(), used.diag);
    fs::remove_all(dir);
    EXPECT_TRUE(used.warnings().empty()) << used.warnings().front();
    Points2d liberation = pointsOf("text(\"Ag\");");
    std::vector<Vec3> points = distinctPoints(worldPoints(used.scene), true);
    ASSERT_EQ(points.size(), liberation.points.size());
    expectPointsCovered(points, liberation.points, "registered font point missing:");
}

}  // namespace
}  // namespace rt::scad::test
