// SPDX-License-Identifier: MIT
// import(): STL/OFF/glTF paths relative to the calling file, errors, skipped formats, one mesh
// per file, materials; and a cross-check of the mesh readers on OpenSCAD's own exports.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>

#include "core/ir/scene_defaults.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/mesh/mesh_test_support.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

using meshio::test::asciiStl;
using meshio::test::binaryStl;
using meshio::test::boxTriangles;
using meshio::test::testDir;
using meshio::test::writeFile;
namespace fs = std::filesystem;

const char *const kUnitCubeOff =
    "OFF 8 6 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n0 1 0\n1 1 0\n1 0 0\n0 0 0\n"
    "4 0 1 2 3\n4 4 5 6 7\n4 7 6 1 0\n4 6 5 2 1\n4 5 4 3 2\n4 4 7 0 3\n";

const ir::Mesh &meshOf(const ir::Scene &s, const ir::Node &n) {
    return *s.meshes.at(std::get<ir::MeshPrim>(n.shape).mesh);
}

Imported importFile(const std::string &path) {
    Imported r;
    r.scene = importScad(path, r.diag);
    return r;
}

/// The EvalError (or ParseError) an import throws; fails the test when it throws none.
template <typename E>
E errorOf(const std::string &path) {
    DiagnosticSink diag;
    try {
        importScad(path, diag);
    } catch (const E &e) {
        return e;
    }
    ADD_FAILURE() << "no error from " << path;
    return E(SourceLoc(), "");
}

TEST(Import, StlAndOffRelativeToTheFileHoldingTheCall) {
    std::string dir = testDir();
    fs::create_directories(dir + "/models");
    fs::create_directories(dir + "/lib");
    writeFile(dir + "/models/box.stl", asciiStl(boxTriangles({0, 0, 0}, {2, 2, 2})));
    writeFile(dir + "/models/cube.OFF", kUnitCubeOff);
    // A used library and an included file import next to themselves, not next to main.scad
    writeFile(dir + "/lib/part.scad", "module part() import(\"part.stl\");\n");
    writeFile(dir + "/lib/part.stl", binaryStl(boxTriangles({0, 0, 0}, {1, 2, 3}), "solid part"));
    writeFile(dir + "/lib/inc.scad", "import(file = \"inc.off\");\n");
    writeFile(dir + "/lib/inc.off", kUnitCubeOff);
    std::string main =
        writeFile(dir + "/main.scad",
                  "use <lib/part.scad>\n"
                  "import(\"models/box.stl\");\n"
                  "translate([5, 0, 0]) import(\"models/cube.OFF\", convexity = 3);\n"
                  "part();\n"
                  "include <lib/inc.scad>\n");
    Imported r = importFile(main);
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().at(0);
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 4u);
    ASSERT_EQ(r.scene.meshes.size(), 4u);
    EXPECT_EQ(meshOf(r.scene, *p[0].node).bounds().max, Vec3(2, 2, 2));
    EXPECT_EQ(meshOf(r.scene, *p[1].node).bounds().max, Vec3(1, 1, 1));
    EXPECT_EQ(p[1].worldFromObject, Mat4::translate(Vec3(5, 0, 0)));
    EXPECT_EQ(meshOf(r.scene, *p[2].node).bounds().max, Vec3(1, 2, 3));
    EXPECT_EQ(meshOf(r.scene, *p[3].node).name, "inc.off");
    for (const auto &pp : p) {
        const ir::Mesh &m = meshOf(r.scene, *pp.node);
        EXPECT_TRUE(ir::analyzeMesh(m).oriented()) << m.name;
        EXPECT_GT(meshio::signedVolume(m), 0) << m.name;
    }
    // Each node is located at its call; the included file's call in the included file
    EXPECT_EQ(p[0].node->loc.line, 2);
    EXPECT_EQ(p[2].node->loc.fileName(), dir + "/lib/part.scad");
    EXPECT_EQ(p[3].node->loc.fileName(), dir + "/lib/inc.scad");
}

TEST(Import, MissingFileIsAnErrorAtTheCall) {
    std::string dir = testDir();
    std::string main = writeFile(dir + "/main.scad", "cube();\n  import(\"nope.stl\");\n");
    EvalError e = errorOf<EvalError>(main);
    EXPECT_EQ(e.loc().fileName(), main);
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 3);
    EXPECT_EQ(std::string(e.what()),
              "import(): can't open file 'nope.stl' (" + dir + "/nope.stl): no such file");
    // A folder is not a mesh file either
    fs::create_directories(dir + "/dir.stl");
    writeFile(main, "import(\"dir.stl\");");
    e = errorOf<EvalError>(main);
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos);
}

