// SPDX-License-Identifier: MIT
// Header-only helper of the text() tests: an installed font copied under a family name that
// is not installed, for use<x.ttf> to register.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace rt::scad::test {

/// The installed font the tests copy under another family name (fonts-liberation).
inline const char *kLiberationSans =
    "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf";

/// A copy of Liberation Sans whose family is `family` (ten letters, replacing "Liberation" in
/// the name table's ASCII and UTF-16 strings), written to `path`.
inline bool writeRenamedFont(const std::string &family, const std::filesystem::path &path) {
    std::ifstream in(kLiberationSans, std::ios::binary);
    if (!in || family.size() != 10) return false;
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto replaceAll = [&](const std::string &from, const std::string &to) {
        for (size_t at = bytes.find(from); at != std::string::npos; at = bytes.find(from, at))
            bytes.replace(at, from.size(), to);
    };
    auto utf16 = [](const std::string &s) {
        std::string out;
        for (char c : s) out += std::string(1, '\0') + c;
        return out;
    };
    replaceAll("Liberation", family);
    replaceAll(utf16("Liberation"), utf16(family));
    std::ofstream(path, std::ios::binary) << bytes;
    return true;
}

}  // namespace rt::scad::test
