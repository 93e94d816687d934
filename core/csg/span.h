// SPDX-License-Identifier: MIT
// Ray-interval (span) lists: the parts of a ray line inside a solid, with the surface crossed at
// each end, as in the lecture notes behind the project.
#pragma once

#include <vector>

namespace rt {

class PrimitiveInstance;

/// One surface crossing along a ray: parameter t, the primitive whose surface it is, and which
/// face of that primitive (used to compute the normal of the winning hit only).
struct Crossing {
    double t = 0;
    const PrimitiveInstance *leaf = nullptr;
    int face = 0;
};

/// The closed interval [in.t, out.t] of the ray line inside a solid; in.t < out.t.
struct Span {
    Crossing in, out;
};

/// Sorted, disjoint, non-touching spans of positive length.
using SpanList = std::vector<Span>;

}  // namespace rt
