// SPDX-License-Identifier: MIT
// Linear RGB colour triple in double precision.
#pragma once

#include <algorithm>
#include <cmath>

namespace rt {

struct Rgb {
    double r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Rgb(double s) : r(s), g(s), b(s) {}

    constexpr Rgb operator+(const Rgb &o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Rgb operator-(const Rgb &o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Rgb operator*(const Rgb &o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Rgb operator*(double s) const { return {r * s, g * s, b * s}; }
    constexpr Rgb operator/(double s) const { return {r / s, g / s, b / s}; }
    Rgb &operator+=(const Rgb &o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    Rgb &operator*=(const Rgb &o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    Rgb &operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr bool operator==(const Rgb &o) const { return r == o.r && g == o.g && b == o.b; }
    constexpr bool operator!=(const Rgb &o) const { return !(*this == o); }
    double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    double &operator[](int i) { return i == 0 ? r : (i == 1 ? g : b); }

    double maxComponent() const { return std::max({r, g, b}); }
    bool isBlack() const { return r == 0 && g == 0 && b == 0; }
    bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Rgb operator*(double s, const Rgb &c) { return c * s; }

}  // namespace rt
