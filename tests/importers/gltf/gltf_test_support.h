// SPDX-License-Identifier: MIT
// Helpers for the glTF importer tests: the Khronos sample models, temp files and the IR tree.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "core/ir/scene_ir.h"
#include "importers/gltf/gltf_importer.h"

namespace rt::gltf::test {

/// The Khronos glTF sample models, kept in the repository with their licences
/// (tests/data/gltf/khronos/README.md).
inline std::string samplesDir() {
    return std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/khronos";
}

inline std::string sample(const std::string &name) { return samplesDir() + "/" + name; }

/// A model made for scadray's tests by a script beside it in tests/data/gltf/.
inline std::string testModel(const std::string &name) {
    return std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/" + name;
}

/// Fails the calling test when a sample model is missing: they are part of the checkout, so a
/// missing one is a broken tree, never a reason to skip.
#define REQUIRE_GLTF_SAMPLE(name)                                            \
    do {                                                                     \
        ASSERT_TRUE(std::filesystem::exists(::rt::gltf::test::sample(name))) \
            << "glTF sample " << ::rt::gltf::test::sample(name)              \
            << " is missing from the checkout (tests/data/gltf/khronos)";    \
    } while (0)

inline std::vector<unsigned char> readBytes(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<unsigned char>((std::istreambuf_iterator<char>(in)),
                                      std::istreambuf_iterator<char>());
}

inline std::string readText(const std::string &path) {
    std::vector<unsigned char> b = readBytes(path);
    return std::string(b.begin(), b.end());
}

inline void writeBytes(const std::string &path, const void *data, size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char *>(data), static_cast<std::streamsize>(size));
}

inline void writeText(const std::string &path, const std::string &text) {
    writeBytes(path, text.data(), text.size());
}

