// SPDX-License-Identifier: MIT
// glTF geometry as a viewer shows it: vertex colours, second UV set, tangents, quantized
// attributes, Draco and meshopt compression, skins, morph targets and GPU instancing.
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

#include "core/ir/diagnostics.h"
#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

/// A glTF under construction: buffer 0 holds the data, one view per accessor.
struct GltfBuilder {
    TestBuffer buf;
    std::vector<std::string> views, accessors;

    /// Adds `values` as an accessor of `count` elements of `type`; returns its index.
    template <typename T>
    int accessor(const std::vector<T> &values, int componentType, const std::string &type,
                 size_t count, bool normalized = false) {
        size_t offset = buf.add(values);
        views.push_back(viewJson(offset, values.size() * sizeof(T)));
        accessors.push_back("{\"bufferView\":" + std::to_string(views.size() - 1) +
                            ",\"componentType\":" + std::to_string(componentType) +
                            ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type + "\"" +
                            (normalized ? ",\"normalized\":true" : "") + "}");
        return static_cast<int>(accessors.size() - 1);
    }
    int floats(const std::vector<float> &v, const std::string &type, int per) {
        return accessor(v, 5126, type, v.size() / static_cast<size_t>(per));
    }
    static std::string join(const std::vector<std::string> &items) {
        std::string out;
        for (const std::string &s : items) out += (out.empty() ? "" : ",") + s;
        return out;
    }
    /// The whole file; `members` are the top-level members besides the data
    /// ("\"nodes\":[...],\"meshes\":[...]").
    std::string json(const std::string &members, const std::string &sceneNodes = "[0]") const {
        return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":)" + sceneNodes + "}]," +
               members + ",\"buffers\":[" + buf.json() + "],\"bufferViews\":[" + join(views) +
               "],\"accessors\":[" + join(accessors) + "]}";
    }
};

/// Imports `text` written to a temporary file.
ir::Scene importText(const std::string &text, DiagnosticSink &diag, const char *name = "m.gltf") {
    TempDir tmp;
    writeText(tmp.file(name), text);
    return importGltf(tmp.file(name), diag);
}

/// The one mesh of the scene `text` describes (null, with a test failure, when there is not
/// exactly one).
ir::MeshPtr onlyMesh(const std::string &text) {
    DiagnosticSink diag;
    ir::Scene scene = importText(text, diag);
    EXPECT_EQ(scene.meshes.size(), 1u);
    return scene.meshes.size() == 1 ? scene.meshes[0] : nullptr;
}

/// Expects importing `text` to fail with a message containing every one of `parts`.
void expectFailure(const std::string &text, std::initializer_list<std::string> parts) {
    DiagnosticSink diag;
    try {
        importText(text, diag);
        ADD_FAILURE() << "imported without the expected error";
    } catch (const LocatedError &e) {
        std::string what = e.what();
        for (const std::string &p : parts)
            EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
    }
}

