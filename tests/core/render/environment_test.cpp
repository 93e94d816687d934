// SPDX-License-Identifier: MIT
// The environment rays see when they leave the scene: the studio gradient by direction height,
// the equirectangular image by the documented orientation (u from +X through -Y, top row +Z)
// at known pixels, its mean, files read through the image loader, and a mirror sphere that
// shows the environment instead of black.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/image/environment_image.h"
#include "core/image/image_io.h"
#include "core/render/environment.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

void expectRgbNear(const Rgb &a, const Rgb &b, double tol = 1e-9) {
    EXPECT_NEAR(a.r, b.r, tol);
    EXPECT_NEAR(a.g, b.g, tol);
    EXPECT_NEAR(a.b, b.b, tol);
}

TEST(Environment, StudioGradientByHeight) {
    ir::Environment e = ir::studioEnvironment();
    expectRgbNear(environmentRadiance(e, Vec3(0, 0, 1)), Rgb(1));
    expectRgbNear(environmentRadiance(e, Vec3(0, 0, -3)), Rgb(0.1));
    expectRgbNear(environmentRadiance(e, Vec3(1, 0, 0)), Rgb(0.5));
    expectRgbNear(environmentRadiance(e, Vec3(0, -7, 0)), Rgb(0.5));
    // z = 0.25: halfway between the horizon and the z = 0.5 stop, whatever the length
    Vec3 d(std::sqrt(1 - 0.25 * 0.25), 0, 0.25);
    expectRgbNear(environmentRadiance(e, d * 5), Rgb(0.65, 0.66, 0.675));
    // z = -0.5: halfway between the ground and the horizon
    expectRgbNear(environmentRadiance(e, Vec3(0, std::sqrt(0.75), -0.5)), Rgb(0.3));
}

TEST(Environment, NoneLeavesTheBackground) {
    ir::Settings s;
    s.background = Rgb(0.2, 0.3, 0.4);
    expectRgbNear(missRadiance(s, Vec3(0, 0, 1)), Rgb(0.2, 0.3, 0.4));
    s.environment = ir::studioEnvironment();
    expectRgbNear(missRadiance(s, Vec3(0, 0, 1)), Rgb(1));
}

TEST(Environment, EquirectangularOrientation) {
    double u, v;
    auto uv = [&](const Vec3 &d, double rot = 0) { environmentUv(rot, d, &u, &v); };
    uv(Vec3(1, 0, 0));
    EXPECT_NEAR(u, 0, 1e-12);
    EXPECT_NEAR(v, 0.5, 1e-12);
    uv(Vec3(0, -1, 0));
    EXPECT_NEAR(u, 0.25, 1e-12);
    uv(Vec3(-1, 0, 0));
    EXPECT_NEAR(u, 0.5, 1e-12);
    uv(Vec3(0, 2, 0));
    EXPECT_NEAR(u, 0.75, 1e-12);
    uv(Vec3(0, 0, 1));
    EXPECT_NEAR(v, 0, 1e-12);
    uv(Vec3(0, 0, -1));
    EXPECT_NEAR(v, 1, 1e-12);
    uv(Vec3(1, 0, 1));
    EXPECT_NEAR(v, 0.25, 1e-12);
    // Turned 90 degrees counterclockwise: what was along +X is now along +Y
    uv(Vec3(0, 1, 0), 90);
    EXPECT_NEAR(std::min(u, 1 - u), 0, 1e-12);  // 0 and 1 are the same place
    // and what was along -Y (u = 0.25) is now along +X
    uv(Vec3(1, 0, 0), 90);
    EXPECT_NEAR(u, 0.25, 1e-12);
}

/// An 8 x 4 image whose every pixel has its own colour.
ir::TexturePtr numberedImage() {
    auto t = std::make_shared<ir::Texture>();
    t->width = 8;
    t->height = 4;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) t->rgba.insert(t->rgba.end(), {float(x), float(y), 2.f, 1.f});
    return t;
}

/// The direction whose (u, v) is the centre of pixel (x, y) of a w x h equirectangular image.
Vec3 pixelDirection(int x, int y, int w, int h) {
    double theta = 2 * kPi * (x + 0.5) / w;
    double elevation = kPi * (0.5 - (y + 0.5) / h);
    return {std::cos(elevation) * std::cos(theta), -std::cos(elevation) * std::sin(theta),
            std::sin(elevation)};
}

