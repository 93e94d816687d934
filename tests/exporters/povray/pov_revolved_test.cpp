// SPDX-License-Identifier: MIT
// Tori and lathes in POV-Ray SDL: the objects written, and (with povray installed) POV-Ray's
// picture of whole and partial turns against scadray's, pixel for pixel of the silhouette, so
// the orientation of the axis and of the wedge is checked by rendering.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "exporters/povray/pov_writer.h"
#include "support/pov_pictures.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

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
        s.root->children.push_back(translated(
            Vec3(2, -6, 0),
            csg(ir::NodeKind::Difference, box(Vec3(-1.5, -1.5, -0.5), Vec3(1.5, 1.5, 0.1), white),
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

TEST(PovRevolved, PovRayDrawsTheSameSilhouettes) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = revolvedScene();
    const int w = 200, h = 150;
    Image ours = scadrayPicture(s, w, h);
    std::string sdl = pov::writeSdl(s, "revolved");
    Image theirs = povrayPicture(sdl, "scadray_pov_revolved", "scene", w, h);
    ASSERT_EQ(theirs.width(), w);
    ASSERT_EQ(theirs.height(), h);

    // Pixels covered in one picture and not in the other: only along silhouettes, where a
    // pixel centre's ray grazes the surface
    int covered = expectSameSilhouettes(ours, theirs, "revolved");

    // The comparison can say no: the solids turned the other way about x (the axis to -Z)
    // and the wedges drawn from -X differ in many pixels
    std::string flipped = std::regex_replace(sdl, std::regex("rotate x\\*90"), "rotate x*-90");
    flipped = std::regex_replace(flipped, std::regex("plane \\{ <0, -1, 0>, 0 \\}"),
                                 "plane { <0, 1, 0>, 0 }");
    int differ2 =
        coverage(ours, povrayPicture(flipped, "scadray_pov_revolved", "flipped", w, h)).second;
    std::printf("negative control (solids upside down, wedges mirrored): %d pixels differ\n",
                differ2);
    EXPECT_GT(differ2, covered / 10);
}

TEST(PovRevolved, PovRayShadesTheSameSurfaces) {
    // Lit by a point light, with shadows: away from silhouettes each pixel is the same in both
    // renderers, which needs the same normals (and the CSG of a block less a torus to agree)
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = revolvedScene(true);
    const int w = 200, h = 150;
    Image ours = scadrayPicture(s, w, h);
    Image theirs =
        povrayPicture(pov::writeSdl(s, "revolved"), "scadray_pov_revolved", "shaded", w, h);
    ASSERT_EQ(theirs.width(), w);
    expectSameShading(ours, theirs, "revolved");
}

}  // namespace
}  // namespace rt
