// SPDX-License-Identifier: MIT
// rotate_extrude, lifted to exact 3D CSG like linear_extrude: revolving distributes over 2D
// booleans (a bijection of each half-plane), so each 2D primitive becomes a torus (a circle)
// or a lathe (a polygon's outlines), and the 2D CSG tree a 3D one (OpenSCAD 2021.01
// rotateextrude.cc, GeometryEvaluator.cc rotatePolygon).
#include <cmath>
#include <cstdio>

#include "core/ir/facet_mode.h"
#include "importers/scad/evaluator.h"
#include "importers/scad/revolve.h"

namespace rt::scad {

namespace {

/// A profile whose points span at most this many of Clipper's grid steps in x may vanish on
/// the grid for its size alone.
constexpr double kBelowGridSteps = 4;

std::string rangeText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

}  // namespace

ir::NodePtr Evaluator::moduleRotateExtrude(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // 2021.01: positional file, layer, origin, scale (the deprecated DXF form); named
    // convexity and angle
    BoundArgs a = bindBuiltin(inst, {"file", "layer", "origin", "scale", "convexity", "angle"}, f,
                              dollars.get(), 4);
    FrameGuard g(dyn_, dollars.get());
    RevolveSpec spec;
    spec.loc = inst.loc;
    spec.fragments = currentFragments(inst.loc);
    spec.material = resolveMaterial(inst.loc);
    double angle = 360;
    if (a[5].isNumber()) angle = revolveAngle(a[5].toNumber());

    ir::NodePtr children = newNode(ir::NodeKind::Group, inst.loc);
    children->label = "rotate_extrude children";
    instantiateChildren(inst, f, children->children);
    spec.silentUnion = children.get();
    ir::NodePtr out = newNode(ir::NodeKind::Group, inst.loc);
    out->label = "rotate_extrude";

    if (!a[0].isUndef()) {
        // OpenSCAD reads the file named by any first argument (rotate_extrude(180) opens a
        // DXF file called "180") and ignores the children
        deprecated(a.loc(0), "Support for reading files in rotate_extrude will be removed in "
                             "future releases. Use a child import() instead.",
                   false);
        Dxf2dArgs d = dxfArgs("rotate_extrude", a[1], a[2], a.loc(2), a[3], a.loc(3));
        children->children.clear();
        children->children.push_back(dxfFileShape(a[0], d, inst));
    }
    if (angle == 0) {
        warn(inst.loc, "rotate_extrude(): angle 0 makes empty geometry, as in OpenSCAD");
        return out;
    }
    // OpenSCAD tests the points of the children's polygon set (Clipper's union of them) for
    // the sides of the axis and counts segments from its largest |x|; the lifted solid
    // below is the same set revolved
    XRange range;
    {
        ++quiet_;
        struct Restore {
            int &q;
            ~Restore() { --q; }
        } restore{quiet_};
        clipper2d::PolygonSet polygons = evaluate2d(*children);
        for (const Outline &o : polygons.outlines)
            for (Vec2 p : o) range.add(p.x);
    }
    if (range.empty) {
        // Nothing on OpenSCAD's 2D grid (2^-16): either no area at all, or a profile that
        // small, which OpenSCAD rounds away but the exact revolve below keeps
        // (the points' extent decides: a profile spanning more than a few grid steps that
        // Clipper empties has no area, e.g. two identical outlines under the even-odd rule)
        range = pointRange2d(*children, Affine2());
        if (range.empty || range.min == range.max ||
            range.max - range.min > kBelowGridSteps / clipper2d::kScale)
            return out;
        warn(inst.loc, "rotate_extrude(): the 2D profile is smaller than OpenSCAD's 2D grid "
                       "(1/65536), where OpenSCAD makes nothing of it; scadray revolves it "
                       "exactly");
    }
    if (range.crossesAxis()) {
        diag_.report(Severity::Error, inst.loc,
                     "all points for rotate_extrude() must have the same X coordinate sign "
                     "(range is " + rangeText(range.min) + " -> " + rangeText(range.max) +
                         "); OpenSCAD leaves the rotate_extrude() out, and so does scadray");
        return out;
    }
    // A profile on the -X side revolves as its mirror image turned half a turn; a negative
    // angle sweeps clockwise, which is the positive sweep turned back by the angle
    bool negativeSide = range.min < 0;
    spec.angle = std::abs(angle);
    spec.segments = revolveFragments(range, angle, spec.fragments);
    // OpenSCAD's mesh of it: a ring of the profile's points at every segment
    chargeGeometryWork(inst.loc, "rotate_extrude()",
                       pointCount2d(*children) * (static_cast<double>(spec.segments) + 1));
    double turn = (angle < 0 ? angle : 0) + (negativeSide ? 180 : 0);
    Affine2 mirror;
    if (negativeSide) mirror.m00 = -1;
    ir::NodePtr solid = liftRevolve(*children, spec, mirror, false);
    if (!solid) return out;
    if (turn != 0) {
        ir::NodePtr t = ir::Node::makeTransform(Mat4::rotateZ(turn), inst.loc);
        t->children.push_back(std::move(solid));
        solid = std::move(t);
    }
    out->children.push_back(std::move(solid));
    return out;
}

XRange Evaluator::pointRange2d(const ir::Node &n, const Affine2 &placed) {
    XRange r;
    if (const Shape2d *s = shape2dOf(n)) {
        for (const Outline &o : shapeOutlines(*s))
            for (Vec2 p : o) r.add(placed.apply(p).x);
        return r;
    }
    Affine2 inner = placed;
    if (n.kind == ir::NodeKind::Transform) inner = placed * Affine2::fromMat4(n.matrix);
    for (const ir::Node *c : children2d(n, false, false)) r.add(pointRange2d(*c, inner));
    return r;
}

ir::NodePtr Evaluator::liftRevolve(const ir::Node &n, const RevolveSpec &spec,
                                   const Affine2 &placed, bool subtracted) {
    if (const Shape2d *s = shape2dOf(n)) return revolveShape(*s, spec, placed, subtracted);
    if (n.kind == ir::NodeKind::Primitive) return nullptr;
    // 2D transforms fold into the profile: only a shift along y is a 3D map of the solid
    Affine2 inner = placed;
    ir::NodePtr out;
    if (n.kind == ir::NodeKind::Transform) {
        Affine2 t = Affine2::fromMat4(n.matrix);
        if (!(t.det() != 0)) {
            warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return nullptr;
        }
        inner = placed * t;
        out = newNode(ir::NodeKind::Group, n.loc);
    } else {
        out = newNode(n.kind, n.loc);
    }
    out->label = n.label;
    out->highlight = n.highlight;
    size_t operands = 0;
    for (const ir::Node *c : children2d(n, &n != spec.silentUnion)) {
        bool subtrahend = n.kind == ir::NodeKind::Difference && operands > 0;
        ir::NodePtr lifted = liftRevolve(*c, spec, inner, subtracted || subtrahend);
        ++operands;
        if (lifted) {
            out->children.push_back(std::move(lifted));
        } else if ((n.kind == ir::NodeKind::Difference && operands == 1) ||
                   n.kind == ir::NodeKind::Intersection) {
            return nullptr;
        }
    }
    return out;
}

ir::NodePtr Evaluator::revolveShape(const Shape2d &s, const RevolveSpec &spec,
                                    const Affine2 &placed, bool subtracted) {
    int material = spec.material >= 0 ? spec.material : s.material;
    // What is subtracted reaches one segment beyond both end faces of a partial sweep, on
    // the same segment grid, so no end face of it lies in an end face of what it cuts
    double angle = spec.angle, turn = 0;
    int segments = spec.segments;
    if (subtracted && angle < 360) {
        double step = angle / segments;
        if (angle + 2 * step <= 360) {
            angle += 2 * step;
            segments += 2;
            turn = -step;
        }
    }
    std::vector<Outline> outlines = shapeOutlines(s);
    for (Outline &o : outlines)
        for (Vec2 &p : o) p = placed.apply(p);

    ir::NodePtr leaf;
    double shiftZ = 0;
    std::optional<PlacedCircle> circle;
    if (s.kind == Shape2dKind::Circle) circle = placedCircle(placed, s.radius);
    if (circle && circle->centre.x >= circle->radius) {
        // A torus (a horn torus where the circle touches the axis); its faceted form is the
        // circle's polygon revolved, as in OpenSCAD
        ir::TorusPrim t;
        t.major = circle->centre.x;
        t.minor = circle->radius;
        t.angle = angle;
        t.fragments = segments;
        for (Vec2 p : outlines[0]) t.facetOutline.push_back({std::max(p.x, 0.0), p.y - circle->centre.y});
        shiftZ = circle->centre.y;
        leaf = makeLifted(std::move(t), material, s.loc);
    } else {
        // A lathe of the outlines' parts on the +X side (all of them, but for what is
        // subtracted or intersected); its even-odd fill is OpenSCAD's sanitized polygon's
        ir::LathePrim l;
        l.angle = angle;
        l.fragments = segments;
        // Repeated points and straight corners dropped, as OpenSCAD's Clipper pass does
        for (const Outline &o : outlines) {
            Outline c = cleanOutline(clipToPositiveX(o));
            if (c.size() >= 3 && twiceSignedArea(c) != 0) l.outlines.push_back(toProfile(c));
        }
        if (l.outlines.empty()) return nullptr;
        leaf = makeLifted(std::move(l), material, s.loc);
    }
    leaf->fragments = spec.fragments;
    if (turn == 0 && shiftZ == 0) return leaf;
    ir::NodePtr t = ir::Node::makeTransform(
        Mat4::translate(Vec3(0, 0, shiftZ)) * Mat4::rotateZ(turn), s.loc);
    t->children.push_back(std::move(leaf));
    return t;
}

}  // namespace rt::scad
