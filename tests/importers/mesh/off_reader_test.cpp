// SPDX-License-Identifier: MIT
// OFF reader tests: header variants, polygons (quads, a concave pentagon), located errors.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "importers/mesh/mesh_reader.h"
#include "importers/mesh/mesh_test_support.h"
#include "importers/mesh/reader_support.h"

namespace rt::meshio::test {
namespace {

/// The unit cube as OpenSCAD 2021.01 exports it (`openscad -o cube.off` of `cube(1);`).
const char *const kCubeVertices = "0 0 1\n1 0 1\n1 1 1\n0 1 1\n0 1 0\n1 1 0\n1 0 0\n0 0 0\n";
const char *const kCubeFaces = "4 0 1 2 3\n4 4 5 6 7\n4 7 6 1 0\n4 6 5 2 1\n4 5 4 3 2\n4 4 7 0 3\n";

void expectUnitCube(const ir::Mesh &m) {
    EXPECT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(m.triangles.size(), 12u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_NEAR(signedVolume(m), 1.0, 1e-12);
    EXPECT_EQ(m.bounds().min, Vec3(0, 0, 0));
    EXPECT_EQ(m.bounds().max, Vec3(1, 1, 1));
}

ir::Mesh readText(const std::string &text, DiagnosticSink &diag, const std::string &name = "m") {
    std::string path = writeFile(testDir() + "/" + name + ".off", text);
    return readOff(path, diag);
}

TEST(OffReader, OpenScadCubeWithQuadsIsAClosedOrientedSolid) {
    DiagnosticSink diag;
    expectUnitCube(readText(std::string("OFF 8 6 0\n") + kCubeVertices + kCubeFaces, diag));
    EXPECT_TRUE(diag.all().empty());
}

TEST(OffReader, ConcavePentagonPrismIsTriangulatedKeepingOrientation) {
    // Caps: the pentagon (0,0) (4,0) (4,4) (2,1) (0,4), concave at (2,1), area 10. A fan from
    // the first corner would put a clockwise triangle outside the polygon.
    std::string off =
        "OFF\n10 7 0\n"
        "0 0 0\n4 0 0\n4 4 0\n2 1 0\n0 4 0\n"
        "0 0 2\n4 0 2\n4 4 2\n2 1 2\n0 4 2\n"
        "5 4 3 2 1 0\n"
        "5 5 6 7 8 9\n"
        "4 0 1 6 5\n4 1 2 7 6\n4 2 3 8 7\n4 3 4 9 8\n4 4 0 5 9\n";
    DiagnosticSink diag;
    ir::Mesh m = readText(off, diag);
    EXPECT_EQ(m.positions.size(), 10u);
    EXPECT_EQ(m.triangles.size(), 3u + 3u + 5u * 2u);
    EXPECT_TRUE(ir::analyzeMesh(m).oriented());
    EXPECT_EQ(ir::analyzeMesh(m).degenerateTriangles, 0u);
    EXPECT_NEAR(signedVolume(m), 20.0, 1e-12);
    // Every triangle of the top cap faces up, every one of the bottom cap faces down
    for (const auto &t : m.triangles) {
        Vec3 n =
            cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
        double z = m.positions[t[0]].z;
        if (z == m.positions[t[1]].z && z == m.positions[t[2]].z) {
            EXPECT_GT(z == 2 ? n.z : -n.z, 0);
        }
    }
}

TEST(OffReader, HeaderVariantsCommentsAndColoursAreAccepted) {
    DiagnosticSink diag;
    // Comments, counts on their own line, colours after vertices and faces
    expectUnitCube(readText(std::string("# made by hand\nOFF # the keyword\n\n8 6 12 # counts\n") +
                                kCubeVertices +
                                "4 0 1 2 3 255 0 0\n4 4 5 6 7 0.5 0.5 0.5 1\n"
                                "4 7 6 1 0\n4 6 5 2 1\n4 5 4 3 2\n4 4 7 0 3\n",
                            diag, "comments"));
    // COFF: RGBA per vertex
    std::string coff = "COFF\n8 6 0\n";
    for (const char *v : {"0 0 1", "1 0 1", "1 1 1", "0 1 1", "0 1 0", "1 1 0", "1 0 0", "0 0 0"})
        coff += std::string(v) + " 0.1 0.2 0.3 1\n";
    expectUnitCube(readText(coff + kCubeFaces, diag, "coff"));
    // NOFF: normals; CNOFF: colours and normals; STOFF: texture coordinates
    expectUnitCube(readText(std::string("NOFF\n8 6 0\n") +
                                "0 0 1 0 0 1\n1 0 1 0 0 1\n1 1 1 0 0 1\n0 1 1 0 0 1\n"
                                "0 1 0 0 0 -1\n1 1 0 0 0 -1\n1 0 0 0 0 -1\n0 0 0 0 0 -1\n" +
                                kCubeFaces,
                            diag, "noff"));
    // Edge count left out; the counts on the keyword's line
    expectUnitCube(readText(std::string("STCNOFF 8 6\n") + kCubeVertices + kCubeFaces, diag, "st"));
    // 4OFF: homogeneous coordinates are divided by w
    expectUnitCube(readText(std::string("4OFF\n8 6 0\n") +
                                "0 0 2 2\n2 0 2 2\n1 1 1 1\n0 3 3 3\n0 1 0 1\n1 1 0 1\n"
                                "0.5 0 0 0.5\n0 0 0 1\n" +
                                kCubeFaces,
                            diag, "4off"));
    // nOFF with dimension 3
    expectUnitCube(
        readText(std::string("nOFF 3\n8 6 0\n") + kCubeVertices + kCubeFaces, diag, "noff3"));
    EXPECT_TRUE(diag.all().empty());
}

TEST(OffReader, OutOfRangeIndexIsAnErrorAtItsColumn) {
    DiagnosticSink diag;
    std::string path = writeFile(testDir() + "/range.off",
                                 std::string("OFF\n8 6 0\n") + kCubeVertices +
                                     "4 0 1 2 3\n4 4 5 6 7\n4 7 6 1 0\n4 6 5 2 1\n4 5 4 3 2\n"
                                     "4 4 7  8 3\n");
    ParseError e = parseErrorOf([&] { readOff(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":16:8");
    EXPECT_EQ(std::string(e.what()), "vertex index 8 is out of range (the file has 8 vertices)");
}

TEST(OffReader, MalformedFilesAreLocatedErrors) {
    DiagnosticSink diag;
    std::string path = testDir() + "/bad.off";
    auto errorOf = [&](const std::string &text) {
        writeFile(path, text);
        return parseErrorOf([&] { readOff(path, diag); });
    };
    // The keyword is case-sensitive, as in CGAL (which OpenSCAD uses)
    ParseError e = errorOf("off\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(e.loc().toString(), path + ":1:1");
    EXPECT_NE(std::string(e.what()).find("unexpected 'off': expected an OFF header"),
              std::string::npos);

    e = errorOf("OFF BINARY\n");
    EXPECT_EQ(e.loc().toString(), path + ":1:5");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n");
    EXPECT_EQ(e.loc().toString(), path + ":6:6");
    EXPECT_EQ(std::string(e.what()), "face 0: expected 3 vertex indices, found 2");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n");
    EXPECT_EQ(e.loc().toString(), path + ":6:1");
    EXPECT_EQ(std::string(e.what()), "face 0 has 2 vertices; a face needs at least 3");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(e.loc().toString(), path + ":4:3");
    EXPECT_EQ(std::string(e.what()), "vertex coordinate 'nan' is not finite");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(e.loc().toString(), path + ":4:4");
    EXPECT_EQ(std::string(e.what()), "vertex 1: expected a z coordinate on this line");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(std::string(e.what()), "bad number 'x'");

    e = errorOf("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    EXPECT_EQ(e.loc().toString(), path + ":7:1");
    EXPECT_EQ(std::string(e.what()), "unexpected end of file: expected face 1");

    e = errorOf("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n");
    EXPECT_EQ(std::string(e.what()), "bad vertex index '-2'");

    e = errorOf("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    EXPECT_EQ(std::string(e.what()), "OFF file holds no faces");

    e = errorOf("");
    EXPECT_EQ(std::string(e.what()), "empty file: expected 'OFF'");
}

TEST(OffReader, CountsTheFileCannotHoldAreRefusedBeforeAllocating) {
    // 4e9 vertices must not be reserved at once (that ends in an unlocated "out of memory")
    DiagnosticSink diag;
    std::string path = testDir() + "/huge.off";
    writeFile(path, "OFF\n4000000000 1 0\n0 0 0\n");
    ParseError e = parseErrorOf([&] { readOff(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":2:1");
    EXPECT_EQ(std::string(e.what()),
              "the header promises 4000000000 vertices and 1 faces, more than a file of 25 bytes "
              "can hold");
    writeFile(path, "OFF 3 99999999999999 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    e = parseErrorOf([&] { readOff(path, diag); });
    EXPECT_EQ(e.loc().toString(), path + ":1:5");
    // The smallest file holding its counts is still read
    writeFile(path, "OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2");
    EXPECT_EQ(readOff(path, diag).triangles.size(), 1u);
}

TEST(OffReader, FifosFoldersAndHugeFilesAreRefusedWithoutReading) {
    DiagnosticSink diag;
    std::string dir = testDir();
    std::string fifo = dir + "/pipe.off";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(
        std::string(parseErrorOf([&] { readOff(fifo, diag); }).what()).find("not a regular file"),
        std::string::npos);
    fs::create_directories(dir + "/folder.stl");
    EXPECT_NE(std::string(parseErrorOf([&] { readStl(dir + "/folder.stl", diag); }).what())
                  .find("not a regular file (a directory)"),
              std::string::npos);
    std::string big = writeFile(dir + "/big.stl", "");
    ASSERT_EQ(truncate(big.c_str(), static_cast<off_t>(detail::kMaxMeshFileBytes + 1)), 0);
    EXPECT_NE(std::string(parseErrorOf([&] { readStl(big, diag); }).what()).find("is too large"),
              std::string::npos);
}

TEST(OffReader, DegenerateFacesAndTrailingTextWarn) {
    DiagnosticSink diag;
    std::string text = std::string("OFF\n9 8 0\n") + kCubeVertices + "5 5 5\n" + kCubeFaces +
                       "3 0 0 1\n4 8 8 8 8\nextra words\n";
    ir::Mesh m = readText(text, diag);
    expectUnitCube(m);  // the unused ninth vertex is dropped too
    ASSERT_EQ(diag.count(Severity::Warning), 3);
    EXPECT_EQ(diag.all()[0].message,
              "face 6 is degenerate (fewer than 3 distinct points or no area); skipped");
    EXPECT_EQ(diag.all()[0].loc.line, 18);
    EXPECT_EQ(diag.all()[2].message, "text after the 8 faces the header announces; ignored");
    EXPECT_EQ(diag.all()[2].loc.line, 20);
}

}  // namespace
}  // namespace rt::meshio::test
