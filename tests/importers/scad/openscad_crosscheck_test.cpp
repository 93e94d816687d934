// SPDX-License-Identifier: MIT
// Cross-checks against the installed OpenSCAD 2021.01 binary: echo output of language probes,
// and the IR of .scad files against the IR of OpenSCAD's own .csg export of them.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/meshing/facets.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

bool haveOpenScad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

#define REQUIRE_OPENSCAD()                                                                   \
    do {                                                                                     \
        if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped"; \
    } while (0)

struct RunResult {
    int exitCode = -1;
    std::string stderrText;
};

/// Runs `openscad -o out in` (with extra environment) and captures stderr.
RunResult runOpenScad(const std::string &in, const std::string &out, const std::string &env = "") {
    std::string errFile = out + ".stderr";
    std::string cmd =
        env + " openscad -o '" + out + "' '" + in + "' 2>'" + errFile + "' >/dev/null";
    RunResult r;
    int status = std::system(cmd.c_str());
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream e(errFile);
    std::stringstream ss;
    ss << e.rdbuf();
    r.stderrText = ss.str();
    return r;
}

std::string tempDir() {
    fs::path p = fs::temp_directory_path() / ("scadray_xcheck_" + std::to_string(getpid()));
    fs::create_directories(p);
    return p.string();
}

std::vector<std::string> echoLines(const std::string &file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("ECHO: ", 0) == 0) out.push_back(line.substr(6));
    return out;
}