/// World-space positions of every placed mesh, in placement order.
std::vector<Vec3> allWorldVertices(const ir::Scene &scene) {
    std::vector<Vec3> out;
    for (const Instance &i : instances(scene))
        for (const Vec3 &p : scene.meshes[static_cast<size_t>(i.mesh)]->positions)
            out.push_back(i.world.transformPoint(p));
    return out;
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// Vertex attributes

TEST(GltfGeometry, VertexColoursInThreeComponentTypes) {
    GltfBuilder b;
    int pos = b.floats(kTriangle, "VEC3", 3);
    int rgbFloat = b.floats({1, 0.5f, 0.25f, 0, 1, 0, 0, 0, 1}, "VEC3", 3);
    int rgbaByte = b.accessor(std::vector<uint8_t>{255, 0, 0, 255, 0, 51, 0, 102, 0, 0, 255, 0},
                              5121, "VEC4", 3, true);
    int rgbaShort =
        b.accessor(std::vector<uint16_t>{65535, 0, 0, 65535, 0, 65535, 0, 0, 0, 0, 13107, 32768},
                   5123, "VEC4", 3, true);
    std::string prims;
    for (int c : {rgbFloat, rgbaByte, rgbaShort})
        prims += std::string(prims.empty() ? "" : ",") +
                 "{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
                 ",\"COLOR_0\":" + std::to_string(c) + "}}";
    DiagnosticSink diag;
    ir::Scene scene = importText(
        b.json("\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[" + prims + "]}]"), diag);
    ASSERT_EQ(scene.meshes.size(), 3u);
    const auto &f = scene.meshes[0]->colors;
    ASSERT_EQ(f.size(), 3u);
    EXPECT_FLOAT_EQ(f[0][1], 0.5f);
    EXPECT_FLOAT_EQ(f[0][3], 1.0f);  // vec3: alpha 1
    const auto &u8 = scene.meshes[1]->colors;
    EXPECT_FLOAT_EQ(u8[1][1], 0.2f);
    EXPECT_FLOAT_EQ(u8[1][3], 0.4f);
    const auto &u16 = scene.meshes[2]->colors;
    EXPECT_FLOAT_EQ(u16[1][1], 1.0f);
    EXPECT_FLOAT_EQ(u16[2][2], 0.2f);
    EXPECT_NEAR(u16[2][3], 0.5f, 1e-4);
    EXPECT_EQ(diag.countContaining("COLOR_0"), 0);

    // Signed bytes are not a colour type
    GltfBuilder bad;
    bad.floats(kTriangle, "VEC3", 3);
    bad.accessor(std::vector<int8_t>(12, 1), 5120, "VEC4", 3, true);
    expectFailure(
        bad.json(R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":)"
                 R"({"POSITION":0,"COLOR_0":1}}]}])"),
        {"meshes[0].primitives[0].attributes.COLOR_0", "accessors[1]", "not allowed for COLOR_0"});
}

TEST(GltfGeometry, SecondTexCoordSetAndTangents) {
    GltfBuilder b;
    b.floats(kTriangle, "VEC3", 3);
    b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);  // normals
    b.floats({0.5f, 0.5f, 1, 0.5f, 0.5f, 1}, "VEC2", 2);
    b.accessor(
        std::vector<int16_t>{32767, 0, 0, -32767, 0, 32767, 0, 32767, 32767, 32767, 0, 32767}, 5122,
        "VEC4", 3, true);
    DiagnosticSink diag;
    ir::Scene scene =
        importText(b.json(R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":)"
                          R"({"POSITION":0,"NORMAL":1,"TEXCOORD_1":2,"TANGENT":3}}]}],)"
                          R"("extensionsUsed":["KHR_mesh_quantization"],)"
                          R"("extensionsRequired":["KHR_mesh_quantization"])"),
                   diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    ASSERT_EQ(m.uvs1.size(), 3u);
    EXPECT_TRUE(m.uvs.empty());
    EXPECT_FLOAT_EQ(m.uvs1[1][0], 1.0f);
    ASSERT_EQ(m.tangents.size(), 3u);
    EXPECT_FLOAT_EQ(m.tangents[0][0], 1.0f);
    EXPECT_FLOAT_EQ(m.tangents[0][3], -1.0f);
    EXPECT_NEAR(m.tangents[2][0], std::sqrt(0.5), 1e-6);  // normalised
    EXPECT_FLOAT_EQ(m.tangents[2][3], 1.0f);
}

TEST(GltfGeometry, QuantizedPositionsAndNormals) {
    GltfBuilder b;
    b.accessor(std::vector<uint16_t>{0, 0, 0, 4, 0, 0, 0, 2, 0}, 5123, "VEC3", 3);  // plain
    b.accessor(std::vector<int8_t>{0, 0, 127, 0, 0, 127, 0, 0, 127, 0, 0, 0}, 5120, "VEC3", 3,
               true);
    DiagnosticSink diag;
    std::string meshes =
        R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}],)"
        R"("extensionsUsed":["KHR_mesh_quantization"],"extensionsRequired":["KHR_mesh_quantization"])";
    ir::Scene scene = importText(b.json(meshes), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    expectNear(m.positions[1], Vec3(4, 0, 0), 0);
    expectNear(m.positions[2], Vec3(0, 2, 0), 0);
    expectNear(m.normals[0], Vec3(0, 0, 1), 1e-7);

    // Unnormalized bytes are not a normal type; unsigned int is no position type
    std::string text = b.json(meshes);
    expectFailure(
        replaceOnce(text, R"("componentType":5120,"count":3,"type":"VEC3","normalized":true)",
                    R"("componentType":5120,"count":3,"type":"VEC3")"),
        {"attributes.NORMAL", "not allowed for NORMAL"});
    expectFailure(replaceOnce(text, R"("componentType":5123,"count":3,"type":"VEC3"})",
                              R"("componentType":5125,"count":3,"type":"VEC3"})"),
                  {"attributes.POSITION", "not allowed for POSITION"});
}

