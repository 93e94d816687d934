// SPDX-License-Identifier: MIT
// UTF-8 helpers: OpenSCAD strings are indexed, iterated and measured in code points, and glTF
// URIs decode %-escapes to them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace rt {

/// Byte length of the code point starting with byte `c` (1 for stray continuation bytes).
inline size_t utf8SequenceLength(unsigned char c) {
    if (c >= 0xF0 && c < 0xF8) return 4;
    if (c >= 0xE0) return c < 0xF0 ? 3 : 1;
    if (c >= 0xC0) return 2;
    return 1;
}

/// The string split into one string per code point.
inline std::vector<std::string> utf8Chars(const std::string &s) {
    std::vector<std::string> out;
    for (size_t i = 0; i < s.size();) {
        size_t n = utf8SequenceLength(static_cast<unsigned char>(s[i]));
        if (i + n > s.size()) n = s.size() - i;
        out.push_back(s.substr(i, n));
        i += n;
    }
    return out;
}

inline size_t utf8Length(const std::string &s) {
    size_t count = 0;
    for (size_t i = 0; i < s.size(); ++count)
        i += utf8SequenceLength(static_cast<unsigned char>(s[i]));
    return count;
}

/// Code point of a single-character string, or -1 when it is not valid UTF-8.
inline long utf8Decode(const std::string &ch) {
    if (ch.empty()) return -1;
    auto c0 = static_cast<unsigned char>(ch[0]);
    size_t n = utf8SequenceLength(c0);
    if (n != ch.size()) return -1;
    if (n == 1) return c0 < 0x80 ? c0 : -1;
    long cp = c0 & (0x7F >> n);
    for (size_t i = 1; i < n; ++i) {
        auto c = static_cast<unsigned char>(ch[i]);
        if ((c & 0xC0) != 0x80) return -1;
        cp = (cp << 6) | (c & 0x3F);
    }
    return cp;
}

/// Appends the UTF-8 encoding of a code point.
inline void appendUtf8(std::string &out, unsigned cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

}  // namespace rt