std::vector<fs::path> filesIn(const std::string &dir) {
    std::vector<fs::path> out;
    for (const auto &e : fs::directory_iterator(dir))
        if (e.path().extension() == ".scad") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

/// Compares the echo lines of OpenSCAD and of our importer for one file.
void expectSameEchoes(const fs::path &f, const std::string &tmp) {
    SCOPED_TRACE(f.string());
    std::string out = tmp + "/" + f.stem().string() + ".echo";
    RunResult r = runOpenScad(f.string(), out);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    std::vector<std::string> expected = echoLines(out);
    DiagnosticSink diag;
    importScad(f.string(), diag);
    std::vector<std::string> ours;
    for (const auto &d : diag.all())
        if (d.message.rfind("ECHO: ", 0) == 0) ours.push_back(d.message.substr(6));
    ASSERT_EQ(ours.size(), expected.size());
    for (size_t i = 0; i < ours.size(); ++i) EXPECT_EQ(ours[i], expected[i]) << "echo #" << i;
}

TEST(OpenScadCrossCheck, EchoOutputMatches) {
    REQUIRE_OPENSCAD();
    std::string tmp = tempDir();
    auto files = filesIn(dataDir() + "/echo");
    ASSERT_GE(files.size(), 8u);
    for (const auto &f : files) expectSameEchoes(f, tmp);
}

/// OpenSCAD's installed example files that do not need uninstalled libraries (MCAD).
std::vector<fs::path> installedExamples() {
    std::vector<fs::path> out;
    const std::string examples = "/usr/share/openscad/examples";
    if (!fs::is_directory(examples)) return out;
    for (const auto &dir : fs::directory_iterator(examples)) {
        if (!dir.is_directory()) continue;
        for (const auto &f : filesIn(dir.path().string())) {
            std::ifstream in(f);
            std::stringstream text;
            text << in.rdbuf();
            if (text.str().find("MCAD/") == std::string::npos) out.push_back(f);
        }
    }
    return out;
}

TEST(OpenScadCrossCheck, InstalledExamplesEchoTheSame) {
    REQUIRE_OPENSCAD();
    auto files = installedExamples();
    if (files.empty()) GTEST_SKIP() << "OpenSCAD's examples are not installed";
    std::string tmp = tempDir() + "/examples_echo";
    fs::create_directories(tmp);
    for (const auto &f : files) expectSameEchoes(f, tmp);
    EXPECT_GE(files.size(), 40u);
}

/// A node of the canonical form: groups with children are spliced into their parent, empty
/// groups stay (they are real operands, e.g. a difference()'s minuend); primitives carry their
/// world matrix and resolved material.
struct Canon {
    ir::NodeKind kind;
    Mat4 world;
    /// 1 + the sum of the largest entries of the transforms above: the .csg rounds each
    /// matrix to 6 digits, so world entries carry that much absolute error (cancelling
    /// translations can leave 1e-5 next to 0).
    double magnitude;
    const ir::Node *node;
    bool highlight;
    std::vector<Canon> children;
};

void canonicalize(const ir::Node &n, const Mat4 &parentWorld, std::vector<Canon> &out,
                  double magnitude = 1) {
    Mat4 world = parentWorld;
    if (n.kind == ir::NodeKind::Transform) {
        world = parentWorld * n.matrix;
        double largest = 0;
        for (const auto &row : n.matrix.m)
            for (double e : row) largest = std::max(largest, std::fabs(e));
        magnitude += largest;
    }
    std::vector<Canon> kids;
    for (const auto &c : n.children) canonicalize(*c, world, kids, magnitude);
    bool splice = (n.kind == ir::NodeKind::Group || n.kind == ir::NodeKind::Transform) &&
                  !n.children.empty() && !n.highlight;
    if (splice) {
        for (auto &k : kids) out.push_back(std::move(k));
        return;
    }
    ir::NodeKind kind = n.kind == ir::NodeKind::Transform ? ir::NodeKind::Group : n.kind;
    out.push_back({kind, world, magnitude, &n, n.highlight, std::move(kids)});
}

bool near(double a, double b, double relative = 1e-5) {
    return std::fabs(a - b) <= relative * std::max({1.0, std::fabs(a), std::fabs(b)});
}

/// The .csg rounds linear_extrude's twist to 6 digits (411.429 for 411.4286): the top of a
/// twisted mesh turns by up to 1e-5 degrees per degree of twist less or more.
constexpr double kTwistedMeshTolerance = 1e-3;

void expectSameShape(const ir::PrimShape &a, const ir::PrimShape &b, const std::string &where) {
    ASSERT_EQ(a.index(), b.index()) << where;
    if (auto *s = std::get_if<ir::SpherePrim>(&a)) {
        EXPECT_TRUE(near(s->radius, std::get<ir::SpherePrim>(b).radius)) << where;
    } else if (auto *x = std::get_if<ir::BoxPrim>(&a)) {
        const auto &y = std::get<ir::BoxPrim>(b);
        for (int i = 0; i < 3; ++i) {
            EXPECT_TRUE(near(x->min[i], y.min[i])) << where;
            EXPECT_TRUE(near(x->max[i], y.max[i])) << where;
        }
    } else if (auto *c = std::get_if<ir::CylinderPrim>(&a)) {
        const auto &d = std::get<ir::CylinderPrim>(b);
        EXPECT_TRUE(near(c->z0, d.z0) && near(c->z1, d.z1) && near(c->r1, d.r1) &&
                    near(c->r2, d.r2))
            << where;
    } else if (auto *p = std::get_if<ir::PrismPrim>(&a)) {
        const auto &q = std::get<ir::PrismPrim>(b);
        EXPECT_TRUE(near(p->z0, q.z0) && near(p->z1, q.z1) && near(p->k0, q.k0) &&
                    near(p->k1, q.k1))
            << where;
        EXPECT_EQ(p->mesh < 0, q.mesh < 0) << where;
        ASSERT_EQ(p->outline.size(), q.outline.size()) << where;
        // Outlines computed from 3D geometry (projection()) carry the .csg's 6-digit rounding
        // of the matrices above them, relative to the geometry's extent, plus Clipper's grid
        double extent = 1;
        for (const auto &pt : p->outline)
            extent = std::max({extent, std::fabs(pt.x), std::fabs(pt.y)});
        double tolerance = 4e-6 * extent + 2.0 / 65536;
        auto close = [&](double u, double v) {
            return near(u, v) || std::fabs(u - v) <= tolerance;
        };
        for (size_t i = 0; i < p->outline.size(); ++i)
            EXPECT_TRUE(close(p->outline[i].x, q.outline[i].x) &&
                        close(p->outline[i].y, q.outline[i].y))
                << where << " outline point " << i << ": " << p->outline[i].x << ", "
                << p->outline[i].y << " vs " << q.outline[i].x << ", " << q.outline[i].y;
    }
}

/// Meshes (polyhedron(), import()) agree in size, bounds and volume: the .csg export rounds
/// polyhedron points to 6 digits.
void expectSameMesh(const ir::Mesh &a, const ir::Mesh &b, const std::string &where) {
    EXPECT_EQ(a.triangles.size(), b.triangles.size()) << where;
    double tol = a.name == "linear_extrude" ? kTwistedMeshTolerance : 1e-5;
    Bounds3 ba = a.bounds(), bb = b.bounds();
    for (int i = 0; i < 3; ++i)
        EXPECT_TRUE(near(ba.min[i], bb.min[i], tol) && near(ba.max[i], bb.max[i], tol)) << where;
    EXPECT_TRUE(near(meshio::signedVolume(a), meshio::signedVolume(b), tol)) << where;
}

void expectSameTree(const Canon &a, const ir::Scene &sa, const Canon &b, const ir::Scene &sb,
                    const std::string &path) {
    std::string where =
        path + " (" + a.node->loc.toString() + " vs " + b.node->loc.toString() + ")";
    ASSERT_EQ(static_cast<int>(a.kind), static_cast<int>(b.kind)) << where;
    ASSERT_EQ(a.children.size(), b.children.size()) << where;
    EXPECT_EQ(a.highlight, b.highlight) << where;
    if (a.kind == ir::NodeKind::Primitive) {
        double tolerance = 1e-5 * std::max(a.magnitude, b.magnitude);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                EXPECT_NEAR(a.world.m[i][j], b.world.m[i][j],
                            tolerance * std::max(1.0, std::fabs(a.world.m[i][j])))
                    << where << " matrix[" << i << "][" << j << "] " << a.world.m[i][j] << " vs "
                    << b.world.m[i][j];
        expectSameShape(a.node->shape, b.node->shape, where);
        if (auto *ma = std::get_if<ir::MeshPrim>(&a.node->shape))
            expectSameMesh(*sa.meshes.at(ma->mesh),
                           *sb.meshes.at(std::get<ir::MeshPrim>(b.node->shape).mesh), where);
        if (auto *pa = std::get_if<ir::PrismPrim>(&a.node->shape); pa && pa->mesh >= 0)
            expectSameMesh(*sa.meshes.at(pa->mesh),
                           *sb.meshes.at(std::get<ir::PrismPrim>(b.node->shape).mesh), where);
        // The .csg records $fn/$fa/$fs for round primitives only
        if (!std::holds_alternative<ir::BoxPrim>(a.node->shape)) {
            EXPECT_TRUE(near(a.node->fragments.fn, b.node->fragments.fn)) << where;
            EXPECT_TRUE(near(a.node->fragments.fa, b.node->fragments.fa)) << where;
            EXPECT_TRUE(near(a.node->fragments.fs, b.node->fragments.fs)) << where;
        }
        const ir::Material &ma = sa.materials.at(a.node->material);
        const ir::Material &mb = sb.materials.at(b.node->material);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(ma.color[c], mb.color[c], 1 / 255.0) << where << " colour";
        EXPECT_NEAR(ma.transmit, mb.transmit, 1 / 255.0) << where << " transmit";
    }
    for (size_t i = 0; i < a.children.size(); ++i)
        expectSameTree(a.children[i], sa, b.children[i], sb, path + "/" + std::to_string(i));
}

/// Imports `scad` and OpenSCAD's .csg export of it and compares the two IRs.
void crossCheckFile(const fs::path &scad, const std::string &tmp) {
    SCOPED_TRACE(scad.string());
    std::string csg = tmp + "/" + scad.stem().string() + ".csg";
    RunResult r = runOpenScad(scad.string(), csg);
    ASSERT_EQ(r.exitCode, 0) << r.stderrText;
    // The .csg keeps import()'s relative file names: give it the files next to the .scad
    for (const auto &e : fs::directory_iterator(scad.parent_path()))
        if (e.is_regular_file() && e.path().extension() != ".scad" &&
            !fs::exists(fs::path(tmp) / e.path().filename()))
            fs::copy_file(e.path(), fs::path(tmp) / e.path().filename());
    DiagnosticSink d1, d2;
    ir::Scene original = importScad(scad.string(), d1);
    ir::Scene exported = importScad(csg, d2);
    std::vector<Canon> a, b;
    for (const auto &c : original.root->children) canonicalize(*c, Mat4(), a);
    for (const auto &c : exported.root->children) canonicalize(*c, Mat4(), b);
    EXPECT_EQ(original.root->primitiveCount(), exported.root->primitiveCount());
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i)
        expectSameTree(a[i], original, b[i], exported, "root/" + std::to_string(i));
}

