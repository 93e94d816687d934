// SPDX-License-Identifier: MIT
// Exact number formatting for the POV-Ray writer.
#include "exporters/povray/pov_format.h"

#include <cctype>

#include <charconv>

namespace rt::pov {

std::string num(double v) {
    if (v == 0) return "0";
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
}

std::string vec(const Vec3 &v) { return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">"; }

std::string rgb(const Rgb &c) {
    return "rgb <" + num(c.r) + ", " + num(c.g) + ", " + num(c.b) + ">";
}

std::string matrix(const Mat4 &m) {
    const auto &a = m.m;
    return "matrix <" + num(a[0][0]) + ", " + num(a[1][0]) + ", " + num(a[2][0]) + ",  " +
           num(a[0][1]) + ", " + num(a[1][1]) + ", " + num(a[2][1]) + ",  " + num(a[0][2]) +
           ", " + num(a[1][2]) + ", " + num(a[2][2]) + ",  " + num(a[0][3]) + ", " +
           num(a[1][3]) + ", " + num(a[2][3]) + ">";
}

std::string transform(const Mat4 &m) {
    const auto &a = m.m;
    bool linearIdentity = true, diagonal = true;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            if (a[i][j] != (i == j ? 1.0 : 0.0)) linearIdentity = false;
            if (i != j && a[i][j] != 0) diagonal = false;
        }
    bool noTranslation = a[0][3] == 0 && a[1][3] == 0 && a[2][3] == 0;
    if (linearIdentity) return "translate " + vec(Vec3(a[0][3], a[1][3], a[2][3]));
    if (diagonal && noTranslation) return "scale " + vec(Vec3(a[0][0], a[1][1], a[2][2]));
    return matrix(m);
}

std::string commentText(std::string_view text) {
    static const char *hex = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        unsigned char c = static_cast<unsigned char>(text[i]);
        bool pair = (c == '*' && i + 1 < text.size() && text[i + 1] == '/') ||
                    (c == '/' && i + 1 < text.size() && text[i + 1] == '*');
        if (c >= 0x20 && c < 0x7f && c != '\\' && !pair) {
            out += static_cast<char>(c);
        } else {
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    return out;
}

std::string safeFileName(std::string_view name) {
    std::string out(name);
    for (char &c : out)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '_')
            c = '_';
    return out;
}

bool iniSafe(std::string_view value) {
    for (char c : value) {
        unsigned char u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7f || c == ';') return false;
    }
    return true;
}

}  // namespace rt::pov
