// SPDX-License-Identifier: MIT
// Cross-checks DXF import (import(), the file forms of linear_extrude/rotate_extrude) and
// surface() against the installed OpenSCAD 2021.01: the points of its OFF export against
// ours, both ways, and for surfaces the enclosed volume.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>

#include "core/image/png_io.h"
#include "importers/scad/openscad_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

/// OFF's 6 significant digits (and Clipper's 2^-16 grid for the 2D outlines).
constexpr double kDigits = 6e-6;

std::string data(const std::string &name) { return dataDir() + "/import2d/" + name; }

fs::path caseDir(const char *what) {
    fs::path dir = fs::temp_directory_path() /
                   (std::string("scadray_import2d_") + what + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir;
}

void expectSamePoints(const std::string &src, bool flatten) {
    SCOPED_TRACE(src);
    fs::path dir = caseDir("dxf");
    ir::Mesh theirs = openscadOff(src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());
    Imported ours = importText(src);
    // The file forms of the extrusions are deprecated: OpenSCAD says so too
    for (const std::string &w : ours.warnings()) EXPECT_EQ(w.rfind("DEPRECATED: ", 0), 0u) << w;
    meshing::applyFacets(ours.scene, ir::FacetMode::OpenScad, ours.diag);
    std::vector<Vec3> mine = worldPoints(ours.scene), ref = theirs.positions;
    if (flatten) {
        for (Vec3 &v : mine) v.z = 0;
        for (Vec3 &v : ref) v.z = 0;
    }
    expectCovered(mine, ref, "our point missing from OpenSCAD's:", kDigits);
    expectCovered(ref, mine, "OpenSCAD's point missing from ours:", kDigits);
}

class DxfCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(DxfCrossCheck, OutlinePointsMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    std::string src = "f = \"" + data("shapes.dxf") + "\";\n" + GetParam();
    expectSamePoints(src, std::string(GetParam()).find("rotate_extrude") == std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Layers, DxfCrossCheck,
    ::testing::Values("linear_extrude(1) import(f, layer=\"square\");",
                      "linear_extrude(1) import(f, layer=\"hole\", $fn=9);",
                      "linear_extrude(1) import(f, layer=\"hole\", $fa=5, $fs=0.5);",
                      "linear_extrude(1) import(f, layer=\"tri\");",
                      "linear_extrude(1) import(f, layer=\"open\");",
                      "linear_extrude(1) import(f, layer=\"arc\", $fn=30);",
                      "linear_extrude(1) import(f, layer=\"ell\", $fn=20);",
                      "linear_extrude(1) import(f, layer=\"blk\");",
                      // 13 segments of a full ellipse: 13 * 2 pi / (2 pi) rounds up to 14
                      "linear_extrude(1) import(f, layer=\"ell\");",
                      "linear_extrude(1) import(f, layer=\"arc\");",
                      "linear_extrude(1) import(f, layer=\"square\", origin=[3, -2], scale=1.5);",
                      // Square and circle of two layers in one import: the circle is a hole
                      "linear_extrude(1) difference() { import(f, layer=\"square\"); "
                      "import(f, layer=\"hole\"); }",
                      "linear_extrude(file=f, layer=\"blk\", height=3, center=true);",
                      "rotate_extrude(file=f, layer=\"square\", origin=[-12, 0], $fn=12);"));

class SvgCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(SvgCrossCheck, OutlinePointsMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    std::string src = "d = \"" + dataDir() + "/import2d/\";\n" + GetParam();
    expectSamePoints(src, true);
}

INSTANTIATE_TEST_SUITE_P(
    Files, SvgCrossCheck,
    ::testing::Values("linear_extrude(1) import(str(d, \"basic.svg\"));",
                      "linear_extrude(1) import(str(d, \"basic.svg\"), dpi=96, center=true);",
                      "linear_extrude(1) import(str(d, \"path.svg\"));",
                      "linear_extrude(1) import(str(d, \"viewbox.svg\"));",
                      "linear_extrude(1) import(str(d, \"viewbox.svg\"), center=true);",
                      // slice alignment, matrix/rotate-about/skew transforms, round caps
                      "linear_extrude(1) import(str(d, \"page_e1.svg\"));",
                      // no page size: the viewBox at the dpi; percent sizes
                      "linear_extrude(1) import(str(d, \"page_e2.svg\"), dpi=50);",
                      "linear_extrude(1) import(str(d, \"page_e3.svg\"));"));

void expectSameSurface(const std::string &src, bool warns = false) {
    SCOPED_TRACE(src);
    fs::path dir = caseDir("surface");
    ir::Mesh theirs = openscadOff(src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());
    Imported ours = importText(src);
    EXPECT_EQ(ours.warnings().empty(), !warns);
    auto prims = primitives(*ours.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    const ir::Mesh &mesh = *ours.scene.meshes.at(std::get<ir::MeshPrim>(prims[0].node->shape).mesh);
    // Ours fans the bottom from its centre; OpenSCAD's tessellation of it adds no point
    std::vector<Vec3> mine;
    Bounds3 b = mesh.bounds();
    Vec3 bottomCentre((b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, b.min.z);
    for (const Vec3 &v : mesh.positions)
        if (v != bottomCentre) mine.push_back(v);
    expectCovered(mine, theirs.positions, "our point missing from OpenSCAD's:", 2e-5);
    expectCovered(theirs.positions, mesh.positions, "OpenSCAD's point missing from ours:", 2e-5);
    double v = meshVolume(theirs);
    EXPECT_NEAR(meshio::signedVolume(mesh), v, 1e-4 * std::max(1.0, std::fabs(v)));
}

TEST(SurfaceCrossCheck, DatFilesMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    expectSameSurface("surface(\"" + data("bump.dat") + "\");");
    expectSameSurface("surface(\"" + data("ragged.dat") + "\", center=true);");
    expectSameSurface("surface(\"" + data("bad.dat") + "\");", true);
}

TEST(SurfaceCrossCheck, PngMatchesOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    fs::path dir = caseDir("png");
    std::string png = (dir / "h.png").string();
    const uint8_t px[] = {10, 200, 30, 250, 250, 250, 0, 0, 0, 90, 90, 90, 30, 60, 90, 255, 0, 0};
    writePng(png, 3, 2, 8, px, false);
    expectSameSurface("surface(\"" + png + "\");");
    expectSameSurface("surface(\"" + png + "\", invert=true, center=true);");
    fs::remove_all(dir);
}

}  // namespace
}  // namespace rt::scad::test
