// SPDX-License-Identifier: MIT
// Prisms in POV-Ray SDL: the objects written for straight, scaled (conic) and pointed prisms,
// and (with povray installed) POV-Ray's picture of them against scadray's, silhouettes pixel
// for pixel and shading away from them, so the axis, handedness and scale mapping are checked
// by rendering.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "exporters/povray/pov_writer.h"
#include "importers/scad/geometry2d/extrude.h"
#include "support/pov_pictures.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

/// A prism node; a non-convex outline gets its mesh (as the importer builds it) in `s`.
ir::NodePtr prism(ir::Scene &s, std::vector<ir::Point2> outline, double z0, double z1, double k0,
                  double k1, bool convex, int material) {
    ir::PrismPrim p{std::move(outline), z0, z1, k0, k1, -1};
    if (!convex) {
        auto mesh = std::make_shared<ir::Mesh>();
        EXPECT_TRUE(scad::prismMesh(p, *mesh));
        s.meshes.push_back(mesh);
        p.mesh = static_cast<int>(s.meshes.size()) - 1;
    }
    return ir::Node::makePrimitive(std::move(p), material, {});
}

const std::vector<ir::Point2> kEll{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
const std::vector<ir::Point2> kArrow{{-1, -1}, {1.5, 0}, {-1, 1}, {-0.3, 0}};
const std::vector<ir::Point2> kTriangle{{-1, -1}, {1.5, -0.5}, {0, 1.5}};

/// White solids on black: an L (straight), an arrow narrowing upwards (conic, non-convex),
/// a triangle to an apex on top, an arrow from an apex below, and a triangle at a constant
/// scale of 0.75. Flat (ambient only), or shaded by a point light with a block less an L.
ir::Scene prismScene(bool shaded = false) {
    ir::Scene s = emptyScene();
    int white = s.addMaterial(plainMaterial(Rgb(1), shaded ? 0.2 : 1, shaded ? 0.8 : 0));
    if (shaded) {
        s.lights.push_back(pointLight(Vec3(6, 2, 12)));
        s.root->children.push_back(translated(
            Vec3(2, -6, 0),
            csg(ir::NodeKind::Difference, box(Vec3(-1.5, -1.5, -0.5), Vec3(1.5, 1.5, 0.1), white),
                prism(s, kEll, -1, 1, 0.4, 0.4, false, white))));
    }
    s.root->children.push_back(prism(s, kEll, 0, 2, 1, 1, false, white));
    s.root->children.push_back(
        translated(Vec3(-5, 0, 0), prism(s, kArrow, -0.5, 2, 1.5, 0.5, false, white)));
    s.root->children.push_back(
        translated(Vec3(0, -5, 0), prism(s, kTriangle, 0, 3, 1, 0, true, white)));
    s.root->children.push_back(
        translated(Vec3(-5, -6, 0), prism(s, kArrow, 0, 2, 0, 1.2, false, white)));
    s.root->children.push_back(
        translated(Vec3(-2, 3, 0), prism(s, kTriangle, 0, 1, 0.75, 0.75, true, white)));
    s.camera = lookAt(Vec3(5, 4, 8), Vec3(-2.5, -3, 0.5), 60);
    return s;
}

TEST(PovPrism, PrismsAreWrittenAlongZ) {
    ir::Scene s = prismScene();
    std::string t = pov::writeSdl(s, "prisms");
    // Straight: heights are z; the first point closes the outline; y and z swapped
    EXPECT_EQ(count(t,
                    "prism { linear_sweep linear_spline 0, 2, 7, <0, 0>, <3, 0>, <3, 1>, "
                    "<1, 1>, <1, 3>, <0, 3>, <0, 0> matrix <1, 0, 0,  0, 0, 1,  0, 1, 0,  "
                    "0, 0, 0>"),
              1)
        << t;
    // Constant scale 0.75: the points scaled
    EXPECT_EQ(count(t,
                    "prism { linear_sweep linear_spline 0, 1, 4, <-0.75, -0.75>, <1.125, "
                    "-0.375>, <0, 1.125>, <-0.75, -0.75> matrix <1, 0, 0,  0, 0, 1,  0, 1, 0,"
                    "  0, 0, 0>"),
              1)
        << t;
    // Scale 1.5 at z -0.5 to 0.5 at z 2: heights 0.5 .. 1.5, z = -0.5 + (k - 1.5) * -2.5
    EXPECT_EQ(count(t,
                    "prism { conic_sweep linear_spline 0.5, 1.5, 5, <-1, -1>, <1.5, 0>, "
                    "<-1, 1>, <-0.3, 0>, <-1, -1> matrix <1, 0, 0,  0, 0, -2.5,  0, 1, 0,  0, "
                    "0, 3.25>"),
              1)
        << t;
    // To an apex at z 3: heights 0 .. 1, z = 3 - 3 k; from an apex at z 0: z = k / 1.2 * 2
    EXPECT_EQ(count(t,
                    "prism { conic_sweep linear_spline 0, 1, 4, <-1, -1>, <1.5, -0.5>, "
                    "<0, 1.5>, <-1, -1> matrix <1, 0, 0,  0, 0, -3,  0, 1, 0,  0, 0, 3>"),
              1)
        << t;
    EXPECT_EQ(count(t, "prism { conic_sweep linear_spline 0, 1.2, 5,"), 1) << t;
    EXPECT_EQ(count(t, "sturm"), 0) << t;
    // Prism meshes are for rendering only: POV-Ray gets the outline
    EXPECT_EQ(count(t, "mesh2"), 0) << t;
}

const int kWidth = 200, kHeight = 150;

TEST(PovPrism, PovRayDrawsTheSameSilhouettes) {
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = prismScene();
    Image ours = scadrayPicture(s, kWidth, kHeight);
    std::string sdl = pov::writeSdl(s, "prisms");
    Image theirs = povrayPicture(sdl, "scadray_pov_prism", "scene", kWidth, kHeight);
    ASSERT_EQ(theirs.width(), kWidth);
    ASSERT_EQ(theirs.height(), kHeight);

    // Pixels covered in one picture and not in the other: only along silhouettes
    int covered = expectSameSilhouettes(ours, theirs, "prism");

    // The comparison can say no: each outline mirrored in its own x
    std::string mirrored =
        std::regex_replace(sdl, std::regex("matrix <1, 0, 0,"), "matrix <-1, 0, 0,");
    int differ2 =
        coverage(ours, povrayPicture(mirrored, "scadray_pov_prism", "mirrored", kWidth, kHeight))
            .second;
    std::printf("negative control (outlines mirrored): %d pixels differ\n", differ2);
    EXPECT_GT(differ2, covered / 10);
}

TEST(PovPrism, PovRayShadesTheSameSurfaces) {
    // Lit by a point light, with shadows: away from silhouettes each pixel is the same in both
    // renderers, which needs the same normals (the swap of y and z is a reflection)
    if (!pov::povrayAvailable()) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    ir::Scene s = prismScene(true);
    Image ours = scadrayPicture(s, kWidth, kHeight);
    Image theirs =
        povrayPicture(pov::writeSdl(s, "prisms"), "scadray_pov_prism", "shaded", kWidth, kHeight);
    ASSERT_EQ(theirs.width(), kWidth);
    expectSameShading(ours, theirs, "prism");
}

}  // namespace
}  // namespace rt
