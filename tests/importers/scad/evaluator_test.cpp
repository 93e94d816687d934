// SPDX-License-Identifier: MIT
// Evaluator tests: OpenSCAD 2021.01 scoping rules (docs/design/openscad-subset.md sections 3-6),
// recursion, comprehensions, include/use, and the limits on runaway programs.
#include "importers/scad/lang/evaluator.h"

#include <gtest/gtest.h>

#include <cstdlib>

#include "importers/mesh/mesh_test_support.h"
#include "importers/scad/lang/parser.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

using Echoes = std::vector<std::string>;

Echoes echoes(const std::string &src) { return importText(src).echoes(); }

TEST(Scoping, LastExpressionIsEvaluatedAtFirstPosition) {
    Imported r = importText("a = 1;\necho(a);\na = 2;\n");
    EXPECT_EQ(r.echoes(), Echoes{"2"});
    Diagnostic w = r.warning("overwritten");
    EXPECT_EQ(w.message, "a was assigned on line 1 but was overwritten");
    EXPECT_EQ(w.loc.line, 3);
    EXPECT_EQ(w.loc.col, 1);
}

TEST(Scoping, ForwardVariableReferenceIsUndefWithWarning) {
    Imported r = importText("b = c + 1;\nc = 10;\necho(b, c);");
    EXPECT_EQ(r.echoes(), Echoes{"undef, 10"});
    Diagnostic w = r.warning("unknown variable");
    EXPECT_EQ(w.message, "Ignoring unknown variable 'c'");
    EXPECT_EQ(w.loc.toString(), dataDir() + "/inline.scad:1:5");
    EXPECT_TRUE(r.hasWarning("undefined operation (undefined + number)"));
}

TEST(Scoping, ModuleBodySeesOuterValueBeforeItsOwnAssignment) {
    EXPECT_EQ(echoes("x = 1; module m() { y = x; echo(y); x = 2; } m();"), Echoes{"1"});
}

TEST(Scoping, IfBodyAssignmentsAreLocal) {
    EXPECT_EQ(echoes("x = 3; if (true) { x = 100; echo(x); } echo(x);"), (Echoes{"100", "3"}));
}

TEST(Scoping, AssignmentsRunBeforeInstantiations) {
    // echo() is an instantiation: it sees the value assigned after it
    EXPECT_EQ(echoes("echo(v); v = 5;"), Echoes{"5"});
}

TEST(Scoping, TopLevelBlockDoesNotOpenAScope) {
    EXPECT_EQ(echoes("x = 1; { x = 2; } echo(x);"), Echoes{"2"});
}

TEST(Scoping, DollarVariableReachesChildrenOfModuleCall) {
    EXPECT_EQ(echoes("module m() children(); m($fn = 7) echo($fn);"), Echoes{"7"});
    EXPECT_EQ(echoes("module m() echo($fn); m($fn = 7); m();"), (Echoes{"7", "0"}));
    // Dynamic, not lexical: a function sees the caller's binding
    EXPECT_EQ(echoes("function f() = $fa; module m() echo(f()); m($fa = 3);"), Echoes{"3"});
}

TEST(Scoping, DollarArgumentsOfTransformsReachChildrenButCsgIgnoresThem) {
    EXPECT_EQ(echoes("translate([1, 0, 0], $fn = 5) echo($fn);"), Echoes{"5"});
    EXPECT_EQ(echoes("union($fn = 5) echo($fn);"), Echoes{"0"});
    EXPECT_EQ(echoes("difference($fn = 5) { echo($fn); }"), Echoes{"0"});
    Imported r = importText("translate([0, 0, 0], $fn = 9) sphere(1); union($fn = 9) sphere(1);");
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 2u);
    EXPECT_EQ(prims[0].node->fragments.fn, 9);
    EXPECT_EQ(prims[1].node->fragments.fn, 0);
}

