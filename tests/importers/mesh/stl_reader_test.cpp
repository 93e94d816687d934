// SPDX-License-Identifier: MIT
// STL reader tests: binary vs ASCII detection, welding into closed solids, located errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "importers/mesh/mesh_reader.h"
#include "importers/mesh/mesh_test_support.h"

namespace rt::meshio::test {
namespace {

void expectClosedBox(const ir::Mesh &m, Vec3 lo, Vec3 hi) {
    EXPECT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(m.triangles.size(), 12u);
    ir::MeshTopology t = ir::analyzeMesh(m);
    EXPECT_TRUE(t.oriented()) << t.boundaryEdges << " boundary, " << t.nonManifoldEdges
                              << " non-manifold, " << t.misorientedEdges << " misoriented";
    EXPECT_EQ(t.degenerateTriangles, 0u);
    Vec3 d = hi - lo;
    EXPECT_NEAR(signedVolume(m), d.x * d.y * d.z, 1e-9);
    EXPECT_EQ(m.bounds().min, lo);
    EXPECT_EQ(m.bounds().max, hi);
    EXPECT_EQ(solidProblem(m), "");
}

TEST(StlReader, AsciiBoxIsWeldedIntoAClosedOrientedSolid) {
    std::string dir = testDir();
    std::string path = writeFile(dir + "/box.stl", asciiStl(boxTriangles({0, 0, 0}, {2, 3, 4})));
    DiagnosticSink diag;
    ir::Mesh m = readStl(path, diag);
    expectClosedBox(m, {0, 0, 0}, {2, 3, 4});
    EXPECT_EQ(m.name, "box.stl");
    EXPECT_EQ(m.loc.fileName(), path);
    EXPECT_TRUE(diag.all().empty());
}

TEST(StlReader, WeldingSharesTheCornersOfUnsharedTriangles) {
    // Control for the test above: STL stores every corner of every facet separately. The
    // topology analysis judges by position, so the raw soup is already closed; welding is
    // what turns 36 corners into 8 shared vertices (smaller meshes, smooth-normal friendly).
    ir::Mesh raw;
    for (const auto &t : boxTriangles({0, 0, 0}, {1, 1, 1})) {
        uint32_t base = static_cast<uint32_t>(raw.positions.size());
        for (const Vec3 &v : t) raw.positions.push_back(v);
        raw.triangles.push_back({base, base + 1, base + 2});
    }
    EXPECT_EQ(raw.positions.size(), 36u);
    EXPECT_TRUE(ir::analyzeMesh(raw).closed());
    EXPECT_EQ(weldMesh(raw), 0u);
    EXPECT_TRUE(ir::analyzeMesh(raw).closed());
    EXPECT_TRUE(ir::analyzeMesh(raw).oriented());
    EXPECT_EQ(raw.positions.size(), 8u);
    EXPECT_EQ(raw.triangles.size(), 12u);
}

TEST(StlReader, BinaryFileWhoseHeaderStartsWithSolidIsReadAsBinary) {
    std::string dir = testDir();
    // Text in the header, like many exporters write; only the size tells it is binary
    std::string header = "solid binary box written by a careless exporter";
    header.resize(80, ' ');
    std::string path =
        writeFile(dir + "/box.stl", binaryStl(boxTriangles({-1, -2, -3}, {1, 2, 3}), header));
    DiagnosticSink diag;
    ir::Mesh m = readStl(path, diag);
    expectClosedBox(m, {-1, -2, -3}, {1, 2, 3});
}

TEST(StlReader, AsciiIsCaseAndWhitespaceTolerantAndIgnoresFacetNormals) {
    std::string dir = testDir();
    // Mixed case, CRLF, tabs, a name with spaces, a normal pointing the wrong way and a NaN
    // normal (written by some exporters for slivers); vertex order alone decides orientation
    std::string text =
        "  SOLID my part 1\r\n"
        "FACET NORMAL 0 0 1\r\n\tOUTER   LOOP\r\n"
        "\t\tVERTEX 0 0 0\r\n\t\tvertex +1.0e+000 0 -0\r\n\t\tVertex 0 1 0\r\n"
        "\tENDLOOP\r\nENDFACET\r\n"
        "facet normal nan -nan NaN outer loop vertex 0 0 0 vertex 0 0 1 vertex 1 0 0 endloop "
        "endfacet\r\n"
        "facet outer loop vertex 0 0 0 vertex 0 1 0 vertex 0 0 1 endloop endfacet\n"
        "facet normal 1 1 1\n outer loop\n vertex 1 0 0\n vertex 0 0 1\n vertex 0 1 0\n"
        " endloop\n endfacet\n"
        "ENDSOLID my part 1\r\n";
    std::string path = writeFile(dir + "/tet.stl", text);
    DiagnosticSink diag;
    ir::Mesh m = readStl(path, diag);
    EXPECT_EQ(m.positions.size(), 4u);  // "-0" and "0" are the same point
    ASSERT_EQ(m.triangles.size(), 4u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    // Clockwise from outside as written: a closed solid turned inside out
    EXPECT_NEAR(signedVolume(m), -1.0 / 6, 1e-12);
    EXPECT_EQ(solidProblem(m), "is inside out (its enclosed volume is negative)");
}

TEST(StlReader, SeveralSolidsInOneAsciiFileAndSingleLineFiles) {
    std::string dir = testDir();
    std::string one = asciiStl(boxTriangles({0, 0, 0}, {1, 1, 1}));
    std::string two = asciiStl(boxTriangles({5, 0, 0}, {6, 1, 1}));
    for (char &c : two)
        if (c == '\n') c = ' ';
    std::string path = writeFile(dir + "/two.stl", one + two);
    DiagnosticSink diag;
    ir::Mesh m = readStl(path, diag);
    EXPECT_EQ(m.positions.size(), 16u);
    EXPECT_EQ(m.triangles.size(), 24u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_NEAR(signedVolume(m), 2.0, 1e-12);
}

TEST(StlReader, TruncatedBinaryFileIsAnErrorAtItsEnd) {
    std::string dir = testDir();
    auto tris = boxTriangles({0, 0, 0}, {1, 1, 1});
    std::string bytes = binaryStl(tris, "binary");
    bytes.resize(bytes.size() - 30);  // the last triangle loses 30 of its 50 bytes
    std::string path = writeFile(dir + "/cut.stl", bytes);
    DiagnosticSink diag;
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().fileName(), path);
    EXPECT_EQ(e.loc().line, 0);
    EXPECT_EQ(std::string(e.what()),
              "byte 654: binary STL is truncated: the header promises 12 triangles (684 bytes) "
              "but the file ends after 654 bytes");
}

TEST(StlReader, BinaryCountThatDoesNotMatchTheSizeIsAnError) {
    std::string dir = testDir();
    auto tris = boxTriangles({0, 0, 0}, {1, 1, 1});
    std::string path = writeFile(dir + "/count.stl", binaryStl(tris, "solid x", 11));
    DiagnosticSink diag;
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(std::string(e.what()),
              "byte 634: binary STL triangle count does not match the file size: the header "
              "promises 11 triangles (634 bytes) but the file has 684 bytes");
    // Shorter than the header itself
    std::string tiny = writeFile(dir + "/tiny.stl", std::string("\0\1\2", 3));
    e = parseErrorOf([&] { readStl(tiny, diag); });
    EXPECT_NE(std::string(e.what()).find("byte 3: binary STL is truncated"), std::string::npos)
        << e.what();
}

TEST(StlReader, BinaryNonFiniteCoordinateIsAnErrorAtItsByte) {
    std::string dir = testDir();
    auto tris = boxTriangles({0, 0, 0}, {1, 1, 1});
    tris[2][1].y = std::numeric_limits<double>::quiet_NaN();
    std::string path = writeFile(dir + "/nan.stl", binaryStl(tris, "nan"));
    DiagnosticSink diag;
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    // Triangle 2 starts at 84 + 100; its second vertex's y follows the normal and 4 floats
    EXPECT_EQ(std::string(e.what()).substr(0, 45), "byte 212: triangle 2, vertex 2: coordinate na");
    EXPECT_NE(std::string(e.what()).find("is not finite"), std::string::npos);
}

TEST(StlReader, AsciiSyntaxErrorIsReportedAtLineAndColumn) {
    std::string dir = testDir();
    std::string text =
        "solid s\n"
        "facet normal 0 0 1\n"
        "  outer loop\n"
        "    vertex 0 0 0\n"
        "    vertex 1 0 0\n"
        "    vertext 0 1 0\n"
        "  endloop\n"
        "endfacet\n"
        "endsolid s\n";
    std::string path = writeFile(dir + "/bad.stl", text);
    DiagnosticSink diag;
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":6:5");
    EXPECT_EQ(std::string(e.what()), "unexpected 'vertext': expected 'vertex'");
}

TEST(StlReader, NanCoordinateIsAnError) {
    std::string dir = testDir();
    std::string text = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 nan 0\n";
    std::string path = writeFile(dir + "/nan.stl", text);
    DiagnosticSink diag;
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":5:10");
    EXPECT_EQ(std::string(e.what()), "vertex coordinate 'nan' is not finite");
    // Overflow to infinity is not finite either
    writeFile(path, "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 1e999\n");
    e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":4:12");
}