TEST(OpenScadCrossCheck, IrMatchesIrOfOpenScadCsgExport) {
    REQUIRE_OPENSCAD();
    std::string tmp = tempDir();
    auto files = filesIn(dataDir() + "/csg");
    ASSERT_GE(files.size(), 5u);
    size_t primitivesChecked = 0;
    for (const auto &f : files) {
        crossCheckFile(f, tmp);
        DiagnosticSink diag;
        primitivesChecked += importScad(f.string(), diag).root->primitiveCount();
    }
    EXPECT_GT(primitivesChecked, 100u);
}

TEST(OpenScadCrossCheck, InstalledExamplesMatchTheirCsgExport) {
    REQUIRE_OPENSCAD();
    // Modules we skip are skipped on both sides alike
    auto files = installedExamples();
    if (files.empty()) GTEST_SKIP() << "OpenSCAD's examples are not installed";
    std::string tmp = tempDir() + "/examples_csg";
    fs::create_directories(tmp);
    for (const auto &f : files) crossCheckFile(f, tmp);
    EXPECT_GE(files.size(), 40u);
}

}  // namespace
}  // namespace rt::scad::test

namespace rt::scad::test {
namespace {

TEST(OpenScadCrossCheck, MetadataLibraryIsCleanOpenScad) {
    REQUIRE_OPENSCAD();
    // Every metadata module with every parameter named: OpenSCAD must accept it silently
    std::string tmp = tempDir();
    std::string env = "OPENSCADPATH='" + std::string(SCADRAY_SOURCE_DIR) + "/scenes'";
    RunResult r = runOpenScad(dataDir() + "/metadata_scene.scad", tmp + "/metadata.csg", env);
    EXPECT_EQ(r.exitCode, 0) << r.stderrText;
    EXPECT_EQ(r.stderrText.find("WARNING"), std::string::npos) << r.stderrText;
    EXPECT_EQ(r.stderrText.find("ERROR"), std::string::npos) << r.stderrText;
    // And the export still holds the geometry under material()
    std::ifstream csg(tmp + "/metadata.csg");
    std::stringstream ss;
    ss << csg.rdbuf();
    EXPECT_NE(ss.str().find("sphere("), std::string::npos);
}

}  // namespace
}  // namespace rt::scad::test

