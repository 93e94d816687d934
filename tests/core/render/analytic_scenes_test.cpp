// SPDX-License-Identifier: MIT
// Whole renders checked against values computed by hand from POV-Ray's classic shading model:
// a lit diffuse sphere, highlights, mirrors, a glass slab's lateral shift, total internal
// reflection in a prism, filtered shadows through glass, trace-depth limits, light fade.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/camera.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

RenderResult renderScene(const ir::Scene &scene, int w, int h, int spp = 1, int threads = 2) {
    DiagnosticSink diag;
    auto rs = RenderScene::compile(scene, diag);
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.samplesPerPixel = spp;
    o.threads = threads;
    return renderImage(*rs, o);
}

void expectRgbNear(const Rgb &got, const Rgb &want, double tol = 2e-6) {
    EXPECT_NEAR(got.r, want.r, tol);
    EXPECT_NEAR(got.g, want.g, tol);
    EXPECT_NEAR(got.b, want.b, tol);
}

// Camera on -y looking at the origin; with an odd image size the centre pixel's ray is +y.
ir::Scene sphereScene(const ir::Material &m, const Vec3 &lightPos) {
    ir::Scene s = emptyScene();
    s.root->children.push_back(sphere(1, s.addMaterial(m)));
    s.lights.push_back(pointLight(lightPos));
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(0, 0, 0), 30);
    return s;
}

TEST(AnalyticScenes, LitDiffuseSphereCentrePixel) {
    ir::Material m = plainMaterial(Rgb(1, 0.5, 0.25), 0.1, 0.6);
    ir::Scene s = sphereScene(m, Vec3(0, -10, 0));
    RenderResult r = renderScene(s, 33, 33);
    // Head-on light: ambient 0.1 + diffuse 0.6 * cos(0)
    expectRgbNear(r.image.at(16, 16), Rgb(1, 0.5, 0.25) * 0.7);
    // Background is black, corners miss the sphere
    expectRgbNear(r.image.at(0, 0), Rgb(0));
}

TEST(AnalyticScenes, BrillianceAmbientLightPhongAndSpecular) {
    ir::Material m = plainMaterial(Rgb(1, 0.5, 0.25), 0.1, 0.6);
    m.finish.brilliance = 2;
    m.finish.phong = 0.5;
    m.finish.phongSize = 10;
    m.finish.specular = 0.3;
    m.finish.roughness = 0.1;
    ir::Scene s = sphereScene(m, Vec3(0, -10, 10));
    s.settings.ambientLight = Rgb(0.5, 1, 1);
    RenderResult r = renderScene(s, 33, 33);
    // Hit point (0,-1,0), normal N = (0,-1,0), view d = (0,1,0)
    Vec3 L = normalize(Vec3(0, -9, 10));
    double cosNL = 9 / std::sqrt(181.0);
    Rgb c(1, 0.5, 0.25);
    Rgb want = c * Rgb(0.5, 1, 1) * 0.1 + c * (0.6 * cosNL * cosNL);
    Vec3 R(0, -1, 0);  // mirror of d about N
    want += Rgb(0.5 * std::pow(dot(R, L), 10));
    Vec3 H = (L - Vec3(0, 1, 0)) * 0.5;
    want += Rgb(0.3 * std::pow(dot(H, Vec3(0, -1, 0)) / length(H), 1 / 0.1));
    expectRgbNear(r.image.at(16, 16), want);
}

TEST(AnalyticScenes, LightBehindTheSurfaceDoesNothing) {
    ir::Material m = plainMaterial(Rgb(1), 0.2, 0.6);
    ir::Scene s = sphereScene(m, Vec3(0, 10, 0));
    RenderResult r = renderScene(s, 33, 33);
    expectRgbNear(r.image.at(16, 16), Rgb(0.2));
}

TEST(AnalyticScenes, LightFadeIsNominalAtFadeDistance) {
    ir::Material m = plainMaterial(Rgb(1), 0, 1);
    for (auto [dist, factor] : {std::pair{4.0, 1.0}, std::pair{2.0, 1.6}}) {
        ir::Scene s = sphereScene(m, Vec3(0, -1 - dist, 0));
        s.lights[0].fadeDistance = 4;
        s.lights[0].fadePower = 2;
        RenderResult r = renderScene(s, 33, 33);
        // 2 / (1 + (d/4)^2): 1 at d = 4, 1.6 at d = 2
        expectRgbNear(r.image.at(16, 16), Rgb(factor));
    }
}

ir::Scene mirrorScene(const ir::Finish &mirrorFinish) {
    ir::Scene s = emptyScene();
    ir::Material mirror = plainMaterial(Rgb(0));
    mirror.finish = mirrorFinish;
    s.root->children.push_back(box(Vec3(-5, 1, -5), Vec3(5, 2, 5), s.addMaterial(mirror)));
    // A red, purely ambient sphere behind the camera, seen only in the mirror
    s.root->children.push_back(
        translated(Vec3(0, -8, 0), sphere(1, s.addMaterial(plainMaterial(Rgb(1, 0, 0), 1)))));
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(0, 0, 0), 30);
    return s;
}

