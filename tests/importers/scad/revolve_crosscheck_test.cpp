// SPDX-License-Identifier: MIT
// Cross-checks rotate_extrude against the installed OpenSCAD 2021.01: drawn faceted
// (--facets openscad), each revolved leaf is OpenSCAD's mesh: the same vertices (its rings at
// its angles, for both sides of the axis and both senses of the angle) and the same volume.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/ir/facets.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

/// OFF files print 6 significant digits, and OpenSCAD snaps 2D outlines to a fixed-point
/// grid (Clipper) before revolving them.
constexpr double kVertexTolerance = 2e-5;
constexpr double kVolumeTolerance = 1e-5;  ///< relative

bool haveOpenScad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

class RevolveCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(RevolveCrossCheck, FacetedMeshIsOpenScads) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const char *src = GetParam();
    SCOPED_TRACE(src);
    fs::path dir = fs::temp_directory_path() / ("scadray_revolve_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::string in = (dir / "case.scad").string(), off = (dir / "case.off").string();
    std::ofstream(in) << src << "\n";
    fs::remove(off);
    std::string cmd = "openscad -o '" + off + "' '" + in + "' >/dev/null 2>&1";
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
    DiagnosticSink offDiag;
    ir::Mesh ref = meshio::readOff(off, offDiag);

    DiagnosticSink diag;
    ir::Scene scene = importScad(in, diag);
    ir::applyFacets(scene, ir::FacetMode::OpenScad, diag);
    auto prims = primitives(*scene.root);
    ASSERT_EQ(prims.size(), 1u);
    const auto *mp = std::get_if<ir::MeshPrim>(&prims[0].node->shape);
    ASSERT_NE(mp, nullptr) << "the faceted form of a revolved leaf is a mesh";
    const ir::Mesh &mesh = *scene.meshes.at(mp->mesh);
    EXPECT_EQ(meshio::solidProblem(mesh), "");
    std::vector<Vec3> ours;
    for (const Vec3 &v : mesh.positions) ours.push_back(prims[0].worldFromObject.transformPoint(v));

    EXPECT_NEAR(meshio::signedVolume(mesh), std::abs(meshio::signedVolume(ref)),
                kVolumeTolerance * std::abs(meshio::signedVolume(ref)));
    auto has = [](const std::vector<Vec3> &set, const Vec3 &v) {
        for (const Vec3 &w : set)
            if (length(w - v) < kVertexTolerance * std::max(1.0, length(v))) return true;
        return false;
    };
    for (const Vec3 &v : ref.positions)
        EXPECT_TRUE(has(ours, v)) << "OpenSCAD vertex missing: " << v.x << " " << v.y << " "
                                  << v.z;
    for (const Vec3 &v : ours)
        EXPECT_TRUE(has(ref.positions, v))
            << "vertex not in OpenSCAD's: " << v.x << " " << v.y << " " << v.z;
}

INSTANTIATE_TEST_SUITE_P(
    Revolve, RevolveCrossCheck,
    ::testing::Values(
        "rotate_extrude($fn=8) translate([2, 0]) square([1, 2]);",
        "rotate_extrude($fn=5) translate([2, -1]) square(1);",
        "rotate_extrude(angle=90, $fn=12) translate([2, 0]) square([1, 2]);",
        "rotate_extrude($fn=6) translate([3, 1]) circle(1, $fn=5);",
        "rotate_extrude(angle=-120, $fn=9) polygon([[0, 0], [3, 0], [1, 2], [0, 3]]);",
        "rotate_extrude(angle=200) translate([-4, 0]) circle(1, $fn=7);",
        "rotate_extrude($fn=7) translate([-4, 0]) rotate(10) square([1, 2]);",
        "rotate_extrude(angle=45) translate([1, 0]) circle(1, $fn=8);",
        "rotate_extrude($fn=10) polygon([[1, 0], [4, 0], [4, 3], [1, 3], [2, 1], [3, 1], "
        "[3, 2], [2, 2]], [[0, 1, 2, 3], [4, 5, 6, 7]]);"));

}  // namespace
}  // namespace rt::scad::test