namespace rt::scad::test {
namespace {

std::string readAll(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

size_t countLinesStartingWith(const std::string &text, const std::string &prefix) {
    size_t n = 0;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) ++n;
    return n;
}

/// A snippet for both programs: whether they accept it, what it echoes, how many DEPRECATED
/// messages it gives, and (when set) a message each must give about it.
struct Probe {
    std::string src;
    const char *openscadSays = nullptr;  ///< in OpenSCAD's .echo output
    const char *weSay = nullptr;         ///< in one of our warnings
};

void expectSameVerdict(const Probe &p, const std::string &tmp, int index) {
    SCOPED_TRACE(p.src);
    std::string scad = tmp + "/probe" + std::to_string(index) + ".scad";
    std::ofstream(scad, std::ios::binary) << p.src;
    RunResult r = runOpenScad(scad, scad + ".echo");
    std::string theirs = readAll(scad + ".echo");
    bool theyAccept = theirs.find("Parser error") == std::string::npos;
    EXPECT_EQ(r.exitCode == 0, theyAccept) << theirs << r.stderrText;
    Imported ours;
    bool weAccept = true;
    try {
        ours.scene = importScadSource(p.src, scad, ours.diag);
    } catch (const ParseError &) {
        weAccept = false;
    }
    ASSERT_EQ(weAccept, theyAccept) << theirs;
    if (!theyAccept) return;
    EXPECT_EQ(ours.echoes(), echoLines(scad + ".echo"));
    size_t ourDeprecations = 0;
    for (const auto &w : ours.warnings()) ourDeprecations += w.rfind("DEPRECATED: ", 0) == 0;
    EXPECT_EQ(ourDeprecations, countLinesStartingWith(theirs, "DEPRECATED: ")) << theirs;
    if (p.openscadSays) {
        EXPECT_NE(theirs.find(p.openscadSays), std::string::npos) << theirs;
    }
    if (p.weSay) {
        EXPECT_TRUE(ours.hasWarning(p.weSay));
    }
}

TEST(OpenScadCrossCheck, LanguageGapProbesAgree) {
    REQUIRE_OPENSCAD();
    std::string tmp = tempDir() + "/probes";
    fs::create_directories(tmp);
    const Probe probes[] = {
        // Empty elements: accepted
        {"echo([8, 1.4,,\"E\"], [,], [1,,]);"},
        {"cylinder(h=2, r1=2,, $fn=50); echo(,,1, 2);"},
        {"module m(,a,,) echo(a); m(,1);"},
        {"x = [let(a = 1,, b = 2) for (i = [a:b]) i]; echo(x);"},
        // and rejected: trailing commas in arguments, a comma before a vector's first element
        {"echo(1, 2,);"},
        {"echo(,);"},
        {"cube(1,);"},
        {"for (i = [0:1],) echo(i);"},
        {"x = let(a = 1,) a;"},
        {"x = [let(a = 1,) for (i = [0:1]) i];"},
        {"x = [, 1];"},
        // C-style for: init and update may be empty, the condition not
        {"i = 0; echo([for (; i < 2; i = i + 1) i], [for (j = 0; j < 0; ) j]);"},
        {"x = [for (i = 0; ; i = i + 1) i];"},
        {"x = [for (i = 0,; i < 1; i = i + 1) i];"},
        // No-break space between tokens, not inside a name or number
        {"echo(\xC2\xA0"
         "1\xA0+\xC2\xA0\xA0"
         "2, \"a\xC2\xA0"
         "b\");"},
        {"echo(1\xC2\xA0"
         "2);"},
        {"echo(\xC2\xA2);"},
        // Deprecated modules
        {"assign(a = 1, b = 2) echo(a, b); for (i = [0:1]) assign(c = i) echo(c);"},
        {"module m() { child(); child(1); } m() { echo(0); echo(1); }"},
        // A background part is evaluated, a disabled one is not
        {"%echo(\"bg\"); *echo(\"off\"); %union() { assign(x = 2) echo(x); }"},
        // A missing font is reported and skipped
        {"use <no_such_font.ttf>\necho(1);", "Can't read font", "can't read font"},
    };
    int index = 0;
    for (const auto &p : probes) expectSameVerdict(p, tmp, index++);
}

TEST(OpenScadCrossCheck, ImportWithoutFileOrTrianglesIsEmptyGeometry) {
    REQUIRE_OPENSCAD();
    std::string tmp = tempDir() + "/empty_import";
    fs::create_directories(tmp);
    std::ofstream(tmp + "/empty.stl") << "solid empty\nendsolid empty\n";
    std::ofstream(tmp + "/empty_bin.stl", std::ios::binary) << std::string(84, '\0');
    struct Case {
        const char *src;
        const char *openscadSays;  ///< on stderr of the STL export, or null: no warning at all
    };
    const Case cases[] = {
        {"import(); cube();", "Unsupported file format"},
        {"difference() { import(\"empty.stl\"); cube(); } import(\"empty_bin.stl\"); cube();",
         nullptr},
    };
    int index = 0;
    for (const auto &c : cases) {
        SCOPED_TRACE(c.src);
        std::string scad = tmp + "/case" + std::to_string(index++) + ".scad";
        std::ofstream(scad) << c.src;
        // The STL export evaluates the geometry (the .csg export would not read the files)
        RunResult r = runOpenScad(scad, scad + ".stl");
        EXPECT_EQ(r.exitCode, 0) << r.stderrText;
        // One unit cube survives: 12 triangles
        EXPECT_EQ(countLinesStartingWith(readAll(scad + ".stl"), "  facet"), 12u);
        Imported ours;
        ours.scene = importScad(scad, ours.diag);
        EXPECT_TRUE(ours.scene.meshes.empty());
        std::vector<PlacedPrimitive> prims = primitives(*ours.scene.root);
        if (c.openscadSays) {
            EXPECT_NE(r.stderrText.find(c.openscadSays), std::string::npos) << r.stderrText;
            EXPECT_TRUE(ours.hasWarning("unsupported file format"));
            EXPECT_EQ(prims.size(), 1u);
        } else {
            EXPECT_EQ(r.stderrText.find("WARNING"), std::string::npos) << r.stderrText;
            EXPECT_EQ(r.stderrText.find("ERROR"), std::string::npos) << r.stderrText;
            EXPECT_TRUE(ours.warnings().empty());
        }
    }
}

}  // namespace
}  // namespace rt::scad::test