TEST(AnalyticScenes, MirrorReflectsWhatIsBehindTheCamera) {
    ir::Finish f;
    f.ambient = 0;
    f.diffuse = 0;
    f.reflectionMin = f.reflectionMax = Rgb(0.8);
    RenderResult r = renderScene(mirrorScene(f), 33, 33);
    expectRgbNear(r.image.at(16, 16), Rgb(0.8, 0, 0));
    EXPECT_GT(r.stats.reflection, 0);
}

TEST(AnalyticScenes, ReflectionFalloffUsesMinimumHeadOn) {
    ir::Finish f;
    f.ambient = 0;
    f.diffuse = 0;
    f.reflectionMin = Rgb(0.2);
    f.reflectionMax = Rgb(0.8);
    RenderResult r = renderScene(mirrorScene(f), 33, 33);
    expectRgbNear(r.image.at(16, 16), Rgb(0.2, 0, 0));
}

TEST(AnalyticScenes, TraceLevelLimitReturnsBlackNotBackground) {
    ir::Finish f;
    f.ambient = 0;
    f.diffuse = 0;
    f.reflectionMin = f.reflectionMax = Rgb(1);
    ir::Scene s = emptyScene();
    ir::Material mirror = plainMaterial(Rgb(0));
    mirror.finish = f;
    s.root->children.push_back(box(Vec3(-5, 1, -5), Vec3(5, 2, 5), s.addMaterial(mirror)));
    s.settings.background = Rgb(0, 0, 1);
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(0, 0, 0), 30);
    s.settings.maxTraceLevel = 1;
    expectRgbNear(renderScene(s, 33, 33).image.at(16, 16), Rgb(0));
    s.settings.maxTraceLevel = 2;
    expectRgbNear(renderScene(s, 33, 33).image.at(16, 16), Rgb(0, 0, 1));
}

/// A slab y in [0,1], seen at 30 degrees; behind it at y = 10 a green strip where the refracted
/// ray arrives and a blue wall elsewhere.
ir::Scene slabScene(double ior) {
    ir::Scene s = emptyScene();
    s.root->children.push_back(
        box(Vec3(-50, 0, -50), Vec3(50, 1, 50), s.addMaterial(glassMaterial(ior))));
    s.root->children.push_back(
        box(Vec3(8.40, 10, -1), Vec3(8.47, 11, 1), s.addMaterial(plainMaterial(Rgb(0, 1, 0), 1))));
    s.root->children.push_back(
        box(Vec3(-50, 11, -50), Vec3(50, 12, 50), s.addMaterial(plainMaterial(Rgb(0, 0, 1), 1))));
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(5 * std::tan(M_PI / 6), 0, 0), 10);
    return s;
}

TEST(AnalyticScenes, GlassSlabShiftsTheRayLaterally) {
    // Entry at x = 5 tan 30; inside sin(phi) = sin(30)/1.5 adds tan(phi) over the unit
    // thickness; then 9 tan 30 to y = 10: x = 8.43645, against 8.66025 without the slab
    double sinPhi = 0.5 / 1.5, tanPhi = sinPhi / std::sqrt(1 - sinPhi * sinPhi);
    double x = 14 * std::tan(M_PI / 6) + tanPhi;
    ASSERT_GT(x, 8.40);
    ASSERT_LT(x, 8.47);
    RenderResult r = renderScene(slabScene(1.5), 33, 33);
    expectRgbNear(r.image.at(16, 16), Rgb(0, 1, 0));
    EXPECT_GT(r.stats.refraction, 0);
    // Same slab with ior 1: the ray goes straight through to the wall
    RenderResult straight = renderScene(slabScene(1.0), 33, 33);
    expectRgbNear(straight.image.at(16, 16), Rgb(0, 0, 1));
    EXPECT_EQ(straight.stats.refraction, 0);
    EXPECT_GT(straight.stats.transmission, 0);
}

/// Right-angled glass prism (box cut by x + y <= 1) seen along +y at x = 0.3: the ray meets the
/// hypotenuse at 45 degrees, beyond the critical angle for ior 1.5, reflects to -x and leaves
/// through the face x = 0 towards a green wall; a blue wall stands behind the prism.
ir::Scene prismScene(double ior) {
    ir::Scene s = emptyScene();
    int glass = s.addMaterial(glassMaterial(ior));
    auto cut =
        transformed(Mat4::rotateZ(45), box(Vec3(-20, -20, -2), Vec3(std::sqrt(0.5), 20, 2), glass));
    s.root->children.push_back(
        csg(ir::NodeKind::Intersection, box(Vec3(0, 0, -1), Vec3(1, 1, 1), glass), std::move(cut)));
    s.root->children.push_back(
        box(Vec3(-7, -20, -20), Vec3(-6, 20, 20), s.addMaterial(plainMaterial(Rgb(0, 1, 0), 1))));
    s.root->children.push_back(
        box(Vec3(-5, 5, -20), Vec3(20, 6, 20), s.addMaterial(plainMaterial(Rgb(0, 0, 1), 1))));
    s.camera = lookAt(Vec3(0.3, -5, 0), Vec3(0.3, 0, 0), 5);
    return s;
}

