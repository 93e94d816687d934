// SPDX-License-Identifier: MIT
// Builtin 2D shapes: square, circle, polygon, offset, projection.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <variant>

#include "core/math/degree_trig.h"
#include "core/math/float_util.h"
#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/extrude.h"
#include "importers/scad/geometry2d/projection.h"

namespace rt::scad {

namespace {

/// OffsetNode's miter limit, fixed high in 2021.01 so that delta never chamfers a corner.
constexpr double kOffsetMiterLimit = 1000000.0;

/// Clipper's default arc tolerance, in its integer units (clipper.cpp def_arc_tolerance).
constexpr double kClipperDefaultArcTolerance = 0.25;

/// An upper estimate of the points Clipper 6.4.2's ClipperOffset makes of `input` (DoOffset,
/// DoRound), from the outlines and the parameters only: a round join steps steps / 2 pi times
/// per radian the outline turns at a corner, with the step count from the arc tolerance
/// (both in Clipper's units); each corner gives at most two more points.
double offsetPoints(const clipper2d::PolygonSet &input, double delta, clipper2d::JoinType join,
                    double arcTolerance) {
    double stepsPerRadian = 0;
    double d = std::abs(delta) * clipper2d::kScale;
    if (join == clipper2d::JoinType::Round && d > 0) {
        double y = arcTolerance * clipper2d::kScale;
        if (!(y > 0))
            y = kClipperDefaultArcTolerance;
        else if (y > d * kClipperDefaultArcTolerance)
            y = d * kClipperDefaultArcTolerance;
        double steps = kPi / std::acos(1 - y / d);
        // Clipper's "excessive precision check"
        if (!(steps <= d * kPi)) steps = d * kPi;
        stepsPerRadian = steps / (2 * kPi);
    }
    double points = 0;
    for (const Outline &o : input.outlines) {
        size_t n = o.size();
        for (size_t i = 0; i < n; ++i) {
            Vec2 a = o[(i + n - 1) % n], b = o[i], c = o[(i + 1) % n];
            double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
            double turn = std::abs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy));
            points += 2 + stepsPerRadian * turn;
        }
    }
    return points;
}

ir::NodePtr moduleSquare(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"size", "center"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    double x = 1, y = 1;
    const Value &size = a[0];
    if (size.isNumber()) {
        x = y = size.toNumber();
    } else if (!size.isUndef() && !getVec2(size, x, y)) {
        ev.warn(a.loc(0), "Unable to convert square(size=" + size.toEchoString() +
                              ", ...) parameter to a number or a vec2 of numbers");
        x = y = 1;
    }
    bool center = a[1].isBool() && a[1].boolValue();
    if (!(x > 0 && y > 0) || !std::isfinite(x) || !std::isfinite(y))
        return emptyPrimitive(
            ev, inst,
            "size [" + formatNumber(x) + ", " + formatNumber(y) + "] is not positive and finite");
    Shape2d s;
    s.kind = Shape2dKind::Square;
    s.min = center ? Vec2{-x / 2, -y / 2} : Vec2{0, 0};
    s.max = center ? Vec2{x / 2, y / 2} : Vec2{x, y};
    return shape2dNode(ev, std::move(s), inst);
}

ir::NodePtr moduleCircle(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"r", "d"}, f, dollars.get(), 1);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    Value rv = radiusArgument(ev, a, inst);
    double r = rv.isNumber() ? rv.toNumber() : 1;
    if (!(r > 0) || !std::isfinite(r))
        return emptyPrimitive(ev, inst,
                              "radius " + formatNumber(r) + " is not positive and finite");
    Shape2d s;
    s.kind = Shape2dKind::Circle;
    s.radius = r;
    s.fragments = ev.currentFragments(inst.loc);
    // Its points are made whenever the circle is evaluated or extruded
    ev.chargeGeometryWork(inst.loc, "circle()", static_cast<double>(shapePointCount(s)));
    return shape2dNode(ev, std::move(s), inst);
}

