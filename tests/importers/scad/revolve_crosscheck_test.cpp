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

#include "core/meshing/facets.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/openscad_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

constexpr double kVolumeTolerance = 1e-5;  ///< relative (OFF's 6 digits)

class RevolveCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(RevolveCrossCheck, FacetedMeshIsOpenScads) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const char *src = GetParam();
    SCOPED_TRACE(src);
    fs::path dir = fs::temp_directory_path() / ("scadray_revolve_" + std::to_string(getpid()));
    fs::create_directories(dir);
    ir::Mesh ref = openscadOff(src, dir);

    DiagnosticSink diag;
    ir::Scene scene = importScad((dir / "case.scad").string(), diag);
    meshing::applyFacets(scene, ir::FacetMode::OpenScad, diag);
    auto prims = primitives(*scene.root);
    ASSERT_EQ(prims.size(), 1u);
    const auto *mp = std::get_if<ir::MeshPrim>(&prims[0].node->shape);
    ASSERT_NE(mp, nullptr) << "the faceted form of a revolved leaf is a mesh";
    const ir::Mesh &mesh = *scene.meshes.at(mp->mesh);
    EXPECT_EQ(meshio::solidProblem(mesh), "");
    std::vector<Vec3> ours;
    for (const Vec3 &v : mesh.positions) ours.push_back(prims[0].worldFromObject.transformPoint(v));

    double refVolume = std::abs(meshVolume(ref));
    EXPECT_NEAR(meshVolume(mesh), refVolume, kVolumeTolerance * refVolume);
    expectCovered(ref.positions, ours, "OpenSCAD vertex missing:");
    expectCovered(ours, ref.positions, "vertex not in OpenSCAD's:");
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
