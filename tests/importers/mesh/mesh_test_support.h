// SPDX-License-Identifier: MIT
// Header-only helpers of the mesh reader tests: temporary files, STL writers, error capture.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/mesh.h"
#include "core/math/vec3.h"

namespace rt::meshio::test {

namespace fs = std::filesystem;

using Triangle = std::array<Vec3, 3>;

/// A fresh folder for the running test.
inline std::string testDir() {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path p = fs::temp_directory_path() / ("scadray_meshio_" + std::to_string(getpid())) /
                 (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

inline std::string writeFile(const std::string &path, const std::string &bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    return path;
}

/// The 12 triangles of the box [lo, hi], counter-clockwise seen from outside, each with its
/// own copies of the corners (as STL stores them).
inline std::vector<Triangle> boxTriangles(Vec3 lo, Vec3 hi) {
    auto c = [&](int i) {
        return Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    // Quads as corner numbers (bit 0 = x, bit 1 = y, bit 2 = z), CCW from outside
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    std::vector<Triangle> out;
    for (const auto &q : quads) {
        out.push_back({c(q[0]), c(q[1]), c(q[2])});
        out.push_back({c(q[0]), c(q[2]), c(q[3])});
    }
    return out;
}

/// ASCII STL text; `normal` is written for every facet (the readers must ignore it).
inline std::string asciiStl(const std::vector<Triangle> &tris,
                            const std::string &normal = "0 0 0") {
    std::string s = "solid test\n";
    for (const auto &t : tris) {
        s += "  facet normal " + normal + "\n    outer loop\n";
        for (const Vec3 &v : t)
            s += "      vertex " + std::to_string(v.x) + " " + std::to_string(v.y) + " " +
                 std::to_string(v.z) + "\n";
        s += "    endloop\n  endfacet\n";
    }
    return s + "endsolid test\n";
}

inline void appendLe32(std::string &s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s += static_cast<char>((v >> (8 * i)) & 0xff);
}

inline void appendFloat(std::string &s, float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    appendLe32(s, bits);
}

/// Binary STL bytes: `header` padded to 80 bytes with NULs, the count (`count` < 0: the number
/// of triangles), then the triangles with zero normals and attributes.
inline std::string binaryStl(const std::vector<Triangle> &tris, const std::string &header,
                             int64_t count = -1) {
    std::string s = header.substr(0, 80);
    s.resize(80, '\0');
    appendLe32(s, static_cast<uint32_t>(count < 0 ? static_cast<int64_t>(tris.size()) : count));
    for (const auto &t : tris) {
        for (int i = 0; i < 3; ++i) appendFloat(s, 0.0f);
        for (const Vec3 &v : t) {
            appendFloat(s, static_cast<float>(v.x));
            appendFloat(s, static_cast<float>(v.y));
            appendFloat(s, static_cast<float>(v.z));
        }
        s += std::string(2, '\0');
    }
    return s;
}

/// The message and location of the ParseError `fn` throws (fails the test if none).
template <typename Fn>
ParseError parseErrorOf(Fn &&fn) {
    try {
        fn();
    } catch (const ParseError &e) {
        return e;
    }
    ADD_FAILURE() << "no ParseError thrown";
    return ParseError(SourceLoc(), "");
}

}  // namespace rt::meshio::test