TEST(Scoping, DefaultsAreEvaluatedInTheDefiningScope) {
    // y's default sees the global x (assigned before any instantiation), not the parameter x
    EXPECT_EQ(echoes("module m(x = 5, y = x * 2) echo(x, y); m(1); x = 7;"), Echoes{"1, 14"});
    EXPECT_EQ(echoes("function f(a, b = a) = b; echo(f(1));"), Echoes{"undef"});
}

TEST(Scoping, FunctionValueShadowsFunctionDefinition) {
    EXPECT_EQ(echoes("function f(x) = x + 1; f = function(x) x * 10; echo(f(1));"), Echoes{"10"});
    // A non-function variable does not hide the definition
    EXPECT_EQ(echoes("function g(x) = x + 1; g = 3; echo(g(1), g);"), Echoes{"2, 3"});
}

TEST(Scoping, ChildBlockAssignmentsBelongToTheCaller) {
    // They are evaluated before the module body, so the module's $q is not visible yet
    EXPECT_EQ(echoes("module m() { $q = 5; children(); } m() { r = $q; echo(r); }"),
              Echoes{"undef"});
    EXPECT_EQ(echoes("module m() { x = 5; children(); } m() { y = 2; echo(y); }"), Echoes{"2"});
    // and arguments are evaluated in that frame too (UserModule::instantiate)
    EXPECT_EQ(echoes("y = 1; module m(w) echo(w); m(y) { y = 5; }"), Echoes{"5"});
}

TEST(Scoping, ModuleBodyAssignmentOverridesParameter) {
    EXPECT_EQ(echoes("module m(v) { echo(v); v = 5; } m(1);"), Echoes{"5"});
}

TEST(Scoping, UnknownNamedArgumentWarnsButIsBound) {
    Imported r = importText("module m(a) echo(a, b); m(1, b = 2);");
    EXPECT_EQ(r.echoes(), Echoes{"1, 2"});
    EXPECT_TRUE(r.hasWarning("variable b not specified as parameter"));
    // `$` names are exempt
    Imported s = importText("module m(a) echo($x); m(1, $x = 3);");
    EXPECT_EQ(s.echoes(), Echoes{"3"});
    EXPECT_FALSE(s.hasWarning("not specified"));
}

TEST(Scoping, PositionalAndNamedArgumentsBindLikeOpenScad) {
    EXPECT_EQ(echoes("function g(a, b) = [a, b]; echo(g(b = 1, 2), g(1, a = 2));"),
              Echoes{"[2, 1], [2, undef]"});
    Imported r = importText("module m(a) echo(a); m(1, 2);");
    EXPECT_TRUE(r.hasWarning("Too many unnamed arguments supplied"));
}

TEST(Scoping, NestedDefinitionsAreLexical) {
    EXPECT_EQ(echoes("module outer() { module inner() echo(\"in\"); inner(); } outer();"),
              Echoes{"\"in\""});
    EXPECT_THROW(importText("module outer() { module inner() cube(); } inner();"), EvalError);
}

TEST(Scoping, ChildrenCountsChildStatementsAndIsLexical) {
    EXPECT_EQ(echoes("module m() echo($children); m() { cube(); for (i = [0:2]) cube(); }"),
              Echoes{"2"});
    // Inside the children, $children is the one of the module whose body wrote the call
    EXPECT_EQ(echoes("module n() { echo(c = $children); children(0); }\n"
                     "module w() { n() { echo(inner = $children); } }\n"
                     "w() { cube(); cube(); }"),
              (Echoes{"c = 1", "inner = 2"}));
}

