// SPDX-License-Identifier: MIT
// Tori and lathes in POV-Ray SDL: the objects written, and (with povray installed) POV-Ray's
// picture of whole and partial turns against scadray's, pixel for pixel of the silhouette, so
// the orientation of the axis and of the wedge is checked by rendering.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "core/image/image_io.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

int count(const std::string &text, const std::string &what) {
    int n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

ir::ProfileOutline rect(double r0, double r1, double z0, double z1) {
    return {{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
}

ir::NodePtr prim(ir::PrimShape shape, int material) {
    return ir::Node::makePrimitive(std::move(shape), material, {});
}

/// White solids on black: a lathe with a hole cut to a quarter turn, a three-quarter torus,
/// a lopsided profile (wider at the top) and a whole horn torus. Flat (ambient only), or
/// shaded by a point light with a block cut by a thin torus beside them.
ir::Scene revolvedScene(bool shaded = false) {
    ir::Scene s = emptyScene();
    int white = s.addMaterial(plainMaterial(Rgb(1), shaded ? 0.2 : 1, shaded ? 0.8 : 0));
    if (shaded) {
        s.lights.push_back(pointLight(Vec3(6, 2, 12)));
        s.root->children.push_back(
            translated(Vec3(2, -6, 0), csg(ir::NodeKind::Difference,
                                           box(Vec3(-1.5, -1.5, -0.5), Vec3(1.5, 1.5, 0.1), white),
                                           prim(ir::TorusPrim{1, 0.2, 360, {}, 0}, white))));
    }
    s.root->children.push_back(
        prim(ir::LathePrim{{rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)}, 90, 0}, white));
    s.root->children.push_back(
        translated(Vec3(-5, 0, 0), prim(ir::TorusPrim{1.5, 0.5, 270, {}, 0}, white)));
    s.root->children.push_back(translated(
        Vec3(0, -5, 0), prim(ir::LathePrim{{{{0, 0}, {0.5, 0}, {2, 3}, {0, 3}}}, 360, 0}, white)));
    s.root->children.push_back(
        translated(Vec3(-5, -6, 0), prim(ir::TorusPrim{1, 1, 360, {}, 0}, white)));
    s.camera = lookAt(Vec3(5, 4, 8), Vec3(-2.5, -3, 0.5), 60);
    return s;
}

TEST(PovRevolved, TorusAndLatheAreWrittenAboutZ) {
    ir::Scene s = revolvedScene();
    std::string t = pov::writeSdl(s, "revolved");
    EXPECT_EQ(count(t, "torus { 1.5, 0.5 sturm rotate x*90 }"), 1) << t;
    EXPECT_EQ(count(t, "torus { 1, 1 sturm rotate x*90"), 1) << t;
    // Two outlines: the hole is a difference; five points close each outline
    EXPECT_EQ(
        count(t, "lathe { linear_spline 5, <1, 0>, <3, 0>, <3, 2>, <1, 2>, <1, 0> rotate x*90 }"),
        1)
        << t;
    EXPECT_EQ(count(t, "difference {"), 1) << t;
    // The quarter: two half-spaces; the three-quarter torus: their merge
    EXPECT_EQ(count(t, "intersection { plane { <0, -1, 0>, 0 } plane { <-1, 0, 0>, 0 } }"), 1) << t;
    EXPECT_EQ(count(t, "merge { plane { <0, -1, 0>, 0 } plane { <1, 0, 0>, 0 } }"), 1) << t;
}

/// Pixels covered (brighter than half) in `a`, and those whose coverage differs in `b`.
std::pair<int, int> coverage(const Image &a, const Image &b) {
    int covered = 0, differ = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            bool p = a.at(x, y).g > 0.5, q = b.at(x, y).g > 0.5;
            covered += p;
            differ += p != q;
        }
    return {covered, differ};
}

TEST(PovRevolved, PovRayDrawsTheSameSilhouettes) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = revolvedScene();
    const int w = 200, h = 150;
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.threads = 2;
    Image ours = renderImage(*rs, o).image;

    auto dir = std::filesystem::temp_directory_path() / "scadray_pov_revolved";
    std::filesystem::create_directories(dir);
    auto povImage = [&](const std::string &sdl, const std::string &name) {
        pov::IniOptions ini;
        ini.povFile = name + ".pov";
        ini.outputFile = name + ".png";
        ini.width = w;
        ini.height = h;
        ini.threads = 2;
        std::ofstream((dir / ini.povFile).string()) << sdl;
        std::ofstream((dir / (name + ".ini")).string()) << pov::writeIni(ini);
        pov::runPovRay(dir.string(), name + ".ini", 2, 120);
        return readImage((dir / ini.outputFile).string(), true);
    };
    std::string sdl = pov::writeSdl(s, "revolved");
    Image theirs = povImage(sdl, "scene");
    ASSERT_EQ(theirs.width(), w);
    ASSERT_EQ(theirs.height(), h);

    // Pixels covered in one picture and not in the other: only along silhouettes, where a
    // pixel centre's ray grazes the surface
    auto [covered, differ] = coverage(ours, theirs);
    std::printf("revolved silhouettes: %d pixels covered, %d differ\n", covered, differ);
    EXPECT_GT(covered, w * h / 10);
    EXPECT_LT(differ, covered / 100 + 5);

    // The comparison can say no: the solids turned the other way about x (the axis to -Z)
    // and the wedges drawn from -X differ in many pixels
    std::string flipped = std::regex_replace(sdl, std::regex("rotate x\\*90"), "rotate x*-90");
    flipped = std::regex_replace(flipped, std::regex("plane \\{ <0, -1, 0>, 0 \\}"),
                                 "plane { <0, 1, 0>, 0 }");
    auto [covered2, differ2] = coverage(ours, povImage(flipped, "flipped"));
    std::printf("negative control (solids upside down, wedges mirrored): %d pixels differ\n",
                differ2);
    EXPECT_GT(differ2, covered / 10);
    (void)covered2;
}

