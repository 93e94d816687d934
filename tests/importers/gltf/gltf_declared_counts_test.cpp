// SPDX-License-Identifier: MIT
// Counts a glTF declares for its data, checked against the bytes present before anything is
// allocated for them: EXT_meshopt_compression views (an 818-byte file whose view declared
// 536,870,908 elements had 2 GB allocated and zero-filled), Draco streams and accessors.
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <optional>

#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

/// The ParseError importing `text` throws (a test failure when it imports), located at the file.
std::optional<ParseError> parseError(const std::string &text) {
    TempDir tmp;
    writeText(tmp.file("m.gltf"), text);
    DiagnosticSink diag;
    try {
        importGltf(tmp.file("m.gltf"), diag);
    } catch (const ParseError &e) {
        EXPECT_EQ(e.loc().file ? *e.loc().file : std::string(), tmp.file("m.gltf"));
        return e;
    }
    ADD_FAILURE() << "imported without an error";
    return std::nullopt;
}

/// Imports `text`; the number of triangles placed.
size_t importedTriangles(const std::string &text) {
    TempDir tmp;
    writeText(tmp.file("m.gltf"), text);
    DiagnosticSink diag;
    return instancedTriangles(importGltf(tmp.file("m.gltf"), diag));
}

void expectParts(const std::optional<ParseError> &e, std::initializer_list<std::string> parts) {
    if (!e) return;
    std::string what = e->what();
    for (const std::string &p : parts)
        EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
}

const std::vector<float> kTriangle = {0, 0, 0, 1, 0, 0, 0, 1, 0};

/// A triangle whose positions (3 VEC3 floats) are the first elements of an EXT_meshopt_compression
/// view of `count` elements of `stride` bytes in `mode`, compressed as `data`, over a fallback
/// buffer without data.
std::string meshoptGltf(const std::vector<unsigned char> &data, uint64_t count, size_t stride,
                        const std::string &mode = "ATTRIBUTES") {
    TestBuffer buf;
    buf.add(data);
    std::string decoded = std::to_string(count * stride);
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
           R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
           R"("buffers":[)" +
           buf.json() + R"(,{"byteLength":)" + decoded +
           R"(,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}],)"
           R"("bufferViews":[{"buffer":1,"byteLength":)" +
           decoded + R"(,"byteStride":)" + std::to_string(stride) +
           R"(,"extensions":{"EXT_meshopt_compression":{"buffer":0,"byteLength":)" +
           std::to_string(data.size()) + R"(,"byteStride":)" + std::to_string(stride) +
           R"(,"count":)" + std::to_string(count) + R"(,"mode":")" + mode +
           R"("}}}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
           R"("extensionsUsed":["EXT_meshopt_compression"],)"
           R"("extensionsRequired":["EXT_meshopt_compression"]})";
}

std::vector<unsigned char> meshoptVertices(const std::vector<float> &values, size_t stride) {
    size_t count = values.size() * sizeof(float) / stride;
    std::vector<unsigned char> out(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), values.data(), count, stride));
    return out;
}

