// SPDX-License-Identifier: MIT
// Boolean operations on span lists: union, intersection and difference by one merge sweep.
#pragma once

#include "core/csg/span.h"

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
/// material sorts first by value (PrimitiveInstance::tieRank) wins, the first operand's only if
/// the ranks are equal, so swapping their operands never changes the picture.
void combineSpans(const SpanList &a, const SpanList &b, SpanOp op, SpanList &out);

}  // namespace rt
