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
           num(a[0][1]) + ", " + num(a[1][1]) + ", " + num(a[2][1]) + ",  " + num(a[0][2]) + ", " +
           num(a[1][2]) + ", " + num(a[2][2]) + ",  " + num(a[0][3]) + ", " + num(a[1][3]) + ", " +
           num(a[2][3]) + ">";
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
        if (u < 0x20 || u == 0x7f || c == ';' || c == '"') return false;
    }
    return true;
}

std::string iniValue(const std::string &name) {
    for (char c : name)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.' &&
            c != '/')
            return '"' + name + '"';
    return name;
}

std::string iniFileName(const std::string &value) {
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        return value.substr(1, value.size() - 2);
    return value;
}

std::string sdlDirectiveProblem(std::string_view sdl) {
    auto isIdent = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    int line = 1, commentDepth = 0;
    bool inString = false;
    for (size_t i = 0; i < sdl.size(); ++i) {
        char c = sdl[i];
        char next = i + 1 < sdl.size() ? sdl[i + 1] : '\0';
        if (c == '\n') ++line;
        if (commentDepth > 0) {  // POV-Ray's block comments nest
            if (c == '/' && next == '*')
                ++commentDepth, ++i;
            else if (c == '*' && next == '/')
                --commentDepth, ++i;
        } else if (inString) {
            if (c == '\\' && next != '\0' && next != '\n')
                ++i;
            else if (c == '"')
                inString = false;
            else if (c == '\n' || c == '\r')
                return "line " + std::to_string(line) + ": a string runs past the end of its line";
        } else if (c == '"') {
            inString = true;
        } else if (c == '/' && next == '*') {
            commentDepth = 1, ++i;
        } else if (c == '/' && next == '/') {
            while (i + 1 < sdl.size() && sdl[i + 1] != '\n' && sdl[i + 1] != '\r') ++i;
        } else if (c == '#') {
            size_t j = i + 1;
            while (j < sdl.size() && (sdl[j] == ' ' || sdl[j] == '\t')) ++j;
            size_t k = j;
            while (k < sdl.size() && isIdent(sdl[k])) ++k;
            std::string_view word = sdl.substr(j, k - j);
            if (word != "version" && word != "declare")
                return "line " + std::to_string(line) + ": directive #" +
                       commentText(word.substr(0, 32)) +
                       " (only #version and #declare are allowed)";
            i = k - 1;
        }
    }
    if (inString) return "a string is not closed";
    if (commentDepth > 0) return "a /* comment is not closed";
    return "";
}

}  // namespace rt::pov