TEST(AnalyticScenes, TotalInternalReflectionInAPrism) {
    RenderResult r = renderScene(prismScene(1.5), 33, 33);
    // TIR adds the reflected colour unfiltered; entry and exit are head-on
    expectRgbNear(r.image.at(16, 16), Rgb(0, 1, 0));
    EXPECT_GT(r.stats.internalReflection, 0);
    // Below the critical angle the ray refracts out of the hypotenuse instead
    RenderResult below = renderScene(prismScene(1.2), 33, 33);
    EXPECT_LT(below.image.at(16, 16).g, 0.5);
}

TEST(AnalyticScenes, ShadowThroughGlassIsFilteredAtEachSurface) {
    for (auto [filter, transmit, want] :
         {std::tuple{0.9, 0.0, 0.81}, std::tuple{0.0, 0.5, 0.25}, std::tuple{0.0, 0.0, 0.0}}) {
        ir::Scene s = emptyScene();
        s.root->children.push_back(
            box(Vec3(-10, -10, -1), Vec3(10, 10, 0), s.addMaterial(plainMaterial(Rgb(1), 0, 1))));
        ir::Material glass = glassMaterial(1.0, transmit, filter);
        s.root->children.push_back(translated(Vec3(0, 0, 3), sphere(1, s.addMaterial(glass))));
        s.lights.push_back(pointLight(Vec3(0, 0, 10)));
        s.camera = lookAt(Vec3(0, -10, 1), Vec3(0, 0, 0), 10);
        RenderResult r = renderScene(s, 33, 33);
        expectRgbNear(r.image.at(16, 16), Rgb(want), 1e-5);
    }
}

TEST(AnalyticScenes, RendersIdenticallyForAnyThreadCount) {
    ir::Scene s = prismScene(1.5);
    s.root->children.push_back(translated(
        Vec3(1, 2, 0), sphere(0.7, s.addMaterial(plainMaterial(Rgb(1, 1, 0), 0.1, 0.7)))));
    s.lights.push_back(pointLight(Vec3(-3, -4, 5)));
    RenderResult one = renderScene(s, 40, 30, 4, 1);
    RenderResult two = renderScene(s, 40, 30, 4, 2);
    RenderResult three = renderScene(s, 40, 30, 4, 3);
    EXPECT_EQ(one.image.data(), two.image.data());
    EXPECT_EQ(one.image.data(), three.image.data());
    EXPECT_EQ(one.stats.totalRays(), two.stats.totalRays());
}

TEST(Camera, FollowsPovRayLookAtConstruction) {
    ir::Camera c = lookAt(Vec3(0, -10, 0), Vec3(0, 0, 0), 60);
    Camera cam(c, 64, 48);
    // Right edge centre: 30 degrees to the right (+x, right-handed Z-up)
    Ray r = cam.generateRay(64, 24);
    EXPECT_NEAR(std::atan2(r.d.x, r.d.y), M_PI / 6, 1e-12);
    EXPECT_NEAR(r.d.z, 0, 1e-15);
    // Top edge: vertical half-angle atan(tan(30)/aspect), upwards
    Ray top = cam.generateRay(32, 0);
    EXPECT_NEAR(std::atan2(top.d.z, top.d.y), std::atan(std::tan(M_PI / 6) * 48 / 64), 1e-12);
    ir::Camera bad = lookAt(Vec3(0, 0, 5), Vec3(0, 0, 0), 60);  // sky parallel to the view
    EXPECT_THROW(Camera(bad, 64, 48), SceneError);
    ir::Camera vertical = c;
    vertical.fov = 22.5;
    vertical.fovAxis = ir::FovAxis::Vertical;
    Camera vc(vertical, 64, 48);
    Ray vtop = vc.generateRay(32, 0);
    EXPECT_NEAR(std::atan2(vtop.d.z, vtop.d.y), radians(11.25), 1e-12);
}

TEST(Renderer, RejectsAbsurdOptions) {
    RenderOptions o;
    o.width = 0;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.width = 100000;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.width = 64;
    o.samplesPerPixel = 0;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.samplesPerPixel = kMaxSamplesPerPixel + 1;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.samplesPerPixel = 5;
    EXPECT_NO_THROW(validateRenderOptions(o));
    // Each side allowed, the total too large (36 GB of images): refused before allocating
    o.width = o.height = kMaxImageSide;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.width = o.height = 16384;
    EXPECT_NO_THROW(validateRenderOptions(o));
}

TEST(Renderer, StrataAreTheSquarestGrid) {
    auto grid = [](int n) {
        int c, r;
        strataGrid(n, c, r);
        return std::make_pair(c, r);
    };
    EXPECT_EQ(grid(1), std::make_pair(1, 1));
    EXPECT_EQ(grid(2), std::make_pair(2, 1));
    EXPECT_EQ(grid(8), std::make_pair(4, 2));
    EXPECT_EQ(grid(16), std::make_pair(4, 4));
    EXPECT_EQ(grid(7), std::make_pair(7, 1));
    EXPECT_EQ(grid(12), std::make_pair(4, 3));
}

}  // namespace
}  // namespace rt
