// SPDX-License-Identifier: MIT
// glTF importer on broken files: each fails with a located error naming the culprit, never a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

/// Imports `path` expecting an error of type E whose message contains every `parts` entry;
/// returns the message.
template <typename E>
std::string expectError(const std::string &path, std::initializer_list<std::string> parts,
                        const ImportOptions &opts = {}) {
    DiagnosticSink diag;
    try {
        importGltf(path, diag, opts);
    } catch (const E &e) {
        std::string msg = e.what();
        for (const std::string &p : parts)
            EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
        EXPECT_EQ(e.loc().fileName(), path);
        EXPECT_EQ(e.loc().line, 0);
        return msg;
    }
    ADD_FAILURE() << path << " imported without the expected error";
    return "";
}

/// Box.gltf with its embedded buffer moved to `binName` (written only when `writeBin`), and
/// the buffer bytes edited by `edit`.
std::string boxWithExternalBuffer(const TempDir &tmp, const std::string &binName, bool writeBin,
                                  const std::function<void(std::vector<unsigned char> &)> &edit) {
    std::string text = readText(sample("Box.gltf"));
    const std::string prefix = "data:application/octet-stream;base64,";
    size_t start = text.find(prefix);
    size_t end = text.find('"', start);
    EXPECT_NE(start, std::string::npos);
    std::vector<unsigned char> bin =
        base64Decode(text.substr(start + prefix.size(), end - start - prefix.size()));
    EXPECT_EQ(bin.size(), 648u);
    if (edit) edit(bin);
    if (writeBin) writeBytes(tmp.file(binName), bin.data(), bin.size());
    text.replace(start, end - start, binName);
    std::string path = tmp.file("box.gltf");
    writeText(path, text);
    return path;
}

TEST(GltfErrors, MissingFile) {
    expectError<ParseError>("/nonexistent/model.glb",
                            {"can't open file", "model.glb", "no such file"});
}

/// The ParseError importing `path` throws, or none (a test failure) when it imports.
std::optional<ParseError> parseErrorOf(const std::string &path) {
    DiagnosticSink diag;
    try {
        importGltf(path, diag);
    } catch (const ParseError &e) {
        return e;
    }
    ADD_FAILURE() << path << " imported without an error";
    return std::nullopt;
}

