// SPDX-License-Identifier: MIT
// glTF files written to harm: URIs reaching outside the model's folder, non-regular
// files, JSON that recursion or regular expressions choke on, headers declaring huge textures,
// GLB buffers that multiply the BIN chunk. Each is a located error or a warning, read nothing
// it should not and allocate nothing it declares before checking it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <optional>

#include "tests/importers/gltf/gltf_test_support.h"

namespace rt::gltf::test {
namespace {

namespace fs = std::filesystem;

/// Box.gltf's 648 bytes of geometry (an outside file holding them would import as a box).
std::vector<unsigned char> boxBin() {
    std::string text = readText(sample("Box.gltf"));
    const std::string prefix = "data:application/octet-stream;base64,";
    size_t start = text.find(prefix);
    size_t end = text.find('"', start);
    return base64Decode(text.substr(start + prefix.size(), end - start - prefix.size()));
}

/// Box.gltf with its buffer's uri replaced by `uri` (written as it stands into the JSON).
std::string boxWithUri(const std::string &path, const std::string &uri) {
    std::string text = readText(sample("Box.gltf"));
    const std::string prefix = "data:application/octet-stream;base64,";
    size_t start = text.find(prefix);
    size_t end = text.find('"', start);
    text.replace(start, end - start, uri);
    writeText(path, text);
    return text;
}

/// The ParseError importing `path` throws (a test failure when it imports).
std::optional<ParseError> parseError(const std::string &path, DiagnosticSink *sink = nullptr) {
    DiagnosticSink local;
    try {
        importGltf(path, sink ? *sink : local);
    } catch (const ParseError &e) {
        return e;
    }
    ADD_FAILURE() << path << " imported without an error";
    return std::nullopt;
}

/// Imports `path`, which may fail for a reason of its own (a library with no scenes), but not
/// with an error whose message contains `text`.
void expectNoErrorContaining(const std::string &path, const std::string &text) {
    DiagnosticSink sink;
    try {
        importGltf(path, sink);
    } catch (const std::exception &e) {
        EXPECT_EQ(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

/// Line and column (from 1) of the first `needle` in `text`.
std::pair<int, int> lineColumn(const std::string &text, const std::string &needle) {
    size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos);
    int line =
        1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    size_t lineStart = text.rfind('\n', at);
    return {line, static_cast<int>(lineStart == std::string::npos ? at + 1 : at - lineStart)};
}

TEST(GltfHostile, UrisOutsideTheModelFolderAreRefusedAtTheirPosition) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::vector<unsigned char> bin = boxBin();
    writeBytes(tmp.file("secret.bin"), bin.data(), bin.size());
    fs::create_directories(tmp.file("model/sub"));
    fs::create_symlink(tmp.file("secret.bin"), tmp.file("model/link.bin"));
    std::string model = tmp.file("model/box.gltf");
    for (const std::string &uri :
         {std::string("../secret.bin"), std::string("%2e%2e/secret.bin"),
          std::string("%2E%2E%2Fsecret.bin"), std::string("sub/../../secret.bin"),
          std::string("..\\\\secret.bin"), std::string("link.bin"), tmp.file("secret.bin"),
          "file://" + tmp.file("secret.bin"), std::string("file:../secret.bin")}) {
        SCOPED_TRACE(uri);
        std::string text = boxWithUri(model, uri);
        if (auto e = parseError(model)) {
            std::string msg = e->what();
            EXPECT_NE(msg.find("buffers[0].uri"), std::string::npos) << msg;
            EXPECT_NE(msg.find("not read"), std::string::npos) << msg;
            EXPECT_EQ(e->loc().fileName(), model);
            auto [line, col] = lineColumn(text, "\"" + uri + "\"");
            EXPECT_EQ(e->loc().line, line);
            EXPECT_EQ(e->loc().col, col);
        }
    }
}

TEST(GltfHostile, FilesInsideTheFolderAreRead) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    std::vector<unsigned char> bin = boxBin();
    fs::create_directories(tmp.file("model/sub"));
    writeBytes(tmp.file("model/sub/box data.bin"), bin.data(), bin.size());
    fs::create_symlink("sub/box data.bin", tmp.file("model/inside.bin"));
    std::string model = tmp.file("model/box.gltf");
    for (const char *uri : {"sub/box%20data.bin", "./sub/../sub/box data.bin", "inside.bin"}) {
        SCOPED_TRACE(uri);
        boxWithUri(model, uri);
        DiagnosticSink diag;
        ir::Scene scene = importGltf(model, diag);
        EXPECT_EQ(instancedTriangles(scene), 12u);
    }
}

TEST(GltfHostile, ImageUriOutsideIsAnError) {
    TempDir tmp;
    writeText(tmp.file("secret.png"), "not an image");
    fs::create_directories(tmp.file("model"));
    std::string text =
        triangleGltf("", R"(,"textures":[{"source":0}],"images":[{"uri":"../secret.png"}])");
    writeText(tmp.file("model/tri.gltf"), text);
    if (auto e = parseError(tmp.file("model/tri.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("images[0].uri '../secret.png'"), std::string::npos)
            << e->what();
        EXPECT_EQ(e->loc().line, lineColumn(text, "\"../secret.png\"").first);
    }
}

TEST(GltfHostile, NonRegularFilesAreRefused) {
    REQUIRE_GLTF_SAMPLE("Box.gltf");
    TempDir tmp;
    ASSERT_EQ(::mkfifo(tmp.file("fifo.bin").c_str(), 0600), 0);
    fs::create_directories(tmp.file("folder.bin"));
    for (const char *uri : {"fifo.bin", "folder.bin"}) {
        SCOPED_TRACE(uri);
        boxWithUri(tmp.file("box.gltf"), uri);
        if (auto e = parseError(tmp.file("box.gltf"))) {
            EXPECT_NE(std::string(e->what()).find("is not a regular file"), std::string::npos)
                << e->what();
        }
    }
    // The model itself
    if (auto e = parseError(tmp.file("fifo.bin"))) {
        EXPECT_NE(std::string(e->what()).find("not a regular file"), std::string::npos)
            << e->what();
    }
}

TEST(GltfHostile, GlbBuffersWithoutUriCannotMultiplyTheBinChunk) {
    // 2000 buffers, each a copy of a 64 KiB BIN chunk, would take 128 MiB; refused before
    std::string json = R"({"asset":{"version":"2.0"},"buffers":[)";
    for (int i = 0; i < 2000; ++i) json += std::string(i ? "," : "") + R"({"byteLength":65536})";
    json += "]}";
    std::string glb = Glb{.binLength = 65536, .binBytes = 65536}.bytes(json);
    TempDir tmp;
    writeText(tmp.file("many.glb"), glb);
    if (auto e = parseError(tmp.file("many.glb"))) {
        EXPECT_NE(std::string(e->what()).find("2000 buffers have no uri"), std::string::npos)
            << e->what();
    }
}

TEST(GltfHostile, GlbChunkLengthsAreCheckedAgainstTheFile) {
    // tinygltf 2.7 bounds the BIN chunk's data by the header's length without the chunk's own
    // 8-byte header: a BIN chunk declaring 8 bytes more than follow made a buffer copy from
    // past the end of the file (found by glb_fuzz; tests/fuzz/regressions/glb)
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":16}]})";
    const uint32_t j = static_cast<uint32_t>(json.size() + 3) / 4 * 4;  // padded
    struct Case {
        Glb glb;
        std::string expect;
    };
    const Case cases[] = {
        {{.binLength = 16, .binBytes = 8},
         "the chunk at byte " + std::to_string(20 + j) +
             " declares 16 bytes, but 8 follow its header"},
        {{.binLength = 16, .binBytes = 12}, "declares 16 bytes, but 12 follow"},
        {{.length = 20 + j + 8 + 20, .binLength = 16, .binBytes = 16},
         "length (at byte 8) is " + std::to_string(20 + j + 8 + 20) + " bytes, but the file has " +
             std::to_string(20 + j + 8 + 16)},
        {{.jsonLength = j + 32, .binLength = 16, .binBytes = 16},
         "the JSON chunk (at byte 12) declares " + std::to_string(j + 32) + " bytes, but " +
             std::to_string(j + 24) + " follow its header"},
        {{.length = 20 + j + 4, .binLength = 16, .binBytes = 16}, "4 bytes after the JSON chunk"},
        {{.version = 1, .binLength = 16, .binBytes = 16},
         "container version 1 (at byte 4); only version 2 is read"},
    };
    TempDir tmp;
    auto expectLayoutError = [&](const std::string &bytes, const std::string &expect) {
        writeText(tmp.file("bad.glb"), bytes);
        if (auto e = parseError(tmp.file("bad.glb"))) {
            EXPECT_NE(std::string(e->what()).find("invalid binary glTF (.glb): "),
                      std::string::npos)
                << e->what();
            EXPECT_NE(std::string(e->what()).find(expect), std::string::npos) << e->what();
        }
    };
    for (const Case &c : cases) expectLayoutError(c.glb.bytes(json), c.expect);
    expectLayoutError(Glb{.binLength = 16, .binBytes = 16}.bytes(json).substr(0, 19),
                      "the file is 19 bytes");
    expectLayoutError(Glb{}.bytes(""), "the JSON chunk (at byte 12) is empty");
    std::string notJson = Glb{}.bytes(json);
    notJson.replace(16, 3, "BIN");  // and a NUL: the BIN chunk's type
    notJson[19] = '\0';
    expectLayoutError(notJson, "the first chunk (at byte 12) is not the JSON chunk");
    // Bytes after the container's length are not a chunk: with no BIN chunk inside the length
    // and a BIN-like chunk after it, buffers[0] has no data. (The rewrite of a meshopt
    // fallback buffer used to carry those bytes into the container, where tinygltf read them
    // as its BIN chunk, 8 bytes past the end.)
    {
        const std::string fallbackJson =
            R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":16},)"
            R"({"byteLength":8,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}]})";
        const uint32_t length = static_cast<uint32_t>(20 + (fallbackJson.size() + 3) / 4 * 4);
        writeText(tmp.file("trailing.glb"),
                  Glb{.length = length, .binLength = 16, .binBytes = 8}.bytes(fallbackJson));
        DiagnosticSink sink;
        if (auto e = parseError(tmp.file("trailing.glb"), &sink)) {
            EXPECT_NE(std::string(e->what()).find("empty BIN chunk"), std::string::npos)
                << e->what();
        }
        EXPECT_EQ(sink.countContaining("16 bytes after the binary glTF's length (" +
                                       std::to_string(length) + " bytes, at byte 8) are ignored"),
                  1);
    }
    // A BIN chunk of length 0 is allowed (tinygltf 2.7 refused it: "Insufficient storage space
    // for Chunk1"); the triangle imports from its data URI
    {
        writeText(tmp.file("empty_bin.glb"), Glb{.emptyBin = true}.bytes(triangleGltf("")));
        DiagnosticSink sink;
        ir::Scene scene = importGltf(tmp.file("empty_bin.glb"), sink);
        EXPECT_EQ(instancedTriangles(scene), 1u);
        // and stays dropped when the JSON is rewritten for a meshopt fallback buffer (the
        // rewrite keeps what follows the JSON chunk)
        std::string withFallback = replaceOnce(
            triangleGltf(""), "],\"bufferViews\"",
            R"(,{"byteLength":8,"extensions":{"EXT_meshopt_compression":{"fallback":true}}}])"
            R"(,"bufferViews")");
        writeText(tmp.file("empty_bin_fallback.glb"), Glb{.emptyBin = true}.bytes(withFallback));
        scene = importGltf(tmp.file("empty_bin_fallback.glb"), sink);
        EXPECT_EQ(instancedTriangles(scene), 1u);
    }
    // So is a second chunk of an unknown type, which readers skip (a warning names it)
    {
        std::string bytes = Glb{.binLength = 8, .binBytes = 8}.bytes(triangleGltf(""));
        size_t type = bytes.size() - 12;
        bytes.replace(type, 4, "XYZ\x01");
        writeText(tmp.file("unknown_chunk.glb"), bytes);
        DiagnosticSink sink;
        ir::Scene scene = importGltf(tmp.file("unknown_chunk.glb"), sink);
        EXPECT_EQ(instancedTriangles(scene), 1u);
        EXPECT_EQ(sink.countContaining("the chunk at byte " + std::to_string(type - 4) +
                                       " has the unknown type 'XYZ\\x01' and is ignored"),
                  1);
    }
    // The same file with its 16 BIN bytes present imports (a library: no scenes, no error
    // about its layout)
    writeText(tmp.file("good.glb"), Glb{.binLength = 16, .binBytes = 16}.bytes(json));
    expectNoErrorContaining(tmp.file("good.glb"), "invalid binary glTF");
}

TEST(GltfHostile, EmptyBuffersAreLocatedErrors) {
    // byteLength 0 made tinygltf 2.7 throw std::out_of_range from a .glb (its message,
    // "vector::_M_range_check ...", was all the user saw); the schema's minimum is 1
    TempDir tmp;
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\n\"buffers\":[{\"byteLength\":16},{\"byteLength\":0}]}";
    writeText(tmp.file("empty.glb"), Glb{.binLength = 16, .binBytes = 16}.bytes(json));
    if (auto e = parseError(tmp.file("empty.glb"))) {
        EXPECT_NE(std::string(e->what()).find("buffers[1].byteLength is 0; a buffer holds at "
                                              "least 1 byte (JSON chunk of the binary glTF, "
                                              "its line 2, column 44)"),
                  std::string::npos)
            << e->what();
    }
    // In a .gltf at its line and column; a negative or fractional length too
    for (std::string length : {"0", "-3", "0.5", "0e9"}) {
        std::string text =
            "{\"asset\":{\"version\":\"2.0\"},\n \"buffers\":[{\"uri\":\"b.bin\", "
            "\"byteLength\":" +
            length + "}]}";
        writeText(tmp.file("empty.gltf"), text);
        if (auto e = parseError(tmp.file("empty.gltf"))) {
            EXPECT_NE(std::string(e->what()).find("buffers[0].byteLength is " + length + ";"),
                      std::string::npos)
                << e->what();
            EXPECT_EQ(e->loc().line, 2);
            EXPECT_EQ(e->loc().col, static_cast<int>(text.find(length, 30) - text.find('\n')));
        }
    }
    // Other numbers named byteLength (a bufferView's, an image's extras) are not a buffer's
    std::string view =
        "{\"asset\":{\"version\":\"2.0\"},\"bufferViews\":[{\"buffer\":0,"
        "\"byteLength\":0}],\"buffers\":[{\"uri\":\"b.bin\",\"byteLength\":4}]}";
    writeText(tmp.file("b.bin"), "abcd");
    writeText(tmp.file("view.gltf"), view);
    expectNoErrorContaining(tmp.file("view.gltf"), "a buffer holds at least");
}

TEST(GltfHostile, OneFileNamedByManyBuffersIsNotReadAgainAndAgain) {
    // 200 buffers naming one 256 KiB file would keep 50 MiB; reading stops past twice the
    // file's size plus 16 MiB
    TempDir tmp;
    writeText(tmp.file("one.bin"), std::string(256 << 10, '\0'));
    std::string json = R"({"asset":{"version":"2.0"},"buffers":[)";
    for (int i = 0; i < 200; ++i)
        json += std::string(i ? "," : "") + R"({"byteLength":262144,"uri":"one.bin"})";
    writeText(tmp.file("many.gltf"), json + "]}");
    if (auto e = parseError(tmp.file("many.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("more than twice the size of the files it names"),
                  std::string::npos)
            << e->what();
    }
    // Named twice is fine
    json = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[]}],"buffers":[)"
           R"({"byteLength":262144,"uri":"one.bin"},{"byteLength":262144,"uri":"one.bin"}]})";
    writeText(tmp.file("twice.gltf"), json);
    DiagnosticSink diag;
    EXPECT_NO_THROW(importGltf(tmp.file("twice.gltf"), diag));
}

TEST(GltfHostile, AccessorOfZerosIsBoundedByTheBuffers) {
    // No bufferView: glTF starts the accessor as zeros; 6e7 of them took 2.4 GB from 650 bytes
    TempDir tmp;
    std::string text =
        replaceOnce(triangleGltf(""), R"({"bufferView":0,"componentType":5126,"count":3,)",
                    R"({"componentType":5126,"count":60000000,)");
    writeText(tmp.file("zeros.gltf"), text);
    if (auto e = parseError(tmp.file("zeros.gltf"))) {
        EXPECT_NE(
            std::string(e->what()).find("count 60000000 without a bufferView is more than 65536"),
            std::string::npos)
            << e->what();
    }
}

TEST(GltfHostile, LongStringInInvalidJsonIsLocated) {
    // The error message quotes the bad token; a std::regex over it recursed per character and
    // overflowed the stack near 26,000 characters
    TempDir tmp;
    std::string text =
        "{\"asset\": {\"version\": \"2.0\"},\n \"x\": \"" + std::string(300000, 'a') + "\x01\"}";
    writeText(tmp.file("long.gltf"), text);
    if (auto e = parseError(tmp.file("long.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("invalid JSON"), std::string::npos);
        EXPECT_EQ(e->loc().line, 2);
    }
}

TEST(GltfHostile, DeepNestingIsLocatedBeforeParsing) {
    TempDir tmp;
    std::string text =
        "{\"asset\": {\"version\": \"2.0\"},\n \"extras\": " + std::string(1000000, '[');
    writeText(tmp.file("deep.gltf"), text);
    if (auto e = parseError(tmp.file("deep.gltf"))) {
        EXPECT_NE(std::string(e->what()).find("nested more than 512 levels"), std::string::npos)
            << e->what();
        EXPECT_EQ(e->loc().line, 2);
        EXPECT_EQ(e->loc().col, 12 + 511);  // the 513th level
    }
    // Just within the limit: tinygltf's recursive conversion of extras copes
    std::string ok =
        triangleGltf("", ",\"extras\":" + std::string(500, '[') + std::string(500, ']'));
    writeText(tmp.file("ok.gltf"), ok);
    DiagnosticSink diag;
    EXPECT_EQ(instancedTriangles(importGltf(tmp.file("ok.gltf"), diag)), 1u);
}

/// A PNG that is only a header declaring `width` x `height` RGBA pixels, padded to `size`.
std::vector<unsigned char> pngHeaderOnly(uint32_t width, uint32_t height, size_t size) {
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n',
                                      0,    0,   0,   13,  'I',  'H',  'D',  'R'};
    for (uint32_t v : {width, height})
        for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<unsigned char>(v >> s));
    for (unsigned char c : {8, 6, 0, 0, 0}) png.push_back(c);
    png.resize(std::max(size, png.size() + 4), 0);
    return png;
}

/// Imports a triangle whose base colour texture is `image`; returns the warnings.
std::string importWithTexture(const std::vector<unsigned char> &image,
                              const ImportOptions &opts = {}) {
    // metallicRoughnessTexture: decoded (for its mean) without texture coordinates
    std::string text =
        triangleGltf(R"({"pbrMetallicRoughness":{"metallicRoughnessTexture":{"index":0}}})",
                     R"(,"textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" +
                         base64Encode(image) + R"("}])");
    TempDir tmp;
    writeText(tmp.file("tex.gltf"), text);
    DiagnosticSink diag;
    ir::Scene scene = importGltf(tmp.file("tex.gltf"), diag, opts);
    EXPECT_EQ(instancedTriangles(scene), 1u);
    EXPECT_LE(scene.textures.size(), 1u);  // kept (for per-texel use) only when it decodes
    std::string warnings;
    for (const auto &d : diag.all())
        if (d.message.find("no TEXCOORD_0") == std::string::npos) warnings += d.message + "\n";
    return warnings;
}

TEST(GltfHostile, HugeTexturesAreIgnoredBeforeDecoding) {
    // 30000 x 30000 in 68 bytes: 3.6 GB if stb believed it
    std::string w = importWithTexture(pngHeaderOnly(30000, 30000, 68));
    EXPECT_NE(
        w.find(
            "cannot decode images[0] (image/png): PNG declares 30000 x 30000 pixels, a side longer "
            "than the limit of 16384 for a texture; texture ignored"),
        std::string::npos)
        << w;
    // 16384 x 16384: within the side limit, over the pixel limit
    w = importWithTexture(pngHeaderOnly(16384, 16384, 100));
    EXPECT_NE(w.find("more than the limit of 67108864 pixels"), std::string::npos) << w;
    // 8000 x 8000 RGBA (256 MB inflated) cannot come out of 100 bytes
    w = importWithTexture(pngHeaderOnly(8000, 8000, 100));
    EXPECT_NE(w.find("more than its 100 bytes can hold"), std::string::npos) << w;
    // The total over a model's textures (here with a limit of 3 pixels)
    ImportOptions opts;
    opts.maxTotalTexturePixels = 3;
    w = importWithTexture(bmp2x2(0, 0, 0, 0), opts);
    EXPECT_NE(w.find("its 2 x 2 pixels would bring the model's decoded texture pixels to 4, more "
                     "than the limit of 3"),
              std::string::npos)
        << w;
    EXPECT_EQ(importWithTexture(bmp2x2(0, 0, 0, 0)), "");
    // Neither PNG, JPEG nor BMP
    w = importWithTexture(std::vector<unsigned char>(64, 'G'));
    EXPECT_NE(w.find("is not a PNG, JPEG or BMP image"), std::string::npos) << w;
}

}  // namespace
}  // namespace rt::gltf::test
