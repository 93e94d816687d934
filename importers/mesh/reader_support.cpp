// SPDX-License-Identifier: MIT
// File reading, the located text scanner, number parsing and position welding of the mesh readers.
#include "importers/mesh/reader_support.h"

#include "core/math/rng.h"

#include <charconv>
#include <cstring>
#include <limits>

namespace rt::meshio::detail {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

uint64_t bitsOf(double d) {
    d += 0.0;  // -0 becomes +0, so that the two compare (and hash) alike
    uint64_t b;
    std::memcpy(&b, &d, sizeof b);
    return b;
}

}  // namespace

std::string readFileBytes(const std::string &path, const std::shared_ptr<const std::string> &file) {
    return readInputFileAt(path, SourceLoc(file, 0, 0), kMaxMeshFileBytes);
}

ParseError byteError(const std::shared_ptr<const std::string> &file, uint64_t offset,
                     const std::string &message) {
    return ParseError(SourceLoc(file, 0, 0), "byte " + std::to_string(offset) + ": " + message);
}

// ---------------------------------------------------------------------------------------------
// TextScanner

TextScanner::TextScanner(std::string_view text, std::shared_ptr<const std::string> file,
                         char comment)
    : text_(text), file_(std::move(file)), comment_(comment) {}

void TextScanner::skipBlanks(bool acrossLines) {
    while (pos_ < text_.size()) {
        char c = text_[pos_];
        if (isBlank(c)) {
            ++pos_;
        } else if (comment_ != '\0' && c == comment_) {
            while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        } else if (c == '\n' && acrossLines) {
            ++pos_;
            ++line_;
            lineStart_ = pos_;
        } else {
            return;
        }
    }
}

Token TextScanner::take() {
    Token t;
    t.line = line_;
    t.col = static_cast<int>(pos_ - lineStart_) + 1;
    size_t start = pos_;
    while (pos_ < text_.size() && !isBlank(text_[pos_]) && text_[pos_] != '\n' &&
           !(comment_ != '\0' && text_[pos_] == comment_))
        ++pos_;
    t.text = text_.substr(start, pos_ - start);
    lastLine_ = line_;
    lastEndCol_ = static_cast<int>(pos_ - lineStart_) + 1;
    return t;
}

bool TextScanner::next(Token &t) {
    skipBlanks(true);
    if (pos_ >= text_.size()) return false;
    t = take();
    return true;
}

bool TextScanner::nextOnLine(Token &t) {
    skipBlanks(false);
    if (pos_ >= text_.size() || text_[pos_] == '\n') return false;
    t = take();
    return true;
}

void TextScanner::skipLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
}

SourceLoc TextScanner::endLoc() const {
    // Line and column of the last character's successor
    int line = 1;
    size_t lineStart = 0;
    for (size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n') {
            ++line;
            lineStart = i + 1;
        }
    return SourceLoc(file_, line, static_cast<int>(text_.size() - lineStart) + 1);
}

// ---------------------------------------------------------------------------------------------
// Words

bool equalsKeyword(std::string_view word, std::string_view lowerKeyword) {
    if (word.size() != lowerKeyword.size()) return false;
    for (size_t i = 0; i < word.size(); ++i) {
        char c = word[i];
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
        if (c != lowerKeyword[i]) return false;
    }
    return true;
}

bool parseNumber(std::string_view word, double &out) {
    // from_chars takes a leading '-' but not '+'
    if (word.size() > 1 && word[0] == '+' && word[1] != '-') word.remove_prefix(1);
    if (word.empty()) return false;
    double value = 0;
    auto [end, ec] =
        std::from_chars(word.data(), word.data() + word.size(), value, std::chars_format::general);
    if (end != word.data() + word.size()) return false;
    if (ec == std::errc::result_out_of_range) {
        // A negative exponent underflows towards zero, anything else overflows
        size_t e = word.find_first_of("eE");
        bool underflow = e != std::string_view::npos && e + 1 < word.size() && word[e + 1] == '-';
        double magnitude = underflow ? 0.0 : std::numeric_limits<double>::infinity();
        value = word[0] == '-' ? -magnitude : magnitude;
    } else if (ec != std::errc()) {
        return false;
    }
    out = value;
    return true;
}

bool parseCount(std::string_view word, uint64_t &out) {
    if (word.size() > 1 && word[0] == '+') word.remove_prefix(1);
    if (word.empty() || word[0] == '-') return false;
    auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
    return ec == std::errc() && end == word.data() + word.size();
}

// ---------------------------------------------------------------------------------------------
// PositionWelder

size_t PositionWelder::KeyHash::operator()(const Key &k) const {
    return static_cast<size_t>(
        rt::mixBits(k.bits[0] ^ rt::mixBits(k.bits[1] ^ rt::mixBits(k.bits[2]))));
}

uint32_t PositionWelder::add(const Vec3 &p) {
    Key key{{bitsOf(p.x), bitsOf(p.y), bitsOf(p.z)}};
    auto [it, inserted] = index_.try_emplace(key, static_cast<uint32_t>(positions_.size()));
    if (inserted) positions_.push_back(p);
    return it->second;
}

void checkIndexRange(size_t count, const SourceLoc &loc) {
    if (count >= std::numeric_limits<uint32_t>::max())
        throw ParseError(loc, "too many vertices for 32-bit indices: " + std::to_string(count));
}

}  // namespace rt::meshio::detail
