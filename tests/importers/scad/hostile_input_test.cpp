// SPDX-License-Identifier: MIT
// Hostile input: generated inputs that could overflow the stack, exhaust memory,
// hang or reach undefined behaviour must each end in a located error (or OpenSCAD's defined
// result) quickly and before allocating much.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "importers/scad/formats/surface.h"
#include "importers/scad/lang/evaluator.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

const std::string kFile = "/virtual/hostile.scad";

std::string repeat(const std::string &s, size_t n) {
    std::string out;
    out.reserve(s.size() * n);
    for (size_t i = 0; i < n; ++i) out += s;
    return out;
}

/// The error `src` must end in, with its message containing `part`.
template <typename E>
E errorOf(const std::string &src, const std::string &part, const std::string &file = kFile) {
    try {
        importText(src, file);
    } catch (const E &e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        EXPECT_TRUE(e.loc().isValid()) << e.loc().toString();
        return e;
    } catch (const LocatedError &e) {
        ADD_FAILURE() << "wrong error type: " << e.what();
        return E(e.loc(), e.what());
    }
    ADD_FAILURE() << "expected an error containing '" << part << "'";
    return E(SourceLoc(), "");
}

constexpr size_t kLinks = 1000000;
/// For links of several tokens: still ten times the nesting limit, lexed in a fraction of the
/// time (every token of the input is lexed before parsing starts).
constexpr size_t kLongLinks = 100000;

void expectTooDeep(const std::string &src) {
    ParseError e = errorOf<ParseError>(src, "nesting too deep");
    EXPECT_EQ(e.loc().fileName(), kFile);
    EXPECT_EQ(e.loc().line, 1);
}

// --- Chains a million links long -----------------------------------------------------------------

TEST(Hostile, PostfixChainsOfAMillionLinksAreTooDeep) {
    // Parsed without recursion, they built a tree a million deep whose evaluation (and
    // destruction) overflowed the stack
    expectTooDeep("function f(x) = f; x = f(1)" + repeat("(1)", kLinks) + ";\n");
}

TEST(Hostile, IndexAndMemberChainsAreTooDeep) {
    expectTooDeep("a = [0]; x = a" + repeat("[0]", kLinks) + ";\n");
    expectTooDeep("a = [1]; x = a" + repeat(".x", kLinks) + ";\n");
}

TEST(Hostile, LeftAssociativeChainsAreTooDeep) {
    expectTooDeep("x = 1" + repeat("+1", kLinks) + ";\n");
    expectTooDeep("x = 1" + repeat(" == 1", kLinks) + ";\n");
    // Chains of different operators nest in each other: their links add up
    expectTooDeep("x = 1" + repeat("*1+1", kLongLinks) + ";\n");
    expectTooDeep("x = true" + repeat(" && true || true", kLongLinks) + ";\n");
}

TEST(Hostile, PrefixChainsAreTooDeep) {
    expectTooDeep("x = " + repeat("-", kLinks) + "1;\n");
    expectTooDeep("x = " + repeat("!", kLinks) + "true;\n");
    expectTooDeep("x = " + repeat("-(", kLongLinks) + "1" + repeat(")", kLongLinks) + ";\n");
    expectTooDeep("x = " + repeat("let(a = 1) ", kLongLinks) + "1;\n");
    expectTooDeep("x = " + repeat("assert(true) ", kLongLinks) + "1;\n");
    expectTooDeep("x = " + repeat("true ? 1 : ", kLongLinks) + "1;\n");
}

TEST(Hostile, ComprehensionChainsAreTooDeep) {
    expectTooDeep("x = [" + repeat("for (i = [0:0]) ", kLongLinks) + "1];\n");
    expectTooDeep("x = [" + repeat("each ", kLongLinks) + "[1]];\n");
    expectTooDeep("x = [" + repeat("if (true) ", kLongLinks) + "1];\n");
}

