// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's 2D geometry engine (clipper-utils.cc over Clipper 6.4.2): polygon sets,
// their sanitizing, booleans and offsets in Clipper's fixed-point coordinates.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad::clipper2d {

/// 2021.01's CLIPPER_SCALE: coordinates are multiplied by 2^16 and truncated to 64-bit
/// integers (an implicit double -> integer conversion), so every result of a boolean or an
/// offset is a multiple of 2^-16 [verified: offset(delta=0.1) square(1) has corners at
/// 1.100006 = 72090 / 65536; a polygon corner at y = -0.3 becomes -0.299988]. Later releases
/// scale by a power of 2 taken from the bounding box (getScalePow2); 2021.01 does not.
constexpr double kScale = 65536;

/// Clipper's range for exact arithmetic (hiRange, 2^62 - 1) in model units: about 7e13.
constexpr double kMaxCoordinate = 4611686018427387903.0 / kScale;

/// A coordinate or offset beyond kMaxCoordinate (or not finite): Clipper cannot represent it.
class RangeError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A point coordinate in Clipper's integers, as 2021.01 converts it (truncation toward 0);
/// throws RangeError beyond kMaxCoordinate. Every function below may throw it.
int64_t toFixed(double v);
/// An integer coordinate back in model units.
inline double fromFixed(int64_t v) { return static_cast<double>(v) / kScale; }

/// OpenSCAD's Polygon2d: outlines filled by the even-odd rule, or, once sanitized, simple
/// outlines with the outer ones counter-clockwise and the holes clockwise.
struct PolygonSet {
    std::vector<Outline> outlines;
    bool sanitized = false;

    bool empty() const { return outlines.empty(); }
    /// The x range of all points (min > max when there are none).
    void xRange(double &minX, double &maxX) const;
};

/// ClipperUtils::sanitize: the even-odd union of the outlines (each first turned
/// counter-clockwise unless the set is already sanitized).
PolygonSet sanitize(const PolygonSet &p);

enum class BoolOp { Union, Intersection, Difference };

/// ClipperUtils::apply: the operands (each sanitized first unless it is) combined with
/// non-zero filling; an intersection goes pairwise from the first operand. An empty operand
/// stands for OpenSCAD's null child.
PolygonSet apply(const std::vector<PolygonSet> &operands, BoolOp op);

enum class JoinType { Round, Miter, Square };

/// ClipperUtils::applyOffset: the outlines offset by `delta` (closed polygons), with the
/// miter limit and the arc tolerance (in model units) of Clipper's ClipperOffset.
PolygonSet offset(const PolygonSet &p, double delta, JoinType join, double miterLimit,
                  double arcTolerance);

enum class LineEnd { Butt, Round, Square };

/// An open polyline widened by `halfWidth` with mitred joins and the given ends (ClipperOffset
/// on an open path), in integers of its own `scale` rather than kScale: libsvg strokes SVG
/// lines at 10000. The caller keeps every scaled coordinate within Clipper's range; the
/// outlines come back in model units, unclosed.
std::vector<Outline> strokeOpenPath(const Outline &path, double scale, double halfWidth,
                                    LineEnd end);

/// ClipperUtils::applyMinkowski: the Minkowski sum folded over the operands (one operand is
/// returned as it is). Each pair of outlines is convolved into quads (one per edge of one and
/// corner of the other, without Clipper's own union of them, for robustness as 2021.01 does),
/// a copy of each operand is placed at a point of every positive outline of the other (so
/// a sum that swallows a hole is filled), and everything is united with non-zero filling.
PolygonSet minkowski(const std::vector<PolygonSet> &operands);

/// The regions of a polygon set (filled even-odd, or non-zero once sanitized) with their
/// holes, all outlines counter-clockwise and strictly simple (an outline touching itself at
/// a corner is split there), nested as Clipper's PolyTree nests them: outlines that only
/// touch at a corner are told apart without any point-in-polygon test.
std::vector<Region> regions(const PolygonSet &p);

}  // namespace rt::scad::clipper2d
