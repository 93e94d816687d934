// SPDX-License-Identifier: MIT
// Profiles for rotate_extrude (OpenSCAD 2021.01 rotateextrude.cc, GeometryEvaluator.cc
// rotatePolygon): which side of the axis a profile lies on, OpenSCAD's segment count, and the
// outlines of a 2D shape as a lathe's (r, z) profile.
#pragma once

#include <optional>

#include "core/ir/node.h"
#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad {

/// The x extent of a 2D region (or an outer bound of it).
struct XRange {
    double min = 0, max = 0;
    bool empty = true;

    void add(double x) {
        min = empty ? x : std::min(min, x);
        max = empty ? x : std::max(max, x);
        empty = false;
    }
    void add(const XRange &o) {
        if (!o.empty) add(o.min), add(o.max);
    }
    /// OpenSCAD's test: points on both sides of the Y axis (a point on it is on either).
    bool crossesAxis() const { return !empty && min < 0 && max > 0; }
};

/// rotate_extrude's angle as OpenSCAD 2021.01 takes it: values outside (-360, 360] are 360.
double revolveAngle(double given);

/// OpenSCAD's segment count over the angle: max(trunc(fragments(max |x|) |angle| / 360), 1).
int revolveFragments(const XRange &x, double angle, const ir::Fragments &f);

/// The part of an outline with x >= 0 (Sutherland-Hodgman against the Y axis), which has
/// the same even-odd fill on that side; fewer than 3 points when nothing of it is there.
Outline clipToPositiveX(const Outline &o);

/// An outline in the (x >= 0, y) half-plane as a lathe profile (r = x, z = y).
ir::ProfileOutline toProfile(const Outline &o);

/// The centre and radius of a circle placed by an affine map, when the map keeps it a circle
/// (orthogonal columns of equal length).
struct PlacedCircle {
    Vec2 centre;
    double radius = 0;
};
std::optional<PlacedCircle> placedCircle(const Affine2 &a, double radius);

}  // namespace rt::scad