// Compression

TEST(GltfGeometry, DracoRoundTrip) {
    // A two-triangle quad, encoded with Draco's encoder
    const float quad[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    int att = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    for (int f = 0; f < 2; ++f)
        builder.SetAttributeValuesForFace(att, draco::FaceIndex(f), quad[faces[f][0]],
                                          quad[faces[f][1]], quad[faces[f][2]]);
    std::unique_ptr<draco::Mesh> source = builder.Finalize();
    ASSERT_TRUE(source);
    draco::Encoder encoder;
    draco::EncoderBuffer encoded;
    ASSERT_TRUE(encoder.EncodeMeshToBuffer(*source, &encoded).ok());
    std::vector<unsigned char> bytes(encoded.data(), encoded.data() + encoded.size());
    uint32_t id = source->attribute(att)->unique_id();
    draco::DecoderBuffer check;
    check.Init(encoded.data(), encoded.size());
    size_t points = draco::Decoder().DecodeMeshFromBuffer(&check).value()->num_points();

    auto file = [&](const std::vector<unsigned char> &data) {
        GltfBuilder b;
        size_t offset = b.buf.add(data);
        b.views.push_back(viewJson(offset, data.size()));
        b.accessors.push_back(R"({"componentType":5126,"count":)" + std::to_string(points) +
                              R"(,"type":"VEC3"})");
        b.accessors.push_back(R"({"componentType":5125,"count":6,"type":"SCALAR"})");
        return b.json(
            R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},)"
            R"("indices":1,"extensions":{"KHR_draco_mesh_compression":{"bufferView":0,)"
            R"("attributes":{"POSITION":)" +
            std::to_string(id) +
            R"(}}}}]}],"extensionsUsed":["KHR_draco_mesh_compression"],)"
            R"("extensionsRequired":["KHR_draco_mesh_compression"])");
    };
    DiagnosticSink diag;
    ir::Scene scene = importText(file(bytes), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    ASSERT_EQ(m.triangles.size(), 2u);
    // The same triangles, whatever order Draco put the vertices in
    auto key = [](const Vec3 &p) { return std::array<double, 3>{p.x, p.y, p.z}; };
    std::vector<std::array<std::array<double, 3>, 3>> got, want;
    for (const auto &t : m.triangles) {
        std::array<std::array<double, 3>, 3> tri = {key(m.positions[t[0]]), key(m.positions[t[1]]),
                                                    key(m.positions[t[2]])};
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        got.push_back(tri);
    }
    for (const auto &f : faces) {
        std::array<std::array<double, 3>, 3> tri;
        for (int k = 0; k < 3; ++k)
            tri[static_cast<size_t>(k)] = {quad[f[k]][0], quad[f[k]][1], quad[f[k]][2]};
        std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
        want.push_back(tri);
    }
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(got, want);

    // Corrupt data: a located error naming the extension
    std::vector<unsigned char> corrupt(bytes.begin(), bytes.begin() + 8);
    expectFailure(file(corrupt), {"meshes[0].primitives[0].extensions.KHR_draco_mesh_compression",
                                  "does not decode"});

    // Every byte flipped, every length cut: an error or a mesh, never a crash
    for (size_t i = 0; i < bytes.size(); ++i)
        for (int cut = 0; cut < 2; ++cut) {
            std::vector<unsigned char> mutated(bytes);
            if (cut)
                mutated.resize(i);
            else
                mutated[i] ^= 0xa5;
            DiagnosticSink quiet;
            try {
                importText(file(mutated), quiet);
            } catch (const LocatedError &) {
            }
        }
}