TEST(Hostile, StatementChainsAreTooDeep) {
    expectTooDeep(repeat("translate([1, 0, 0]) ", kLongLinks) + "cube();\n");
    expectTooDeep("if (false) cube(); " + repeat("else if (false) cube(); ", kLongLinks) + "\n");
    expectTooDeep(repeat("{", kLinks) + repeat("}", kLinks) + "\n");
}

TEST(Hostile, ChainsWithinTheNestingLimitStillWork) {
    EXPECT_NO_THROW(
        importText("x = 1" + repeat("+1", 5000) + "; a = [[1]]; y = a" + repeat("[0]", 2) + ";\n"));
}

TEST(Hostile, DeepSceneTreesAreALocatedError) {
    // Module recursion within the call-depth limit builds a tree thousands of levels deep,
    // which later stages would walk recursively
    EvalError e = errorOf<EvalError>(
        "module m(n) if (n > 0) translate([1, 0, 0]) m(n - 1); else cube();\nm(9000);\n",
        "geometry nested too deep: more than 20000 levels");
    EXPECT_EQ(e.loc().fileName(), kFile);
    EXPECT_EQ(e.loc().line, 1);
    // A shallow recursion is fine
    EXPECT_NO_THROW(importText(
        "module m(n) if (n > 0) translate([1, 0, 0]) m(n - 1); else cube();\nm(100);\n"));
}

TEST(Hostile, DeeplyNestedVectorsAreALocatedError) {
    // Tail calls and C-style loops build nesting without recursion; freeing, printing or
    // comparing such a value would recurse a million deep
    EvalError e = errorOf<EvalError>(
        "function f(n, acc = []) = n == 0 ? acc : f(n - 1, [acc]);\nx = f(1000000);\n",
        "vectors nested too deep: more than 100000 levels");
    EXPECT_EQ(e.loc().line, 1);
    EXPECT_EQ(e.loc().col, 51);
    errorOf<EvalError>("x = [for (a = [], i = 0; i < 1000000; a = [a], i = i + 1) 0];\n",
                       "vectors nested too deep");
}

// --- Values shared by reference ------------------------------------------------------------------

/// t(60) is 2^60 elements deep down, described by 61 vectors.
const std::string kTower = "function t(n) = n == 0 ? [1] : let(s = t(n - 1)) [s, s];\n";

TEST(Hostile, TheElementCapIsAnOption) {
    const std::string src = "x = [for (i = [0:9999]) i];\ny = x == [for (i = [0:9999]) i];\n";
    EXPECT_NO_THROW(importText(src, kFile));
    ImportOptions low;
    low.maxElements = 5000;
    try {
        importText(src, kFile, low);
        ADD_FAILURE() << "expected the element cap";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("more than 5000 values"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("--max-elements"), std::string::npos) << e.what();
        EXPECT_EQ(e.loc().line, 1);
    }
    // A comparison visiting more than the cap stops, naming the option (t(20): 2^20 leaves
    // from 21 small vectors): it passes under the default cap
    const std::string tower = kTower + "y = t(20) == t(20);\n";
    EXPECT_NO_THROW(importText(tower, kFile));
    try {
        importText(tower, kFile, low);
        ADD_FAILURE() << "expected the comparison cap";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("comparison too large"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("--max-elements"), std::string::npos) << e.what();
        EXPECT_EQ(e.loc().line, 2);
    }
}

TEST(Hostile, ComparingHugeSharedVectorsStops) {
    // Two separately built towers share nothing with each other: equality would visit 2^60
    EvalError e = errorOf<EvalError>(kTower + "x = t(60) == t(60);\n", "comparison too large");
    EXPECT_EQ(e.loc().line, 2);
    errorOf<EvalError>(kTower + "x = t(60) != t(60);\n", "comparison too large");
    errorOf<EvalError>(kTower + "x = t(60) < t(60);\n", "comparison too large");
    // The same vector is equal to itself at once
    EXPECT_NO_THROW(importText(kTower + "v = t(60); x = v == v;\n"));
}