TEST(Import, NoFileIsEmptyGeometryWithAWarning) {
    // OpenSCAD: "Unsupported file format while trying to import file ''", then goes on; the
    // empty node stays a difference()'s minuend
    for (const char *call :
         {"import()", "import(file = undef)", "import(\"\")", "import(5)", "import(\"noext\")"}) {
        Imported r = importText(std::string("difference() {\n  ") + call + "; cube(); }");
        ASSERT_EQ(r.warnings().size(), 1u) << call;
        Diagnostic w = r.warning("unsupported file format");
        EXPECT_EQ(w.loc.line, 2) << call;
        EXPECT_EQ(r.scene.stats.skippedModules, 0) << call;
        const ir::Node &diff = *r.scene.root->children.at(0);
        ASSERT_EQ(diff.children.size(), 2u) << call;
        EXPECT_EQ(diff.children[0]->kind, ir::NodeKind::Group) << call;
        EXPECT_TRUE(diff.children[0]->children.empty()) << call;
    }
    EXPECT_EQ(importText("import(5);").warning("unsupported").message,
              "import(): unsupported file format while trying to import file '5'; empty geometry");
}

TEST(Import, StlWithoutTrianglesIsSilentEmptyGeometry) {
    std::string dir = testDir();
    writeFile(dir + "/empty.stl", "solid empty\nendsolid empty\n");
    writeFile(dir + "/empty_bin.stl", std::string(80, '\0') + std::string(4, '\0'));
    std::string main = writeFile(dir + "/main.scad",
                                 "difference() { import(\"empty.stl\"); cube(); }\n"
                                 "import(\"empty_bin.stl\"); import(\"empty.stl\");\n");
    Imported r = importFile(main);
    EXPECT_TRUE(r.diag.all().empty());
    EXPECT_TRUE(r.scene.meshes.empty());
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);  // the cube
    ASSERT_EQ(r.scene.root->children.size(), 3u);
    const ir::Node &diff = *r.scene.root->children[0];
    ASSERT_EQ(diff.children.size(), 2u);
    EXPECT_TRUE(diff.children[0]->children.empty());
}

TEST(Import, ReaderErrorsAreLocatedInTheMeshFile) {
    std::string dir = testDir();
    std::string stl = writeFile(dir + "/bad.stl", "solid s\nfacet normal 0 0 1\n  outer lop\n");
    std::string main = writeFile(dir + "/main.scad", "import(\"bad.stl\");\n");
    ParseError e = errorOf<ParseError>(main);
    EXPECT_EQ(e.loc().toString(), stl + ":3:9");
    EXPECT_EQ(std::string(e.what()), "unexpected 'lop': expected 'loop'");
}

TEST(Import, OtherFormatsWarnAndAreSkipped) {
    // (.dxf and .svg are read: dxf_test.cpp, svg_test.cpp)
    for (const char *ext : {"amf", "3mf", "csg", "png", "nef3"}) {
        std::string lower = ext;
        for (char &c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        // The file need not exist: the format decides first
        Imported r =
            importText(std::string("difference() {\n  import(\"part.") + ext + "\"); cube(); }");
        EXPECT_EQ(r.scene.stats.skippedModules, 1) << ext;
        Diagnostic w = r.warning("not supported");
        EXPECT_EQ(w.message, "import of ." + lower + " files is not supported yet; skipped");
        EXPECT_EQ(w.loc.line, 2);
        EXPECT_EQ(w.loc.col, 3);
        const ir::Node &diff = *r.scene.root->children.at(0);
        ASSERT_EQ(diff.children.size(), 2u);
        EXPECT_EQ(diff.children[0]->kind, ir::NodeKind::Group);
        EXPECT_TRUE(diff.children[0]->children.empty());
    }
}

TEST(Import, SameFileTwiceSharesOneMeshWithItsOwnNodesAndMaterials) {
    std::string dir = testDir();
    writeFile(dir + "/box.stl", asciiStl(boxTriangles({0, 0, 0}, {1, 1, 1})));
    std::string main = writeFile(dir + "/main.scad",
                                 "import(\"box.stl\");\n"
                                 "translate([3, 0, 0]) color(\"blue\") import(\"box.stl\");\n"
                                 "import(\"./sub/../box.stl\");\n"
                                 "color(\"red\") cube();\n");
    fs::create_directories(dir + "/sub");
    Imported r = importFile(main);
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 4u);
    EXPECT_EQ(r.scene.meshes.size(), 1u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(std::get<ir::MeshPrim>(p[i].node->shape).mesh, 0) << i;
        EXPECT_EQ(p[i].node->loc.line, i + 1);
    }
    EXPECT_EQ(r.scene.materials.at(p[0].node->material).color, ir::kOpenScadDefaultColor);
    EXPECT_EQ(r.scene.materials.at(p[1].node->material).color, Rgb(0, 0, 1));
    EXPECT_EQ(p[2].node->material, p[0].node->material);
    EXPECT_NE(p[3].node->material, p[1].node->material);
}

