// SPDX-License-Identifier: MIT
// Lexer for OpenSCAD 2021.01 source text: longest-match identifiers/numbers, strings, comments.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "importers/scad/lang/token.h"

namespace rt::scad {

/// Splits one file's text into tokens. As in OpenSCAD's flex lexer, identifiers and numbers
/// compete by longest match with numbers winning ties, so `3d` is an identifier and `1e3` a
/// number. `include <f>` and `use <f>` become single tokens. Throws ParseError on an
/// unterminated string or comment or a character outside the language.
class Lexer {
  public:
    Lexer(std::string source, std::shared_ptr<const std::string> file,
          DiagnosticSink *diag = nullptr);

    /// All tokens of the file, ending with one End token.
    std::vector<Token> tokenize();

  private:
    char peek(size_t ahead = 0) const;
    void advance(size_t n = 1);
    SourceLoc here() const { return SourceLoc(file_, line_, col_); }
    void skipSpaceAndComments();
    Token lexNumberOrIdentifier();
    Token lexString();
    bool lexIncludeOrUse(Token &tok);
    Token lexOperator();

    std::string src_;
    std::shared_ptr<const std::string> file_;
    DiagnosticSink *diag_;
    size_t pos_ = 0;
    int line_ = 1;
    int col_ = 1;
};

}  // namespace rt::scad