TEST(Children, SelectionForms) {
    std::string lib = "module pick(s) children(s); module all() children();\n";
    EXPECT_EQ(echoes(lib + "pick(1) { echo(0); echo(1); echo(2); }"), Echoes{"1"});
    EXPECT_EQ(echoes(lib + "pick(1.9) { echo(0); echo(1); echo(2); }"), Echoes{"1"});
    EXPECT_EQ(echoes(lib + "pick([0, 2]) { echo(0); echo(1); echo(2); }"), (Echoes{"0", "2"}));
    EXPECT_EQ(echoes(lib + "pick([1:2]) { echo(0); echo(1); echo(2); }"), (Echoes{"1", "2"}));
    EXPECT_EQ(echoes(lib + "all() { echo(0); echo(1); }"), (Echoes{"0", "1"}));
    Imported r = importText(lib + "pick(5) echo(0); pick(-1) echo(0); pick(\"a\") echo(0);");
    EXPECT_TRUE(r.echoes().empty());
    EXPECT_TRUE(r.hasWarning("Children index (5) out of bounds (1 children)"));
    EXPECT_TRUE(r.hasWarning("Negative children index (-1) not allowed"));
    EXPECT_TRUE(r.hasWarning("Bad parameter type (\"a\") for children"));
}

TEST(Children, TopLevelChildrenIsNothing) {
    Imported r = importText("children(); difference() { children(); sphere(1); }");
    ASSERT_EQ(r.scene.root->children.size(), 1u);
    const ir::Node &diff = *r.scene.root->children[0];
    ASSERT_EQ(diff.children.size(), 1u);  // children() at top level is null: sphere is the minuend
    EXPECT_EQ(diff.children[0]->kind, ir::NodeKind::Primitive);
}

TEST(Recursion, DeepNonTailRecursion) {
    EXPECT_EQ(echoes("function sumr(n) = n == 0 ? 0 : n + sumr(n - 1); echo(sumr(3000));"),
              Echoes{"4.5015e+6"});
    EXPECT_EQ(echoes("module r(n) { if (n > 0) r(n - 1); else echo(\"bottom\"); } r(2000);"),
              Echoes{"\"bottom\""});
}

TEST(Recursion, TailCallsInTernaryBranchesRunIteratively) {
    EXPECT_EQ(echoes("function sumt(n, acc = 0) = n == 0 ? acc : sumt(n - 1, acc + n);"
                     "echo(sumt(100000));"),
              Echoes{"5.00005e+9"});
    // Mutual tail recursion through let() as well
    EXPECT_EQ(echoes("function ev(n) = n == 0 ? true : let(m = n - 1) od(m);"
                     "function od(n) = n == 0 ? false : ev(n - 1); echo(ev(200001));"),
              Echoes{"false"});
}

TEST(Recursion, RunawayRecursionIsALocatedError) {
    try {
        importText("function f(n) = f(n + 1) + 1;\nx = f(0);");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("recursion too deep calling function 'f'"),
                  std::string::npos);
        EXPECT_EQ(e.loc().line, 1);
        EXPECT_EQ(e.loc().col, 17);
    }
    try {
        importText("module m(n) { cube(); m(n + 1); }\nm(0);");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("recursion too deep calling module 'm'"),
                  std::string::npos);
    }
}

/// Evaluates with explicit limits (on this thread), for budgets too slow to reach by default.
ir::Scene evaluateWithLimits(const std::string &src, const EvalLimits &limits) {
    DiagnosticSink diag;
    SourceLoader loader({}, diag);
    auto file = parseSource(src, "limits.scad", loader);
    Evaluator evaluator(diag, limits);
    return evaluator.evaluate(*file, loader);
}

TEST(Recursion, RunawayTailLoopHitsTheStepBudget) {
    EvalLimits limits;
    limits.maxSteps = 100000;
    try {
        evaluateWithLimits("function f(n) = f(n + 1);\nx = f(0);", limits);
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_EQ(std::string(e.what()),
                  "evaluation too long: more than 100000 steps (calls, loop iterations and "
                  "module instances); runaway loop or recursion? If the model needs more, raise "
                  "the cap with --max-steps N (0 = no cap)");
        EXPECT_EQ(e.loc().toString(), "limits.scad:1:17");
    }
    // Loops count too
    EXPECT_THROW(evaluateWithLimits("for (i = [0:999], j = [0:999]) echo();", limits), EvalError);
    EXPECT_NO_THROW(evaluateWithLimits("for (i = [0:99], j = [0:99]) echo();", limits));
}

