// SPDX-License-Identifier: MIT
// The environment in POV-Ray SDL: the gradient as a sky_sphere colour_map whose entries are
// the gradient's stops mapped from z in [-1, 1] to [0, 1]; an image as a map_type 1 image_map
// turned so its pole is +Z, written beside the .pov; no sky_sphere without an environment.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/ir/scene_defaults.h"
#include "exporters/povray/pov_writer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

ir::Scene sphereScene() {
    ir::Scene s = emptyScene();
    s.root->children.push_back(sphere(1, s.addMaterial(ir::Material())));
    DiagnosticSink diag;
    ir::completeScene(s, diag);
    return s;
}

TEST(PovEnvironment, GradientIsAColourMapOverZ) {
    ir::Scene s = sphereScene();
    EXPECT_EQ(pov::writeSdl(s, "t").find("sky_sphere"), std::string::npos);
    s.settings.environment = ir::studioEnvironment();
    std::string sdl = pov::writeSdl(s, "t");
    EXPECT_NE(sdl.find("sky_sphere {\n    pigment {\n        gradient z\n"), std::string::npos)
        << sdl;
    EXPECT_NE(sdl.find("            [0 rgb <0.1, 0.1, 0.1>]\n"
                       "            [0.5 rgb <0.5, 0.5, 0.5>]\n"
                       "            [0.75 rgb <0.8, 0.82, 0.85>]\n"
                       "            [1 rgb <1, 1, 1>]\n"),
              std::string::npos)
        << sdl;
    EXPECT_NE(sdl.find("scale 2 translate -z"), std::string::npos);
}

TEST(PovEnvironment, ImageIsASphericalMapWrittenBesideThePov) {
    ir::Scene s = sphereScene();
    auto t = std::make_shared<ir::Texture>();
    t->width = 4;
    t->height = 2;
    t->rgba.assign(4 * 8, 2.0f);
    s.settings.environment.kind = ir::EnvironmentKind::Image;
    s.settings.environment.image = t;
    s.settings.environment.imagePath = "sky.hdr";
    s.settings.environment.rotateDegrees = 30;
    std::vector<pov::TextureFile> files;
    std::string sdl = pov::writeSdl(s, "t", &files, "scene");
    EXPECT_NE(sdl.find("image_map { exr \"scene_environment.exr\" map_type 1 interpolate 2 }\n"
                       "        rotate x*90\n        rotate z*30\n"),
              std::string::npos)
        << sdl;
    ASSERT_EQ(files.size(), 1u);
    EXPECT_EQ(files[0].fileName, "scene_environment.exr");
    EXPECT_EQ(files[0].image.width(), 4);
    EXPECT_FLOAT_EQ(files[0].image.at(3, 1).g, 2.0f) << "values above 1 are kept";
}

}  // namespace
}  // namespace rt
