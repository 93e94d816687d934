// SPDX-License-Identifier: MIT
// The automatic camera frames the whole model from OpenSCAD's default view; default lights are
// added only when the scene has none; the gimbal camera follows OpenSCAD's conventions.
#include <gtest/gtest.h>

#include "core/camera/camera.h"
#include "core/ir/ir_dump.h"
#include "core/ir/scene_defaults.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

TEST(SceneDefaults, AutomaticCameraFramesTheModel) {
    ir::Scene s;
    int m = s.addMaterial(ir::Material());
    s.root->children.push_back(translated(Vec3(10, 20, 5), box(Vec3(0), Vec3(30, 10, 4), m)));
    DiagnosticSink diag;
    ir::completeScene(s, diag);
    ASSERT_TRUE(s.camera);
    EXPECT_EQ(s.camera->source, ir::CameraSource::Automatic);
    EXPECT_EQ(s.camera->fovAxis, ir::FovAxis::Vertical);
    EXPECT_DOUBLE_EQ(s.camera->fov, 22.5);
    EXPECT_EQ(s.camera->lookAt, Vec3(25, 25, 7));
    // Eye in front (-y), to the right (+x) and above, as OpenSCAD's default view
    Vec3 eye = s.camera->location - s.camera->lookAt;
    EXPECT_GT(eye.x, 0);
    EXPECT_LT(eye.y, 0);
    EXPECT_GT(eye.z, 0);
    // Every corner of the bounds projects inside a 4:3 image
    Camera cam(*s.camera, 640, 480);
    Vec3 fwd = normalize(s.camera->lookAt - s.camera->location);
    Bounds3 b = ir::worldBounds(*s.root);
    for (int i = 0; i < 8; ++i) {
        Vec3 c(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
        Vec3 d = normalize(c - s.camera->location);
        double angle = std::acos(dot(d, fwd));
        EXPECT_LT(angle, radians(22.5 / 2) + 1e-9);
    }
    EXPECT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.lights[0].shadowless);
    EXPECT_TRUE(s.lights[1].shadowless);
    EXPECT_EQ(diag.count(Severity::Note), 2);
}

TEST(SceneDefaults, KeepsWhatTheSceneSets) {
    ir::Scene s;
    s.root->children.push_back(sphere(1, s.addMaterial(ir::Material())));
    s.camera = lookAt(Vec3(1, 2, 3), Vec3(0), 50);
    s.lights.push_back(pointLight(Vec3(5)));
    DiagnosticSink diag;
    ir::completeScene(s, diag);
    EXPECT_EQ(s.camera->location, Vec3(1, 2, 3));
    EXPECT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(diag.all().size(), 0u);
}

TEST(SceneDefaults, GimbalCameraConventions) {
    // vpr = 0 looks straight down with +y up; vpr = [90,0,0] looks along +y
    ir::Camera top = ir::cameraFromViewport(Vec3(1, 2, 3), Vec3(0, 0, 0), 10, 22.5);
    EXPECT_EQ(top.location, Vec3(1, 2, 13));
    EXPECT_EQ(top.sky, Vec3(0, 1, 0));
    ir::Camera front = ir::cameraFromViewport(Vec3(0), Vec3(90, 0, 0), 10, 30);
    EXPECT_EQ(front.location, Vec3(0, -10, 0));
    EXPECT_EQ(front.sky, Vec3(0, 0, 1));
    EXPECT_EQ(front.fovAxis, ir::FovAxis::Vertical);
}

TEST(IrDump, CanonicalText) {
    ir::Scene s;
    int m = s.addMaterial(ir::Material());
    EXPECT_EQ(s.addMaterial(ir::Material()), m);  // deduplicated by appearance
    s.root->children.push_back(csg(ir::NodeKind::Difference, box(Vec3(0), Vec3(1), m),
                                   translated(Vec3(0.5, -0.25, 1e-12), sphere(0.3, m))));
    std::string text = ir::dump(*s.root);
    EXPECT_EQ(text,
              "group\n"
              "  difference\n"
              "    box min [0, 0, 0] max [1, 1, 1] material 0 fn 0 fa 12 fs 2\n"
              "    transform [[1, 0, 0, 0.5], [0, 1, 0, -0.25], [0, 0, 1, 1e-12]]\n"
              "      sphere r 0.3 material 0 fn 0 fa 12 fs 2\n");
    EXPECT_EQ(ir::formatNumber(-0.0), "0");
    EXPECT_EQ(ir::formatNumber(1.0 / 3), "0.3333333333");
}

}  // namespace
}  // namespace rt