TEST(Limits, GeometryWorkCapStopsBigProjectionsAndMinkowskiSums) {
    // The fuzz target sets it far below the default. A sphere of 50 x 25 fragments has 1,252
    // faces: its shadow, or the boundary of a difference cut from it, examines 1.6 M face pairs
    EvalLimits limits;
    limits.maxGeometryWork = 100'000;
    const char *shadow = "linear_extrude(1)\n projection() sphere(5, $fn=50);";
    try {
        evaluateWithLimits(shadow, limits);
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("projection(): about 1.6e+06 face pairs, more "
                                             "than the 99950 left of the geometry budget of "
                                             "100000 (--max-geometry N raises it"),
                  std::string::npos)
            << e.what();
        EXPECT_EQ(e.loc().toString(), "limits.scad:2:2");
    }
    EXPECT_THROW(
        evaluateWithLimits("minkowski() { difference() { sphere(5, $fn=50); cube(1); } cube(1); }",
                           limits),
        EvalError);
    EXPECT_NO_THROW(evaluateWithLimits("linear_extrude(1) projection() sphere(5, $fn=8);", limits));
    EXPECT_NO_THROW(evaluateWithLimits(shadow, EvalLimits{}));
}

TEST(Limits, StepCapComesFromTheImportOptionsAndZeroMeansNone) {
    const std::string src = "x = [for (i = [0:199999]) i];\necho(len(x));";
    ImportOptions opts;
    opts.maxSteps = 1000;
    try {
        importText(src, "", opts);
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("more than 1000 steps"), std::string::npos);
        EXPECT_EQ(e.loc().line, 1);
    }
    // 0 is no cap, not a cap of 0
    opts.maxSteps = 0;
    EXPECT_EQ(importText(src, "", opts).echoes(), Echoes{"200000"});
}

TEST(Limits, ProgressIsReportedEvery65536Steps) {
    ImportOptions opts;
    std::vector<int64_t> calls;
    opts.progress = [&](int64_t steps) { calls.push_back(steps); };
    importText("x = [for (i = [0:199999]) i];", "", opts);
    EXPECT_EQ(calls, (std::vector<int64_t>{65536, 131072, 196608}));
}

TEST(Limits, HugeEchoIsCutWithALocatedWarning) {
    Imported r = importText("x = 1;\necho(v = [for (i = [0:99999]) i], w = \"\u00e9\");");
    ASSERT_EQ(r.echoes().size(), 1u);
    std::string e = r.echoes()[0];
    EXPECT_EQ(e.rfind("v = [0, 1, 2, ", 0), 0u);
    EXPECT_EQ(e.substr(e.size() - 4), " ...");
    EXPECT_LE(e.size(), (64u << 10) + 4);
    EXPECT_GE(e.size(), (64u << 10) - 8);
    Diagnostic w = r.warning("echo output cut");
    EXPECT_EQ(w.message, "echo output cut after 64 KiB");
    EXPECT_EQ(w.loc.line, 2);
    // Below the cap nothing changes; a cut never splits a UTF-8 character
    EXPECT_EQ(echoOf("echo([for (i = [0:999]) i][999]);"), "999");
    std::string s;
    for (int i = 0; i < 40000; ++i) s += "\u00e9";  // two bytes each
    Imported u = importText("echo(\"" + s + "\");");
    ASSERT_EQ(u.echoes().size(), 1u);
    std::string cut = u.echoes()[0];
    ASSERT_EQ(cut.substr(cut.size() - 4), " ...");
    cut.resize(cut.size() - 4);
    EXPECT_EQ(cut[0], '"');
    EXPECT_EQ((cut.size() - 1) % 2, 0u) << "a character was split";
    EXPECT_EQ(cut.substr(cut.size() - 2), "\u00e9");
}