TEST(GltfGeometry, RealDracoAsset) {
    // tests/data/gltf/assets/pmndrs.glb (CC0, glTF-Transform): Draco required, a texture
    std::string path = std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/assets/pmndrs.glb";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not found";
    DiagnosticSink diag;
    ir::Scene scene = importGltf(path, diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    EXPECT_EQ(m.triangles.size(), 1551u);
    EXPECT_EQ(m.uvs.size(), m.positions.size());
    EXPECT_EQ(m.normals.size(), m.positions.size());
    EXPECT_EQ(diag.countContaining("KHR_draco_mesh_compression"), 0);
}

TEST(GltfGeometry, MeshoptRoundTripWithFallbackBuffer) {
    std::vector<float> positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    std::vector<unsigned> indices = {0, 1, 2, 0, 2, 3};
    std::vector<unsigned char> vb(meshopt_encodeVertexBufferBound(4, 12));
    vb.resize(meshopt_encodeVertexBuffer(vb.data(), vb.size(), positions.data(), 4, 12));
    std::vector<unsigned char> ib(meshopt_encodeIndexBufferBound(6, 4));
    ib.resize(meshopt_encodeIndexBuffer(ib.data(), ib.size(), indices.data(), 6));

    auto file = [&](const std::vector<unsigned char> &vertexData) {
        TestBuffer buf;
        size_t vOff = buf.add(vertexData), iOff = buf.add(ib);
        auto ext = [](size_t off, size_t len, size_t stride, size_t count, const char *mode) {
            return R"("extensions":{"EXT_meshopt_compression":{"buffer":0,"byteOffset":)" +
                   std::to_string(off) + ",\"byteLength\":" + std::to_string(len) +
                   ",\"byteStride\":" + std::to_string(stride) +
                   ",\"count\":" + std::to_string(count) + ",\"mode\":\"" + mode + "\"}}";
        };
        return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
               R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},)"
               R"("indices":1}]}],"buffers":[)" +
               buf.json() +
               R"(,{"byteLength":72,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],)"
               R"("bufferViews":[{"buffer":1,"byteOffset":0,"byteLength":48,"byteStride":12,)" +
               ext(vOff, vertexData.size(), 12, 4, "ATTRIBUTES") +
               R"(},{"buffer":1,"byteOffset":48,"byteLength":24,)" +
               ext(iOff, ib.size(), 4, 6, "TRIANGLES") +
               R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},)"
               R"({"bufferView":1,"componentType":5125,"count":6,"type":"SCALAR"}],)"
               R"("extensionsUsed":["EXT_meshopt_compression"],)"
               R"("extensionsRequired":["EXT_meshopt_compression"]})";
    };
    DiagnosticSink diag;
    ir::Scene scene = importText(file(vb), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    ASSERT_EQ(m.positions.size(), 4u);
    for (size_t i = 0; i < 4; ++i)
        expectNear(m.positions[i],
                   Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]), 0);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));

    std::vector<unsigned char> corrupt(vb.size(), 0xff);
    expectFailure(file(corrupt),
                  {"bufferViews[0].extensions.EXT_meshopt_compression", "does not decode"});
}

