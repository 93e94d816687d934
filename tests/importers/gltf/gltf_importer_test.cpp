// SPDX-License-Identifier: MIT
// glTF importer on the Khronos sample models (tests/data/gltf/khronos): hierarchy, accessors,
// topology, cameras, instancing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/math/float_util.h"
#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

constexpr double kTol = 1e-6;

TEST(GltfImport, BoxColumnMajorMatrixCancelsTheZUpRotation) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("Box.gltf"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[0];
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.normals.size(), 24u);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    EXPECT_EQ(mesh.name, "Mesh");
    ir::validateMesh(mesh);

    // Box's root matrix (column-major) turns its Z-up data Y-up; with the importer's Y-up to
    // Z-up rotation the two cancel. Read row-major, the matrix would be the transpose and the
    // box would come out turned 180 degrees about X.
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 1u);
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(inst[0].world.m[r][c], r == c ? 1.0 : 0.0, kTol) << r << "," << c;

    // Material 'Red': base colour 0.8, 0, 0, metallic 0, roughness 1
    ASSERT_EQ(scene.materials.size(), 1u);
    const ir::Material &red = scene.materials[static_cast<size_t>(inst[0].material)];
    EXPECT_NEAR(red.color.r, 0.8, 1e-6);
    EXPECT_EQ(red.color.g, 0);
    EXPECT_EQ(red.color.b, 0);
    EXPECT_EQ(red.finish.metallic, 0);
    EXPECT_NEAR(red.finish.diffuse, 1.0, kTol);
    EXPECT_FALSE(red.finish.hasReflection());  // roughness 1: no mirror reflection
    EXPECT_EQ(red.filter, 0);
    EXPECT_EQ(red.transmit, 0);
    EXPECT_FALSE(scene.camera.has_value());
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_EQ(diag.count(Severity::Warning), 0);
}

TEST(GltfImport, YUpBecomesZUp) {
    REQUIRE_GLTF_SAMPLE("TriangleWithoutIndices.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("TriangleWithoutIndices.gltf"), diag);
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[static_cast<size_t>(inst[0].mesh)];
    ASSERT_EQ(mesh.positions.size(), 3u);
    // glTF vertex (0, 1, 0) is one unit up: world +Z
    expectNear(mesh.positions[2], Vec3(0, 1, 0), 0);
    expectNear(inst[0].world.transformPoint(mesh.positions[2]), Vec3(0, 0, 1), kTol);
    // glTF +Z (towards the viewer) faces world -Y
    expectNear(inst[0].world.transformVector(Vec3(0, 0, 1)), Vec3(0, -1, 0), kTol);
    EXPECT_NEAR(inst[0].world.det3(), 1.0, kTol);

    // The unit scale multiplies the whole scene
    ImportOptions mm;
    mm.unitScale = 1000;
    ir::Scene scaled = importGltf(sample("TriangleWithoutIndices.gltf"), diag, mm);
    std::vector<Instance> sinst = instances(scaled);
    ASSERT_EQ(sinst.size(), 1u);
    expectNear(sinst[0].world.transformPoint(mesh.positions[2]), Vec3(0, 0, 1000), 1e-9);
}

TEST(GltfImport, TriangleWithoutIndicesUsesVerticesInOrderAndFlatShading) {
    REQUIRE_GLTF_SAMPLE("TriangleWithoutIndices.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("TriangleWithoutIndices.gltf"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[0];
    ASSERT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_TRUE(mesh.normals.empty());  // no NORMAL: the renderer shades flat
    EXPECT_TRUE(mesh.uvs.empty());
    // No material: glTF's default, a white fully rough metal
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].color, Rgb(1));
    EXPECT_EQ(scene.materials[0].finish.metallic, 1);
}

/// Distance from p to an axis-aligned box around `pts`.
double distanceToBox(const Vec3 &p, const std::vector<Vec3> &pts) {
    Bounds3 b;
    for (const Vec3 &q : pts) b = unionBounds(b, q);
    Vec3 d = max(max(b.min - p, p - b.max), Vec3(0));
    return length(d);
}