TEST(Limits, HugeListsAndStringsAreLocatedErrors) {
    EXPECT_THROW(importText("x = [for (i = [0:99999]) [for (j = [0:99999]) j]];"), EvalError);
    EXPECT_THROW(importText("function g(s) = g(str(s, s)); x = g(\"ab\");"), EvalError);
    EXPECT_THROW(importText("x = [for (i = 0; i < 1e9; i = i + 1) i];"), EvalError);
    try {
        importText("x = [for (i = [0:99999]) [for (j = [0:99999]) j]];");
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("too many elements"), std::string::npos);
    }
}

TEST(Limits, TooManyGeometryNodesIsALocatedError) {
    try {
        importText("for (i = [0:9998]) for (j = [0:9998]) cube();");
        FAIL() << "expected EvalError";
    } catch (const EvalError &e) {
        EXPECT_NE(std::string(e.what()).find("too many geometry nodes"), std::string::npos);
        EXPECT_EQ(e.loc().line, 1);
    }
}

TEST(Limits, ModuleForOverTenThousandRangeElementsIsSkipped) {
    Imported r = importText("for (i = [0:9999]) cube(); for (i = [0:9998]) cube();");
    EXPECT_TRUE(r.hasWarning("Bad range parameter in for statement: too many elements (10000)"));
    EXPECT_EQ(r.scene.root->primitiveCount(), 9999u);
    // List comprehensions allow up to a million
    EXPECT_EQ(echoes("echo(len([for (i = [0:999998]) 0]), [for (i = [0:1e6]) i]);"),
              Echoes{"999999, []"});
}

TEST(Comprehensions, AllElementForms) {
    EXPECT_EQ(echoes("echo([for (i = [0:3]) if (i % 2) i else -i]);"), Echoes{"[0, 1, -2, 3]"});
    EXPECT_EQ(echoes("echo([for (i = [0:1], j = [0:1]) [i, j]]);"),
              Echoes{"[[0, 0], [0, 1], [1, 0], [1, 1]]"});
    EXPECT_EQ(echoes("echo([for (i = 0, j = 1; i < 3; i = i + 1, j = j * 2) [i, j]]);"),
              Echoes{"[[0, 1], [1, 2], [2, 4]]"});
    EXPECT_EQ(echoes("echo([for (i = [1:3]) let(a = i * 2) if (a > 2) a]);"), Echoes{"[4, 6]"});
    EXPECT_EQ(echoes("echo([each [1, 2], each \"ab\", each [0:2], 7]);"),
              Echoes{"[1, 2, \"a\", \"b\", 0, 1, 2, 7]"});
    EXPECT_EQ(echoes("echo([for (i = [0:2]) for (j = [0:i]) j]);"), Echoes{"[0, 0, 1, 0, 1, 2]"});
    EXPECT_EQ(echoes("echo([for (c = \"hé\") c], [for (x = 5) x], [for (x = undef) x]);"),
              Echoes{"[\"h\", \"é\"], [5], []"});
}

TEST(Comprehensions, ClosuresCaptureTheLoopFrame) {
    // OpenSCAD reuses one frame per loop variable, so every closure sees the last value
    EXPECT_EQ(echoes("fs = [for (i = [0:2]) function(y) y + i]; echo(fs[0](10), fs[2](10));"),
              Echoes{"12, 12"});
}

TEST(Functions, LiteralsClosuresAndPrefixExpressions) {
    EXPECT_EQ(echoes("add = function(a, b = 2) a + b; echo(add(1), add(b = 3, a = 1));"),
              Echoes{"3, 4"});
    EXPECT_EQ(echoes("function adder(n) = function(x) x + n; echo(adder(10)(1));"), Echoes{"11"});
    EXPECT_EQ(echoes("echo(let(a = 1, b = a + 1) a + b);"), Echoes{"3"});
    EXPECT_EQ(echoes("x = echo(\"side\") 5; echo(x);"), (Echoes{"\"side\"", "5"}));
    EXPECT_EQ(echoes("echo(function(x) x * 2);"), Echoes{"function(x) (x * 2)"});
}

