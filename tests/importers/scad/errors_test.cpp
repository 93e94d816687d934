// SPDX-License-Identifier: MIT
// Fatal errors: each must name the file, line and column of the offending text.
#include <gtest/gtest.h>

#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

const std::string kFile = "/virtual/errors.scad";

template <typename E>
void expectError(const std::string &src, int line, int col, const std::string &message,
                 const std::string &file = kFile) {
    try {
        importText(src, file);
        FAIL() << "expected an error for:\n" << src;
    } catch (const E &e) {
        EXPECT_EQ(e.loc().toString(), file + ":" + std::to_string(line) + ":" + std::to_string(col))
            << src;
        EXPECT_EQ(std::string(e.what()), message) << src;
    } catch (const LocatedError &e) {
        FAIL() << "wrong error type: " << e.what();
    }
}

TEST(Errors, UnterminatedString) {
    expectError<ParseError>("cube();\necho(\"oops);\n", 2, 6, "unterminated string");
}

TEST(Errors, MissingSemicolon) {
    expectError<ParseError>("a = 1;\nb = 2\ncube(b);", 3, 1,
                            "syntax error: expected ';' after the assignment, found 'cube'");
    expectError<ParseError>("function f(x) = x\nmodule m() {}", 2, 1,
                            "syntax error: expected ';' after the function definition, found "
                            "'module'");
}

TEST(Errors, UnexpectedClosingBrace) {
    expectError<ParseError>("translate([1, 0, 0]) {\n  cube();\n}\n}\n", 4, 1,
                            "syntax error: unexpected '}' (no block to close)");
}

TEST(Errors, UnexpectedToken) {
    expectError<ParseError>("cube(1)) ;", 1, 8,
                            "syntax error: unexpected ')' where a statement was expected");
    expectError<ParseError>("x = [1 : ];", 1, 10,
                            "syntax error: unexpected ']' where an expression was expected");
}

TEST(Errors, UnknownModule) {
    expectError<EvalError>("cube();\n  frobnicate(2) cube();", 2, 3, "unknown module 'frobnicate'");
    // Also inside a module body, at the call site
    expectError<EvalError>("module m() { tyop(); }\nm();", 1, 14, "unknown module 'tyop'");
}

TEST(Errors, UnknownFunction) {
    expectError<EvalError>("x = 1;\ny = 2 + frob(x);", 2, 9, "unknown function 'frob'");
}

TEST(Errors, MissingIncludeAndUseFiles) {
    expectError<ParseError>("cube();\ninclude <no/such/file.scad>\n", 2, 1,
                            "can't find include file 'no/such/file.scad'");
    expectError<ParseError>("  use <missing_lib.scad>\n", 1, 3,
                            "can't find used file 'missing_lib.scad'");
}

TEST(Errors, RecursiveIncludeIsAnError) {
    std::string lib = dataDir() + "/lib/recursive_include.scad";
    try {
        importText("include <lib/recursive_include.scad>\n");
        FAIL() << "expected ParseError";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.loc().fileName(), lib);
        EXPECT_EQ(e.loc().line, 2);
        EXPECT_NE(std::string(e.what()).find("recursive include?"), std::string::npos);
    }
}

TEST(Errors, FailedAssert) {
    expectError<EvalError>("x = [1, 2];\nassert(x[0] > 1 && len(x) == 2);", 2, 1,
                           "Assertion '((x[0] > 1) && (len(x) == 2))' failed");
    expectError<EvalError>("a = 1;\nmodule m() assert(a == 2, str(\"a is \", a));\nm();", 2, 12,
                           "Assertion '(a == 2)' failed: \"a is 1\"");
    // assert() as an expression
    expectError<EvalError>("function f(n) = assert(n > 0, \"positive\") n;\ny = f(-1);", 1, 17,
                           "Assertion '(n > 0)' failed: \"positive\"");
}

TEST(Errors, NonAffineMultmatrix) {
    expectError<EvalError>(
        "multmatrix([[1, 0, 0, 0],\n            [0, 1, 0, 0],\n            [0, 0, 1, 0],\n"
        "            [0.1, 0, 0, 1]]) cube();",
        1, 12,
        "multmatrix() with bottom row [0.1, 0, 0, 1] is a projective (non-affine) transform, "
        "which is not supported");
}

TEST(Errors, FormattedDiagnosticNamesFileLineColumn) {
    try {
        importText("cube();\nbogus();", kFile);
        FAIL();
    } catch (const EvalError &e) {
        EXPECT_EQ(formatDiagnostic(e.diagnostic(), false),
                  kFile + ":2:1: error: unknown module 'bogus'");
    }
}

TEST(Errors, WarningsCarryLocations) {
    Imported r = importText("x = 1;\n  y = q;\n", kFile);
    Diagnostic w = r.warning("unknown variable");
    EXPECT_EQ(w.loc.toString(), kFile + ":2:7");
    EXPECT_EQ(w.message, "Ignoring unknown variable 'q'");
}

TEST(Errors, MissingMainFile) {
    DiagnosticSink diag;
    EXPECT_THROW(importScad("/no/such/dir/main.scad", diag), ParseError);
}

TEST(Errors, TwoDCoordinatesBeyondClippersRangeAreLocated) {
    // Clipper's integers hold |x| <= 7e13 (2^62 / 2^16): beyond, a located error, never a crash
    expectError<EvalError>("linear_extrude(1)\n  offset(r=1e14) square(1);", 2, 3,
                           "2D coordinate 100000000000000.000000 is beyond the range of "
                           "OpenSCAD's 2D geometry (|x| <= 7e13)");
    // A self-crossing polygon is sanitized by Clipper (plain shapes are lifted exactly, with no
    // such limit)
    expectError<EvalError>("linear_extrude(1)\n  polygon([[0,0],[1e15,1e15],[1e15,0],[0,1e15]]);",
                           2, 3,
                           "2D coordinate 1000000000000000.000000 is beyond the range of "
                           "OpenSCAD's 2D geometry (|x| <= 7e13)");
}

}  // namespace
}  // namespace rt::scad::test