TEST(GltfGeometry, MeshoptOctahedralNormals) {
    // Normals as octahedral-filtered normalized bytes (stride 4), as gltfpack writes them
    std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<float> normals = {0, 0, 1, 0, 0.6f, 0, 0.8f, 0, 1, 0, 0, 0};
    std::vector<int8_t> filtered(12);
    meshopt_encodeFilterOct(filtered.data(), 3, 4, 8, normals.data());
    std::vector<unsigned char> nb(meshopt_encodeVertexBufferBound(3, 4));
    nb.resize(meshopt_encodeVertexBuffer(nb.data(), nb.size(), filtered.data(), 3, 4));
    TestBuffer buf;
    size_t pOff = buf.add(positions), nOff = buf.add(nb);
    std::string text =
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}],"buffers":[)" +
        buf.json() +
        R"(,{"byteLength":12,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],)"
        R"("bufferViews":[)" +
        viewJson(pOff, 36) +
        R"(,{"buffer":1,"byteLength":12,"byteStride":4,"extensions":{"EXT_meshopt_compression":)"
        R"({"buffer":0,"byteOffset":)" +
        std::to_string(nOff) + R"(,"byteLength":)" + std::to_string(nb.size()) +
        R"(,"byteStride":4,"count":3,"mode":"ATTRIBUTES","filter":"OCTAHEDRAL"}}}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5120,"normalized":true,"count":3,"type":"VEC3"}],)"
        R"("extensionsUsed":["EXT_meshopt_compression","KHR_mesh_quantization"],)"
        R"("extensionsRequired":["EXT_meshopt_compression","KHR_mesh_quantization"]})";
    ir::MeshPtr m = onlyMesh(text);
    ASSERT_TRUE(m);
    ASSERT_EQ(m->normals.size(), 3u);
    expectNear(m->normals[0], Vec3(0, 0, 1), 0.02);
    expectNear(m->normals[1], Vec3(0.6, 0, 0.8), 0.02);
    expectNear(m->normals[2], Vec3(1, 0, 0), 0.02);
}

TEST(GltfGeometry, MeshoptFallbackBufferInBinaryGltf) {
    // buffers[0] is the BIN chunk with the compressed data; buffers[1] the uri-less fallback
    std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::vector<unsigned char> vb(meshopt_encodeVertexBufferBound(3, 12));
    vb.resize(meshopt_encodeVertexBuffer(vb.data(), vb.size(), positions.data(), 3, 12));
    size_t encodedSize = vb.size();
    while (vb.size() % 4 != 0) vb.push_back(0);  // the BIN chunk is padded, the data is not
    std::string json =
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("buffers":[{"byteLength":)" +
        std::to_string(vb.size()) +
        R"(},{"byteLength":36,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],)"
        R"("bufferViews":[{"buffer":1,"byteLength":36,"byteStride":12,"extensions":)"
        R"({"EXT_meshopt_compression":{"buffer":0,"byteLength":)" +
        std::to_string(encodedSize) +
        R"(,"byteStride":12,"count":3,"mode":"ATTRIBUTES"}}}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
        R"("extensionsUsed":["EXT_meshopt_compression"],)"
        R"("extensionsRequired":["EXT_meshopt_compression"]})";
    while (json.size() % 4 != 0) json.push_back(' ');
    std::vector<unsigned char> glb;
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) glb.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    glb.insert(glb.end(), {'g', 'l', 'T', 'F'});
    u32(2);
    u32(static_cast<uint32_t>(12 + 8 + json.size() + 8 + vb.size()));
    u32(static_cast<uint32_t>(json.size()));
    glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
    glb.insert(glb.end(), json.begin(), json.end());
    u32(static_cast<uint32_t>(vb.size()));
    glb.insert(glb.end(), {'B', 'I', 'N', 0});
    glb.insert(glb.end(), vb.begin(), vb.end());
    TempDir tmp;
    writeBytes(tmp.file("m.glb"), glb.data(), glb.size());
    DiagnosticSink diag;
    ir::Scene scene = importGltf(tmp.file("m.glb"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    expectNear(scene.meshes[0]->positions[1], Vec3(1, 0, 0), 0);
    expectNear(scene.meshes[0]->positions[2], Vec3(0, 1, 0), 0);
}

// Skins, morph targets, instancing

/// A strip of three rows of two vertices, y = 0, 1, 2; the middle row half on each joint.
std::string skinnedStrip(const std::string &joints, const std::string &weightsFix = "") {
    GltfBuilder b;
    b.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0, 1, 2, 0}, "VEC3", 3);
    b.accessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3, 2, 3, 4, 3, 5, 4}, 5123, "SCALAR", 12);
    b.accessor(std::vector<uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
                                    0, 1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0},
               5121, "VEC4", 6);
    std::vector<float> w = {1,    0,    0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0,
                            0.5f, 0.5f, 0, 0, 1, 0, 0, 0, 1,    0,    0, 0};
    b.floats(w, "VEC4", 4);
    // Inverse bind matrices: identity and translate(0, -1, 0), column-major
    b.floats({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
              1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
             "MAT4", 16);
    std::string text = b.json(
        R"("nodes":[{"mesh":0,"skin":0,"translation":[5,0,0]},{"children":[2]},)"
        R"({"translation":[0,1,0],"rotation":[0,0,0.70710678,0.70710678]}],)"
        R"("skins":[{"joints":)" +
            joints +
            R"(,"inverseBindMatrices":4}],)"
            R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"JOINTS_0":2,"WEIGHTS_0":3},)"
            R"("indices":1}]}])",
        "[0,1]");
    if (!weightsFix.empty())
        text = replaceOnce(text, R"("componentType":5126,"count":6,"type":"VEC4")", weightsFix);
    return text;
}

