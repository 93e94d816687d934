// SPDX-License-Identifier: MIT
// Scene validation: absurd sizes and non-finite values are located errors; empty scenes warn.
#include <gtest/gtest.h>

#include "core/ir/ir_validate.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

SourceLoc at(int line) { return SourceLoc(std::make_shared<const std::string>("s.scad"), line, 3); }

TEST(IrValidate, AcceptsOrdinaryAndExtremeButRepresentableScenes) {
    ir::Scene s;
    int m = s.addMaterial(ir::Material());
    s.root->children.push_back(translated(Vec3(1e6, -1e6, 0), sphere(1e-6, m)));
    s.root->children.push_back(box(Vec3(-1e99), Vec3(1e99), m));
    DiagnosticSink diag;
    EXPECT_NO_THROW(ir::validateScene(s, diag));
    EXPECT_EQ(diag.all().size(), 0u);
}

TEST(IrValidate, HugeObjectIsALocatedError) {
    ir::Scene s;
    auto b = box(Vec3(0), Vec3(1e150), s.addMaterial(ir::Material()));
    b->loc = at(7);
    s.root->children.push_back(std::move(b));
    DiagnosticSink diag;
    try {
        ir::validateScene(s, diag);
        FAIL() << "expected SceneError";
    } catch (const SceneError &e) {
        EXPECT_EQ(e.loc().line, 7);
        EXPECT_NE(std::string(e.what()).find("beyond the supported range"), std::string::npos);
    }
}

TEST(IrValidate, TinyObjectOrScaleIsALocatedError) {
    ir::Scene s;
    auto t = transformed(Mat4::scale(Vec3(1e-120)), sphere(1, s.addMaterial(ir::Material())));
    t->children[0]->loc = at(2);
    s.root->children.push_back(std::move(t));
    DiagnosticSink diag;
    EXPECT_THROW(ir::validateScene(s, diag), SceneError);
}

TEST(IrValidate, UnresolvedTwoDimensionalPlaceholderIsAnInternalError) {
    ir::Scene s;
    s.root->children.push_back(sphere(1, s.addMaterial(ir::Material())));
    auto g = ir::Node::makeGroup(ir::NodeKind::Group, at(4));
    g->shape2d = 0;
    // Cloning keeps the marker, so a copied subtree cannot lose it silently
    s.root->children.push_back(g->clone());
    DiagnosticSink diag;
    try {
        ir::validateScene(s, diag);
        FAIL() << "expected SceneError";
    } catch (const SceneError &e) {
        EXPECT_EQ(e.loc().line, 4);
        EXPECT_NE(std::string(e.what()).find("internal error"), std::string::npos);
    }
}

TEST(IrValidate, NonFiniteLightsCameraAndMaterials) {
    DiagnosticSink diag;
    {
        ir::Scene s;
        s.root->children.push_back(sphere(1, s.addMaterial(ir::Material())));
        s.lights.push_back(pointLight(Vec3(NAN, 0, 0)));
        EXPECT_THROW(ir::validateScene(s, diag), SceneError);
    }
    {
        ir::Scene s;
        s.root->children.push_back(sphere(1, s.addMaterial(ir::Material())));
        s.camera = lookAt(Vec3(0, -10, 0), Vec3(0), 200);
        EXPECT_THROW(ir::validateScene(s, diag), SceneError);
    }
    {
        ir::Scene s;
        ir::Material bad;
        bad.interior.ior = INFINITY;
        s.root->children.push_back(sphere(1, s.addMaterial(bad)));
        EXPECT_THROW(ir::validateScene(s, diag), SceneError);
    }
}

/// The message of the SceneError a scene with this light and material raises ("" if none).
std::string validationError(const ir::Light &light, const ir::Material &m = ir::Material()) {
    ir::Scene s;
    s.root->children.push_back(sphere(1, s.addMaterial(m)));
    s.lights.push_back(light);
    DiagnosticSink diag;
    try {
        ir::validateScene(s, diag);
    } catch (const SceneError &e) {
        EXPECT_EQ(e.loc().line, light.loc.line);
        return e.what();
    }
    return "";
}

TEST(IrValidate, AreaLightsAndBlurredMaterialsOutOfRange) {
    ir::Light l = pointLight(Vec3(0, 0, 5));
    l.loc = at(4);
    l.area = true;
    EXPECT_EQ(validationError(l), "");
    auto expectError = [](const std::string &got, const char *want) {
        EXPECT_NE(got.find(want), std::string::npos) << got;
    };
    ir::Light bad = l;
    bad.areaLight.axis1 = Vec3(NAN, 0, 0);
    expectError(validationError(bad), "area light axes are not finite");
    bad = l;
    bad.areaLight.n1 = ir::kMaxAreaLightGrid + 1;
    expectError(validationError(bad), "is outside 1..256 per axis");
    bad = l;
    bad.areaLight.n2 = 0;
    expectError(validationError(bad), "is outside 1..256 per axis");
    bad = l;
    bad.areaLight.adaptive = -1;
    expectError(validationError(bad), "adaptive must be >= 0");
    bad = l;
    bad.areaLight.orient = true;  // on a 1 x 1 grid
    expectError(validationError(bad), "need at least 2x2");
    bad = l;
    bad.kind = ir::Light::Kind::Directional;
    expectError(validationError(bad), "a parallel light cannot be an area light");
    // Materials are located at their own definition
    ir::Light plain = pointLight(Vec3(0, 0, 5));
    ir::Material m;
    m.loc = plain.loc;
    m.finish.glossy = 91;
    expectError(validationError(plain, m), "glossy and frosted spreads must be between 0 and 90");
    m.finish.glossy = 0;
    m.finish.frosted = NAN;
    expectError(validationError(plain, m), "glossy and frosted spreads must be between 0 and 90");
    m.finish.frosted = 0;
    m.finish.blurSamples = 0;
    expectError(validationError(plain, m), "blur_samples must be between 1 and 4096");
}

TEST(IrValidate, EmptySceneWarns) {
    ir::Scene s;
    DiagnosticSink diag;
    ir::validateScene(s, diag);
    EXPECT_EQ(diag.countContaining("no geometry"), 1);
}

}  // namespace
}  // namespace rt