/// The EvalError evaluating `src` with `limits` ends in (on this thread: keep it shallow).
EvalError errorWithLimits(const std::string &src, const EvalLimits &limits,
                          const std::string &part) {
    DiagnosticSink diag;
    SourceLoader loader({}, diag);
    auto file = parseSource(src, kFile, loader);
    Evaluator evaluator(diag, limits);
    try {
        evaluator.evaluate(*file, loader);
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
        return e;
    }
    ADD_FAILURE() << "expected an error containing '" << part << "'";
    return EvalError(SourceLoc(), "");
}

EvalLimits smallBudget() {
    EvalLimits limits;
    limits.maxLiveElements = 100000;
    limits.maxSteps = 100000;
    limits.maxStringLength = 1 << 20;
    return limits;
}

TEST(Hostile, ArithmeticOnHugeSharedVectorsStops) {
    // Element-wise operations expand the sharing: the element budget stops them
    for (const char *op :
         {"x = t(60) + t(60);", "x = -t(60);", "x = t(60) * 2;", "x = t(60) / 2;"}) {
        EvalError e = errorWithLimits(kTower + op + "\n", smallBudget(), "too many elements");
        EXPECT_EQ(e.loc().line, 2) << op;
    }
}

TEST(Hostile, StrOfHugeSharedVectorsStopsAtTheStringLimit) {
    EvalError e = errorWithLimits(kTower + "x = str(t(60));\n", smallBudget(),
                                  "string too long: more than 1048576 bytes");
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 5);
}

TEST(Hostile, EchoOfHugeSharedVectorsIsCut) {
    Imported r = importText(kTower + "echo(t(60));\n");
    ASSERT_EQ(r.echoes().size(), 1u);
    EXPECT_LT(r.echoes()[0].size(), 70000u);
    EXPECT_TRUE(r.hasWarning("echo output cut"));
}

TEST(Hostile, DoublingByConcatStops) {
    errorWithLimits("function d(v, n) = n == 0 ? v : d(concat(v, v), n - 1);\nx = d([1], 60);\n",
                    smallBudget(), "too many elements");
}

TEST(Hostile, SearchingHugeSharedVectorsStops) {
    errorOf<EvalError>(kTower + "x = search([t(40)], [t(40)]);\n", "comparison too large");
    // n needles in m entries are n * m comparisons: the step budget bounds them
    errorWithLimits("v = [for (i = [0:9999]) i];\nx = search(v, v, 0);\n", smallBudget(),
                    "evaluation too long");
}

// --- rands() -------------------------------------------------------------------------------------

std::string echoOf(const std::string &src) {
    Imported r = importText(src);
    std::string out;
    for (const auto &e : r.echoes()) out += (out.empty() ? "" : "|") + e;
    return out;
}

TEST(Hostile, RandsSeedsAreHashedAsOpenScadDoes) {
    // Values from `openscad -o x.echo` (2021.01)
    EXPECT_EQ(echoOf("echo(rands(0, 1, 2, 5), rands(0, 1, 2, -5), rands(0, 1, 2, 5.7));"),
              "[0.0551801, 0.831328], [0.580706, 0.0114547], [0.409499, 0.0856015]");
    EXPECT_EQ(echoOf("echo(rands(0, 1, 2, 4294967301), rands(0, 1, 2, 1e300));"),
              "[0.227339, 0.318972], [0.73142, 0.800559]");
    EXPECT_EQ(echoOf("echo(rands(0, 1, 2, 1 / 0), rands(0, 1, 2, -1 / 0), rands(0, 1, 2, 0 / 0));"),
              "[0.0776717, 0.997662], [0.458262, 0.925352], [0.592845, 0.844266]");
}

TEST(Hostile, RandsCountsAndBoundsThatAreNotFinite) {
    Imported r = importText("echo(rands(0, 1, 0 / 0, 1));\necho(rands(0, 1, 1 / 0, 1));\n");
    EXPECT_EQ(r.echoes(), (std::vector<std::string>{"[0.997185]", "[0.997185]"}));
    EXPECT_TRUE(r.hasWarning("rands() cannot create an infinite number of results"));
    Imported b = importText("echo(len(rands(0 / 0, 1 / 0, 3, 1)));\n");
    EXPECT_EQ(b.echoes(), (std::vector<std::string>{"3"}));
    EXPECT_TRUE(b.hasWarning("rands() range min cannot be infinite"));
    EXPECT_TRUE(b.hasWarning("rands() range max cannot be infinite"));
    EvalError e = errorOf<EvalError>("x = rands(0, 1, 1e300);\n", "too many elements");
    EXPECT_EQ(e.loc().col, 5);
}

