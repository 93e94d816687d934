// SPDX-License-Identifier: MIT
// Ray-interval (span) lists: the parts of a ray line inside a solid, with the surface crossed at
// each end, as in the lecture notes behind the project.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/math/vec3.h"

namespace rt {

class LeafShape;

/// One surface crossing along a ray: parameter t, the primitive whose surface it is, and which
/// face of that primitive (used to compute the normal of the winning hit only).
struct Crossing {
    double t = 0;
    const LeafShape *leaf = nullptr;
    int face = 0;
    /// Another surface was within the tie tolerance of this one (coincident faces): which of
    /// them a renderer shows is a convention, so comparisons mask such pixels.
    bool tie = false;
};

/// Two crossings closer than this, relative to the magnitude of the ray's coordinates, count
/// as a tie: a hundred thousand times the rounding error of a double at that magnitude.
constexpr double kTieTolerance = 1e-11;

/// Tie tolerance for crossings near t along a ray from `o`.
inline double tieEpsilon(const Vec3 &o, double t) {
    return kTieTolerance *
           (std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)}) + std::abs(t) + 1e-300);
}

/// The closed interval [in.t, out.t] of the ray line inside a solid; in.t < out.t.
struct Span {
    Crossing in, out;
};

/// Sorted, disjoint, non-touching spans of positive length.
using SpanList = std::vector<Span>;

}  // namespace rt
