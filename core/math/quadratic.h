// SPDX-License-Identifier: MIT
// Numerically stable real roots of a*t^2 + b*t + c (pbrt-v4 util/math.h Quadratic).
#pragma once

#include <cmath>
#include <utility>

#include "core/math/float_util.h"

namespace rt {

/// Solves a*t^2 + b*t + c = 0. Returns false when there is no real root; otherwise t0 <= t1.
/// Uses q = -1/2 (b + sign(b) sqrt(disc)) to avoid cancellation, and the FMA-exact
/// discriminant b^2 - 4ac, so grazing rays neither lose nor invent roots.
inline bool solveQuadratic(double a, double b, double c, double *t0, double *t1) {
    if (a == 0) {
        // Linear case
        if (b == 0) return false;
        *t0 = *t1 = -c / b;
        return true;
    }
    double discrim = differenceOfProducts(b, b, 4 * a, c);
    if (discrim < 0) return false;
    double rootDiscrim = std::sqrt(discrim);
    double q = -0.5 * (b + std::copysign(rootDiscrim, b));
    *t0 = q / a;
    *t1 = (q != 0) ? c / q : *t0;
    if (*t0 > *t1) std::swap(*t0, *t1);
    return true;
}

}  // namespace rt