/// A fresh folder under the system temp directory, removed with the object.
class TempDir {
  public:
    TempDir() {
        const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("scadray_gltf_") + (info ? info->name() : "test") + "_" +
                           std::to_string(reinterpret_cast<uintptr_t>(this) & 0xffffff);
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::string file(const std::string &name) const { return (path_ / name).string(); }

  private:
    std::filesystem::path path_;
};

/// A .glb built to order: `json` padded with spaces to 4 bytes, then a BIN chunk declaring
/// `binLength` bytes with `binBytes` zero bytes after its header (none when both are 0 and
/// `emptyBin` is not set). Zeros in `version`, `length` and `jsonLength` stand for the true
/// values.
struct Glb {
    uint32_t version = 2, length = 0, jsonLength = 0, binLength = 0;
    size_t binBytes = 0;
    bool emptyBin = false;
    std::string bytes(std::string json) const {
        auto u32 = [](std::string &out, uint32_t v) {
            out.append(reinterpret_cast<const char *>(&v), 4);
        };
        while (json.size() % 4) json += ' ';
        bool bin = binLength || binBytes || emptyBin;
        size_t size = 20 + json.size() + (bin ? 8 + binBytes : 0);
        std::string out = "glTF";
        u32(out, version ? version : 2);
        u32(out, length ? length : static_cast<uint32_t>(size));
        u32(out, jsonLength ? jsonLength : static_cast<uint32_t>(json.size()));
        u32(out, 0x4E4F534Au);
        out += json;
        if (bin) {
            u32(out, binLength);
            u32(out, 0x004E4942u);
            out += std::string(binBytes, '\0');
        }
        return out;
    }
};

/// Replaces the one occurrence of `from` in `text` (fails the test if it is not there once).
inline std::string replaceOnce(std::string text, const std::string &from, const std::string &to) {
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not found";
    if (at == std::string::npos) return text;
    EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' found twice";
    return text.replace(at, from.size(), to);
}

inline std::vector<unsigned char> base64Decode(const std::string &s) {
    auto value = [](char c) -> int {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    };
    std::vector<unsigned char> out;
    unsigned bits = 0;
    int n = 0;
    for (char c : s) {
        int v = value(c);
        if (v < 0) continue;
        bits = (bits << 6) | static_cast<unsigned>(v);
        n += 6;
        if (n >= 8) {
            n -= 8;
            out.push_back(static_cast<unsigned char>((bits >> n) & 0xff));
        }
    }
    return out;
}

inline std::string base64Encode(const std::vector<unsigned char> &data) {
    static const char *digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        unsigned v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        for (int k = 3; k >= 0; --k) out += digits[(v >> (6 * k)) & 63];
    }
    size_t rest = data.size() - i;
    if (rest > 0) {
        unsigned v = data[i] << 16;
        if (rest == 2) v |= data[i + 1] << 8;
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += rest == 2 ? digits[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

/// A w x h 32-bit BMP (with alpha), pixel(x, y) = 0xRRGGBBAA, y = 0 the top row.
inline std::vector<unsigned char> bmp32(int w, int h,
                                        const std::function<uint32_t(int, int)> &pixel) {
    std::vector<unsigned char> b = {'B', 'M'};
    auto u32 = [&](uint32_t v) {
        for (int i = 0; i < 4; ++i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
    };
    auto u16 = [&](uint16_t v) {
        b.push_back(static_cast<unsigned char>(v));
        b.push_back(static_cast<unsigned char>(v >> 8));
    };
    uint32_t size = static_cast<uint32_t>(w * h * 4);
    u32(14 + 40 + size);
    u32(0);
    u32(14 + 40);
    u32(40);
    u32(static_cast<uint32_t>(w));
    u32(static_cast<uint32_t>(h));  // bottom row first
    u16(1);
    u16(32);
    u32(0);
    u32(size);
    u32(2835);
    u32(2835);
    u32(0);
    u32(0);
    for (int y = h - 1; y >= 0; --y)
        for (int x = 0; x < w; ++x) {
            uint32_t p = pixel(x, y);
            b.push_back(static_cast<unsigned char>(p >> 8));   // B
            b.push_back(static_cast<unsigned char>(p >> 16));  // G
            b.push_back(static_cast<unsigned char>(p >> 24));  // R
            b.push_back(static_cast<unsigned char>(p));        // A
        }
    return b;
}

/// A 2x2 opaque BMP, pixels given top row first as 0xRRGGBB.
inline std::vector<unsigned char> bmp2x2(uint32_t tl, uint32_t tr, uint32_t bl, uint32_t br) {
    const uint32_t px[2][2] = {{tl, tr}, {bl, br}};
    return bmp32(2, 2, [&](int x, int y) { return px[y][x] << 8 | 0xff; });
}

/// Binary data for a generated glTF, kept 4-byte aligned.
struct TestBuffer {
    std::vector<unsigned char> bytes;

    /// Appends raw values and returns their byte offset.
    template <typename T>
    size_t add(const std::vector<T> &values) {
        while (bytes.size() % 4 != 0) bytes.push_back(0);
        size_t offset = bytes.size();
        const auto *p = reinterpret_cast<const unsigned char *>(values.data());
        bytes.insert(bytes.end(), p, p + values.size() * sizeof(T));
        return offset;
    }
    std::string json() const {
        return "{\"byteLength\":" + std::to_string(bytes.size()) +
               ",\"uri\":\"data:application/octet-stream;base64," + base64Encode(bytes) + "\"}";
    }
};

/// A bufferView of buffer 0.
inline std::string viewJson(size_t offset, size_t length, size_t stride = 0) {
    return "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
           ",\"byteLength\":" + std::to_string(length) +
           (stride ? ",\"byteStride\":" + std::to_string(stride) : std::string()) + "}";
}

/// A glTF with one node showing one mesh with one primitive, over the data of `buf`.
inline std::string meshGltf(const std::string &primitive, const TestBuffer &buf,
                            const std::string &bufferViews, const std::string &accessors) {
    return R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[)" +
           primitive + "]}],\"buffers\":[" + buf.json() + "],\"bufferViews\":[" + bufferViews +
           "],\"accessors\":[" + accessors + "]}";
}

/// A one-triangle glTF ((0,0,0), (1,0,0), (0,1,0), no normals) with the given material JSON
/// ("" for none) and extra top-level members (",\"extensionsUsed\":[...]").
inline std::string triangleGltf(const std::string &material, const std::string &extra = "") {
    TestBuffer buf;
    buf.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
    std::string prim = "{\"attributes\":{\"POSITION\":0}" +
                       std::string(material.empty() ? "" : ",\"material\":0") + "}";
    return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
           "\"nodes\":[{\"mesh\":0,\"name\":\"tri\"}],\"meshes\":[{\"primitives\":[" +
           prim + "]}]," + (material.empty() ? "" : "\"materials\":[" + material + "],") +
           "\"buffers\":[" + buf.json() +
           "],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
           "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
           "\"type\":\"VEC3\"}]" +
           extra + "}";
}

/// One placed primitive of the IR tree.
struct Instance {
    Mat4 world;
    int mesh = -1;
    int material = -1;
    std::string label;  ///< label of the nearest labelled ancestor transform
};

inline void collectInstances(const ir::Node &node, const Mat4 &parent, const std::string &label,
                             std::vector<Instance> &out) {
    Mat4 m = node.kind == ir::NodeKind::Transform ? parent * node.matrix : parent;
    std::string l =
        node.kind == ir::NodeKind::Transform && !node.label.empty() ? node.label : label;
    if (node.kind == ir::NodeKind::Primitive) {
        if (const auto *mp = std::get_if<ir::MeshPrim>(&node.shape))
            out.push_back({m, mp->mesh, node.material, l});
    }
    for (const auto &c : node.children) collectInstances(*c, m, l, out);
}

inline std::vector<Instance> instances(const ir::Scene &scene) {
    std::vector<Instance> out;
    collectInstances(*scene.root, Mat4(), "", out);
    return out;
}

inline size_t instancedTriangles(const ir::Scene &scene) {
    size_t n = 0;
    for (const Instance &i : instances(scene))
        n += scene.meshes[static_cast<size_t>(i.mesh)]->triangles.size();
    return n;
}

/// World-space vertices of every instance whose label is `label`.
inline std::vector<Vec3> worldVertices(const ir::Scene &scene, const std::string &label) {
    std::vector<Vec3> out;
    for (const Instance &i : instances(scene))
        if (i.label == label)
            for (const Vec3 &p : scene.meshes[static_cast<size_t>(i.mesh)]->positions)
                out.push_back(i.world.transformPoint(p));
    return out;
}

inline void expectNear(const Vec3 &a, const Vec3 &b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol) << a.toString() << " vs " << b.toString();
    EXPECT_NEAR(a.y, b.y, tol) << a.toString() << " vs " << b.toString();
    EXPECT_NEAR(a.z, b.z, tol) << a.toString() << " vs " << b.toString();
}

/// glTF (x, y, z) in the importer's Z-up world: (x, -z, y).
inline Vec3 zUp(const Vec3 &p) { return Vec3(p.x, -p.z, p.y); }

}  // namespace rt::gltf::test
