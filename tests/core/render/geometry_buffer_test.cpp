// SPDX-License-Identifier: MIT
// Geometry buffers: depths and normals against hand computation, the analytic box against its
// mesh (agree), and negative controls: a moved face, the other diagonal of a skew quad and a
// missing part must all count as differing pixels.
#include <gtest/gtest.h>

#include "core/render/geometry_buffer.h"
#include "support/mesh_builder.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

GeometryBuffer trace(const ir::Scene &scene, int w = 64, int h = 48) {
    DiagnosticSink diag;
    auto rs = RenderScene::compile(scene, diag);
    return renderGeometry(*rs, w, h, 2);
}

ir::Scene sceneWith(ir::NodePtr node, ir::Scene s = emptyScene()) {
    s.root->children.push_back(std::move(node));
    s.camera = lookAt(Vec3(4, -5, 3.5), Vec3(0), 40);
    return s;
}

ir::Scene boxScene(double top) {
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1)));
    return sceneWith(box(Vec3(-1), Vec3(1, 1, top), m), std::move(s));
}

/// A block with a skew top: the quad (-1,-1,1) (1,-1,1.6) (1,1,1) (-1,1,1.3) split along the
/// diagonal from corner 4 or from corner 5.
ir::Scene skewBlockScene(bool otherDiagonal) {
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1)));
    auto mesh = std::make_shared<ir::Mesh>();
    mesh->positions = {{-1, -1, -1}, {1, -1, -1},  {1, 1, -1}, {-1, 1, -1},
                       {-1, -1, 1},  {1, -1, 1.6}, {1, 1, 1},  {-1, 1, 1.3}};
    mesh->triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 5}, {0, 5, 4}, {1, 2, 6},
                       {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    if (otherDiagonal)
        mesh->triangles.insert(mesh->triangles.end(), {{4, 5, 7}, {5, 6, 7}});
    else
        mesh->triangles.insert(mesh->triangles.end(), {{4, 5, 6}, {4, 6, 7}});
    s.meshes.push_back(mesh);
    return sceneWith(ir::Node::makePrimitive(ir::MeshPrim{0}, m, {}), std::move(s));
}

TEST(GeometryBuffer, DepthAndNormalMatchHandComputation) {
    // Looking down -Z at a box whose top is at z = 1, from z = 5
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1)));
    s.root->children.push_back(box(Vec3(-1), Vec3(1), m));
    s.camera = lookAt(Vec3(0, 0, 5), Vec3(0), 40, Vec3(0, 1, 0));
    GeometryBuffer g = trace(s, 33, 33);
    const GeometrySample &centre = g.at(16, 16);
    ASSERT_TRUE(centre.hit());
    EXPECT_NEAR(centre.depth, 4, 1e-12);
    EXPECT_NEAR(centre.normal.z, 1, 1e-12);
    EXPECT_FALSE(centre.tie);
    EXPECT_FALSE(g.at(0, 0).hit());
}

TEST(GeometryBuffer, NormalsFaceTheCamera) {
    // From inside the box every hit is a back face of the solid; normals still face the ray
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1)));
    s.root->children.push_back(box(Vec3(-1), Vec3(1), m));
    s.camera = lookAt(Vec3(0, 0, 0.5), Vec3(0, 0, -1), 40, Vec3(0, 1, 0));
    GeometryBuffer g = trace(s, 9, 9);
    ASSERT_TRUE(g.at(4, 4).hit());
    EXPECT_NEAR(g.at(4, 4).depth, 1.5, 1e-12);
    EXPECT_NEAR(g.at(4, 4).normal.z, 1, 1e-12);
}

TEST(GeometryBuffer, AnalyticBoxAgreesWithItsMesh) {
    ir::Scene mesh = emptyScene();
    int m = mesh.addMaterial(plainMaterial(Rgb(1)));
    mesh.meshes.push_back(cubeMesh(Vec3(-1), Vec3(1)));
    mesh = sceneWith(ir::Node::makePrimitive(ir::MeshPrim{0}, m, {}), std::move(mesh));
    GeometryCompareResult r = compareGeometry(trace(boxScene(1)), trace(mesh));
    EXPECT_TRUE(r.pass) << r.summary({});
    EXPECT_EQ(r.differing(), 0);
    EXPECT_GT(r.agreeing, 500);
    EXPECT_GT(r.silhouette, 0);
    EXPECT_LT(r.maxDepthRel, 1e-12);
}

TEST(GeometryBuffer, MovedFaceIsCaught) {
    // The top 1 % higher: depth differences over the whole top face
    GeometryCompareResult r = compareGeometry(trace(boxScene(1.01)), trace(boxScene(1)));
    EXPECT_FALSE(r.pass);
    EXPECT_GT(r.depthDiffer, 50) << r.summary({});
}

TEST(GeometryBuffer, OtherDiagonalOfASkewQuadIsCaught) {
    GeometryCompareResult same =
        compareGeometry(trace(skewBlockScene(false)), trace(skewBlockScene(false)));
    EXPECT_TRUE(same.pass);
    EXPECT_EQ(same.agreeing + same.silhouette + same.bothMiss, 64 * 48);
    GeometryCompareResult r =
        compareGeometry(trace(skewBlockScene(true)), trace(skewBlockScene(false)));
    EXPECT_FALSE(r.pass);
    EXPECT_GT(r.depthDiffer + r.normalDiffer, 50) << r.summary({});
}

TEST(GeometryBuffer, MissingPartIsCaughtAndToleranceAllowsIt) {
    ir::Scene two = boxScene(1);
    int m = two.addMaterial(plainMaterial(Rgb(1)));
    two.root->children.push_back(box(Vec3(-0.5, -0.5, 1), Vec3(0.5, 0.5, 1.5), m));
    GeometryCompareResult r = compareGeometry(trace(boxScene(1)), trace(two));
    EXPECT_FALSE(r.pass);
    GeometryTolerances lenient;
    lenient.maxDiffering = r.differing();
    EXPECT_TRUE(compareGeometry(trace(boxScene(1)), trace(two), lenient).pass);
}

TEST(GeometryBuffer, SizesMustMatch) {
    EXPECT_THROW(compareGeometry(trace(boxScene(1), 8, 8), trace(boxScene(1), 8, 9)),
                 std::invalid_argument);
}

TEST(GeometryBuffer, NormalImageShowsNormalsAndBackground) {
    ir::Scene s = emptyScene();
    int m = s.addMaterial(plainMaterial(Rgb(1)));
    s.root->children.push_back(box(Vec3(-1), Vec3(1), m));
    s.camera = lookAt(Vec3(0, 0, 5), Vec3(0), 40, Vec3(0, 1, 0));
    Image img = normalImage(trace(s, 9, 9));
    EXPECT_NEAR(img.at(4, 4).b, 1, 1e-6);
    EXPECT_NEAR(img.at(4, 4).r, 0.5, 1e-6);
    EXPECT_EQ(img.at(0, 0).r, 0);
}

}  // namespace
}  // namespace rt