TEST(IncludeUse, IncludeIsTextualAndMainOverridesLibraryValues) {
    Imported r = importText("include <lib/inc_lib.scad>\nsize = 3;\nlibcube();\necho(libf());");
    EXPECT_EQ(r.echoes(), (Echoes{"\"inc top\"", "30"}));
    auto prims = primitives(*r.scene.root);
    ASSERT_EQ(prims.size(), 1u);
    EXPECT_EQ(std::get<ir::BoxPrim>(prims[0].node->shape).max, Vec3(3, 3, 3));
    // No overwrite warning across files
    EXPECT_FALSE(r.hasWarning("overwritten"));
}

TEST(IncludeUse, UseImportsOnlyModulesAndFunctions) {
    Imported r = importText("use <lib/use_lib.scad>\nusedmod();\necho(usedf(1));\necho(libvar);");
    // The library's own top-level echo and usedmod() call are not instantiated
    EXPECT_EQ(r.echoes(), (Echoes{"libvar = 7, nested = \"nested\"", "8", "undef"}));
    EXPECT_TRUE(r.hasWarning("Ignoring unknown variable 'libvar'"));
    // The library's own `use` is not visible to its users
    EXPECT_THROW(importText("use <lib/use_lib.scad>\necho(nestedf());"), EvalError);
}

TEST(IncludeUse, LaterUseWins) {
    EXPECT_EQ(echoes("use <lib/override_a.scad>\nuse <lib/override_b.scad>\nwho();"),
              Echoes{"\"b\""});
    EXPECT_EQ(echoes("use <lib/override_a.scad>\nuse <lib/override_b.scad>\nmodule who() "
                     "echo(\"own\");\nwho();"),
              Echoes{"\"own\""});
}

TEST(IncludeUse, SearchPathOrder) {
    ImportOptions opts;
    opts.libraryPaths.push_back(dataDir() + "/extra");
    EXPECT_EQ(importText("use <extra_lib.scad>\necho(extra());", "", opts).echoes(),
              Echoes{"\"extra\""});
    setenv("OPENSCADPATH", (dataDir() + "/nonexistent:" + dataDir() + "/envlib").c_str(), 1);
    Echoes e = importText("use <env_lib.scad>\necho(fromenv());").echoes();
    unsetenv("OPENSCADPATH");
    EXPECT_EQ(e, Echoes{"\"env\""});
    // scadray.scad is found in SCADRAY_LIBRARY_DIR (the project's scenes folder)
    Imported r = importText("use <scadray.scad>\nbackground(color = \"red\");");
    EXPECT_EQ(r.scene.settings.background, Rgb(1, 0, 0));
    EXPECT_FALSE(r.hasWarning("metadata module"));
}

TEST(IncludeUse, DefinesOverrideTopLevelAssignments) {
    ImportOptions opts;
    opts.defines = {{"a", "5"}, {"b", "[1, 2] * 2"}};
    Imported r = importText("a = 1; echo(a, b);", "", opts);
    EXPECT_EQ(r.echoes(), Echoes{"5, [2, 4]"});
    EXPECT_FALSE(r.hasWarning("overwritten"));
}