TEST(GltfGeometry, SkinnedStripPosedByHand) {
    DiagnosticSink diag;
    ir::Scene scene = importText(skinnedStrip("[1,2]"), diag);
    std::vector<Vec3> got = allWorldVertices(scene);
    // Joint 1 turns the top row 90 degrees about Z around (0, 1, 0): (x, 2) -> (-1 x, 1 + x)
    // ... with x in {0, 1}: (0, 2) -> (-1, 1), (1, 2) -> (-1, 2); the middle row halfway:
    // (1, 1) -> ((1 + 0) / 2, (1 + 2) / 2). The node's translation (5, 0, 0) is ignored.
    std::vector<Vec3> want = {{0, 0, 0},     {1, 0, 0},  {0, 1, 0},
                              {0.5, 1.5, 0}, {-1, 1, 0}, {-1, 2, 0}};
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) expectNear(got[i], zUp(want[i]), 1e-6);
}

TEST(GltfGeometry, BadSkins) {
    expectFailure(skinnedStrip("[1]"), {"meshes[0].primitives[0].attributes.JOINTS_0",
                                        "names joint 1", "skins[0] has 1"});
    expectFailure(skinnedStrip("[1,9]"), {"skins[0].joints[1]: node 9 does not exist"});
    expectFailure(skinnedStrip("[1,2]", R"("componentType":5126,"count":5,"type":"VEC4")"),
                  {"meshes[0].primitives[0].attributes.WEIGHTS_0", "5 elements for 6 vertices"});
    // Joint transforms that overflow a double
    std::string huge = replaceOnce(skinnedStrip("[1,2]"), R"({"children":[2]})",
                                   R"({"children":[2],"scale":[1e300,1e300,1e300]})");
    expectFailure(
        replaceOnce(huge, R"("translation":[0,1,0],)",
                    R"("translation":[0,1,0],"scale":[1e300,1e300,1e300],)"),
        {"meshes[0].primitives[0].attributes.POSITION", "is not finite", "(after skinning)"});
}