namespace rt::scad::test {
namespace {

/// The one primitive of a scene with identity transforms above it.
const ir::Node *onlyPrimitive(const ir::Node &n) {
    if (n.kind == ir::NodeKind::Primitive) return &n;
    const ir::Node *found = nullptr;
    for (const auto &c : n.children)
        if (const ir::Node *p = onlyPrimitive(*c)) found = p;
    return found;
}

TEST(OpenScadCrossCheck, FacetedPrimitivesHaveOpenScadsVertices) {
    REQUIRE_OPENSCAD();
    // OpenSCAD's OFF export of a lone primitive keeps its polygons; its vertices (6 digits)
    // must be ours, one for one
    const char *cases[] = {
        "sphere(r=2, $fn=6);",
        "sphere(1);",                         // defaults: 5 fragments, 3 rings
        "sphere(r=10);",                      // 30 fragments
        "sphere(r=3, $fn=7);",                // odd: no equator ring
        "cylinder(h=3, r1=2, r2=0, $fn=5);",  // cone: one apex
        "cylinder(h=3, r1=0, r2=1.5, $fn=4, center=true);",
        "cylinder(h=2, r1=1, r2=2, $fn=7, center=true);",
        "cylinder(h=1, r=3, $fa=30, $fs=1);",
        "cylinder(h=4, d=5, $fn=6.8);",  // $fn truncates in 2021.01
    };
    std::string tmp = tempDir();
    for (const char *src : cases) {
        SCOPED_TRACE(src);
        std::string scad = tmp + "/facet.scad", off = tmp + "/facet.off";
        std::ofstream(scad) << src << "\n";
        RunResult r = runOpenScad(scad, off);
        ASSERT_EQ(r.exitCode, 0) << r.stderrText;
        DiagnosticSink diag;
        ir::Mesh theirs = meshio::readMeshFile(off, diag);
        Imported ours = importText(src);
        meshing::applyFacets(ours.scene, ir::FacetMode::OpenScad, ours.diag);
        const ir::Node *prim = onlyPrimitive(*ours.scene.root);
        ASSERT_TRUE(prim);
        const auto *poly = std::get_if<ir::PolytopePrim>(&prim->shape);
        ASSERT_TRUE(poly);
        ASSERT_EQ(poly->vertices.size(), theirs.positions.size());
        for (const Vec3 &v : theirs.positions) {
            double best = kInfinity;
            for (const Vec3 &w : poly->vertices) best = std::min(best, length(v - w));
            EXPECT_LT(best, 1e-5 * std::max(1.0, length(v))) << v.x << " " << v.y << " " << v.z;
        }
    }
}

}  // namespace
}  // namespace rt::scad::test
