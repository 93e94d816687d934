// SPDX-License-Identifier: MIT
// The importer's 2D shapes (square, circle, polygon) and the outline geometry that linear
// extrusion needs; none of it reaches the IR, which is 3D only.
#pragma once

#include <string>
#include <vector>

#include "core/ir/node.h"
#include "core/ir/source_loc.h"
#include "core/meshing/hull.h"

namespace rt::scad {

struct Vec2 {
    double x = 0, y = 0;
};

inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline bool operator==(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }
inline bool operator!=(Vec2 a, Vec2 b) { return !(a == b); }

/// A closed polygon outline (the last point joins the first).
using Outline = std::vector<Vec2>;

/// A 2D affine map p -> M p + t, as OpenSCAD applies a 4x4 transform to 2D objects (rows and
/// columns 0, 1 and 3 of the matrix).
struct Affine2 {
    double m00 = 1, m01 = 0, m10 = 0, m11 = 1, tx = 0, ty = 0;

    static Affine2 fromMat4(const Mat4 &m);
    Vec2 apply(Vec2 p) const { return {m00 * p.x + m01 * p.y + tx, m10 * p.x + m11 * p.y + ty}; }
    double det() const { return m00 * m11 - m01 * m10; }
    Affine2 operator*(const Affine2 &o) const;
    bool isIdentity() const;
};

enum class Shape2dKind { Square, Circle, Polygon };

/// One 2D primitive as its module made it. The evaluator keeps these beside the node tree.
struct Shape2d {
    Shape2dKind kind = Shape2dKind::Square;
    Vec2 min, max;                  ///< Square: its corners
    double radius = 1;              ///< Circle
    ir::Fragments fragments;        ///< Circle: $fn/$fa/$fs at the call
    std::vector<Outline> outlines;  ///< Polygon: the paths, filled by the even-odd rule
    /// Polygon: the outlines are an evaluated polygon set (offset(), 2D hull()) that OpenSCAD
    /// does not sanitize again as it does a polygon() leaf
    bool evaluated = false;
    /// Polygon: the outlines are sanitized by Clipper (simple, outer counter-clockwise, holes
    /// clockwise, non-zero filled); only with `evaluated`
    bool sanitized = false;
    int material = -1;  ///< material at the call (top-level 2D keeps its own)
    SourceLoc loc;
};

/// The shape's outlines as OpenSCAD 2021.01 builds them (a circle is its n-gon).
std::vector<Outline> shapeOutlines(const Shape2d &s);

/// How many points shapeOutlines gives, without making them.
size_t shapePointCount(const Shape2d &s);

/// Twice the signed area (positive when counter-clockwise).
double twiceSignedArea(const Outline &o);

/// Drops repeated points and corners on a straight line (relative tolerance), so that
/// convexity and orientation tests see a proper polygon. Fewer than 3 points: no area.
Outline cleanOutline(const Outline &o);

/// A cleaned, counter-clockwise outline that turns left at every corner and winds once.
bool isConvex(const Outline &ccw);

/// The convex hull of 2D points: counter-clockwise, without straight corners (relative
/// tolerance, as cleanOutline). `kind` says what the points span: Empty, Point, Line (no
/// area; `ccw` is then empty) or Solid.
struct Hull2d {
    meshing::HullKind kind = meshing::HullKind::Empty;
    Outline ccw;
};
Hull2d convexHull2d(std::vector<Vec2> points);

/// The part of a convex counter-clockwise outline inside another (Sutherland-Hodgman); empty
/// when they share no area.
Outline clipConvex(const Outline &subject, const Outline &clip);

/// Even-odd point-in-outline test.
bool insideOutline(Vec2 p, const Outline &o);

/// Whether any two edges of the outlines cross or touch (a repeated corner, a corner on an
/// edge, overlapping edges), not counting the corner two neighbouring edges of one outline
/// share: such outlines do not sweep to closed manifold solids on their own.
bool outlinesIntersect(const std::vector<Outline> &outlines);

/// The even-odd fill of non-crossing outlines as disjoint regions: an outer outline (nesting
/// depth even) minus the outlines directly inside it. All outlines are counter-clockwise.
struct Region {
    Outline outer;
    std::vector<Outline> holes;
};
std::vector<Region> evenOddRegions(const std::vector<Outline> &outlines);

}  // namespace rt::scad