// --- Files named by include<>, use<> and import() ------------------------------------------------

/// A fresh folder for the running test.
std::string testDir() {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    fs::path p =
        fs::temp_directory_path() / ("scadray_hostile_" + std::to_string(getpid())) / info->name();
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

void writeFile(const std::string &path, const std::string &text) {
    std::ofstream(path, std::ios::binary) << text;
}

TEST(Hostile, NonScadIncludeTargetsAreNeverQuoted) {
    std::string dir = testDir();
    writeFile(dir + "/secret.txt", "root:SECRETHASH:19000:0:99999:7:::\n");
    try {
        importText("cube();\ninclude <secret.txt>\n", dir + "/main.scad");
        FAIL() << "expected ParseError";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.loc().toString(), dir + "/secret.txt:1:5");
        std::string shown = formatDiagnostic(e.diagnostic());
        EXPECT_EQ(shown.find("SECRET"), std::string::npos) << shown;
        EXPECT_EQ(shown.find('\n'), std::string::npos) << shown;
    }
    // A warning located in such a file is printed without its line either
    writeFile(dir + "/data.txt", "x = SECRET_NAME_1 + 1;\n");
    Imported r = importText("include <data.txt>\n", dir + "/main.scad");
    Diagnostic w = r.warning("Ignoring unknown variable");
    EXPECT_EQ(w.loc.fileName(), dir + "/data.txt");
    EXPECT_EQ(formatDiagnostic(w).find('\n'), std::string::npos);
    // .scad files are still quoted
    writeFile(dir + "/lib.scad", "y = unknown_y;\n");
    Imported s = importText("include <lib.scad>\n", dir + "/main.scad");
    EXPECT_NE(formatDiagnostic(s.warning("unknown_y")).find("y = unknown_y"), std::string::npos);
}

TEST(Hostile, LinksToNonScadIncludeTargetsAreNeverQuoted) {
    std::string dir = testDir();
    writeFile(dir + "/secret.txt", "root:SECRETHASH:19000:0:99999:7:::\n");
    fs::remove(dir + "/link.scad");
    fs::create_symlink(dir + "/secret.txt", dir + "/link.scad");
    try {
        importText("cube();\ninclude <link.scad>\n", dir + "/main.scad");
        FAIL() << "expected ParseError";
    } catch (const ParseError &e) {
        std::string shown = formatDiagnostic(e.diagnostic());
        EXPECT_EQ(shown.find("SECRET"), std::string::npos) << shown;
        EXPECT_EQ(shown.find('\n'), std::string::npos) << shown;
    }
}

TEST(Hostile, TwoDimensionalFilesAndHeightMapsMustBeRegularFiles) {
    // surface(), import() of SVG and DXF, dxf_dim() and dxf_cross() once opened FIFOs (a
    // hang) and devices (/dev/zero: gigabytes); they go through the input reader now
    std::string dir = testDir();
    for (const char *name : {"pipe.dat", "pipe.svg", "pipe.dxf"}) {
        std::string fifo = dir + "/" + name;
        fs::remove(fifo);
        ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    }
    for (const char *name : {"zero.dat", "zero.svg", "zero.dxf", "zero.png"}) {
        fs::remove(dir + "/" + name);
        fs::create_symlink("/dev/zero", dir + "/" + name);
    }
    std::string main = dir + "/main.scad";
    for (const char *src :
         {"surface(file=\"pipe.dat\");", "surface(file=\"zero.dat\");",
          "surface(file=\"zero.png\");", "surface(file=\"/dev/zero\");",
          "linear_extrude(1) import(\"pipe.svg\");", "linear_extrude(1) import(\"zero.svg\");",
          "linear_extrude(1) import(\"pipe.dxf\");", "linear_extrude(1) import(\"zero.dxf\");",
          "x = dxf_dim(file=\"pipe.dxf\", name=\"a\");", "x = dxf_cross(file=\"zero.dxf\");",
          "linear_extrude(file=\"pipe.dxf\", height=1);"}) {
        SCOPED_TRACE(src);
        EvalError e =
            errorOf<EvalError>(std::string("cube();\n") + src + "\n", "not a regular file", main);
        EXPECT_EQ(e.loc().line, 2);
    }
    // A height map past the reader's cap is refused before it is read
    EXPECT_LT(surface::kMaxFileBytes, uint64_t{1} << 30);
}

