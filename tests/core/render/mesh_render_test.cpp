// SPDX-License-Identifier: MIT
// Meshes and the newer scene features in whole renders: a mesh cube in CSG renders like the
// analytic box, open meshes cannot take part in CSG, textures follow POV-Ray's image_map
// convention, orthographic cameras, spotlights and directional lights match hand computation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/camera.h"
#include "core/materials/texture_sampler.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "support/mesh_builder.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

RenderResult renderScene(const ir::Scene &scene, int w, int h) {
    DiagnosticSink diag;
    auto rs = RenderScene::compile(scene, diag);
    RenderOptions o;
    o.width = w;
    o.height = h;
    return renderImage(*rs, o);
}

ir::NodePtr meshNode(ir::Scene &s, std::shared_ptr<ir::Mesh> mesh, int material) {
    s.meshes.push_back(mesh);
    return ir::Node::makePrimitive(ir::MeshPrim{static_cast<int>(s.meshes.size()) - 1}, material,
                                   {});
}

ir::Scene cutCubeScene(bool meshCube) {
    ir::Scene s = emptyScene();
    int red = s.addMaterial(plainMaterial(Rgb(1, 0.2, 0.1), 0.1, 0.8));
    int blue = s.addMaterial(plainMaterial(Rgb(0.1, 0.3, 1), 0.1, 0.8));
    ir::NodePtr cube =
        meshCube ? meshNode(s, cubeMesh(Vec3(-1), Vec3(1)), red) : box(Vec3(-1), Vec3(1), red);
    s.root->children.push_back(csg(ir::NodeKind::Difference, std::move(cube),
                                   translated(Vec3(0.8, -0.8, 0.8), sphere(1, blue))));
    s.lights.push_back(pointLight(Vec3(4, -6, 8)));
    s.camera = lookAt(Vec3(4, -5, 3.5), Vec3(0), 40);
    return s;
}

TEST(MeshRender, MeshCubeInCsgRendersLikeTheAnalyticBox) {
    RenderResult a = renderScene(cutCubeScene(true), 64, 48);
    RenderResult b = renderScene(cutCubeScene(false), 64, 48);
    int differing = 0;
    for (size_t i = 0; i < a.image.data().size(); ++i)
        differing += std::abs(a.image.data()[i] - b.image.data()[i]) > 1e-4;
    EXPECT_LE(differing, 3) << "only silhouette pixels may round differently";
    // And the cut is really there: the blue sphere's surface shows
    bool blue = false;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) blue |= a.image.at(x, y).b > 2 * a.image.at(x, y).r;
    EXPECT_TRUE(blue);
}

TEST(MeshRender, OpenMeshInCsgIsALocatedError) {
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1), 0.2, 0.5));
    auto open = cubeMesh(Vec3(-1), Vec3(1));
    open->triangles.pop_back();
    open->name = "lid";
    ir::NodePtr node = meshNode(s, open, m);
    node->loc = SourceLoc(std::make_shared<const std::string>("part.scad"), 7, 5);
    s.root->children.push_back(csg(ir::NodeKind::Difference, std::move(node), sphere(0.5, m)));
    s.camera = lookAt(Vec3(4, -5, 3), Vec3(0), 40);
    DiagnosticSink diag;
    try {
        RenderScene::compile(s, diag);
        FAIL() << "expected SceneError";
    } catch (const SceneError &e) {
        EXPECT_EQ(e.loc().line, 7);
        EXPECT_NE(std::string(e.what()).find("mesh 'lid' is open"), std::string::npos) << e.what();
    }
    // On its own an open mesh is fine
    ir::Scene alone = emptyScene();
    int a = alone.addMaterial(plainMaterial(Rgb(1), 0.2, 0.5));
    alone.root->children.push_back(meshNode(alone, open, a));
    alone.camera = lookAt(Vec3(4, -5, 3), Vec3(0), 40);
    EXPECT_NO_THROW(RenderScene::compile(alone, diag));
}

TEST(TextureSampler, FollowsPovRayImageMapConvention) {
    ir::Texture t;
    t.width = 2;
    t.height = 2;
    // Rows top first: red green / blue white
    t.rgba = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
    auto near = [](const Rgb &a, const Rgb &b) {
        return length(Vec3(a.r - b.r, a.g - b.g, a.b - b.b)) < 1e-6;
    };
    // Texel centres (glTF uv, origin top-left)
    EXPECT_TRUE(near(sampleTexture(t, 0.25, 0.25), Rgb(1, 0, 0)));
    EXPECT_TRUE(near(sampleTexture(t, 0.75, 0.25), Rgb(0, 1, 0)));
    EXPECT_TRUE(near(sampleTexture(t, 0.25, 0.75), Rgb(0, 0, 1)));
    EXPECT_TRUE(near(sampleTexture(t, 0.75, 0.75), Rgb(1, 1, 1)));
    // Halfway between the two top texels; the image repeats
    EXPECT_TRUE(near(sampleTexture(t, 0.5, 0.25), Rgb(0.5, 0.5, 0)));
    EXPECT_TRUE(near(sampleTexture(t, 1.25, -0.75), Rgb(1, 0, 0)));
}