TEST(Import, MaterialAndColourApplyAsToOtherPrimitives) {
    std::string dir = testDir();
    writeFile(dir + "/box.off", kUnitCubeOff);
    Imported r = importText(
        "use <scadray.scad>\n"
        "material(reflection = 0.5, ior = 1.5) {\n"
        "  import(\"box.off\");\n"
        "  color(\"lime\", 0.25) import(\"box.off\");\n"
        "  sphere();\n"
        "}\n",
        dir + "/main.scad");
    EXPECT_TRUE(r.warnings().empty()) << r.warnings().at(0);
    auto p = primitives(*r.scene.root);
    ASSERT_EQ(p.size(), 3u);
    const ir::Material &a = r.scene.materials.at(p[0].node->material);
    const ir::Material &b = r.scene.materials.at(p[1].node->material);
    EXPECT_EQ(a.finish.reflectionMax, Rgb(0.5));
    EXPECT_EQ(a.interior.ior, 1.5);
    EXPECT_EQ(p[2].node->material, p[0].node->material);
    EXPECT_EQ(b.color, Rgb(0, 1, 0));
    EXPECT_NEAR(b.transmit, 0.75, 1e-12);
    EXPECT_EQ(b.finish.reflectionMax, Rgb(0.5));
}

TEST(Import, DeprecatedSpellingsAndDocumentRootFallback) {
    std::string dir = testDir();
    fs::create_directories(dir + "/lib");
    writeFile(dir + "/top.stl", binaryStl(boxTriangles({0, 0, 0}, {1, 1, 1}), "x"));
    writeFile(dir + "/lib/m.scad", "module m() import(\"top.stl\");\n");
    std::string main = writeFile(dir + "/main.scad",
                                 "use <lib/m.scad>\nm();\n"
                                 "import(filename = \"top.stl\", layername = \"x\");\n");
    Imported r = importFile(main);
    EXPECT_EQ(r.scene.root->primitiveCount(), 2u);
    EXPECT_EQ(r.scene.meshes.size(), 1u);
    Diagnostic w = r.warning("document root");
    EXPECT_EQ(w.message,
              "DEPRECATED: Imported file (top.stl) found in document root instead of relative "
              "to the importing module. This behavior is deprecated");
    EXPECT_EQ(w.loc.fileName(), dir + "/lib/m.scad");
    EXPECT_TRUE(r.hasWarning("DEPRECATED: filename= is deprecated. Please use file="));
    EXPECT_TRUE(r.hasWarning("DEPRECATED: layername= is deprecated. Please use layer="));
    EXPECT_EQ(r.warnings().size(), 3u);
}

TEST(Import, OldModuleNamesImportWithOpenScadsDeprecation) {
    // 2021.01 still reads import_stl(), import_off() and import_dxf(), with a warning each
    std::string dir = testDir();
    writeFile(dir + "/a.stl", binaryStl(boxTriangles({0, 0, 0}, {1, 1, 1}), "x"));
    writeFile(dir + "/b.off", kUnitCubeOff);
    writeFile(dir + "/c.dxf",
              "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\n0\n90\n3\n70\n1\n"
              "10\n0\n20\n0\n10\n2\n20\n0\n10\n0\n20\n2\n0\nENDSEC\n0\nEOF\n");
    std::string main = writeFile(dir + "/main.scad",
                                 "import_stl(\"a.stl\");\nimport_off(\"b.off\");\n"
                                 "linear_extrude(1) import_dxf(\"c.dxf\");\n");
    Imported r = importFile(main);
    EXPECT_EQ(r.scene.root->primitiveCount(), 3u);
    for (const char *name : {"import_stl", "import_off", "import_dxf"})
        EXPECT_TRUE(r.hasWarning(std::string("DEPRECATED: The ") + name +
                                 "() module will be removed in future releases. Use import() "
                                 "instead."))
            << name;
    EXPECT_EQ(r.warnings().size(), 3u) << r.warnings().at(0);
}