TEST(GltfDeclaredCounts, MeshoptCountBeyondItsBytesIsRefusedBeforeDecoding) {
    std::vector<unsigned char> triangle = meshoptVertices(kTriangle, 12);
    EXPECT_EQ(importedTriangles(meshoptGltf(triangle, 3, 12)), 1u);
    // The reproduction's count (2 GB decoded, within the 2^31 limit on one view) with 4-byte
    // elements: the attribute codec needs at least a byte of header bits per 64 elements and byte
    // of the element, 33,554,465 bytes
    std::string mode = "mode ATTRIBUTES";
    expectParts(parseError(meshoptGltf(triangle, 536870908, 4)),
                {"bufferViews[0].extensions.EXT_meshopt_compression: count "
                 "536870908 of 4-byte "
                 "elements (" +
                 mode +
                 ") needs at least 33554465 compressed bytes, but "
                 "byteLength is " +
                 std::to_string(triangle.size())});
    // Triangle codes take a byte a triangle, index deltas a byte an index
    std::vector<unsigned> indices = {0, 1, 2};
    std::vector<unsigned char> tri(meshopt_encodeIndexBufferBound(3, 3));
    tri.resize(meshopt_encodeIndexBuffer(tri.data(), tri.size(), indices.data(), 3));
    expectParts(parseError(meshoptGltf(tri, 30000000, 4, "TRIANGLES")),
                {"count 30000000 of 4-byte elements (mode TRIANGLES) needs at "
                 "least 10000017"});
    std::vector<unsigned char> seq(meshopt_encodeIndexSequenceBound(3, 3));
    seq.resize(meshopt_encodeIndexSequence(seq.data(), seq.size(), indices.data(), 3));
    expectParts(parseError(meshoptGltf(seq, 30000000, 4, "INDICES")),
                {"count 30000000 of 4-byte elements (mode INDICES) needs at "
                 "least 30000005"});
}

TEST(GltfDeclaredCounts, MeshoptAtItsBestRatioStillDecodes) {
    // 1024 elements of zeros, the codec's most compact input, take exactly the bound: the header
    // byte, 4 header bytes for each of 12 bytes in each block of 256, and a 32-byte tail
    std::vector<unsigned char> zeros = meshoptVertices(std::vector<float>(3 * 1024, 0.0f), 12);
    EXPECT_EQ(zeros.size(), 1u + 4 * 4 * 12 + 32);
    DiagnosticSink diag;
    TempDir tmp;
    writeText(tmp.file("z.gltf"), meshoptGltf(zeros, 1024, 12));
    EXPECT_NO_THROW(importGltf(tmp.file("z.gltf"), diag));
    // One element more needs one more header byte for each byte of the element
    expectParts(parseError(meshoptGltf(zeros, 1025, 12)),
                {"count 1025 of 12-byte elements (mode ATTRIBUTES) needs at least 237 "
                 "compressed bytes, but byteLength is 225"});
}

// Draco

/// A two-triangle quad, Draco-encoded with `method` (edgebreaker or sequential).
std::vector<unsigned char> dracoQuad(draco::MeshEncoderMethod method) {
    const float quad[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    const int faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    int att = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    for (int f = 0; f < 2; ++f)
        builder.SetAttributeValuesForFace(att, draco::FaceIndex(f), quad[faces[f][0]],
                                          quad[faces[f][1]], quad[faces[f][2]]);
    std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    draco::Encoder encoder;
    encoder.SetEncodingMethod(method);
    draco::EncoderBuffer encoded;
    EXPECT_TRUE(mesh && encoder.EncodeMeshToBuffer(*mesh, &encoded).ok());
    EXPECT_EQ(mesh->attribute(att)->unique_id(), 0u);
    return std::vector<unsigned char>(encoded.data(), encoded.data() + encoded.size());
}

/// A quad primitive whose geometry is the Draco stream `data` (POSITION: Draco attribute 0, an
/// accessor of `points` elements).
std::string dracoGltf(const std::vector<unsigned char> &data, size_t points = 4) {
    TestBuffer buf;
    buf.add(data);
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
           R"("nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0},)"
           R"("extensions":{"KHR_draco_mesh_compression":{"bufferView":0,)"
           R"("attributes":{"POSITION":0}}}}]}],"buffers":[)" +
           buf.json() + "],\"bufferViews\":[" + viewJson(0, data.size()) +
           R"(],"accessors":[{"componentType":5126,"count":)" + std::to_string(points) +
           R"(,"type":"VEC3"}],)"
           R"("extensionsUsed":["KHR_draco_mesh_compression"],)"
           R"("extensionsRequired":["KHR_draco_mesh_compression"]})";
}

/// The vertices Draco decodes `data` to.
size_t dracoPoints(const std::vector<unsigned char> &data) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char *>(data.data()), data.size());
    auto mesh = draco::Decoder().DecodeMeshFromBuffer(&buffer);
    EXPECT_TRUE(mesh.ok());
    return mesh.ok() ? mesh.value()->num_points() : 0;
}

