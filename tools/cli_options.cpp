// SPDX-License-Identifier: MIT
// Numeric command-line options with a checked range (kept apart from cli_common.cpp so the
// tests can link it without the importers).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <type_traits>

#include "tools/cli_common.h"

namespace rt::cli {

namespace {

/// "[lo, hi]", "(lo, hi]" or ">= lo" for --help and the error.
template <typename T>
std::string rangeText(T lo, T hi, bool loOpen) {
    auto num = [](T v) {
        if constexpr (std::is_floating_point_v<T>) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%g", v);
            return std::string(buf);
        } else {
            return std::to_string(v);
        }
    };
    bool unbounded = hi == std::numeric_limits<T>::max();
    if (unbounded) return std::string(loOpen ? "> " : ">= ") + num(lo);
    return std::string(loOpen ? "(" : "[") + num(lo) + ", " + num(hi) + "]";
}

/// Parses the whole of `text` as a T; false for anything else (text, overflow, NaN, inf).
template <typename T>
bool parseNumber(const std::string &text, T &v) {
    if (text.empty()) return false;
    const char *begin = text.c_str(), *end = begin + text.size();
    char *stop = nullptr;
    errno = 0;
    if constexpr (std::is_floating_point_v<T>) {
        v = std::strtod(begin, &stop);
        return stop == end && errno == 0 && std::isfinite(v);
    } else if constexpr (std::is_signed_v<T>) {
        long long x = std::strtoll(begin, &stop, 10);
        if (stop != end || errno != 0 || x < std::numeric_limits<T>::min() ||
            x > std::numeric_limits<T>::max())
            return false;
        v = static_cast<T>(x);
        return true;
    } else {
        // strtoull accepts "-1" as the largest value
        if (text.find('-') != std::string::npos) return false;
        unsigned long long x = std::strtoull(begin, &stop, 10);
        if (stop != end || errno != 0 || x > std::numeric_limits<T>::max()) return false;
        v = static_cast<T>(x);
        return true;
    }
}

template <typename T>
CLI::Option *addRanged(CLI::App &cmd, const std::string &names, T &value, const std::string &help,
                       T lo, T hi, bool loOpen) {
    std::string range = rangeText(lo, hi, loOpen);
    const char *kind = std::is_floating_point_v<T> ? "a number" : "an integer";
    CLI::Validator check(
        [lo, hi, loOpen, range, kind](std::string &text) -> std::string {
            T v{};
            if (!parseNumber(text, v))
                return "must be " + std::string(kind) + " " + range + ", not '" + text + "'";
            if (v < lo || (loOpen && v == lo) || v > hi)
                return "must be " + range + ", not " + text;
            return {};
        },
        range);
    return cmd.add_option(names, value, help)->check(check)->capture_default_str();
}

}  // namespace

CLI::Option *addNumber(CLI::App &cmd, const std::string &names, int &value, const std::string &help,
                       int lo, int hi) {
    return addRanged(cmd, names, value, help, lo, hi, false);
}
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, long &value,
                       const std::string &help, long lo, long hi) {
    return addRanged(cmd, names, value, help, lo, hi, false);
}
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, long long &value,
                       const std::string &help, long long lo, long long hi) {
    return addRanged(cmd, names, value, help, lo, hi, false);
}
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, unsigned long &value,
                       const std::string &help, unsigned long lo, unsigned long hi) {
    return addRanged(cmd, names, value, help, lo, hi, false);
}
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, double &value,
                       const std::string &help, double lo, double hi, bool loOpen) {
    return addRanged(cmd, names, value, help, lo, hi, loOpen);
}

}  // namespace rt::cli
