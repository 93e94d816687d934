// SPDX-License-Identifier: MIT
// Boolean operations on span lists: union, intersection and difference by one merge sweep.
#pragma once

#include <span>

#include "core/geometry/span.h"

namespace rt {

enum class SpanOp { Union, Intersection, Difference };

/// out = a OP b. Inputs must be sorted, disjoint and non-touching; so is the result.
///
/// Coincident faces (the tie-break): all crossings of both lists at the same t are applied
/// together, so a boundary appears only where the result's inside/outside state really changes.
/// Touching solids in a union fuse without an internal face, and zero-length results vanish
/// (two solids meeting in a plane intersect in nothing). When crossings of both operands at
/// the same t could each be the result's boundary: in a difference the minuend's face wins (a
/// subtrahend that only touches it does not cut it); in a union or intersection the one whose
/// material sorts first by value (LeafShape::tieRank) wins, the first operand's only if
/// the ranks are equal, so swapping their operands never changes the picture.
/// A boundary of the result that has a crossing of the other operand within `tieEps` (exactly
/// coincident or only rounding apart) is flagged as a tie. Crossings of both operands within
/// `tieEps` that leave no boundary in the result (a subtrahend face flush with the minuend's,
/// two solids meeting in a plane) lower `*cancelledTie` to their t when given: rounded
/// differently, they would have left a surface there.
/// The operands are any contiguous spans (a SpanList, or single spans held elsewhere); `out`
/// must be neither of them.
void combineSpans(std::span<const Span> a, std::span<const Span> b, SpanOp op, SpanList &out,
                  double tieEps = 0, double *cancelledTie = nullptr);

/// The merge sweep itself, which combineSpans runs except for one span a side whose crossings
/// are all more than tieEps apart across the two (there it gives the same result directly).
/// For tests that check the two agree.
void combineSpansBySweep(std::span<const Span> a, std::span<const Span> b, SpanOp op, SpanList &out,
                         double tieEps = 0, double *cancelledTie = nullptr);

}  // namespace rt