TEST(GltfErrors, InvalidJsonIsLocatedAtItsLineAndColumn) {
    TempDir tmp;
    writeText(tmp.file("bad.gltf"), "{\"asset\": {\"version\": \"2.0\"},\n  \"scenes\": [ }\n");
    if (auto e = parseErrorOf(tmp.file("bad.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("invalid JSON"), std::string::npos) << e->what();
        EXPECT_EQ(e->loc().fileName(), tmp.file("bad.gltf"));
        EXPECT_EQ(e->loc().line, 2);
        EXPECT_EQ(e->loc().col, 15);  // the closing brace
    }
    writeText(tmp.file("empty.gltf"), "");
    if (auto e = parseErrorOf(tmp.file("empty.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("cannot load glTF file"), std::string::npos)
            << e->what();
        EXPECT_EQ(e->loc().fileName(), tmp.file("empty.gltf"));
    }
}

TEST(GltfErrors, OverflowingNumberIsLocated) {
    // JSON has no inf or NaN literal; 1e999 is how one sneaks in, and it must not be 'inf'
    TempDir tmp;
    std::string text = replaceOnce(triangleGltf(""), R"({"mesh":0,"name":"tri"})",
                                   "{\"mesh\":0,\n  \"scale\":[1,-1e999,1]}");
    writeText(tmp.file("inf.gltf"), text);
    size_t at = text.find("-1e999");
    int line =
        1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    int col = static_cast<int>(at - text.rfind('\n', at));
    if (auto e = parseErrorOf(tmp.file("inf.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("-1e999 is too large"), std::string::npos)
            << e->what();
        EXPECT_EQ(e->loc().line, line);
        EXPECT_EQ(e->loc().col, col);
    }
    // The same in a .glb's JSON chunk: located within the chunk
    std::string json = "{\"asset\":{\"version\":\"2.0\"},\n\"nodes\":[{\"scale\":[1,1e999,1]}]}";
    writeText(tmp.file("inf.glb"), Glb{}.bytes(json));
    if (auto e = parseErrorOf(tmp.file("inf.glb"))) {
        EXPECT_NE(std::string(e->what()).find("1e999 is too large for a double (JSON chunk of the "
                                              "binary glTF, its line 2, column 22)"),
                  std::string::npos)
            << e->what();
    }
}

TEST(GltfErrors, TruncatedGlb) {
    REQUIRE_GLTF_SAMPLE("BoxInterleaved.glb");
    TempDir tmp;
    std::vector<unsigned char> glb = readBytes(sample("BoxInterleaved.glb"));
    writeBytes(tmp.file("cut.glb"), glb.data(), glb.size() / 2);
    expectError<ParseError>(tmp.file("cut.glb"),
                            {"invalid binary glTF (.glb): the header's length (at byte 8) is " +
                             std::to_string(glb.size()) + " bytes, but the file has " +
                             std::to_string(glb.size() / 2) + " (truncated?)"});
}

TEST(GltfErrors, IndexOutOfRange) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    // Both vertex accessors cut to 20 vertices; the indices still go up to 23
    std::string text = readText(sample("Box.gltf"));
    for (size_t at; (at = text.find("\"count\": 24")) != std::string::npos;)
        text.replace(at, 11, "\"count\": 20");
    writeText(tmp.file("box.gltf"), text);
    expectError<ParseError>(tmp.file("box.gltf"),
                            {"meshes[0].primitives[0]: index 2", "out of range for 20 vertices"});
}

TEST(GltfErrors, NanPosition) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string path = boxWithExternalBuffer(tmp, "box.bin", true, [](auto &bin) {
        float nan = std::numeric_limits<float>::quiet_NaN();
        std::memcpy(bin.data() + 288 + 5 * 12 + 4, &nan, 4);  // vertex 5, y
    });
    expectError<ParseError>(path, {"meshes[0].primitives[0].attributes.POSITION", "accessors[2]",
                                   "vertex 5 is not finite"});
}

TEST(GltfErrors, ExternalBufferIsRead) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string path = boxWithExternalBuffer(tmp, "box.bin", true, nullptr);
    DiagnosticSink diag;
    ir::Scene scene = importGltf(path, diag);
    EXPECT_EQ(instancedTriangles(scene), 12u);
}

TEST(GltfErrors, MissingBin) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string path = boxWithExternalBuffer(tmp, "missing.bin", false, nullptr);
    expectError<ParseError>(path, {"cannot load glTF file", "missing.bin"});
}

TEST(GltfErrors, UnsupportedRequiredExtension) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string text = readText(sample("Box.gltf"));
    text.insert(1, R"("extensionsUsed": ["EXT_scadray_test_unknown"],
        "extensionsRequired": ["EXT_scadray_test_unknown"],)");
    writeText(tmp.file("unknown.gltf"), text);
    expectError<ParseError>(tmp.file("unknown.gltf"),
                            {"requires extension EXT_scadray_test_unknown, which scadray "
                             "does not support"});

    // A supported required extension is fine
    text = readText(sample("Box.gltf"));
    text.insert(1, R"("extensionsUsed": ["KHR_materials_unlit"],
        "extensionsRequired": ["KHR_materials_unlit"],)");
    writeText(tmp.file("unlit.gltf"), text);
    DiagnosticSink diag;
    EXPECT_NO_THROW(importGltf(tmp.file("unlit.gltf"), diag));
}

TEST(GltfErrors, AccessorPastTheEndOfItsView) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string text =
        replaceOnce(readText(sample("Box.gltf")), "\"byteOffset\": 288", "\"byteOffset\": 400");
    writeText(tmp.file("box.gltf"), text);
    expectError<ParseError>(tmp.file("box.gltf"), {"attributes.POSITION (accessors[2])",
                                                   "run past the end", "576 bytes"});
}

TEST(GltfErrors, BufferViewOutsideItsBuffer) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::string text =
        replaceOnce(readText(sample("Box.gltf")), "\"byteLength\": 576", "\"byteLength\": 4000");
    writeText(tmp.file("box.gltf"), text);
    expectError<ParseError>(tmp.file("box.gltf"), {"bufferViews[1]", "outside buffer 0"});
}

TEST(GltfErrors, BadReferencesAndCycles) {
    TempDir tmp;
    std::string base = triangleGltf("");
    auto write = [&](const std::string &name, const std::string &from, const std::string &to) {
        writeText(tmp.file(name), replaceOnce(base, from, to));
        return tmp.file(name);
    };
    expectError<ParseError>(
        write("cycle.gltf", R"({"mesh":0,"name":"tri"})", R"({"mesh":0,"children":[0]})"),
        {"nodes[0]: reached twice"});
    expectError<ParseError>(write("node.gltf", R"("nodes":[0])", R"("nodes":[7])"),
                            {"scenes[0].nodes[0]: node 7 does not exist"});
    expectError<ParseError>(write("mesh.gltf", R"({"mesh":0,"name":"tri"})", R"({"mesh":3})"),
                            {"nodes[0]: mesh 3 does not exist"});
    expectError<ParseError>(write("acc.gltf", R"({"POSITION":0})", R"({"POSITION":5})"),
                            {"meshes[0].primitives[0].attributes.POSITION: accessor 5"});
    expectError<ParseError>(write("type.gltf", R"("type":"VEC3")", R"("type":"VEC2")"),
                            {"type VEC2, expected VEC3"});
    expectError<ParseError>(
        write("mat.gltf", R"({"POSITION":0})", R"({"POSITION":0},"material":2)"),
        {"meshes[0].primitives[0]: material 2 does not exist"});
    expectError<ParseError>(
        write("matrix.gltf", R"({"mesh":0,"name":"tri"})", R"({"mesh":0,"matrix":[1,0,0]})"),
        {"nodes[0].matrix"});
    expectError<ParseError>(write("mode.gltf", R"({"POSITION":0})", R"({"POSITION":0},"mode":9)"),
                            {"invalid mode 9"});
}

