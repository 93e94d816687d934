// SPDX-License-Identifier: MIT
// The scene loader picks the importer by extension, reads the environment first and completes
// every scene the same way.
#include "importers/loader/scene_loader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace rt {
namespace {

namespace fs = std::filesystem;

class SceneLoader : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("scadray_loader_test_" +
                std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string &name, const std::string &text) {
        std::string path = (dir_ / name).string();
        std::ofstream(path) << text;
        return path;
    }
    fs::path dir_;
};

TEST(SceneFormatTest, ChosenByExtensionCaseInsensitively) {
    EXPECT_EQ(sceneFormat("a.scad"), SceneFormat::Scad);
    EXPECT_EQ(sceneFormat("dir.x/A.SCAD"), SceneFormat::Scad);
    EXPECT_EQ(sceneFormat("m.gltf"), SceneFormat::Gltf);
    EXPECT_EQ(sceneFormat("m.GLB"), SceneFormat::Gltf);
    EXPECT_EQ(sceneFormat("p.stl"), SceneFormat::Mesh);
    EXPECT_EQ(sceneFormat("p.Off"), SceneFormat::Mesh);
    EXPECT_FALSE(sceneFormat("p.obj"));
    EXPECT_FALSE(sceneFormat("scad"));
}

TEST_F(SceneLoader, ScadSceneIsCompletedWithCameraLightsAndFacets) {
    std::string path =
        write("part.scad", "cube(10); translate([20,0,0]) cylinder(r=3, h=5, $fn=6);");
    DiagnosticSink diag;
    ir::Scene s = loadScene(path, diag, LoadOptions{});
    EXPECT_TRUE(s.camera.has_value());
    EXPECT_FALSE(s.lights.empty());
    ASSERT_TRUE(s.stats.facets.has_value());
    EXPECT_EQ(s.stats.facets->mode, ir::FacetMode::Auto);
    EXPECT_EQ(s.stats.facets->faceted, 1);  // $fn=6 is a hexagon under `auto`
    EXPECT_EQ(s.settings.environment.kind, ir::EnvironmentKind::None);
}

TEST_F(SceneLoader, DefinesAndFacetModeReachTheImporter) {
    std::string path = write("d.scad", "r = 1; sphere(r, $fn=8);");
    LoadOptions lo;
    lo.defines = {{"r", "4"}};
    lo.facets = ir::FacetMode::Smooth;
    DiagnosticSink diag;
    ir::Scene s = loadScene(path, diag, lo);
    ASSERT_TRUE(s.stats.facets.has_value());
    EXPECT_EQ(s.stats.facets->faceted, 0);
    EXPECT_EQ(s.stats.facets->smooth, 1);
}

TEST_F(SceneLoader, MeshFileIsOneMeshInOpenScadsColour) {
    std::string path = write("t.off",
                             "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    DiagnosticSink diag;
    ir::Scene s = loadScene(path, diag, LoadOptions{});
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0]->triangles.size(), 4u);
    ASSERT_EQ(s.root->children.size(), 1u);
}

TEST_F(SceneLoader, UnknownExtensionAndMissingFileAreErrorsNamingTheFile) {
    std::string obj = write("m.obj", "v 0 0 0\n");
    DiagnosticSink diag;
    try {
        loadScene(obj, diag, LoadOptions{});
        FAIL() << "expected an error";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("unknown scene type '.obj'"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(loadScene((dir_ / "none.scad").string(), diag, LoadOptions{}), std::runtime_error);
}

TEST_F(SceneLoader, BadEnvironmentImageFailsBeforeTheSceneIsEvaluated) {
    // The scene would run for ever; the missing image must be reported first
    std::string path = write("slow.scad", "function f(n) = f(n + 1); x = f(0); cube(1);");
    LoadOptions lo;
    lo.environment = (dir_ / "missing.exr").string();
    int steps = 0;
    lo.progress = [&steps](int64_t) { ++steps; };
    DiagnosticSink diag;
    try {
        loadScene(path, diag, lo);
        FAIL() << "expected an error";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("environment image (-e)"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(steps, 0);
}

TEST_F(SceneLoader, ProgressDoneIsCalledAlsoWhenTheEvaluationFails) {
    std::string path = write("bad.scad", "cube(;");
    LoadOptions lo;
    bool done = false;
    lo.progressDone = [&done] { done = true; };
    DiagnosticSink diag;
    EXPECT_ANY_THROW(loadScene(path, diag, lo));
    EXPECT_TRUE(done);
}

}  // namespace
}  // namespace rt
