// SPDX-License-Identifier: MIT
// 2D subtrees evaluated to polygon sets as OpenSCAD 2021.01's GeometryEvaluator does
// (applyToChildren2D, visit(TransformNode), visit(LeafNode), visit(OffsetNode)), and the
// offset() module (offset.cc), whose result is such a polygon set.
#include <cmath>

#include "core/meshing/facets.h"
#include "core/math/degree_trig.h"
#include "core/math/float_util.h"
#include "importers/scad/evaluator.h"

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
double offsetPoints(const clipper2d::PolygonSet &input, double delta,
                    clipper2d::JoinType join, double arcTolerance) {
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

}  // namespace

clipper2d::PolygonSet Evaluator::evaluate2d(const ir::Node &n) {
    if (std::optional<clipper2d::PolygonSet> p = polygons2d(n, &n)) return std::move(*p);
    return {};
}

std::optional<clipper2d::PolygonSet> Evaluator::polygons2d(const ir::Node &n,
                                                           const ir::Node *silent) {
    // A leaf: squares and circles are made sanitized, a polygon() is sanitized even-odd
    if (const Shape2d *s = shape2dOf(n)) {
        clipper2d::PolygonSet p;
        p.outlines = shapeOutlines(*s);
        if (s->kind != Shape2dKind::Polygon) {
            p.sanitized = true;
        } else if (s->evaluated) {
            p.sanitized = s->sanitized;
        } else {
            p = withClipper(s->loc, [&] { return clipper2d::sanitize(p); });
        }
        return p;
    }
    if (n.kind == ir::NodeKind::Primitive) return std::nullopt;

    // The children, one entry each: 3D ones (ignored with OpenSCAD's warnings) and those with
    // nothing in them are null (collectChildren2D)
    std::vector<clipper2d::PolygonSet> operands;
    bool warnMixing = &n != silent;
    for (const auto &c : n.children) {
        int d = dimensionOf(*c);
        if (d == 3) {
            if (warnMixing) warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            warn(c->loc, "Ignoring 3D child object for 2D operation");
        }
        std::optional<clipper2d::PolygonSet> p;
        if (d == 2) p = polygons2d(*c, silent);
        operands.push_back(p ? std::move(*p) : clipper2d::PolygonSet{});
    }
    // One child is taken as it is, several are combined by Clipper
    std::optional<clipper2d::PolygonSet> result;
    if (operands.size() == 1) {
        if (!operands[0].empty()) result = std::move(operands[0]);
    } else if (operands.size() > 1) {
        clipper2d::BoolOp op = n.kind == ir::NodeKind::Intersection ? clipper2d::BoolOp::Intersection
                               : n.kind == ir::NodeKind::Difference ? clipper2d::BoolOp::Difference
                                                                    : clipper2d::BoolOp::Union;
        result = withClipper(n.loc, [&] { return clipper2d::apply(operands, op); });
    }
    if (n.kind != ir::NodeKind::Transform || !result) return result;

    // A transform acts on the points (rows and columns 0, 1, 3 of its matrix); one that turns
    // the outlines over makes a sanitized set sanitized again
    Affine2 t = Affine2::fromMat4(n.matrix);
    if (!(t.det() != 0)) {
        warn(n.loc, "Scaling a 2D object with 0 - removing object");
        return clipper2d::PolygonSet{};
    }
    for (Outline &o : result->outlines)
        for (Vec2 &v : o) v = t.apply(v);
    if (result->sanitized && t.det() <= 0)
        result = withClipper(n.loc, [&] { return clipper2d::sanitize(*result); });
    return result;
}

ir::NodePtr Evaluator::moduleOffset(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"r", "delta", "chamfer"}, f, dollars.get(), 1);
    FrameGuard g(dyn_, dollars.get());
    ir::Fragments fragments = currentFragments(inst.loc);

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
    ir::NodePtr children = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, f, children->children);
    clipper2d::PolygonSet input = evaluate2d(*children);
    if (input.empty()) return newNode(ir::NodeKind::Group, inst.loc);
    if (!std::isfinite(delta)) {
        warn(inst.loc, "offset(): " + std::string(join == clipper2d::JoinType::Round ? "r" : "delta") +
                           " = " + formatNumber(delta) +
                           " is not finite; OpenSCAD makes no 2D object of it");
        return newNode(ir::NodeKind::Group, inst.loc);
    }

    // Round joins follow the circle of radius |delta|: Clipper's arc tolerance is the
    // sagitta of one of the circle's fragments
    double n = meshing::openscadFragments(std::abs(delta), fragments);
    double arcTolerance = std::abs(delta) * (1 - cosDegrees(180 / n));
    // Charged before Clipper makes them: r = 1e9 with $fn = 1e6 gives a million points
    chargeGeometryWork(inst.loc, "offset()", offsetPoints(input, delta, join, arcTolerance));
    clipper2d::PolygonSet result = withClipper(inst.loc, [&] {
        return clipper2d::offset(input, delta, join, kOffsetMiterLimit, arcTolerance);
    });
    return polygonSetNode(std::move(result), inst);
}

ir::NodePtr Evaluator::polygonSetNode(clipper2d::PolygonSet set, const ModuleInstantiation &inst) {
    if (set.empty()) return newNode(ir::NodeKind::Group, inst.loc);
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    s.outlines = std::move(set.outlines);
    s.evaluated = true;
    s.sanitized = set.sanitized;
    return shape2dNode(std::move(s), inst);
}

}  // namespace rt::scad