TEST(GltfImport, OrientationTestArrowsPointAtTheirTargets) {
    REQUIRE_GLTF_SAMPLE("OrientationTest.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("OrientationTest.glb"), diag);
    EXPECT_EQ(instances(scene).size(), 13u);

    // Each arrow's tip (its vertex farthest from the node origin) touches its target's box;
    // X1, Y1, Z1 are quaternion TRS nodes, X2, Y2, Z2 matrix nodes. A transposed matrix misses
    // by 0.25 to 1.7 units, a (w, x, y, z) quaternion by 2 to 6.
    for (const char *axis : {"X1", "X2", "Y1", "Y2", "Z1", "Z2"}) {
        SCOPED_TRACE(axis);
        std::vector<Instance> arrow;
        for (const Instance &i : instances(scene))
            if (i.label == std::string("node 'Arrow") + axis + "'") arrow.push_back(i);
        ASSERT_EQ(arrow.size(), 1u);
        const ir::Mesh &mesh = *scene.meshes[static_cast<size_t>(arrow[0].mesh)];
        auto tip = std::max_element(
            mesh.positions.begin(), mesh.positions.end(),
            [](const Vec3 &a, const Vec3 &b) { return lengthSquared(a) < lengthSquared(b); });
        Vec3 worldTip = arrow[0].world.transformPoint(*tip);
        std::vector<Vec3> target = worldVertices(scene, std::string("node 'Target") + axis + "'");
        ASSERT_FALSE(target.empty());
        EXPECT_LT(distanceToBox(worldTip, target), 0.01);
    }

    // Two tips computed independently (Python from the file's JSON and binary chunk) in glTF
    // coordinates: ArrowX1 (quaternion) and ArrowX2 (matrix)
    auto tipOf = [&](const std::string &label) {
        for (const Instance &i : instances(scene))
            if (i.label == label) {
                const ir::Mesh &mesh = *scene.meshes[static_cast<size_t>(i.mesh)];
                auto it = std::max_element(mesh.positions.begin(), mesh.positions.end(),
                                           [](const Vec3 &a, const Vec3 &b) { return a.y < b.y; });
                return i.world.transformPoint(*it);
            }
        return Vec3(kInfinity);
    };
    expectNear(tipOf("node 'ArrowX1'"), zUp(Vec3(5.277, 2.457, -1.721)), 2e-3);
    expectNear(tipOf("node 'ArrowX2'"), zUp(Vec3(-5.277, 2.989, 0.261)), 2e-3);
}

TEST(GltfImport, CamerasChoosesTheFirstPerspectiveCamera) {
    REQUIRE_GLTF_SAMPLE("Cameras.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("Cameras.gltf"), diag);
    ASSERT_TRUE(scene.camera.has_value());
    const ir::Camera &cam = *scene.camera;
    EXPECT_EQ(cam.projection, ir::Projection::Perspective);
    EXPECT_EQ(cam.source, ir::CameraSource::Explicit);
    EXPECT_EQ(cam.fovAxis, ir::FovAxis::Vertical);
    EXPECT_NEAR(cam.fov, degrees(0.7), 1e-9);
    expectNear(cam.location, zUp(Vec3(0.5, 0.5, 3.0)), kTol);
    // Looks down glTF -Z (world +Y) with glTF +Y (world +Z) up
    expectNear(normalize(cam.lookAt - cam.location), zUp(Vec3(0, 0, -1)), kTol);
    expectNear(cam.sky, Vec3(0, 0, 1), kTol);
    EXPECT_EQ(cam.loc.fileName(), sample("Cameras.gltf"));
    EXPECT_EQ(diag.countContaining("aspectRatio"), 1);
    EXPECT_EQ(diag.countContaining("more camera"), 1);
    // The mesh has no normals and no material
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_TRUE(scene.meshes[0]->normals.empty());
}

TEST(GltfImport, CamerasOrthographicWhenItIsTheOnlyOne) {
    REQUIRE_GLTF_SAMPLE("Cameras.gltf");
    TempDir tmp;
    std::string text = replaceOnce(readText(sample("Cameras.gltf")), "\"nodes\" : [ 0, 1, 2 ]",
                                   "\"nodes\" : [ 0, 2 ]");
    writeText(tmp.file("ortho.gltf"), text);
    DiagnosticSink diag;
    ImportOptions opts;
    opts.unitScale = 10;
    ir::Scene scene = importGltf(tmp.file("ortho.gltf"), diag, opts);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->projection, ir::Projection::Orthographic);
    EXPECT_NEAR(scene.camera->orthoHeight, 2 * 1.0 * 10, 1e-12);  // 2 ymag x unit scale
    expectNear(scene.camera->location, zUp(Vec3(5, 5, 30)), 1e-9);
    expectNear(normalize(scene.camera->lookAt - scene.camera->location), Vec3(0, 1, 0), kTol);
    EXPECT_EQ(diag.countContaining("more camera"), 0);
}

TEST(GltfImport, SimpleSparseAccessorMovesThreeVertices) {
    REQUIRE_GLTF_SAMPLE("SimpleSparseAccessor.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("SimpleSparseAccessor.gltf"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[0];
    ASSERT_EQ(mesh.positions.size(), 14u);
    // Dense data: a 7 x 2 grid at y = 0 and y = 1; sparse indices 8, 10, 12 are replaced
    expectNear(mesh.positions[7], Vec3(0, 1, 0), 0);
    expectNear(mesh.positions[8], Vec3(1, 2, 0), 0);
    expectNear(mesh.positions[9], Vec3(2, 1, 0), 0);
    expectNear(mesh.positions[10], Vec3(3, 3, 0), 0);
    expectNear(mesh.positions[12], Vec3(5, 4, 0), 0);
    expectNear(mesh.positions[13], Vec3(6, 1, 0), 0);
    EXPECT_EQ(mesh.triangles.size(), 12u);
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 1u);
    expectNear(inst[0].world.transformPoint(mesh.positions[12]), Vec3(5, 0, 4), kTol);
}

TEST(GltfImport, MeshPrimitiveModesStripsFansAndSkippedLines) {
    REQUIRE_GLTF_SAMPLE("MeshPrimitiveModes.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("MeshPrimitiveModes.gltf"), diag);
    // Only TRIANGLES (18 indices), TRIANGLE_STRIP (6) and TRIANGLE_FAN (8) have surfaces
    ASSERT_EQ(scene.meshes.size(), 3u);
    std::vector<size_t> counts;
    for (const auto &m : scene.meshes) counts.push_back(m->triangles.size());
    EXPECT_EQ(counts, (std::vector<size_t>{6, 4, 6}));
    EXPECT_EQ(instancedTriangles(scene), 16u);
    EXPECT_EQ(diag.countContaining("meshes[0].primitives[0]: mode 0 (POINTS)"), 1);
    EXPECT_EQ(diag.countContaining("meshes[1].primitives[0]: mode 1 (LINES)"), 1);
    EXPECT_EQ(diag.countContaining("mode 2 (LINE_LOOP)"), 1);
    EXPECT_EQ(diag.countContaining("mode 3 (LINE_STRIP)"), 1);
    EXPECT_EQ(diag.count(Severity::Warning), 4);
    // The strip alternates its vertex order, so every triangle of the flat strip and fan faces
    // the same way as the plain triangles (glTF +Z)
    for (const auto &m : scene.meshes)
        for (const auto &t : m->triangles) {
            Vec3 n = cross(m->positions[t[1]] - m->positions[t[0]],
                           m->positions[t[2]] - m->positions[t[0]]);
            EXPECT_GT(n.z, 0) << m->name;
        }
}

TEST(GltfImport, MultipleScenesHonoursTheDefaultAndTheOption) {
    REQUIRE_GLTF_SAMPLE("MultipleScenes.gltf");
    DiagnosticSink diag;
    ir::Scene byDefault = importGltf(sample("MultipleScenes.gltf"), diag);  // "scene": 1
    EXPECT_EQ(instancedTriangles(byDefault), 2u);
    ImportOptions first;
    first.sceneIndex = 0;
    ir::Scene scene0 = importGltf(sample("MultipleScenes.gltf"), diag, first);
    EXPECT_EQ(instancedTriangles(scene0), 1u);
    ImportOptions bad;
    bad.sceneIndex = 2;
    try {
        importGltf(sample("MultipleScenes.gltf"), diag, bad);
        FAIL() << "scene 2 accepted";
    } catch (const SceneError &e) {
        EXPECT_NE(std::string(e.what()).find("scene 2"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("2 scene(s)"), std::string::npos) << e.what();
        EXPECT_EQ(e.loc().fileName(), sample("MultipleScenes.gltf"));
    }
}

TEST(GltfImport, SimpleMeshesSharesOneMeshBetweenTwoNodes) {
    REQUIRE_GLTF_SAMPLE("SimpleMeshes.gltf");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("SimpleMeshes.gltf"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 2u);
    EXPECT_EQ(inst[0].mesh, 0);
    EXPECT_EQ(inst[1].mesh, 0);
    EXPECT_EQ(inst[0].material, inst[1].material);
    expectNear(inst[1].world.transformPoint(Vec3(0, 0, 0)), zUp(Vec3(1, 0, 0)), kTol);
    EXPECT_EQ(inst[0].label, "nodes[0]");  // unnamed nodes are labelled by their JSON path
}

TEST(GltfImport, BoxInterleavedReadsStridedAttributesAndDefaultMetallic) {
    REQUIRE_GLTF_SAMPLE("BoxInterleaved.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("BoxInterleaved.glb"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[0];
    ASSERT_EQ(mesh.positions.size(), 24u);
    ASSERT_EQ(mesh.normals.size(), 24u);
    ASSERT_EQ(mesh.triangles.size(), 12u);
    for (const Vec3 &p : mesh.positions) {
        EXPECT_NEAR(std::abs(p.x), 0.5, 1e-6);
        EXPECT_NEAR(std::abs(p.y), 0.5, 1e-6);
        EXPECT_NEAR(std::abs(p.z), 0.5, 1e-6);
    }
    // With the 24-byte stride misread, normals would not match their faces
    for (const auto &t : mesh.triangles) {
        Vec3 face = normalize(cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                    mesh.positions[t[2]] - mesh.positions[t[0]]));
        for (uint32_t v : t) EXPECT_NEAR(dot(face, mesh.normals[v]), 1.0, 1e-5);
    }
    // metallicFactor is omitted: the default 1 makes it a red metal
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].finish.metallic, 1);
    EXPECT_NEAR(scene.materials[0].color.r, 0.8, 1e-6);
}

TEST(GltfImport, BoxAnimatedShowsTheStoredPose) {
    REQUIRE_GLTF_SAMPLE("BoxAnimated.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("BoxAnimated.glb"), diag);
    EXPECT_EQ(instancedTriangles(scene), 254u);
    EXPECT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(diag.countContaining("animation(s) ignored"), 1);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
}

// textured_camera.glb (tests/data/gltf/make_textured_camera.py) stands in for Khronos' Duck.glb,
// whose SCEA licence keeps it out of the repository: a PNG inside the GLB's binary chunk, a
// camera on a child of a matrix node, a mesh with normals and texture coordinates
TEST(GltfImport, GlbDecodesItsEmbeddedPngAndCamera) {
    DiagnosticSink diag;
    ir::Scene scene = importGltf(testModel("textured_camera.glb"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &mesh = *scene.meshes[0];
    EXPECT_EQ(mesh.triangles.size(), 960u);
    EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    ir::validateMesh(mesh);
    EXPECT_EQ(diag.count(Severity::Warning), 0);

    ASSERT_EQ(scene.textures.size(), 1u);
    const ir::Texture &tex = *scene.textures[0];
    EXPECT_EQ(tex.width, 128);
    EXPECT_EQ(tex.height, 128);
    EXPECT_EQ(tex.name, "textured_camera_tex0");
    EXPECT_EQ(tex.wrapU, ir::Texture::Wrap::Repeat);
    EXPECT_EQ(tex.wrapV, ir::Texture::Wrap::Repeat);
    ASSERT_EQ(tex.rgba.size(), 128u * 128u * 4u);
    auto [lo, hi] = std::minmax_element(tex.rgba.begin(), tex.rgba.end());
    EXPECT_GE(*lo, 0.0f);
    EXPECT_LE(*hi, 1.0f);
    EXPECT_LT(*lo, *hi);
    // Yellow and orange bands: red and green well above blue on average (after sRGB decoding)
    double r = 0, b = 0;
    for (size_t i = 0; i < tex.rgba.size(); i += 4) r += tex.rgba[i], b += tex.rgba[i + 2];
    EXPECT_GT(r, 2 * b);
    // Row 0 is the top of the PNG: its white patch is at texel (0, 0), orange never is
    EXPECT_GT(tex.rgba[2], 0.8f);
    EXPECT_LT(tex.rgba[(16 * 128 + 64) * 4 + 1], 0.5f);  // row 16: an orange band (g 140)

    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].baseColorTexture.texture, 0);
    ASSERT_TRUE(scene.camera.has_value());
    EXPECT_EQ(scene.camera->projection, ir::Projection::Perspective);
    EXPECT_NEAR(scene.camera->fov, degrees(0.6), 1e-9);
    EXPECT_EQ(scene.camera->fovAxis, ir::FovAxis::Vertical);
    // The camera node (2.4 from the ball's centre, 30 degrees round from +z) under the root's
    // 20-degree turn: 50 degrees round in the world, looking at the ball's centre (0, 0.5, 0)
    double a = 50 * std::numbers::pi / 180;
    Vec3 eye = zUp(Vec3(2.4 * std::sin(a), 0.5, 2.4 * std::cos(a)));
    expectNear(scene.camera->location, eye, 1e-6);
    Vec3 view = scene.camera->lookAt - scene.camera->location;
    expectNear(view / length(view), (zUp(Vec3(0, 0.5, 0)) - eye) / 2.4, 1e-6);
}

TEST(GltfImport, MetalRoughSpheresImportsAMillionInstancedTriangles) {
    // Speed is measured by scripts/bench_mesh.sh, not asserted here
    REQUIRE_GLTF_SAMPLE("MetalRoughSpheresNoTextures.glb");
    DiagnosticSink diag;
    ir::Scene scene = importGltf(sample("MetalRoughSpheresNoTextures.glb"), diag);
    // 1,040,409 triangles in the file, less the zero-area ones (reported in a note)
    size_t n = instancedTriangles(scene);
    EXPECT_GT(n, 1000000u);
    EXPECT_LE(n, 1040409u);
    EXPECT_EQ(diag.countContaining("zero-area") > 0, n < 1040409u);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
}

TEST(GltfImport, ImportIntoAddsMeshesUnderAGroupAtTheCallSite) {
    DiagnosticSink diag;
    ir::Scene scene;
    scene.materials.push_back(ir::Material{});  // a material already in the scene
    SourceLoc call(std::make_shared<const std::string>("main.scad"), 3, 5);
    ir::NodePtr group =
        importGltfInto(scene, testModel("textured_camera.glb"), call, diag, std::nullopt);
    ASSERT_TRUE(group);
    EXPECT_EQ(group->kind, ir::NodeKind::Group);
    EXPECT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.textures.size(), 1u);
    EXPECT_EQ(scene.materials.size(), 2u);
    EXPECT_FALSE(scene.camera.has_value());  // cameras are ignored in import()
    EXPECT_EQ(diag.countContaining("ignored in import()"), 1);
    std::function<void(const ir::Node &)> checkLoc = [&](const ir::Node &n) {
        EXPECT_EQ(n.loc.line, 3);
        EXPECT_EQ(n.loc.fileName(), "main.scad");
        for (const auto &c : n.children) checkLoc(*c);
    };
    checkLoc(*group);
    ASSERT_EQ(group->children.size(), 1u);
    EXPECT_EQ(group->children[0]->kind, ir::NodeKind::Transform);

    // With a material override the file's materials and textures stay out of the scene
    ir::Scene plain;
    plain.materials.push_back(ir::Material{});
    ir::NodePtr g2 = importGltfInto(plain, testModel("textured_camera.glb"), call, diag, 0);
    EXPECT_TRUE(plain.textures.empty());
    EXPECT_EQ(plain.materials.size(), 1u);
    std::vector<Instance> inst;
    collectInstances(*g2, Mat4(), "", inst);
    ASSERT_EQ(inst.size(), 1u);
    EXPECT_EQ(inst[0].material, 0);
}

}  // namespace
}  // namespace rt::gltf::test