ir::NodePtr modulePolygon(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"points", "paths", "convexity"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    // Points: vec2s of finite numbers; one bad point empties the polygon (an error there)
    Outline points;
    if (a[0].isVector()) {
        const auto &pv = a[0].toVector();
        points.reserve(pv.size());
        for (size_t i = 0; i < pv.size(); ++i) {
            double x, y;
            if (!getVec2(pv[i], x, y) || !std::isfinite(x) || !std::isfinite(y))
                return emptyPrimitive(ev, inst,
                                      "Unable to convert points[" + std::to_string(i) +
                                          "] = " + pv[i].toEchoString() + " to a vec2 of numbers");
            points.push_back({x, y});
        }
    } else if (!a[0].isUndef()) {
        ev.warn(a.loc(0), "polygon(points=" + a[0].toEchoString() + ") is not a list of points");
    }
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    const Value &paths = a[1];
    bool noPaths = !paths.isVector() || paths.toVector().empty();
    if (noPaths) {
        if (points.size() > 2) s.outlines.push_back(points);
    } else {
        // Each path lists point indices; an index is truncated to an unsigned integer and one
        // out of range is skipped with a warning. A path that is not a list is empty.
        const auto &pl = paths.toVector();
        for (size_t p = 0; p < pl.size(); ++p) {
            Outline o;
            if (pl[p].isVector()) {
                const auto &idx = pl[p].toVector();
                for (size_t k = 0; k < idx.size(); ++k) {
                    double v = idx[k].isNumber() ? idx[k].toNumber() : 0;
                    if (v > -1 && v < static_cast<double>(points.size())) {
                        o.push_back(points[static_cast<size_t>(v)]);
                    } else {
                        ev.warn(a.loc(1), "Point index " + formatNumber(v) +
                                              " is out of bounds (from paths[" + std::to_string(p) +
                                              "][" + std::to_string(k) + "])");
                    }
                }
            }
            s.outlines.push_back(std::move(o));
        }
    }
    return shape2dNode(ev, std::move(s), inst);
}

ir::NodePtr moduleOffset(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"r", "delta", "chamfer"}, f, dollars.get(), 1);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    ir::Fragments fragments = ev.currentFragments(inst.loc);

    // r = 1 with round joins unless a numeric r or delta is given; r wins over delta, and
    // chamfer (a true boolean) only counts with delta
    double delta = 1;
    clipper2d::JoinType join = clipper2d::JoinType::Round;
    if (a[0].isNumber()) {
        delta = a[0].toNumber();
    } else if (a[1].isNumber()) {
        delta = a[1].toNumber();
        join = a[2].isBool() && a[2].boolValue() ? clipper2d::JoinType::Square
                                                 : clipper2d::JoinType::Miter;
    }

    // The children's union (no mixing warning: OffsetNode calls applyToChildren2D directly)
    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    ev.instantiateChildren(inst, f, children->children);
    clipper2d::PolygonSet input = evaluate2d(ev, *children);
    if (input.empty()) return ev.newNode(ir::NodeKind::Group, inst.loc);
    if (!std::isfinite(delta)) {
        ev.warn(inst.loc,
                "offset(): " + std::string(join == clipper2d::JoinType::Round ? "r" : "delta") +
                    " = " + formatNumber(delta) +
                    " is not finite; OpenSCAD makes no 2D object of it");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }

    // Round joins follow the circle of radius |delta|: Clipper's arc tolerance is the
    // sagitta of one of the circle's fragments
    double n = meshing::openscadFragments(std::abs(delta), fragments);
    double arcTolerance = std::abs(delta) * (1 - cosDegrees(180 / n));
    // Charged before Clipper makes them: r = 1e9 with $fn = 1e6 gives a million points
    ev.chargeGeometryWork(inst.loc, "offset()", offsetPoints(input, delta, join, arcTolerance));
    clipper2d::PolygonSet result = withClipper(inst.loc, [&] {
        return clipper2d::offset(input, delta, join, kOffsetMiterLimit, arcTolerance);
    });
    return polygonSetNode(ev, std::move(result), inst);
}

ir::NodePtr moduleProjection(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"cut", "convexity"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    bool cut = a[0].isBool() && a[0].boolValue();  // 2021.01: only a boolean sets the mode
    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    ev.instantiateChildren(inst, f, children->children);
    if (contentsOf(ev, *children) & 1)
        ev.warn(inst.loc,
                "projection(): its 2D children are ignored, as in OpenSCAD, which "
                "projects 3D geometry only");
    if (!(contentsOf(ev, *children) & 2)) return ev.newNode(ir::NodeKind::Group, inst.loc);
    // The cut slices each face once; the shadow unites a polygon per face in Clipper, whose
    // PolyTree pass (FixupFirstLefts) grows with the square of their number (5,000 faces of
    // a sphere with $fn = 100: about 25 s), as do the sections of a difference or an
    // intersection, taken in the plane of every face
    double faces = tessellatedFaces(*children, ev.scene());
    if (cut)
        ev.chargeGeometryWork(inst.loc, "projection(cut = true)", faces, "faces");
    else
        ev.chargeGeometryWork(inst.loc, "projection()", faces * faces, "face pairs");
    Tessellation tess(*children, Mat4(), ev.scene());
    clipper2d::PolygonSet result = withClipper(inst.loc, [&] {
        return cut ? projectCut(tess, *children) : projectShadow(tess, *children);
    });
    if (result.empty()) {
        if (cut && ev.state().backgroundDepth == 0)
            ev.warn(inst.loc,
                    "projection(cut = true): the children do not meet the plane z = 0, "
                    "so the cut is empty (OpenSCAD: \"Projection() failed.\")");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }
    return polygonSetNode(ev, std::move(result), inst);
}

}  // namespace

BuiltinFamily shape2dBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"square", moduleSquare}, {"circle", moduleCircle},         {"polygon", modulePolygon},
        {"offset", moduleOffset}, {"projection", moduleProjection},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
