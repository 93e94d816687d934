// SPDX-License-Identifier: MIT
// surface(): DAT and PNG height maps read as OpenSCAD 2021.01 reads them, and the closed mesh
// it builds (cells of four triangles, walls, a bottom one below the lowest height).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "core/image/png_io.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/formats/surface.h"
#include "importers/scad/test_support.h"
#include "support/temp_dir_test.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

surface::HeightMap readMap(const std::string &path, bool invert,
                           std::vector<std::string> *warnings = nullptr) {
    surface::HeightMap m;
    EXPECT_EQ(surface::readHeightMap(path, invert, m,
                                     [&](const std::string &w) {
                                         if (warnings) warnings->push_back(w);
                                     }),
              surface::ReadResult::Ok);
    return m;
}

TEST(Surface, RaggedDatFillsMissingHeightsWithZero) {
    auto m = readMap(dataDir() + "/import2d/ragged.dat", false);
    ASSERT_EQ(m.lines, 3);
    ASSERT_EQ(m.columns, 4);
    EXPECT_EQ(m.at(0, 0), 3);
    EXPECT_EQ(m.at(0, 3), 0);
    EXPECT_EQ(m.at(1, 1), 7);
    EXPECT_EQ(m.at(2, 3), 11);
    EXPECT_EQ(m.bottom, 0);  // min(0, 3 - 1)
}

TEST(Surface, MeshIsClosedWithOpenScadsVertices) {
    auto m = readMap(dataDir() + "/import2d/bump.dat", false);
    EXPECT_EQ(m.bottom, -1);
    ir::Mesh mesh = surface::surfaceMesh(m, true);
    meshio::weldMesh(mesh);
    EXPECT_EQ(meshio::solidProblem(mesh), "");
    Bounds3 b = mesh.bounds();
    EXPECT_EQ(b.min, Vec3(-1, -1, -1));
    EXPECT_EQ(b.max, Vec3(1, 1, 4));
    // The slab below z = 0 (2 x 2 x 1), and each cell's four triangles to its centre (at
    // height 1): two of mean height 5/3 and two of 1/3 over a quarter each, 1 a cell
    EXPECT_NEAR(meshio::signedVolume(mesh), 4 + 4 * 1, 1e-9);
}

TEST(Surface, BadValueStopsReading) {
    std::vector<std::string> w;
    auto m = readMap(dataDir() + "/import2d/bad.dat", false, &w);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].find("Illegal value in '"), std::string::npos);
    // The first line, and the 3 before the bad value
    EXPECT_EQ(m.lines, 2);
    EXPECT_EQ(m.columns, 2);
    EXPECT_EQ(m.at(1, 0), 3);
    EXPECT_EQ(m.at(1, 1), 0);
}

class SurfacePng : public rt::test::TempDirTest {
  protected:
    SurfacePng() : TempDirTest("scadray_surface_png") {}
};

TEST_F(SurfacePng, GreyFromRgbWeightsScaledTo100) {
    std::string path = (dir / "img.png").string();
    // Row 0 is the top of the image: it becomes the last line
    const uint8_t px[] = {0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255};
    writePng(path, 2, 2, 8, px, false);
    auto m = readMap(path, false);
    ASSERT_EQ(m.lines, 2);
    ASSERT_EQ(m.columns, 2);
    EXPECT_DOUBLE_EQ(m.at(1, 0), 0);
    EXPECT_NEAR(m.at(1, 1), 100, 1e-9);
    EXPECT_NEAR(m.at(0, 0), 100.0 / 255 * 0.2126 * 255, 1e-9);
    EXPECT_NEAR(m.at(0, 1), 100.0 / 255 * 0.0722 * 255, 1e-9);
    EXPECT_EQ(m.bottom, -1);
    // 2021.01 inverts as 1 - pixel
    auto inv = readMap(path, true);
    EXPECT_NEAR(inv.at(1, 0), 100.0 / 255, 1e-9);
    EXPECT_NEAR(inv.at(1, 1), 100.0 / 255 * (1 - 255), 1e-9);
}

TEST_F(SurfacePng, SixteenBitSamplesKeepTheirHighByte) {
    std::string path = (dir / "img16.png").string();
    const uint16_t px[] = {0x1234, 0x1234, 0x1234};
    writePng(path, 1, 1, 16, px, false);
    auto m = readMap(path, false);
    ASSERT_EQ(m.lines, 1);
    EXPECT_NEAR(m.at(0, 0), 100.0 / 255 * 0x12, 1e-9);
}

TEST_F(SurfacePng, TooManyPixelsIsALocatedError) {
    std::string path = (dir / "big.png").string();
    std::vector<uint8_t> px(1100 * 1001 * 3, 7);
    writePng(path, 1100, 1001, 8, px.data(), false);
    surface::HeightMap m;
    EXPECT_EQ(surface::readHeightMap(path, false, m, [](const std::string &) {}),
              surface::ReadResult::TooLarge);
    std::string scad = (dir / "main.scad").string();
    std::ofstream(scad) << "\n  surface(\"big.png\");\n";
    DiagnosticSink diag;
    try {
        importScad(scad, diag);
        ADD_FAILURE() << "no error";
    } catch (const EvalError &e) {
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("holds more than 1100000 heights"), std::string::npos);
    }
}

TEST_F(SurfacePng, MissingAndBrokenFilesWarn) {
    std::vector<std::string> w;
    auto m = readMap((dir / "none.png").string(), false, &w);
    EXPECT_EQ(m.lines, 0);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "The file '" + (dir / "none.png").string() + "' couldn't be opened.");
    std::string broken = (dir / "broken.png").string();
    std::ofstream(broken) << "\x89PNG\r\n\x1a\nnot really";
    w.clear();
    readMap(broken, false, &w);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0], "Can't read PNG image '" + broken + "'");
}

TEST(Surface, ModuleMakesOneMesh) {
    Imported r = importText("surface(\"import2d/bump.dat\", center=true, convexity=5);");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().front();
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    Imported missing = importText("surface(\"import2d/none.dat\");");
    EXPECT_TRUE(missing.hasWarning("couldn't be opened"));
    EXPECT_TRUE(primitives(*missing.scene.root).empty());
    Imported nan = importText("surface(\"import2d/nan.dat\");");
    EXPECT_TRUE(nan.hasWarning("not a finite number"));
}

}  // namespace
}  // namespace rt::scad::test