TEST(StlReader, BadNumbersAndPrematureEndAreLocated) {
    std::string dir = testDir();
    std::string path = dir + "/bad.stl";
    DiagnosticSink diag;
    writeFile(path, "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 1,5 0\n");
    ParseError e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":4:10");
    EXPECT_EQ(std::string(e.what()), "bad number '1,5'");

    writeFile(path, "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n  vertex 1");
    e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":5:11");
    EXPECT_EQ(std::string(e.what()), "unexpected end of file: expected a number");

    writeFile(path, asciiStl(boxTriangles({0, 0, 0}, {1, 1, 1})) + "junk\n");
    e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(std::string(e.what()), "unexpected 'junk': expected 'solid' or the end of the file");

    writeFile(path, "hello world\n");
    e = parseErrorOf([&] { readStl(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":1:1");
}

TEST(StlReader, FileWithoutTrianglesIsAnEmptyMesh) {
    // OpenSCAD imports all three as empty geometry, without a message
    std::string dir = testDir();
    DiagnosticSink diag;
    std::string ascii = writeFile(dir + "/empty.stl", "solid empty\nendsolid empty\n");
    std::string binary = writeFile(dir + "/empty_bin.stl", binaryStl({}, "solid empty"));
    std::string nothing = writeFile(dir + "/nothing.stl", "");
    for (const auto &path : {ascii, binary, nothing}) {
        ir::Mesh m = readStl(path, diag);
        EXPECT_TRUE(m.triangles.empty()) << path;
        EXPECT_TRUE(m.positions.empty()) << path;
    }
    EXPECT_TRUE(diag.all().empty());
    ParseError e = parseErrorOf([&] { readStl(dir + "/missing.stl", diag); });
    EXPECT_NE(std::string(e.what()).find("can't open file"), std::string::npos);
}

TEST(StlReader, DegenerateTrianglesAreLeftOutWithANote) {
    std::string dir = testDir();
    auto tris = boxTriangles({0, 0, 0}, {1, 1, 1});
    tris.push_back({Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 1)});
    std::string path = writeFile(dir + "/sliver.stl", binaryStl(tris, "x"));
    DiagnosticSink diag;
    ir::Mesh m = readStl(path, diag);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(diag.countContaining("1 degenerate triangle(s)"), 1);
}

