// SPDX-License-Identifier: MIT
// Exact-at-special-angles degree trigonometry.
#include "core/math/degree_trig.h"

#include <cmath>

#include "core/math/float_util.h"

namespace rt {

namespace {

/// Reduces an angle to [0, 360); non-finite input passes through as NaN.
double reduceDegrees(double deg) {
    if (!std::isfinite(deg)) return std::nan("");
    double r = std::fmod(deg, 360.0);
    if (r < 0) r += 360.0;
    return r;
}

}  // namespace

double sinDegrees(double deg) {
    double x = reduceDegrees(deg);
    if (std::isnan(x)) return x;
    // Exact values at multiples of 30 degrees; the table follows sin's symmetry.
    if (std::fmod(x, 30.0) == 0) {
        switch (static_cast<int>(x)) {
            case 0:
                return 0;
            case 30:
                return 0.5;
            case 90:
                return 1;
            case 150:
                return 0.5;
            case 180:
                return 0;
            case 210:
                return -0.5;
            case 270:
                return -1;
            case 330:
                return -0.5;
            default:
                break;  // 60, 120, 240, 300: irrational, fall through
        }
    }
    if (x == 45 || x == 135) return std::sqrt(0.5);
    if (x == 225 || x == 315) return -std::sqrt(0.5);
    return std::sin(radians(x));
}

double cosDegrees(double deg) {
    double x = reduceDegrees(deg);
    if (std::isnan(x)) return x;
    if (std::fmod(x, 30.0) == 0) {
        switch (static_cast<int>(x)) {
            case 0:
                return 1;
            case 60:
                return 0.5;
            case 90:
                return 0;
            case 120:
                return -0.5;
            case 180:
                return -1;
            case 240:
                return -0.5;
            case 270:
                return 0;
            case 300:
                return 0.5;
            default:
                break;
        }
    }
    if (x == 45 || x == 315) return std::sqrt(0.5);
    if (x == 135 || x == 225) return -std::sqrt(0.5);
    return std::cos(radians(x));
}

}  // namespace rt