TEST(Import, OpenMeshesWarnAndBackgroundImportsAreNotRead) {
    std::string dir = testDir();
    auto tris = boxTriangles({0, 0, 0}, {1, 1, 1});
    tris.pop_back();
    writeFile(dir + "/open.stl", asciiStl(tris));
    // Not even parsed under `%`, but it must exist
    writeFile(dir + "/broken.stl", "not an stl");
    Imported r = importText("import(\"open.stl\");\n%import(\"broken.stl\");", dir + "/main.scad");
    EXPECT_EQ(r.scene.meshes.size(), 1u);
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
    Diagnostic w = r.warning("not closed");
    EXPECT_EQ(w.message, "import(): the mesh of '" + dir +
                             "/open.stl' is not closed (3 edges belong to one triangle only, 0 to "
                             "more than two); it may not render as a solid");
    EXPECT_EQ(w.loc.line, 1);
    EXPECT_THROW(importText("%import(\"missing.stl\");", dir + "/main.scad"), EvalError);
    // Triangles clockwise from outside: closed, but inside out
    auto inverted = boxTriangles({0, 0, 0}, {1, 1, 1});
    for (auto &t : inverted) std::swap(t[1], t[2]);
    writeFile(dir + "/inverted.stl", binaryStl(inverted, "x"));
    Imported inv = importText("import(\"inverted.stl\");", dir + "/main.scad");
    EXPECT_TRUE(inv.hasWarning("inverted.stl' is inside out (its enclosed volume is negative)"));
}

TEST(Import, GltfFilesGoThroughTheGltfImporter) {
    std::string box = std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/khronos/Box.gltf";
    ASSERT_TRUE(fs::exists(box)) << box << " is missing from the checkout";
    std::string src = "import(\"" + box + "\");\ncolor(\"red\") import(\"" + box +
                      "\");\nimport(\"" + box + "\");\n";
    Imported r = importText(src);
    ASSERT_EQ(r.scene.root->children.size(), 3u);
    size_t meshesAfterOne = r.scene.meshes.size();
    EXPECT_GE(meshesAfterOne, 1u);
    std::vector<PlacedPrimitive> plain, red, again;
    collectPrimitives(*r.scene.root->children[0], Mat4(), plain);
    collectPrimitives(*r.scene.root->children[1], Mat4(), red);
    collectPrimitives(*r.scene.root->children[2], Mat4(), again);
    ASSERT_FALSE(plain.empty());
    ASSERT_EQ(red.size(), plain.size());
    ASSERT_EQ(again.size(), plain.size());
    for (size_t i = 0; i < plain.size(); ++i) {
        // The same meshes, placed the same way, located at each call
        EXPECT_EQ(std::get<ir::MeshPrim>(red[i].node->shape).mesh,
                  std::get<ir::MeshPrim>(plain[i].node->shape).mesh);
        EXPECT_EQ(red[i].worldFromObject, plain[i].worldFromObject);
        EXPECT_EQ(red[i].node->loc.line, 2);
        EXPECT_EQ(again[i].node->loc.line, 3);
        EXPECT_EQ(again[i].node->material, plain[i].node->material);
        EXPECT_EQ(r.scene.materials.at(red[i].node->material).color, Rgb(1, 0, 0));
        EXPECT_NE(r.scene.materials.at(plain[i].node->material).color, Rgb(1, 0, 0));
    }
}

// ---------------------------------------------------------------------------------------------
// Cross-check with the installed OpenSCAD 2021.01

bool haveOpenScad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

