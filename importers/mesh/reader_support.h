// SPDX-License-Identifier: MIT
// Shared pieces of the mesh file readers: whole-file reading, a located text scanner, number
// parsing and the merging of identical vertex positions.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/math/vec3.h"

namespace rt::meshio::detail {

/// Largest mesh file read (1 GiB: about 20 million binary STL triangles).
constexpr uint64_t kMaxMeshFileBytes = uint64_t{1} << 30;

/// readInputFileAt of a mesh file, errors located at `file` (line 0).
std::string readFileBytes(const std::string &path, const std::shared_ptr<const std::string> &file);

/// The error for a problem at a byte offset of a binary file (the location names the file; the
/// message starts with the offset).
ParseError byteError(const std::shared_ptr<const std::string> &file, uint64_t offset,
                     const std::string &message);

/// One whitespace-separated word of a text file with its 1-based line and column.
struct Token {
    std::string_view text;
    int line = 0;
    int col = 0;
};

/// Splits text into words, tracking lines and columns (bytes, tabs count as one) and skipping
/// comments from `comment` to the end of the line when `comment` is not '\0'.
class TextScanner {
  public:
    TextScanner(std::string_view text, std::shared_ptr<const std::string> file,
                char comment = '\0');

    /// The next word, on any line; false at the end of the text.
    bool next(Token &t);
    /// The next word on the line of the last word read; false at the end of that line.
    bool nextOnLine(Token &t);
    /// Skips what remains of the current line.
    void skipLine();

    SourceLoc loc(const Token &t) const { return SourceLoc(file_, t.line, t.col); }
    /// Just after the last word read (where a missing word on its line was expected).
    SourceLoc afterLast() const { return SourceLoc(file_, lastLine_, lastEndCol_); }
    /// The end of the text (for "unexpected end of file").
    SourceLoc endLoc() const;
    const std::shared_ptr<const std::string> &file() const { return file_; }

  private:
    /// Skips blanks and comments; stops at a newline unless `acrossLines`.
    void skipBlanks(bool acrossLines);
    Token take();

    std::string_view text_;
    std::shared_ptr<const std::string> file_;
    char comment_;
    size_t pos_ = 0;
    size_t lineStart_ = 0;
    int line_ = 1;
    int lastLine_ = 1;
    int lastEndCol_ = 1;
};

/// ASCII case-insensitive comparison with a lower-case keyword.
bool equalsKeyword(std::string_view word, std::string_view lowerKeyword);

/// Parses a whole word as a decimal floating-point number (optional sign, `inf` and `nan`
/// included; out-of-range values become ±inf or 0). False when the word is not a number.
bool parseNumber(std::string_view word, double &out);

/// Parses a whole word as a non-negative decimal integer. False otherwise (or on overflow).
bool parseCount(std::string_view word, uint64_t &out);

/// Hands out one index per distinct position (exact comparison; -0 equals +0).
class PositionWelder {
  public:
    explicit PositionWelder(std::vector<Vec3> &positions) : positions_(positions) {}
    uint32_t add(const Vec3 &p);
    void reserve(size_t n) { index_.reserve(n); }

  private:
    struct Key {
        uint64_t bits[3];
        bool operator==(const Key &o) const {
            return bits[0] == o.bits[0] && bits[1] == o.bits[1] && bits[2] == o.bits[2];
        }
    };
    struct KeyHash {
        size_t operator()(const Key &k) const;
    };
    std::vector<Vec3> &positions_;
    std::unordered_map<Key, uint32_t, KeyHash> index_;
};

/// Fails with a ParseError when a mesh would exceed 32-bit vertex indices.
void checkIndexRange(size_t count, const SourceLoc &loc);

}  // namespace rt::meshio::detail