TEST(Environment, ImageMapsKnownPixels) {
    ir::Environment e;
    e.kind = ir::EnvironmentKind::Image;
    e.image = numberedImage();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            expectRgbNear(environmentRadiance(e, pixelDirection(x, y, 8, 4)), Rgb(x, y, 2), 1e-6);
    // Rotated by one pixel's width (45 degrees): each pixel moves one step counterclockwise
    e.rotateDegrees = 45;
    Vec3 d = pixelDirection(3, 1, 8, 4);
    double c = std::cos(radians(45)), s = std::sin(radians(45));
    Vec3 turned(c * d.x - s * d.y, s * d.x + c * d.y, d.z);
    expectRgbNear(environmentRadiance(e, turned), Rgb(3, 1, 2), 1e-6);
}

TEST(Environment, MeanOfGradientAndImage) {
    // Directions are uniform in z: numerical integration over z agrees
    ir::Environment e = ir::studioEnvironment();
    Rgb sum(0);
    int n = 200000;
    for (int i = 0; i < n; ++i) {
        double z = -1 + 2 * (i + 0.5) / n;
        sum += environmentRadiance(e, Vec3(std::sqrt(1 - z * z), 0, z));
    }
    expectRgbNear(environmentMean(e), sum * (1.0 / n), 1e-6);
    ir::Environment img;
    img.kind = ir::EnvironmentKind::Image;
    auto t = std::make_shared<ir::Texture>();
    t->width = 2;
    t->height = 2;
    t->rgba = {1, 1, 1, 1, 1, 1, 1, 1, 3, 3, 3, 1, 3, 3, 3, 1};
    img.image = t;
    expectRgbNear(environmentMean(img), Rgb(2), 1e-12);  // the two rows weigh the same
}

TEST(Environment, LoadsAnExrAndNamesABadFile) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / "scadray_environment_test";
    fs::create_directories(dir);
    Image img(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) img.set(x, y, Rgb(x, y, 2.5));
    std::string exr = (dir / "env.exr").string();
    writeImage(img, exr);
    DiagnosticSink diag;
    ir::Environment e = loadEnvironmentImage(exr, 0, diag);
    ASSERT_EQ(e.kind, ir::EnvironmentKind::Image);
    EXPECT_EQ(e.imagePath, exr);
    expectRgbNear(environmentRadiance(e, pixelDirection(5, 2, 8, 4)), Rgb(5, 2, 2.5), 1e-5);
    // Not an image: the error names the file
    std::string bad = (dir / "bad.exr").string();
    { std::ofstream(bad) << "not an image"; }
    try {
        loadEnvironmentImage(bad, 0, diag);
        FAIL() << "expected an error";
    } catch (const std::runtime_error &err) {
        EXPECT_NE(std::string(err.what()).find("bad.exr"), std::string::npos) << err.what();
    }
    fs::remove_all(dir);
}

TEST(Environment, MirrorSphereReflectsTheEnvironment) {
    ir::Scene s = emptyScene();
    ir::Material mirror = plainMaterial(Rgb(0.9), 0, 0);
    mirror.finish.reflectionMin = Rgb(0.9);
    mirror.finish.reflectionMax = Rgb(0.9);
    s.root->children.push_back(sphere(1, s.addMaterial(mirror)));
    s.lights.push_back(pointLight(Vec3(4, -6, 8)));
    s.camera = lookAt(Vec3(0, -5, 0), Vec3(0), 40);
    auto render = [&] {
        DiagnosticSink diag;
        auto rs = RenderScene::compile(s, diag);
        RenderOptions o;
        o.width = 32;
        o.height = 32;
        return renderImage(*rs, o).image;
    };
    Image black = render();
    EXPECT_LT(black.at(16, 16).g, 0.05) << "without an environment the mirror shows black";
    s.settings.environment = ir::studioEnvironment();
    Image lit = render();
    // The sphere's upper half reflects the bright sky, its lower half the darker ground, its
    // centre (facing the camera) the horizon behind the camera
    Rgb top = lit.at(16, 9), centre = lit.at(16, 16), bottom = lit.at(16, 23);
    EXPECT_GT(centre.g, 0.3);
    EXPECT_GT(top.g, centre.g + 0.05);
    EXPECT_LT(bottom.g, centre.g - 0.05);
    // Beyond the sphere the camera sees the horizon
    expectRgbNear(lit.at(0, 16), Rgb(0.5), 0.05);
}

}  // namespace
}  // namespace rt