/// Runs `openscad [extra] -o out in`; true on success.
bool exportWithOpenScad(const std::string &in, const std::string &out, const std::string &extra) {
    std::string cmd = "openscad " + extra + " -o '" + out + "' '" + in + "' >/dev/null 2>&1";
    int status = std::system(cmd.c_str());
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

bool nearRel(double a, double b) {
    return std::abs(a - b) <= 1e-6 * std::max({1.0, std::abs(a), std::abs(b)});
}

/// Sum of the triangles' unsigned areas: triangles that fold over each other (a fan across a
/// concave polygon) add area that signed volume and topology do not show.
double surfaceArea(const ir::Mesh &m) {
    double sum = 0;
    for (const auto &t : m.triangles)
        sum += length(cross(m.positions[t[1]] - m.positions[t[0]],
                            m.positions[t[2]] - m.positions[t[0]])) /
               2;
    return sum;
}

struct ExportCase {
    const char *name;
    const char *scad;
    double volume;
    Vec3 lo, hi;
};

TEST(OpenScadCrossCheck, ExportedStlAndOffReadBackAsTheSameSolid) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const ExportCase cases[] = {
        {"difference",
         "difference() { cube(10, center = true); cube([5, 5, 20], center = true); }",
         1000 - 250,
         {-5, -5, -5},
         {5, 5, 5}},
        {"tetrahedron",
         "polyhedron([[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]],\n"
         "  [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]]);",
         1000.0 / 6,
         {0, 0, 0},
         {10, 10, 10}},
        // OpenSCAD writes the concave pentagons into the OFF file as they are
        {"prism",
         "p = [[0,0],[4,0],[4,4],[2,1],[0,4]];\n"
         "polyhedron(concat(p, [for (q = p) [q.x, q.y, 2]]),\n"
         "  concat([[0,1,2,3,4], [9,8,7,6,5]], [for (i = [0:4]) [i, i + 5, (i + 1) % 5 + 5, "
         "(i + 1) % 5]]));",
         20,
         {0, 0, 0},
         {4, 4, 2}},
        {"union",
         "union() { cube([3, 2, 1]); translate([1, 1, 0]) cube([1, 1, 4]); }",
         9,
         {0, 0, 0},
         {3, 2, 4}},
    };
    std::string dir = testDir();
    for (const auto &c : cases) {
        SCOPED_TRACE(c.name);
        std::string base = dir + "/" + c.name;
        std::string scad = writeFile(base + ".scad", c.scad);
        ASSERT_TRUE(exportWithOpenScad(scad, base + ".stl", ""));
        ASSERT_TRUE(exportWithOpenScad(scad, base + "_bin.stl", "--export-format binstl"));
        ASSERT_TRUE(exportWithOpenScad(scad, base + ".off", ""));
        DiagnosticSink diag;
        std::vector<ir::Mesh> meshes;
        meshes.push_back(meshio::readMeshFile(base + ".stl", diag));
        meshes.push_back(meshio::readMeshFile(base + "_bin.stl", diag));
        meshes.push_back(meshio::readMeshFile(base + ".off", diag));
        // And the same files through import(), next to our own evaluation of the scene
        Imported viaImport = importText(
            "import(\"" + base + ".stl\"); import(\"" + base + ".off\");", base + "_import.scad");
        for (const auto &pp : primitives(*viaImport.scene.root))
            meshes.push_back(meshOf(viaImport.scene, *pp.node));
        Imported ours = importFile(scad);
        auto ownPrims = primitives(*ours.scene.root);
        bool ownMesh =
            ownPrims.size() == 1 && std::holds_alternative<ir::MeshPrim>(ownPrims[0].node->shape);
        if (ownMesh) meshes.push_back(meshOf(ours.scene, *ownPrims[0].node));
        ASSERT_EQ(meshes.size(), ownMesh ? 6u : 5u);

        const ir::Mesh &ref = meshes[0];
        double volume = meshio::signedVolume(ref);
        Bounds3 bounds = ref.bounds();
        for (int i = 0; i < 3; ++i) {
            EXPECT_TRUE(nearRel(bounds.min[i], c.lo[i])) << bounds.min[i];
            EXPECT_TRUE(nearRel(bounds.max[i], c.hi[i])) << bounds.max[i];
        }
        EXPECT_TRUE(nearRel(volume, c.volume)) << volume << " vs " << c.volume;
        for (size_t k = 0; k < meshes.size(); ++k) {
            const ir::Mesh &m = meshes[k];
            SCOPED_TRACE("mesh " + std::to_string(k) + " " + m.name);
            ir::MeshTopology t = ir::analyzeMesh(m);
            EXPECT_TRUE(t.oriented())
                << t.boundaryEdges << " " << t.nonManifoldEdges << " " << t.misorientedEdges;
            EXPECT_EQ(meshio::solidProblem(m), "");
            double v = meshio::signedVolume(m);
            EXPECT_TRUE(nearRel(v, volume)) << v << " vs " << volume;
            EXPECT_TRUE(nearRel(surfaceArea(m), surfaceArea(ref)))
                << surfaceArea(m) << " vs " << surfaceArea(ref);
            Bounds3 b = m.bounds();
            for (int i = 0; i < 3; ++i) {
                EXPECT_TRUE(nearRel(b.min[i], bounds.min[i])) << b.min[i] << " " << bounds.min[i];
                EXPECT_TRUE(nearRel(b.max[i], bounds.max[i])) << b.max[i] << " " << bounds.max[i];
            }
        }
        EXPECT_EQ(viaImport.diag.count(Severity::Warning), 0);
    }
}

}  // namespace
}  // namespace rt::scad::test