TEST(StlReader, ReadMeshFileDispatchesOnTheExtensionInAnyCase) {
    std::string dir = testDir();
    std::string path =
        writeFile(dir + "/BOX.STL", binaryStl(boxTriangles({0, 0, 0}, {1, 1, 1}), "x"));
    DiagnosticSink diag;
    EXPECT_EQ(readMeshFile(path, diag).triangles.size(), 12u);
    ParseError e = parseErrorOf([&] { readMeshFile(dir + "/box.obj", diag); });
    EXPECT_NE(std::string(e.what()).find("unknown mesh file type '.obj'"), std::string::npos);
}

TEST(StlReader, OpenScadExampleFilesAreClosedSolids) {
    // OpenSCAD's own examples: an ASCII file and a binary one whose header starts "COLOR="
    const std::string dir = "/usr/share/openscad/examples/Old/";
    if (!fs::exists(dir + "example012.stl") || !fs::exists(dir + "example016.stl"))
        GTEST_SKIP() << "OpenSCAD's examples are not installed";
    DiagnosticSink diag;
    for (const char *name : {"example012.stl", "example016.stl"}) {
        ir::Mesh m = readStl(dir + name, diag);
        EXPECT_GT(m.triangles.size(), 10u) << name;
        EXPECT_EQ(solidProblem(m), "") << name;
        EXPECT_GT(signedVolume(m), 0) << name;
    }
}

}  // namespace
}  // namespace rt::meshio::test