TEST(Hostile, FifosDevicesAndFoldersAreRefusedWithoutBlocking) {
    std::string dir = testDir();
    std::string fifo = dir + "/pipe.scad";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    fs::create_directories(dir + "/folder.scad");
    for (const std::string &path : {fifo, std::string("/dev/zero"), dir + "/folder.scad"}) {
        DiagnosticSink diag;
        try {
            importScad(path, diag);
            FAIL() << "expected ParseError for " << path;
        } catch (const ParseError &e) {
            EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos)
                << e.what();
        }
    }
    // include<> and use<> never take them for source files
    errorOf<ParseError>("include <pipe.scad>\n", "can't find include file", dir + "/main.scad");
    errorOf<ParseError>("use </dev/zero>\n", "can't find used file", dir + "/main.scad");
    errorOf<ParseError>("include <folder.scad>\n", "can't find include file", dir + "/main.scad");
    std::string stl = dir + "/pipe.stl";
    ASSERT_EQ(mkfifo(stl.c_str(), 0600), 0);
    errorOf<EvalError>("import(\"pipe.stl\");\n", "not a regular file", dir + "/main.scad");
}

TEST(Hostile, HugeSourceFilesAreRefusedBeforeReading) {
    std::string dir = testDir();
    std::string big = dir + "/big.scad";
    { std::ofstream out(big); }
    // Sparse: no disk space and nothing read
    ASSERT_EQ(truncate(big.c_str(), static_cast<off_t>(kMaxSourceBytes + 1)), 0);
    DiagnosticSink diag;
    try {
        importScad(big, diag);
        FAIL() << "expected ParseError";
    } catch (const ParseError &e) {
        EXPECT_NE(std::string(e.what()).find("is too large: 268435457 bytes"), std::string::npos)
            << e.what();
    }
    ParseError e =
        errorOf<ParseError>("cube();\ninclude <big.scad>\n", "is too large", dir + "/main.scad");
    EXPECT_EQ(e.loc().toString(), dir + "/main.scad:2:1");
}

// --- UB on the way: conversions of huge and NaN numbers ----------------------------------

TEST(Hostile, HugeAndNanNumbersConvertDefinedly) {
    Imported r = importText(
        "for (i = [0:1e300]) cube();\n"
        "circle($fn = 0 / 0); circle($fn = 1e300, r = 1e-9);\n"
        "for (i = [0:0:1]) cube();\n"
        "v = [1, 2]; echo(v[1e300], v[0 / 0], v[-1e300], chr(1e300), str(1e308 * 10));\n"
        "echo(search(0 / 0, [1, 0 / 0]), search(1, [1, 1], 0 / 0, 1e300));\n"
        "echo(parent_module(0 / 0), parent_module(-1e300));\n"
        "linear_extrude(height = 1, twist = 1e300, $fn = 1e300) square(1);\n"
        "linear_extrude(height = 1, twist = 1e300, $fa = 1e-300) square(1);\n");
    ASSERT_EQ(r.echoes().size(), 3u);
    EXPECT_EQ(r.echoes()[0], "undef, undef, undef, \"\", \"inf\"");
    EXPECT_TRUE(r.hasWarning("too many elements"));
}

}  // namespace
}  // namespace rt::scad::test