TEST(IncludeUse, FontFileIsRegisteredNotParsed) {
    std::string dir = meshio::test::testDir();
    // Only the signature is looked at; the rest would be a syntax error as source
    meshio::test::writeFile(dir + "/Font.TTF", std::string("\0\1\0\0", 4) + "}}}{{{");
    meshio::test::writeFile(dir + "/cff.otf", "OTTO}}}");
    meshio::test::writeFile(dir + "/fake.ttf", "module q() cube();");
    std::string main = meshio::test::writeFile(
        dir + "/main.scad",
        "use <Font.TTF>\nuse <cff.otf>\nuse <Font.TTF>\nuse <missing.ttf>\nuse <fake.ttf>\n"
        "echo(1);\n");
    Imported r;
    r.scene = importScad(main, r.diag);
    EXPECT_EQ(r.echoes(), Echoes{"1"});
    EXPECT_EQ(r.scene.fontFiles, (std::vector<std::string>{dir + "/Font.TTF", dir + "/cff.otf"}));
    // OpenSCAD goes on without a missing or broken font
    ASSERT_EQ(r.warnings().size(), 2u);
    Diagnostic missing = r.warning("missing.ttf");
    EXPECT_EQ(missing.message,
              "Can't open library 'missing.ttf': can't read font with path 'missing.ttf'");
    EXPECT_EQ(missing.loc.toString(), main + ":4:1");
    EXPECT_EQ(r.warning("fake.ttf").message,
              "Can't register font '" + dir + "/fake.ttf': not a TrueType/OpenType file");
}

TEST(Deprecated, AssignBindsInParallelAndWarnsOncePerLine) {
    Imported r = importText(
        "a = 5;\nfor (i = [0:2]) assign(a = i, b = a + 1) echo(a, b);\n"
        "assign(c = 1, 7, $fn = 3) { c = 2; echo(c, $fn); }\n"
        "assign(d = 1) cube(d); assign(d = 2) echo(d);");
    EXPECT_EQ(r.echoes(), (Echoes{"0, 6", "1, 6", "2, 6", "2, 3", "2"}));
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
    std::vector<int> lines;
    for (const auto &d : r.diag.all())
        if (d.message.rfind("DEPRECATED: The assign() module", 0) == 0) lines.push_back(d.loc.line);
    EXPECT_EQ(lines, (std::vector<int>{2, 3, 4}));
    EXPECT_EQ(r.warnings().size(), 3u);
}

TEST(Deprecated, ChildPicksOneChildAndWarnsOncePerRun) {
    Imported r = importText(
        "module m() { child(); child(1); child(index = 1); child(\"x\"); child(0.7); }\n"
        "m() { echo(\"c0\"); echo(\"c1\"); }\n"
        "module n() child(-1); n() echo(\"no\");\n"
        "module o() child(2); o() echo(\"no\");\n"
        "module p() child(); p() cube(); child();");
    EXPECT_EQ(r.echoes(), (Echoes{"\"c0\"", "\"c1\"", "\"c1\"", "\"c0\"", "\"c0\""}));
    EXPECT_EQ(r.warnings(),
              (std::vector<std::string>{
                  "DEPRECATED: child() will be removed in future releases. Use children() instead.",
                  "Negative child index (-1) not allowed",
                  "Child index (2) out of bounds (1 children)"}));
    EXPECT_EQ(r.warning("Negative").loc.line, 3);
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
}

TEST(Echo, NamedArgumentsAndValueFormatting) {
    EXPECT_EQ(echoes("echo(a = 1, \"s\", [1, \"x\"], undef, v = [0:2]);"),
              Echoes{"a = 1, \"s\", [1, \"x\"], undef, v = [0 : 1 : 2]"});
    Imported r = importText("echo(1);");
    ASSERT_EQ(r.diag.all().size(), 1u);
    EXPECT_EQ(r.diag.all()[0].severity, Severity::Note);
    EXPECT_EQ(r.diag.all()[0].message, "ECHO: 1");
    EXPECT_EQ(r.diag.all()[0].loc.line, 1);
}

// The time it takes is a benchmark, not a test: build/tests/scad_eval_bench
TEST(EvaluatorScale, HundredThousandPrimitives) {
    Imported r = importText(
        "for (i = [0:99], j = [0:99], k = [0:9]) translate([i, j, k]) color([i / 100, j / 100, "
        "0.5])"
        " cube(0.5);");
    EXPECT_EQ(r.scene.root->primitiveCount(), 100000u);
    EXPECT_EQ(r.scene.materials.size(), 10000u);
}

}  // namespace
}  // namespace rt::scad::test
