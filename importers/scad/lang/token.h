// SPDX-License-Identifier: MIT
// Tokens of the OpenSCAD 2021.01 language as produced by the lexer.
#pragma once

#include <string>

#include "core/ir/source_loc.h"

namespace rt::scad {

enum class TokenKind {
    End,
    Identifier,  ///< `$?[A-Za-z0-9_]+` that is not a number or keyword
    Number,
    String,   ///< text holds the unescaped UTF-8 contents
    Include,  ///< `include <path>`; text holds the path
    Use,      ///< `use <path>`; text holds the path
    // Keywords
    KwModule,
    KwFunction,
    KwIf,
    KwElse,
    KwFor,
    KwLet,
    KwAssert,
    KwEcho,
    KwEach,
    KwTrue,
    KwFalse,
    KwUndef,
    // Punctuation and operators
    LParen,
    RParen,
    LBracket,
    RBracket,
    LBrace,
    RBrace,
    Semicolon,
    Comma,
    Dot,
    Colon,
    Question,
    Assign,
    Plus,
    Minus,
    Star,
    Slash,
    Percent,
    Caret,
    Bang,
    Hash,
    Less,
    LessEqual,
    Greater,
    GreaterEqual,
    EqualEqual,
    NotEqual,
    AndAnd,
    OrOr,
};

struct Token {
    TokenKind kind = TokenKind::End;
    std::string text;   ///< identifier name, string contents, include path, or source spelling
    double number = 0;  ///< value of a Number token
    SourceLoc loc;
};

/// Human-readable spelling of a token kind for messages ("';'", "identifier").
const char *tokenKindName(TokenKind kind);

/// How a token is named in a syntax error: its source text in quotes, or "end of file".
std::string describeToken(const Token &tok);

}  // namespace rt::scad
