// SPDX-License-Identifier: MIT
// DXF reading as OpenSCAD 2021.01 reads it: entities, layers, origin and scale, the 1/1024
// grid, open and closed paths, blocks, dimensions (dxf_dim, dxf_cross), the file forms of the
// extrusions, and the warnings for bad files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/system/input_file.h"
#include "importers/scad/formats/dxf.h"
#include "importers/scad/test_support.h"
#include "support/temp_dir_test.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

std::string shapesDxf() { return dataDir() + "/import2d/shapes.dxf"; }

dxf::Data readLayer(const std::string &layer, std::vector<std::string> *warnings = nullptr,
                    double fn = 8) {
    dxf::ReadOptions opts;
    opts.layer = layer;
    opts.fragments.fn = fn;
    dxf::Data d;
    dxf::read(readInputFile(shapesDxf(), dxf::kMaxFileBytes), "shapes.dxf", opts, d,
              [&](const std::string &m) {
                  if (warnings) warnings->push_back(m);
              });
    return d;
}

double area(const Outline &o) { return twiceSignedArea(o) / 2; }

bool near(Vec2 a, Vec2 b, double eps = 1e-9) {
    return std::fabs(a.x - b.x) < eps && std::fabs(a.y - b.y) < eps;
}

TEST(Dxf, ClosedPolylineIsOneClosedPath) {
    dxf::Data d = readLayer("square");
    ASSERT_EQ(d.paths.size(), 1u);
    EXPECT_TRUE(d.paths[0].closed);
    EXPECT_EQ(d.paths[0].indices.size(), 5u);  // the first point again at the end
    auto o = dxf::outlines(d);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].size(), 4u);
    EXPECT_DOUBLE_EQ(std::fabs(area(o[0])), 100);
}

TEST(Dxf, CircleHasTheFragmentsOfItsRadius) {
    dxf::Data d = readLayer("hole", nullptr, 8);
    auto o = dxf::outlines(d);
    ASSERT_EQ(o.size(), 1u);
    EXPECT_EQ(o[0].size(), 8u);
    for (Vec2 p : o[0]) EXPECT_NEAR(std::hypot(p.x - 5, p.y - 5), 2, 1e-3);
    // $fn = 0: $fa 12 and $fs 2 give ceil(max(min(30, 2 pi 2 / 2), 5)) = 7 segments
    EXPECT_EQ(dxf::outlines(readLayer("hole", nullptr, 0))[0].size(), 7u);
}

TEST(Dxf, PointsSnapToTheGridAndJoin) {
    // The last segment ends 0.0003 from the first corner: within the 1/1024 grid
    dxf::Data d = readLayer("tri");
    ASSERT_EQ(d.paths.size(), 1u);
    EXPECT_TRUE(d.paths[0].closed);
    for (Vec2 p : d.points) {
        EXPECT_EQ(p.x * 1024, std::round(p.x * 1024));
        EXPECT_EQ(p.y * 1024, std::round(p.y * 1024));
    }
    EXPECT_NEAR(std::fabs(area(dxf::outlines(d)[0])), 6, 1e-2);
}

TEST(Dxf, OpenPathIsClosedByTheOutline) {
    dxf::Data d = readLayer("open");
    ASSERT_EQ(d.paths.size(), 1u);
    EXPECT_FALSE(d.paths[0].closed);
    auto o = dxf::outlines(d);
    ASSERT_EQ(o[0].size(), 3u);
    EXPECT_DOUBLE_EQ(std::fabs(area(o[0])), 12.5);
}

