// SPDX-License-Identifier: MIT
// rotate_extrude profiles (OpenSCAD 2021.01 rotateextrude.cc, GeometryEvaluator.cc).
#include "importers/scad/geometry2d/revolve.h"

#include <cmath>

#include "core/meshing/facets.h"

namespace rt::scad {

namespace {

/// Columns of a 2D map that are orthogonal and of equal length within this relative
/// tolerance keep a circle a circle (a rotation, uniform scale or mirror, with rounding).
constexpr double kSimilarityTolerance = 1e-12;

}  // namespace

double revolveAngle(double given) {
    if (!std::isfinite(given) || given <= -360 || given > 360) return 360;
    return given;
}

int revolveFragments(const XRange &x, double angle, const ir::Fragments &f) {
    // rotatePolygon starts its range at 0, so max_x - min_x is the largest |x|
    double reach = x.empty ? 0 : std::max(x.max, 0.0) - std::min(x.min, 0.0);
    double n = meshing::openscadFragments(reach, f) * std::abs(angle) / 360;
    return static_cast<int>(std::max(n, 1.0));
}

Outline clipToPositiveX(const Outline &o) {
    Outline out;
    size_t n = o.size();
    for (size_t i = 0; i < n; ++i) {
        Vec2 a = o[i], b = o[(i + 1) % n];
        bool aIn = a.x >= 0, bIn = b.x >= 0;
        if (aIn) out.push_back(a);
        if (aIn != bIn) {
            // The crossing of the axis, computed from the point inside so it is exact there
            double t = a.x / (a.x - b.x);
            out.push_back({0, a.y + (b.y - a.y) * t});
        }
    }
    return out;
}

ir::ProfileOutline toProfile(const Outline &o) {
    ir::ProfileOutline p;
    p.reserve(o.size());
    for (Vec2 v : o) p.push_back({std::max(v.x, 0.0), v.y});
    return p;
}

std::optional<PlacedCircle> placedCircle(const Affine2 &a, double radius) {
    double c0 = std::hypot(a.m00, a.m10), c1 = std::hypot(a.m01, a.m11);
    double dot = a.m00 * a.m01 + a.m10 * a.m11;
    double scale = std::max(c0, c1);
    if (!(scale > 0) || std::abs(c0 - c1) > kSimilarityTolerance * scale ||
        std::abs(dot) > kSimilarityTolerance * scale * scale)
        return std::nullopt;
    return PlacedCircle{{a.tx, a.ty}, radius * 0.5 * (c0 + c1)};
}

}  // namespace rt::scad