/// A triangle with one morph target moving every vertex by (0, 0, 2).
std::string morphedTriangle(const std::string &nodes, size_t deltaCount = 3) {
    GltfBuilder b;
    b.floats(kTriangle, "VEC3", 3);
    std::vector<float> delta;
    for (size_t i = 0; i < deltaCount; ++i) delta.insert(delta.end(), {0, 0, 2});
    b.floats(delta, "VEC3", 3);
    return b.json(R"("nodes":)" + nodes +
                      R"(,"meshes":[{"weights":[0.5],"primitives":[{"attributes":{"POSITION":0},)"
                      R"("targets":[{"POSITION":1}]}]}])",
                  "[0,1]");
}

TEST(GltfGeometry, MorphTargetWeights) {
    DiagnosticSink diag;
    ir::Scene scene = importText(morphedTriangle(R"([{"mesh":0},{"mesh":0,"weights":[1]}])"), diag);
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 2u);
    EXPECT_NE(inst[0].mesh, inst[1].mesh);  // two poses, two meshes
    EXPECT_DOUBLE_EQ(scene.meshes[static_cast<size_t>(inst[0].mesh)]->positions[1].z, 1.0);
    EXPECT_DOUBLE_EQ(scene.meshes[static_cast<size_t>(inst[1].mesh)]->positions[1].z, 2.0);

    // The same weights share one mesh
    scene = importText(morphedTriangle(R"([{"mesh":0},{"mesh":0,"weights":[0.5]}])"), diag);
    inst = instances(scene);
    ASSERT_EQ(inst.size(), 2u);
    EXPECT_EQ(inst[0].mesh, inst[1].mesh);

    expectFailure(morphedTriangle(R"([{"mesh":0},{"mesh":0}])", 2),
                  {"meshes[0].primitives[0].targets[0].POSITION", "2 deltas for 3 vertices"});

    // More weights than targets: a warning naming the node, the extra ones ignored
    DiagnosticSink extra;
    scene = importText(morphedTriangle(R"([{"mesh":0},{"mesh":0,"weights":[1,1]}])"), extra);
    EXPECT_EQ(extra.countContaining("nodes[1].weights: 2 weights for 1 morph targets"), 1);
    EXPECT_EQ(instances(scene).size(), 2u);
}

TEST(GltfGeometry, GpuInstancingSharesTheMesh) {
    GltfBuilder b;
    b.floats(kTriangle, "VEC3", 3);
    b.floats({0, 0, 0, 10, 0, 0, 0, 10, 0}, "VEC3", 3);
    DiagnosticSink diag;
    ir::Scene scene = importText(
        b.json(R"("nodes":[{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":)"
               R"({"TRANSLATION":1}}}}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
               R"("extensionsUsed":["EXT_mesh_gpu_instancing"],)"
               R"("extensionsRequired":["EXT_mesh_gpu_instancing"])"),
        diag);
    std::vector<Instance> inst = instances(scene);
    ASSERT_EQ(inst.size(), 3u);
    EXPECT_EQ(scene.meshes.size(), 1u);
    for (const Instance &i : inst) EXPECT_EQ(i.mesh, 0);
    expectNear(inst[1].world.transformPoint(Vec3(0, 0, 0)), zUp(Vec3(10, 0, 0)), 1e-12);
    expectNear(inst[2].world.transformPoint(Vec3(1, 0, 0)), zUp(Vec3(1, 10, 0)), 1e-12);

    // Attributes of different counts
    GltfBuilder bad;
    bad.floats(kTriangle, "VEC3", 3);
    bad.floats({0, 0, 0, 10, 0, 0, 0, 10, 0}, "VEC3", 3);
    bad.floats({1, 1, 1, 2, 2, 2}, "VEC3", 3);
    expectFailure(
        bad.json(R"("nodes":[{"mesh":0,"extensions":{"EXT_mesh_gpu_instancing":{"attributes":)"
                 R"({"TRANSLATION":1,"SCALE":2}}}}],"meshes":[{"primitives":[{"attributes":)"
                 R"({"POSITION":0}}]}])"),
        {"nodes[0].extensions.EXT_mesh_gpu_instancing.attributes.SCALE",
         "2 instances, but the other attributes have 3"});
}

}  // namespace
}  // namespace rt::gltf::test
