// SPDX-License-Identifier: MIT
// Parser tests: precedence and associativity, statements, scopes, definitions, syntax errors.
#include "importers/scad/lang/parser.h"

#include <gtest/gtest.h>

#include "importers/scad/test_support.h"

namespace rt::scad {
namespace {

/// The parenthesised form OpenSCAD prints for an expression.
std::string shape(const std::string &expr) {
    DiagnosticSink diag;
    SourceLoader loader({}, diag);
    return exprToString(*parseExpressionText(expr, "expr.scad", loader));
}

std::shared_ptr<SourceFile> parse(const std::string &src, DiagnosticSink &diag) {
    SourceLoader l({}, diag);
    return parseSource(src, "parse.scad", l);
}

TEST(ParserPrecedence, PowerIsRightAssociativeAndBindsTighterThanUnaryMinus) {
    EXPECT_EQ(shape("2^3^2"), "(2 ^ (3 ^ 2))");
    EXPECT_EQ(shape("-x^2"), "-(x ^ 2)");
    EXPECT_EQ(shape("2^-x"), "(2 ^ -x)");
    EXPECT_EQ(test::echoOf("echo(2^3^2, -2^2, 2^-1);"), "512, -4, 0.5");
}

TEST(ParserPrecedence, ArithmeticComparisonLogic) {
    EXPECT_EQ(shape("a + b * c - d / e % f"), "((a + (b * c)) - ((d / e) % f))");
    EXPECT_EQ(shape("a < b == c >= d"), "((a < b) == (c >= d))");
    EXPECT_EQ(shape("a || b && c == d"), "(a || (b && (c == d)))");
    EXPECT_EQ(shape("!a == b"), "(!a == b)");
    EXPECT_EQ(shape("-a * b"), "(-a * b)");
    EXPECT_EQ(shape("a - b - c"), "((a - b) - c)");
}

TEST(ParserPrecedence, TernaryNestsToTheRight) {
    EXPECT_EQ(shape("a ? b : c ? d : e"), "(a ? b : (c ? d : e))");
    EXPECT_EQ(shape("a || b ? 1 : 2"), "((a || b) ? 1 : 2)");
    EXPECT_EQ(test::echoOf("echo(true ? 1 : false ? 2 : 3, false ? 1 : false ? 2 : 3);"), "1, 3");
}

TEST(ParserPrecedence, PostfixCallsIndexAndMembers) {
    EXPECT_EQ(shape("f(1)(2)[0].x"), "f(1)(2)[0].x");
    EXPECT_EQ(shape("-v[0]"), "-v[0]");
    EXPECT_EQ(shape("f(a = 1, 2)"), "f(a = 1, 2)");
}

TEST(ParserPrecedence, PrefixExpressionsExtendToTheRight) {
    EXPECT_EQ(shape("let(a = 1) a + 1"), "let(a = 1) (a + 1)");
    EXPECT_EQ(shape("function(x) x * 2"), "function(x) (x * 2)");
    EXPECT_EQ(shape("assert(x > 0) x"), "assert((x > 0)) x");
    EXPECT_EQ(shape("echo(\"hi\")"), "echo(\"hi\")");
}

TEST(ParserVectors, RangesVectorsAndComprehensions) {
    EXPECT_EQ(shape("[0 : 10]"), "[0 : 10]");
    EXPECT_EQ(shape("[0 : 2 : 10]"), "[0 : 2 : 10]");
    EXPECT_EQ(shape("[1, 2, 3, ]"), "[1, 2, 3]");
    EXPECT_EQ(shape("[]"), "[]");
    EXPECT_EQ(shape("[for (i = x) if (i > 0) i else -i]"), "[for(i = x) if((i > 0)) i else -i]");
    EXPECT_EQ(shape("[for (i = 0; i < 3; i = i + 1) i]"), "[for(i = 0; (i < 3); i = (i + 1)) i]");
    EXPECT_EQ(shape("[each v, let(a = 1) for (j = a) j]"), "[each v, let(a = 1) for(j = a) j]");
    EXPECT_EQ(shape("[let(a = 1) a]"), "[let(a = 1) a]");
}

TEST(ParserStatements, AssignmentKeepsFirstPositionAndLastExpression) {
    DiagnosticSink diag;
    auto f = parse("a = 1;\nb = 2;\na = 3;\n", diag);
    ASSERT_EQ(f->top.assignments.size(), 2u);
    EXPECT_EQ(f->top.assignments[0].name.str(), "a");
    EXPECT_EQ(exprToString(*f->top.assignments[0].expr), "3");
    EXPECT_EQ(f->top.assignments[0].loc.line, 1);
    ASSERT_EQ(diag.count(Severity::Warning), 1);
    EXPECT_EQ(diag.all()[0].message, "a was assigned on line 1 but was overwritten");
    EXPECT_EQ(diag.all()[0].loc.toString(), "parse.scad:3:1");
}

TEST(ParserStatements, TopLevelBlockIsNotAScope) {
    DiagnosticSink diag;
    auto f = parse("{ x = 1; { cube(); } } sphere();", diag);
    EXPECT_EQ(f->top.assignments.size(), 1u);
    EXPECT_EQ(f->top.instantiations.size(), 2u);
}

TEST(ParserStatements, DefinitionsAreHoistedIntoTheirScope) {
    DiagnosticSink diag;
    auto f = parse("m(); module m() { module inner() cube(); inner(); } function f(x) = x;", diag);
    ASSERT_EQ(f->top.modules.size(), 1u);
    ASSERT_EQ(f->top.functions.size(), 1u);
    const ModuleDef &m = *f->top.modules.begin()->second;
    EXPECT_EQ(m.body.modules.size(), 1u);
    EXPECT_EQ(m.body.instantiations.size(), 1u);
}

TEST(ParserStatements, ModifiersIfElseAndChildBlocks) {
    DiagnosticSink diag;
    auto f = parse(
        "!#translate([1,0,0]) { y = 2; cube(y); { sphere(); } }\n"
        "if (a) cube(); else if (b) sphere(); else;\n*%cylinder();",
        diag);
    ASSERT_EQ(f->top.instantiations.size(), 3u);
    const auto &t = *f->top.instantiations[0];
    EXPECT_TRUE(t.modifiers.root);
    EXPECT_TRUE(t.modifiers.highlight);
    EXPECT_EQ(t.children.assignments.size(), 1u);
    EXPECT_EQ(t.children.instantiations.size(), 2u);  // nested braces are flattened
    const auto &i = *f->top.instantiations[1];
    EXPECT_TRUE(i.isIf);
    EXPECT_TRUE(i.hasElse);
    ASSERT_EQ(i.elseChildren.instantiations.size(), 1u);
    EXPECT_TRUE(i.elseChildren.instantiations[0]->hasElse);
    EXPECT_TRUE(f->top.instantiations[2]->modifiers.disabled);
    EXPECT_TRUE(f->top.instantiations[2]->modifiers.background);
}

TEST(ParserStatements, KeywordModulesAndTrailingCommas) {
    DiagnosticSink diag;
    auto f = parse(
        "for (i = [0:2]) echo(i); let (a = 1) echo(a); assert(true); module m(a, b = 1,) {}", diag);
    ASSERT_EQ(f->top.instantiations.size(), 3u);
    EXPECT_EQ(f->top.instantiations[0]->name.str(), "for");
    EXPECT_EQ(f->top.instantiations[0]->args.size(), 1u);
    EXPECT_EQ(f->top.instantiations[1]->name.str(), "let");
    EXPECT_EQ(f->top.instantiations[2]->name.str(), "assert");
    EXPECT_EQ(f->top.modules.begin()->second->params.size(), 2u);
}

TEST(ParserCommas, EmptyElementsAreSkippedWhere2021Allows) {
    // Vectors: repeated and trailing commas; commas alone are an empty vector
    EXPECT_EQ(test::echoOf("echo([8, 1.4,,\"E\"], [1,,,2,,,], [,], [,,], [1,,for(i=[0:1]) i]);"),
              "[8, 1.4, \"E\"], [1, 2], [], [], [1, 0, 1]");
    // Arguments: repeated commas, and commas before the first argument
    EXPECT_EQ(test::echoOf("function f(a, b) = a + b; echo(f(1,,2), f(,,1, 2), ,x = 5);"),
              "3, 3, x = 5");
    // Parameters: anywhere, even alone
    EXPECT_EQ(test::echoOf("function f(,a,,b,,) = a + b; g = function(,) 7; echo(f(1, 2), g());"),
              "3, 7");
    EXPECT_EQ(test::echoOf("module m(a,,b,) echo(a, b); m(1,, 2);"), "1, 2");
    EXPECT_EQ(test::echoOf("echo(let(a = 1,, b = 2) a + b, [let(,a = 1) for (i = [0,,a]) i]);"),
              "3, [0, 1]");
    test::Imported r = test::importText(
        "cylinder(h=2, r1=2,, $fn=50); for (i = [0:1],, j = [2]) "
        "echo(i, j); let(a = 1,, b = 2) echo(a, b);");
    EXPECT_EQ(r.echoes(), (std::vector<std::string>{"0, 2", "1, 2", "1, 2"}));
    EXPECT_EQ(r.scene.root->primitiveCount(), 1u);
}

TEST(ParserCommas, TrailingCommaInArgumentsIsASyntaxError) {
    DiagnosticSink diag;
    for (const char *src : {"echo(1, 2,);", "cube(1,);", "for (i = [0:2],) echo(i);", "echo(,);",
                            "x = f(1,);", "x = let(a = 1,) a;", "x = [for (i = [0:1],) i];",
                            "x = [let(a = 1, b = 2,) for (i = [a:b]) i];"}) {
        try {
            parse(src, diag);
            ADD_FAILURE() << "accepted: " << src;
        } catch (const ParseError &e) {
            EXPECT_NE(std::string(e.what()).find("after ','"), std::string::npos) << src;
            EXPECT_EQ(e.loc().line, 1) << src;
        }
    }
}

TEST(ParserCommas, CommaBeforeAVectorsFirstElementIsASyntaxError) {
    DiagnosticSink diag;
    try {
        parse("x = [, 1];", diag);
        FAIL() << "accepted";
    } catch (const ParseError &e) {
        EXPECT_EQ(e.loc().toString(), "parse.scad:1:8");
        EXPECT_EQ(std::string(e.what()),
                  "syntax error: unexpected '1' after ',' (a vector's first element has no comma "
                  "before it)");
    }
}

TEST(ParserForC, InitAndUpdateMayBeEmptyButNotTheCondition) {
    EXPECT_EQ(test::echoOf("i = 0; echo([for (; i < 3; i = i + 1) i]);"), "[0, 1, 2]");
    EXPECT_EQ(test::echoOf("echo([for (; false; ) 1]);"), "[]");
    EXPECT_EQ(test::echoOf("echo([for (,a = 0,, b = 1; a < 3; ,a = a + 1,, b = b * 2) [a, b]]);"),
              "[[0, 1], [1, 2], [2, 4]]");
    DiagnosticSink diag;
    EXPECT_THROW(parse("x = [for (i = 0; ; i = i + 1) i];", diag), ParseError);
    EXPECT_THROW(parse("x = [for (i = 0,; i < 2; i = i + 1) i];", diag), ParseError);
    EXPECT_THROW(parse("x = [for (i = 0; i < 2; i = i + 1,) i];", diag), ParseError);
}

void expectSyntaxError(const std::string &src, const std::string &where, const std::string &msg) {
    DiagnosticSink diag;
    try {
        parse(src, diag);
        FAIL() << "expected a ParseError for: " << src;
    } catch (const ParseError &e) {
        EXPECT_EQ(e.loc().toString(), where) << src;
        EXPECT_EQ(std::string(e.what()), msg) << src;
    }
}

TEST(ParserErrors, MissingSemicolonNamesTheNextToken) {
    expectSyntaxError("x = 5\ncube(x);", "parse.scad:2:1",
                      "syntax error: expected ';' after the assignment, found 'cube'");
}

TEST(ParserErrors, UnexpectedClosingBrace) {
    expectSyntaxError("cube();\n}", "parse.scad:2:1",
                      "syntax error: unexpected '}' (no block to close)");
}

TEST(ParserErrors, UnclosedBlockReachesEndOfFile) {
    expectSyntaxError("module m() {\n  cube();\n", "parse.scad:3:1",
                      "syntax error: expected '}' to close the block, found end of file");
}

TEST(ParserErrors, DefinitionInsideChildBlock) {
    expectSyntaxError("translate([1,0,0]) { module a() {} }", "parse.scad:1:22",
                      "syntax error: unexpected 'module' (definitions are not allowed inside a "
                      "module's child block)");
}

TEST(ParserErrors, BadExpression) {
    expectSyntaxError("x = 1 + ;", "parse.scad:1:9",
                      "syntax error: unexpected ';' where an expression was expected");
    expectSyntaxError("x = [1, 2;", "parse.scad:1:10",
                      "syntax error: expected ']' to close the vector, found ';'");
}

TEST(ParserErrors, DeepNestingIsAnErrorNotACrash) {
    std::string src = "x = " + std::string(20000, '(') + "1" + std::string(20000, ')') + ";";
    DiagnosticSink diag;
    EXPECT_THROW(test::importText(src), ParseError);
    std::string chain = "x = 1";
    for (int i = 0; i < 200000; ++i) chain += "+1";
    EXPECT_THROW(test::importText(chain + ";"), ParseError);
}

}  // namespace
}  // namespace rt::scad
