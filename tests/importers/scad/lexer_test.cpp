// SPDX-License-Identifier: MIT
// Lexer tests: longest-match identifiers/numbers, strings, comments, include/use, locations.
#include "importers/scad/lang/lexer.h"

#include <gtest/gtest.h>

namespace rt::scad {
namespace {

std::vector<Token> lex(const std::string &src, DiagnosticSink *diag = nullptr) {
    Lexer lexer(src, std::make_shared<const std::string>("lex.scad"), diag);
    return lexer.tokenize();
}

std::vector<TokenKind> kinds(const std::vector<Token> &toks) {
    std::vector<TokenKind> out;
    for (const auto &t : toks) out.push_back(t.kind);
    return out;
}

TEST(Lexer, AssignmentStatement) {
    auto t = lex("x = 1.5;");
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(kinds(t),
              (std::vector<TokenKind>{TokenKind::Identifier, TokenKind::Assign, TokenKind::Number,
                                      TokenKind::Semicolon, TokenKind::End}));
    EXPECT_EQ(t[0].text, "x");
    EXPECT_EQ(t[2].number, 1.5);
}

TEST(Lexer, DigitLeadingNameIsAnIdentifier) {
    // Longest match: `3d` (identifier, 2 chars) beats `3` (number, 1 char)
    auto t = lex("3d 1e3 0x10 2abc");
    EXPECT_EQ(t[0].kind, TokenKind::Identifier);
    EXPECT_EQ(t[0].text, "3d");
    // A tie goes to the number rule
    EXPECT_EQ(t[1].kind, TokenKind::Number);
    EXPECT_EQ(t[1].number, 1000);
    EXPECT_EQ(t[2].kind, TokenKind::Identifier);
    EXPECT_EQ(t[2].text, "0x10");
    EXPECT_EQ(t[3].kind, TokenKind::Identifier);
}

TEST(Lexer, NumberForms) {
    auto t = lex(".5 1. 5.e2 1e-7 1.5E+3 1.5e3x");
    EXPECT_EQ(t[0].number, 0.5);
    EXPECT_EQ(t[1].number, 1.0);
    EXPECT_EQ(t[2].number, 500.0);
    EXPECT_EQ(t[3].number, 1e-7);
    EXPECT_EQ(t[4].number, 1500.0);
    // `1.5e3x`: the number rule matches 5 characters, the identifier rule cannot start at '.'
    EXPECT_EQ(t[5].kind, TokenKind::Number);
    EXPECT_EQ(t[5].number, 1500.0);
    EXPECT_EQ(t[6].kind, TokenKind::Identifier);
    EXPECT_EQ(t[6].text, "x");
}

TEST(Lexer, DollarIdentifiersAndKeywords) {
    auto t = lex("$fn $children module function if else for let assert echo each true false undef");
    EXPECT_EQ(t[0].kind, TokenKind::Identifier);
    EXPECT_EQ(t[0].text, "$fn");
    EXPECT_EQ(t[1].text, "$children");
    EXPECT_EQ(kinds(t),
              (std::vector<TokenKind>{
                  TokenKind::Identifier, TokenKind::Identifier, TokenKind::KwModule,
                  TokenKind::KwFunction, TokenKind::KwIf, TokenKind::KwElse, TokenKind::KwFor,
                  TokenKind::KwLet, TokenKind::KwAssert, TokenKind::KwEcho, TokenKind::KwEach,
                  TokenKind::KwTrue, TokenKind::KwFalse, TokenKind::KwUndef, TokenKind::End}));
}

TEST(Lexer, StringEscapes) {
    auto t = lex(R"("a\tb\n\\\"\x41\u00e9\U01F600\r")");
    ASSERT_EQ(t[0].kind, TokenKind::String);
    EXPECT_EQ(t[0].text, "a\tb\n\\\"A\xC3\xA9\xF0\x9F\x98\x80\r");
}

TEST(Lexer, UnknownEscapeDropsBackslashWithWarning) {
    DiagnosticSink diag;
    auto t = lex(R"("a\qb")", &diag);
    EXPECT_EQ(t[0].text, "aqb");
    ASSERT_EQ(diag.count(Severity::Warning), 1);
    EXPECT_EQ(diag.all()[0].loc.col, 3);
}

TEST(Lexer, RawNewlineInsideStringIsDropped) {
    // lexer.l drops it: "line<newline>break" is "linebreak"
    auto t = lex("\"line\nbreak\" x");
    EXPECT_EQ(t[0].text, "linebreak");
    EXPECT_EQ(t[1].loc.line, 2);
}

TEST(Lexer, OperatorsLongestFirst) {
    auto t = lex("<= >= == != && || < > = ! ^ % # ? : .");
    EXPECT_EQ(kinds(t),
              (std::vector<TokenKind>{TokenKind::LessEqual, TokenKind::GreaterEqual,
                                      TokenKind::EqualEqual, TokenKind::NotEqual, TokenKind::AndAnd,
                                      TokenKind::OrOr, TokenKind::Less, TokenKind::Greater,
                                      TokenKind::Assign, TokenKind::Bang, TokenKind::Caret,
                                      TokenKind::Percent, TokenKind::Hash, TokenKind::Question,
                                      TokenKind::Colon, TokenKind::Dot, TokenKind::End}));
}

TEST(Lexer, CommentsAreSkipped) {
    auto t = lex("a // line comment\n/* block\n comment */ b");
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[1].text, "b");
    EXPECT_EQ(t[1].loc.line, 3);
    EXPECT_EQ(t[1].loc.col, 13);
}

TEST(Lexer, LocationsAreOneBased) {
    auto t = lex("cube();\n  sphere(r = 2);");
    EXPECT_EQ(t[0].loc.line, 1);
    EXPECT_EQ(t[0].loc.col, 1);
    EXPECT_EQ(t[4].text, "sphere");
    EXPECT_EQ(t[4].loc.line, 2);
    EXPECT_EQ(t[4].loc.col, 3);
    EXPECT_EQ(t[4].loc.fileName(), "lex.scad");
}

TEST(Lexer, IncludeAndUseTokens) {
    auto t = lex("include <lib/a.scad>\nuse<b.scad> include = 3;");
    ASSERT_EQ(t[0].kind, TokenKind::Include);
    EXPECT_EQ(t[0].text, "lib/a.scad");
    ASSERT_EQ(t[1].kind, TokenKind::Use);
    EXPECT_EQ(t[1].text, "b.scad");
    EXPECT_EQ(t[1].loc.line, 2);
    // Without a following '<' it is an ordinary identifier
    EXPECT_EQ(t[2].kind, TokenKind::Identifier);
    EXPECT_EQ(t[2].text, "include");
}

/// The ParseError lexing `src` throws, as "location: message"; fails the test without one.
std::string lexError(const std::string &src) {
    try {
        lex(src);
    } catch (const ParseError &e) {
        return e.loc().toString() + ": " + e.what();
    }
    ADD_FAILURE() << "expected a ParseError for: " << src;
    return "";
}

TEST(Lexer, UnterminatedStringIsLocatedError) {
    EXPECT_EQ(lexError("x = 1;\necho(\"abc);"), "lex.scad:2:6: unterminated string");
}

TEST(Lexer, UnterminatedCommentIsLocatedError) {
    EXPECT_EQ(lexError("a\n  /* never closed"), "lex.scad:2:3: unterminated comment");
}

TEST(Lexer, StrayCharacterIsLocatedError) {
    EXPECT_EQ(lexError("cube(1) @;"), "lex.scad:1:9: unexpected character '@'");
}

TEST(Lexer, NoBreakSpaceIsWhiteSpaceBetweenTokens) {
    // UTF-8 C2 A0, a lone Latin-1 A0, runs of both, and (as lexer.l's byte class has it) a
    // lone C2
    auto t =
        lex("x\xC2\xA0=\xA0"
            "1\xC2\xA0\xA0\xC2\xA0+\xC2"
            "2;");
    EXPECT_EQ(kinds(t),
              (std::vector<TokenKind>{TokenKind::Identifier, TokenKind::Assign, TokenKind::Number,
                                      TokenKind::Plus, TokenKind::Number, TokenKind::Semicolon,
                                      TokenKind::End}));
    // Columns count bytes, as OpenSCAD's do
    EXPECT_EQ(t[1].loc.col, 4);
    EXPECT_EQ(t[2].loc.col, 6);
}

TEST(Lexer, NoBreakSpaceInsideAStringIsKept) {
    auto t =
        lex("\"a\xC2\xA0"
            "b\xA0"
            "c\"");
    EXPECT_EQ(t[0].text,
              "a\xC2\xA0"
              "b\xA0"
              "c");
}

TEST(Lexer, NoBreakSpaceStartingALongerUtf8RunIsAnError) {
    // `{UNICODE}+` matches C2 A0 C3 A9 (4 bytes), longer than the white-space run (2 bytes)
    EXPECT_EQ(lexError("x =\xC2\xA0\xC3\xA9;"), "lex.scad:1:4: unexpected character '\\xC2'");
    EXPECT_EQ(lexError("echo(\xC2\xA2);"), "lex.scad:1:6: unexpected character '\\xC2'");
}

}  // namespace
}  // namespace rt::scad
