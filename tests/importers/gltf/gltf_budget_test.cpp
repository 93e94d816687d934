// SPDX-License-Identifier: MIT
// A glTF mesh whose primitives repeat one another (the same accessors, indices, mode and
// material) draws each surface once: 500,000 copies of a triangle in one place would cost
// every ray that reaches it 500,000 tests.
#include <gtest/gtest.h>

#include <string>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "gltf_test_support.h"
#include "importers/gltf/gltf_importer.h"

namespace rt::gltf {
namespace {

using test::TempDir;
using test::writeText;

/// A glTF file of one node whose mesh lists `primitives`, separated by commas, over one
/// triangle (accessor 0) and one material.
std::string triangleFile(const std::string &primitives) {
    // Three VEC3 floats: (0,0,0), (1,0,0), (0,1,0), little-endian, base64
    const std::string data = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1]}}],)"
           R"("meshes":[{"primitives":[)" +
           primitives +
           R"(]}],"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" +
           data +
           R"("}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}]})";
}

size_t countPrimitives(const ir::Node &n) {
    size_t count = n.kind == ir::NodeKind::Primitive ? 1 : 0;
    for (const auto &c : n.children) count += countPrimitives(*c);
    return count;
}

TEST(GltfBudget, RepeatedPrimitivesArePlacedOnce) {
    TempDir dir;
    std::string primitives;
    const size_t copies = 500'000;
    primitives.reserve(copies * 32);
    for (size_t i = 0; i < copies; ++i)
        primitives += std::string(i ? "," : "") + R"({"attributes":{"POSITION":0}})";
    std::string path = dir.file("copies.gltf");
    writeText(path, triangleFile(primitives));
    DiagnosticSink diag;
    ir::Scene scene = importGltf(path, diag);
    EXPECT_EQ(countPrimitives(*scene.root), 1u);
    EXPECT_EQ(scene.meshes.size(), 1u);
    int warnings = 0;
    for (const auto &d : diag.all())
        if (d.severity == Severity::Warning && d.message.find("repeating") != std::string::npos) {
            ++warnings;
            EXPECT_NE(d.message.find("499999 primitive(s)"), std::string::npos) << d.message;
        }
    EXPECT_EQ(warnings, 1);
}

TEST(GltfBudget, PrimitivesThatDifferAreAllKept) {
    // Another material, or other indices, makes another surface: nothing is dropped
    TempDir dir;
    std::string path = dir.file("two.gltf");
    writeText(path, triangleFile(R"({"attributes":{"POSITION":0}},)"
                                 R"({"attributes":{"POSITION":0},"material":0})"));
    DiagnosticSink diag;
    ir::Scene scene = importGltf(path, diag);
    EXPECT_EQ(countPrimitives(*scene.root), 2u);
    for (const auto &d : diag.all()) EXPECT_EQ(d.message.find("repeating"), std::string::npos);
}

}  // namespace
}  // namespace rt::gltf
