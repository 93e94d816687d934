// SPDX-License-Identifier: MIT
// Floating-point helpers: rounding-error bounds (pbrt-v3 section 3.9), ULP steps and exact
// products.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace rt {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
/// Unit roundoff of double: half an ULP of 1.
constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon() * 0.5;

/// Bound on the relative error of n chained floating-point operations (pbrt-v3 eq. 3.8).
constexpr double gamma(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

/// std::nextafter(v, +inf) and std::nextafter(v, -inf), without the call into libm (a spawned
/// ray's origin takes three): one step of the bit pattern, which orders doubles of one sign.
inline double nextUp(double v) {
    if (!(v < kInfinity)) return v + v;                            // +inf stays, a NaN stays a NaN
    if (v == 0) return std::numeric_limits<double>::denorm_min();  // from +0 and from -0
    uint64_t bits = std::bit_cast<uint64_t>(v);
    return std::bit_cast<double>(v > 0 ? bits + 1 : bits - 1);
}
inline double nextDown(double v) { return -nextUp(-v); }

/// a*b - c*d with one rounding error via FMA (Kahan; pbrt-v4 DifferenceOfProducts).
inline double differenceOfProducts(double a, double b, double c, double d) {
    double cd = c * d;
    double err = std::fma(-c, d, cd);
    double dop = std::fma(a, b, -cd);
    return dop + err;
}

inline double radians(double deg) { return deg * (kPi / 180.0); }
inline double degrees(double rad) { return rad * (180.0 / kPi); }

template <typename T>
constexpr T clamp(T v, T lo, T hi) {
    return v < lo ? lo : (v > hi ? hi : v);
}

}  // namespace rt