TEST(Camera, OrthographicRaysAreParallel) {
    ir::Camera c = lookAt(Vec3(0, -10, 0), Vec3(0), 40);
    c.projection = ir::Projection::Orthographic;
    c.orthoHeight = 4;
    Camera cam(c, 80, 40);
    Ray a = cam.generateRay(0, 0), b = cam.generateRay(80, 40);
    EXPECT_EQ(a.d, Vec3(0, 1, 0));
    EXPECT_EQ(b.d, Vec3(0, 1, 0));
    // The film is 4 tall and 8 wide, right-handed
    EXPECT_NEAR(a.o.x, -4, 1e-12);
    EXPECT_NEAR(a.o.z, 2, 1e-12);
    EXPECT_NEAR(b.o.x, 4, 1e-12);
    EXPECT_NEAR(b.o.z, -2, 1e-12);
}

/// A white diffuse floor lit from above by one light; returns the pixel under the camera.
Rgb floorPixel(const ir::Light &light) {
    ir::Scene s = emptyScene();
    s.root->children.push_back(
        box(Vec3(-50, -50, -1), Vec3(50, 50, 0), s.addMaterial(plainMaterial(Rgb(1), 0, 1))));
    s.lights.push_back(light);
    s.camera = lookAt(Vec3(0, -0.001, 10), Vec3(0), 10, Vec3(0, 1, 0));
    return renderScene(s, 33, 33).image.at(16, 16);
}

TEST(Lights, SpotlightConeFollowsPovRay) {
    // Spot 4 above the floor, aimed at a point 2 to the side: the centre of the floor is at
    // atan(2/4) = 26.57 degrees from the axis, between radius 20 and falloff 35
    ir::Light spot = pointLight(Vec3(0, 0, 4));
    spot.kind = ir::Light::Kind::Spot;
    spot.direction = normalize(Vec3(2, 0, -4));
    spot.spotRadius = 20;
    spot.spotFalloff = 35;
    spot.spotTightness = 3;
    double cosTheta = std::cos(std::atan(0.5));
    double p = (cosTheta - std::cos(radians(35))) / (std::cos(radians(20)) - std::cos(radians(35)));
    double want = std::pow(cosTheta, 3) * (3 - 2 * p) * p * p;  // times cos(N.L) = 1
    EXPECT_NEAR(floorPixel(spot).g, want, 1e-6);
    // Outside the falloff cone: dark
    spot.direction = normalize(Vec3(4, 0, -1));
    EXPECT_NEAR(floorPixel(spot).g, 0, 1e-9);
}

TEST(Lights, DirectionalLightIgnoresDistance) {
    ir::Light sun = pointLight(Vec3(0, 0, 100));
    sun.kind = ir::Light::Kind::Directional;
    sun.direction = normalize(Vec3(0, 1, -1));
    EXPECT_NEAR(floorPixel(sun).g, std::sqrt(0.5), 1e-6);  // diffuse 1 x cos 45
    sun.position = Vec3(0, -30, 1000);
    EXPECT_NEAR(floorPixel(sun).g, std::sqrt(0.5), 1e-6);
}

/// A cube whose every face is cut along its diagonal into 2 (k + 1) needle triangles (aspect
/// ratio about k) meeting in k vertices on the diagonal, plus a zero-area triangle per face:
/// closed, no T-junctions, and as hard for a ray-triangle test as triangles get.
std::shared_ptr<ir::Mesh> sliverCube(int k) {
    auto m = std::make_shared<ir::Mesh>();
    auto cube = cubeMesh(Vec3(-1), Vec3(1));
    m->positions = cube->positions;
    // The six faces as corner quads a, b, c, d of cubeMesh's positions
    const std::array<std::array<uint32_t, 4>, 6> faces = {
        {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
    for (const auto &f : faces) {
        uint32_t a = f[0], b = f[1], c = f[2], d = f[3];
        // Diagonal a-c with k interior vertices
        std::vector<uint32_t> diag = {a};
        for (int i = 1; i <= k; ++i) {
            double t = double(i) / (k + 1);
            m->positions.push_back(m->positions[a] * (1 - t) + m->positions[c] * t);
            diag.push_back(static_cast<uint32_t>(m->positions.size() - 1));
        }
        diag.push_back(c);
        for (size_t i = 0; i + 1 < diag.size(); ++i) {
            m->triangles.push_back({diag[i], b, diag[i + 1]});  // a-b-c side
            m->triangles.push_back({diag[i], diag[i + 1], d});  // a-c-d side
        }
        m->triangles.push_back({diag[0], diag[1], diag[2]});  // zero area, on the diagonal
    }
    m->name = "sliver cube";
    return m;
}

TEST(MeshRender, SliverTrianglesNeverLeakAndRenderLikeTheBox) {
    auto scene = [](bool mesh) {
        ir::Scene s = emptyScene();
        s.settings.background = Rgb(1, 0, 1);  // any leak shows magenta
        int grey = s.addMaterial(plainMaterial(Rgb(0.6), 0.2, 0.7));
        s.root->children.push_back(mesh ? meshNode(s, sliverCube(400), grey)
                                        : box(Vec3(-1), Vec3(1), grey));
        s.lights.push_back(pointLight(Vec3(3, -5, 6)));
        // Looking down a face diagonal, so rays run along the rows of shared vertices
        s.camera = lookAt(Vec3(4, -4, 3), Vec3(0), 35);
        return s;
    };
    RenderResult a = renderScene(scene(true), 96, 72);
    RenderResult b = renderScene(scene(false), 96, 72);
    int differing = 0;
    for (size_t i = 0; i < a.image.data().size(); ++i)
        differing += std::abs(a.image.data()[i] - b.image.data()[i]) > 1e-4;
    EXPECT_LE(differing, 3) << "only silhouette pixels may round differently";
    EXPECT_EQ(a.stats.nonFinite, 0);
}

}  // namespace
}  // namespace rt