TEST(GltfErrors, ZeroScaleHidesANode) {
    TempDir tmp;
    std::string text = replaceOnce(triangleGltf(""), R"({"mesh":0,"name":"tri"})",
                                   R"({"mesh":0,"scale":[1,0,1]})");
    writeText(tmp.file("flat.gltf"), text);
    DiagnosticSink diag;
    ir::Scene scene = importGltf(tmp.file("flat.gltf"), diag);
    EXPECT_TRUE(instances(scene).empty());
    EXPECT_EQ(diag.countContaining("nodes[0]: its transform is singular"), 1);
}

TEST(GltfErrors, HugeAndTinyScalesAreNotSingular) {
    // Their determinants over- or underflow a double; the transform is still invertible
    for (const char *scale : {"[1e150,1e150,1e150]", "[1e-150,2e-150,1e-150]"}) {
        TempDir tmp;
        std::string text = replaceOnce(triangleGltf(""), R"({"mesh":0,"name":"tri"})",
                                       std::string(R"({"mesh":0,"scale":)") + scale + "}");
        writeText(tmp.file("scaled.gltf"), text);
        DiagnosticSink diag;
        ir::Scene scene = importGltf(tmp.file("scaled.gltf"), diag);
        EXPECT_EQ(instances(scene).size(), 1u) << scale;
        EXPECT_EQ(diag.countContaining("singular"), 0) << scale;
    }
}

TEST(GltfErrors, BadOptions) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    ImportOptions opts;
    opts.unitScale = -1;
    expectError<SceneError>(sample("Box.gltf"), {"unit scale"}, opts);
    ImportOptions scene;
    scene.sceneIndex = 1;
    expectError<SceneError>(sample("Box.gltf"), {"scene 1 requested", "1 scene(s)"}, scene);
}

TEST(GltfErrors, SparseAccessorWithoutBufferViewStartsFromZeros) {
    TempDir tmp;
    TestBuffer buf;
    size_t idx = buf.add(std::vector<uint16_t>{2, 0});  // padded to 4 bytes
    size_t val = buf.add(std::vector<float>{0, 1, 0});
    std::string views = viewJson(idx, 2) + "," + viewJson(val, 12);
    std::string accessor =
        R"({"componentType":5126,"count":3,"type":"VEC3","sparse":{"count":1,)"
        R"("indices":{"bufferView":0,"componentType":5123},"values":{"bufferView":1}}})";
    std::string text = meshGltf(R"({"attributes":{"POSITION":0}})", buf, views, accessor);
    writeText(tmp.file("sparse.gltf"), text);
    DiagnosticSink diag;
    ir::Scene scene = importGltf(tmp.file("sparse.gltf"), diag);
    // Two vertices stay at zero: the only triangle has no area and is dropped
    EXPECT_TRUE(scene.meshes.empty());
    EXPECT_EQ(diag.countContaining("no triangles with area"), 1);

    // A sparse index past the accessor's count is an error, not a write out of bounds
    std::string bad = text;
    TestBuffer buf2;
    buf2.add(std::vector<uint16_t>{3, 0});
    buf2.add(std::vector<float>{0, 1, 0});
    bad = replaceOnce(bad, buf.json(), buf2.json());
    writeText(tmp.file("sparse_bad.gltf"), bad);
    expectError<ParseError>(tmp.file("sparse_bad.gltf"),
                            {"accessors[0]).sparse.indices[0]: element 3 out of range for 3"});
}