/// Replaces the `index`-th LEB128 varint from byte `at` of `data` by `value`.
std::vector<unsigned char> withVarint(std::vector<unsigned char> data, size_t at, int index,
                                      uint32_t value) {
    for (int i = 0; i < index; ++i)
        while (data.at(at++) & 0x80) {
        }
    size_t end = at;
    while (data.at(end++) & 0x80) {
    }
    std::vector<unsigned char> encoded;
    do {
        encoded.push_back(static_cast<unsigned char>((value & 0x7f) | (value > 0x7f ? 0x80 : 0)));
        value >>= 7;
    } while (value);
    data.erase(data.begin() + static_cast<long>(at), data.begin() + static_cast<long>(end));
    data.insert(data.begin() + static_cast<long>(at), encoded.begin(), encoded.end());
    return data;
}

TEST(GltfDeclaredCounts, DracoCountsBeyondTheirBytesAreRefusedBeforeDecoding) {
    // Draco 2.2: "DRACO", version 2.2, mesh, method, 2 flag bytes; then the connectivity
    constexpr size_t kHeader = 11;
    std::vector<unsigned char> edgebreaker = dracoQuad(draco::MESH_EDGEBREAKER_ENCODING);
    ASSERT_GT(edgebreaker.size(), kHeader + 3);
    ASSERT_EQ(edgebreaker[8], 1);  // edgebreaker
    EXPECT_EQ(importedTriangles(dracoGltf(edgebreaker, dracoPoints(edgebreaker))), 2u);
    const std::string what =
        "meshes[0].primitives[0].extensions.KHR_draco_mesh_compression: its "
        "data (bufferViews[0]) declares ";
    // After the traversal type: vertices, faces, the attribute data count (a byte), symbols. Draco
    // takes at most 4/3 faces a symbol but reads no symbol before sizing its tables from them: 100
    // bytes declaring 7 x 10^8 faces took it 64 s and 16 GB; here 0.4 s and 490 MB
    std::vector<unsigned char> faces =
        withVarint(withVarint(edgebreaker, kHeader + 1, 1, 20000000), kHeader + 1, 3, 20000000);
    expectParts(
        parseError(dracoGltf(faces)),
        {what + "20000000 triangles and ", " vertices in " + std::to_string(faces.size()) +
                                               " bytes, more than 1024 of either a byte can hold"});

    std::vector<unsigned char> sequential = dracoQuad(draco::MESH_SEQUENTIAL_ENCODING);
    ASSERT_EQ(sequential[8], 0);  // sequential
    EXPECT_EQ(importedTriangles(dracoGltf(sequential, dracoPoints(sequential))), 2u);
    // Faces, then points (Draco itself refuses more points than 3 a face)
    std::vector<unsigned char> points = withVarint(sequential, kHeader, 1, 50000000);
    expectParts(parseError(dracoGltf(points)),
                {what + "2 triangles and 50000000 vertices in " + std::to_string(points.size())});

    // Other bitstream versions lay the counts out differently: refused
    std::vector<unsigned char> old = edgebreaker;
    old[6] = 1;
    expectParts(parseError(dracoGltf(old)),
                {"is Draco bitstream 2.1; KHR_draco_mesh_compression requires "
                 "version 2.2"});
}

// Accessors

TEST(GltfDeclaredCounts, AccessorCountBeyondItsViewIsRefusedBeforeReading) {
    std::string text = replaceOnce(triangleGltf(""), R"("componentType":5126,"count":3,)",
                                   R"("componentType":5126,"count":100000000,)");
    expectParts(parseError(text), {"meshes[0].primitives[0].attributes.POSITION "
                                   "(accessors[0]): 100000000 elements "
                                   "of 12 bytes (stride 12) from byte 0 run past "
                                   "the end of its bufferView (36 "
                                   "bytes)"});
}

}  // namespace
}  // namespace rt::gltf::test