TEST(Dxf, ArcAndEllipse) {
    auto arc = dxf::outlines(readLayer("arc", nullptr, 8));
    ASSERT_EQ(arc.size(), 1u);
    EXPECT_EQ(arc[0].size(), 3u + 1u);  // two segments of a quarter of an 8-gon, and the centre
    auto ell = dxf::outlines(readLayer("ell", nullptr, 16));
    ASSERT_EQ(ell.size(), 1u);
    double maxX = 0, maxY = 0;
    for (Vec2 p : ell[0]) {
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    EXPECT_NEAR(maxX, 4, 1e-3);
    EXPECT_NEAR(maxY, 2, 1e-2);
}

TEST(Dxf, InsertPlacesTheBlockScaledAndTurned) {
    auto o = dxf::outlines(readLayer("blk"));
    ASSERT_EQ(o.size(), 1u);
    ASSERT_EQ(o[0].size(), 4u);
    // The unit square scaled by (2, 3), turned 90 degrees, moved to (20, 0)
    std::vector<Vec2> want{{20, 0}, {20, 2}, {17, 2}, {17, 0}};
    for (Vec2 w : want) {
        bool found = false;
        for (Vec2 p : o[0]) found = found || near(p, w, 1e-3);
        EXPECT_TRUE(found) << w.x << "," << w.y;
    }
}

TEST(Dxf, OriginAndScale) {
    dxf::ReadOptions opts;
    opts.layer = "square";
    opts.originX = 5;
    opts.originY = 1;
    opts.scale = 2;
    dxf::Data d;
    dxf::read(readInputFile(shapesDxf(), dxf::kMaxFileBytes), "shapes.dxf", opts, d,
              [](const std::string &) {});
    double minX = 1e9, minY = 1e9;
    for (Vec2 p : d.points) {
        minX = std::min(minX, p.x);
        minY = std::min(minY, p.y);
    }
    EXPECT_DOUBLE_EQ(minX, -10);
    EXPECT_DOUBLE_EQ(minY, -2);
}

TEST(Dxf, UnsupportedEntitiesAreCountedPerLayer) {
    std::vector<std::string> w;
    dxf::Data d = readLayer("spl", &w);
    EXPECT_TRUE(d.paths.empty());
    ASSERT_EQ(w.size(), 2u);
    EXPECT_EQ(w[0], "Unsupported DXF Entity 'POLYLINE' (1) in layer 'spl' of shapes.dxf");
    EXPECT_EQ(w[1], "Unsupported DXF Entity 'SPLINE' (2) in layer 'spl' of shapes.dxf");
}

TEST(Dxf, ImportFillsEvenOdd) {
    // Square and hole from two layers of one file: the union of two imports covers the hole,
    // one import of both (no layer) leaves it
    Imported r = importText("import(\"import2d/shapes.dxf\", layer=\"square\");");
    EXPECT_TRUE(r.warnings().size() == 1 && r.hasWarning("plates")) << r.warnings().size();
    Imported missing = importText("import(\"import2d/nothing.dxf\");");
    EXPECT_TRUE(missing.hasWarning("Can't open DXF file '"));
    EXPECT_EQ(missing.warning("Can't open").loc.line, 1);
}

TEST(Dxf, DimensionsAndCross) {
    EXPECT_EQ(echoOf("echo(dxf_dim(file=\"import2d/shapes.dxf\", name=\"w\"));"), "8");
    EXPECT_EQ(echoOf("echo(dxf_dim(file=\"import2d/shapes.dxf\", name=\"len\"));"), "5");
    EXPECT_EQ(echoOf("echo(dxf_dim(file=\"import2d/shapes.dxf\", name=\"w\", scale=2));"), "16");
    EXPECT_EQ(echoOf("echo(dxf_cross(file=\"import2d/shapes.dxf\", layer=\"cross\"));"), "[5, 5]");
    EXPECT_EQ(echoOf("echo(dxf_cross(file=\"import2d/shapes.dxf\", layer=\"cross\", "
                     "origin=[1, 2]));"),
              "[4, 3]");

    Imported odd = importText("echo(dxf_dim(file=\"import2d/shapes.dxf\", name=\"odd\"));");
    EXPECT_EQ(odd.echoes(), std::vector<std::string>{"undef"});
    EXPECT_TRUE(
        odd.hasWarning("Dimension 'odd' in 'import2d/shapes.dxf', layer '' has "
                       "unsupported type!"));
    Imported none = importText("echo(dxf_dim(file=\"import2d/shapes.dxf\", name=\"zz\"));");
    EXPECT_TRUE(none.hasWarning("Can't find dimension 'zz'"));
    Imported missing = importText("x = dxf_dim(file=\"nope.dxf\", name=\"w\");");
    EXPECT_TRUE(missing.hasWarning("Can't open DXF file 'nope.dxf'!"));
    Imported positional = importText("x = dxf_cross(\"import2d/shapes.dxf\");");
    EXPECT_TRUE(positional.hasWarning("dxf_cross(..., =...) is not supported"));
    Imported noCross = importText("x = dxf_cross(file=\"import2d/shapes.dxf\", layer=\"x\");");
    EXPECT_TRUE(noCross.hasWarning("Can't find cross in 'import2d/shapes.dxf', layer 'x'!"));
}

TEST(Dxf, FileFormsOfTheExtrusions) {
    Imported lin = importText(
        "linear_extrude(file=\"import2d/shapes.dxf\", layer=\"square\", height=2) cube(50);");
    EXPECT_TRUE(lin.hasWarning("DEPRECATED: Support for reading files in linear_extrude"));
    auto prims = primitives(*lin.scene.root);
    ASSERT_EQ(prims.size(), 1u);  // the cube child is ignored
    Imported rot = importText(
        "rotate_extrude(file=\"import2d/shapes.dxf\", layer=\"square\", "
        "origin=[-20, 0]);");
    EXPECT_TRUE(rot.hasWarning("DEPRECATED: Support for reading files in rotate_extrude"));
    EXPECT_EQ(primitives(*rot.scene.root).size(), 1u);
}

class DxfBadFiles : public rt::test::TempDirTest {
  protected:
    DxfBadFiles() : TempDirTest("scadray_dxf_bad") {}
    Imported run(const std::string &dxfText, const std::string &fn = "6") {
        std::ofstream(dir / "bad.dxf") << dxfText;
        std::string scad = (dir / "main.scad").string();
        std::ofstream(scad) << "linear_extrude(1) import(\"bad.dxf\", $fn=" << fn << ");\n";
        Imported r;
        r.scene = importScad(scad, r.diag);
        return r;
    }
};

TEST_F(DxfBadFiles, WarnAsOpenScadDoes) {
    // A bad number, a LINE left without its end (the entity stays open), a bad group code
    Imported r =
        run("  0\nSECTION\n  2\nENTITIES\n  0\nLINE\n  8\n0\n 10\nabc\n 20\n0\n 11\n1\n 21\n1\n"
            "  0\nLINE\n  8\n0\n 10\n0\n  0\nCIRCLE\n 10\n1\n 20\n1\n 40\n1\nxx\nfoo\n  0\nEOF\n");
    std::string path = (dir / "bad.dxf").string();
    EXPECT_TRUE(r.hasWarning("Illegal value 'abc'in `" + path + "'"));
    EXPECT_TRUE(r.hasWarning("Not enough input values for LINE. in '" + path + "'"));
    EXPECT_TRUE(r.hasWarning("Illegal ID 'xx' in `" + path + "'"));
    EXPECT_EQ(r.warning("Illegal ID").loc.line, 1);
}

TEST_F(DxfBadFiles, HugeArcsAndNonFiniteAnglesAreLeftOut) {
    Imported r =
        run("  0\nSECTION\n  2\nENTITIES\n  0\nCIRCLE\n 10\n0\n 20\n0\n 40\n1e12\n"
            "  0\nARC\n 10\n0\n 20\n0\n 40\n1\n 50\ninf\n 51\n0\n  0\nENDSEC\n",
            "2e6");
    EXPECT_TRUE(r.hasWarning("CIRCLE in DXF file"));
    EXPECT_TRUE(r.hasWarning("ARC with a non-finite angle"));
}

TEST_F(DxfBadFiles, ABlockInsertedIntoItselfStopsAtTheSegmentLimit) {
    std::string text =
        "  0\nSECTION\n  2\nBLOCKS\n  0\nBLOCK\n  2\nb\n  0\nLINE\n 10\n0\n 20\n0\n"
        " 11\n1\n 21\n1\n";
    for (int i = 0; i < 40; ++i) text += "  0\nINSERT\n  2\nb\n 10\n0.5\n 20\n0\n";
    text += "  0\nENDBLK\n  0\nENDSEC\n  0\nEOF\n";
    Imported r = run(text);
    EXPECT_TRUE(r.hasWarning("segments in DXF file"));
}

TEST_F(DxfBadFiles, EmptyAndBinaryFilesGiveNothing) {
    Imported empty = run("");
    EXPECT_TRUE(primitives(*empty.scene.root).empty());
    Imported binary = run(std::string("\x00\x01\xff\xfe garbage", 12));
    EXPECT_TRUE(primitives(*binary.scene.root).empty());
}

}  // namespace
}  // namespace rt::scad::test