TEST(PovRevolved, PovRayShadesTheSameSurfaces) {
    // Lit by a point light, with shadows: away from silhouettes each pixel is the same in both
    // renderers, which needs the same normals (and the CSG of a block less a torus to agree)
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = revolvedScene(true);
    const int w = 200, h = 150;
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.threads = 2;
    Image ours = renderImage(*rs, o).image;
    auto dir = std::filesystem::temp_directory_path() / "scadray_pov_revolved";
    std::filesystem::create_directories(dir);
    pov::IniOptions ini;
    ini.povFile = "shaded.pov";
    ini.outputFile = "shaded.png";
    ini.width = w;
    ini.height = h;
    ini.threads = 2;
    pov::exportPov(s, (dir / ini.povFile).string(), "revolved", ini);
    pov::runPovRay(dir.string(), "shaded.ini", 2, 120);
    Image theirs = readImage((dir / ini.outputFile).string(), true);
    ASSERT_EQ(theirs.width(), w);

    // Compare pixels whose 3x3 neighbourhood is covered in both pictures
    auto covered = [](const Image &img, int x, int y) { return img.at(x, y).g > 0.05; };
    int compared = 0, off = 0;
    double sum = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            bool inner = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inner = inner && covered(ours, x + dx, y + dy) && covered(theirs, x + dx, y + dy);
            if (!inner) continue;
            ++compared;
            double d = std::abs(ours.at(x, y).g - theirs.at(x, y).g);
            sum += d;
            off += d > 0.02;
        }
    std::printf("revolved shading: %d pixels compared, mean difference %.3g, %d off by > 0.02\n",
                compared, compared ? sum / compared : 0.0, off);
    EXPECT_GT(compared, w * h / 10);
    EXPECT_LT(off, compared / 100 + 5);
}

}  // namespace
}  // namespace rt