TEST(GltfErrors, NormalizedIntegerAttributes) {
    // Quantized positions (i16 normalized, KHR_mesh_quantization style) and u8 normalized uvs
    TempDir tmp;
    TestBuffer buf;
    size_t pos = buf.add(std::vector<int16_t>{0, 0, 0, 0, 32767, 0, 0, 0, 0, -32768, 0, 0});
    size_t uv = buf.add(std::vector<uint8_t>{0, 0, 0, 0, 255, 0, 0, 0, 0, 255, 0, 0});
    std::string views = viewJson(pos, 24, 8) + "," + viewJson(uv, 12, 4);
    std::string accessors =
        R"({"bufferView":0,"componentType":5122,"normalized":true,"count":3,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5121,"normalized":true,"count":3,"type":"VEC2"})";
    std::string text =
        meshGltf(R"({"attributes":{"POSITION":0,"TEXCOORD_0":1}})", buf, views, accessors);
    writeText(tmp.file("quant.gltf"), text);
    DiagnosticSink diag;
    ir::Scene scene = importGltf(tmp.file("quant.gltf"), diag);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const ir::Mesh &m = *scene.meshes[0];
    expectNear(m.positions[1], Vec3(1, 0, 0), 0);
    expectNear(m.positions[2], Vec3(0, -1, 0), 0);  // -32768 clamps to -1
    EXPECT_EQ(m.uvs[1][0], 1.0f);
    EXPECT_EQ(m.uvs[2][1], 1.0f);
}

/// Imports `path`; a LocatedError is fine, a scene must be valid. Anything else fails the test.
void importOrReject(const std::string &path) {
    DiagnosticSink diag;
    try {
        ir::Scene scene = importGltf(path, diag);
        for (const auto &m : scene.meshes) ir::validateMesh(*m);
    } catch (const LocatedError &) {
    }
}

TEST(GltfFuzz, TruncatedGlbAtEveryLength) {
    REQUIRE_GLTF_SAMPLE("BoxInterleaved.glb");
    TempDir tmp;
    std::vector<unsigned char> glb = readBytes(sample("BoxInterleaved.glb"));
    std::string path = tmp.file("cut.glb");
    for (size_t n = 0; n < glb.size(); ++n) {
        writeBytes(path, glb.data(), n);
        DiagnosticSink sink;
        EXPECT_THROW(importGltf(path, sink), ParseError) << n;
    }
    // A larger model with an embedded PNG, cut at a few hundred lengths
    std::vector<unsigned char> textured = readBytes(testModel("textured_camera.glb"));
    ASSERT_GT(textured.size(), 60000u);
    for (size_t n = 0; n < textured.size(); n += 197) {
        writeBytes(path, textured.data(), n);
        DiagnosticSink sink;
        EXPECT_THROW(importGltf(path, sink), ParseError) << n;
    }
}

TEST(GltfFuzz, TruncatedGltfText) {
    REQUIRE_GLTF_SAMPLE("SimpleSparseAccessor.gltf");
    TempDir tmp;
    std::string text = readText(sample("SimpleSparseAccessor.gltf"));
    for (size_t n = 0; n < text.size(); n += 7) {
        writeText(tmp.file("cut.gltf"), text.substr(0, n));
        importOrReject(tmp.file("cut.gltf"));
    }
}

/// Rounds per sample; SCADRAY_GLTF_FUZZ_ROUNDS raises it for a longer run (e.g. under ASan).
int fuzzRounds(int fallback) {
    const char *env = std::getenv("SCADRAY_GLTF_FUZZ_ROUNDS");
    return env ? std::max(1, std::atoi(env)) : fallback;
}

/// Imports corrupted copies of a model: half the edits change a digit (in the JSON: valid
/// JSON with wrong counts, offsets, strides and indices), the others any byte.
void fuzzSample(const std::string &file, int rounds, unsigned seed) {
    SCOPED_TRACE(file);
    TempDir tmp;
    std::vector<unsigned char> original = readBytes(file);
    std::vector<size_t> digits;
    for (size_t i = 0; i < original.size(); ++i)
        if (std::isdigit(original[i])) digits.push_back(i);
    ASSERT_FALSE(digits.empty());
    std::mt19937 rng(seed);
    std::string path = tmp.file("corrupt");
    for (int round = 0; round < rounds; ++round) {
        std::vector<unsigned char> bytes = original;
        int edits = 1 + static_cast<int>(rng() % 3);
        for (int k = 0; k < edits; ++k) {
            if (rng() % 2 == 0)
                bytes[digits[rng() % digits.size()]] = static_cast<unsigned char>('0' + rng() % 10);
            else
                bytes[rng() % bytes.size()] = static_cast<unsigned char>(rng());
        }
        writeBytes(path, bytes.data(), bytes.size());
        importOrReject(path);
    }
}

TEST(GltfFuzz, CorruptedBytes) {
    for (const char *name : {"BoxInterleaved.glb", "SimpleSparseAccessor.gltf",
                             "MeshPrimitiveModes.gltf", "Cameras.gltf", "OrientationTest.glb"}) {
        REQUIRE_GLTF_SAMPLE(name);
        fuzzSample(sample(name), fuzzRounds(300), 12345);
    }
    // With an embedded PNG (decoded on every round)
    fuzzSample(testModel("textured_camera.glb"), fuzzRounds(300) / 5, 777);
}

}  // namespace
}  // namespace rt::gltf::test
