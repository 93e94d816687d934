// SPDX-License-Identifier: MIT
// Builtin extrusions of 2D shapes: linear_extrude, rotate_extrude.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/ir/facet_mode.h"
#include "core/meshing/facets.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/file_support.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/extrude.h"
#include "importers/scad/geometry2d/revolve.h"

namespace rt::scad {

namespace {

/// A non-uniform scale with one zero axis flattens the top to a segment, which leaves the
/// swept mesh open; that axis is scaled by this instead (far below any visible size).
constexpr double kMinAxisScale = 1e-9;

/// More slices than this are refused: they would only multiply triangles.
constexpr int kMaxSlices = 100000;

/// A profile whose points span at most this many of Clipper's grid steps in x may vanish on
/// the grid for its size alone.
constexpr double kBelowGridSteps = 4;

std::string rangeText(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.2f", v);
    return buf;
}

// ---------------------------------------------------------------------------------------------
// linear_extrude

ir::NodePtr moduleLinearExtrude(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // Positional order of 2021.01: file, layer, height, origin, scale, center, twist, slices
    BoundArgs a = ev.bindBuiltin(
        inst,
        {"file", "layer", "height", "origin", "scale", "center", "twist", "slices", "convexity"}, f,
        dollars.get(), 8);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    ExtrudeSpec spec;
    spec.loc = inst.loc;
    spec.fragments = ev.currentFragments(inst.loc);

    // Height: 100 unless a finite `height`, or a first unnamed number (which binds to `file`)
    double height = 100;
    if (a.given[2]) {
        a[2].getFiniteNumber(height);
    } else if (!inst.args.empty() && inst.args[0].name.empty() && a[0].isNumber()) {
        a[0].getFiniteNumber(height);
    }
    // The deprecated file form: the DXF file's polygon instead of the children
    bool fromFile = a[0].isString();
    if (fromFile)
        ev.deprecated(a.loc(0),
                      "Support for reading files in linear_extrude will be removed in "
                      "future releases. Use a child import() instead.",
                      false);
    Dxf2dArgs dxfFile = dxfArgs(ev, "linear_extrude", a[1], a[3], a.loc(3), Value(), a.loc(4));
    // Scale: a number or a vec2 (a bad one keeps [1, 1]); negative axes clamp to 0
    Vec2 scale{1, 1};
    if (a[4].isNumber() && std::isfinite(a[4].toNumber())) {
        scale = {a[4].toNumber(), a[4].toNumber()};
    } else if (!a[4].isUndef()) {
        double sx, sy;
        if (getVec2(a[4], sx, sy) && std::isfinite(sx) && std::isfinite(sy))
            scale = {sx, sy};
        else
            ev.warn(a.loc(4), "linear_extrude(..., scale=" + a[4].toEchoString() +
                                  ") could not be converted");
    }
    scale.x = std::max(scale.x, 0.0);
    scale.y = std::max(scale.y, 0.0);
    bool center = a[5].isBool() && a[5].boolValue();
    a[6].getFiniteNumber(spec.twist);
    double slices = 0;
    a[7].getFiniteNumber(slices);
    spec.sliceArg = slices >= 1 ? static_cast<int>(std::min(slices, 2.0 * kMaxSlices)) : 0;

    // The extrusion takes the colour and material at the call, as OpenSCAD's preview does
    spec.material = resolveMaterial(ev, inst.loc);
    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    children->label = "linear_extrude children";
    ev.instantiateChildren(inst, f, children->children);
    if (fromFile) {
        // OpenSCAD reads the file with the x scale and ignores the children
        dxfFile.scale = scale.x;
        children->children.clear();
        children->children.push_back(dxfFileShape(ev, a[0], dxfFile, inst));
    }
    spec.silentUnion = children.get();
    ir::NodePtr out = ev.newNode(ir::NodeKind::Group, inst.loc);
    out->label = "linear_extrude";
    if (!(height > 0)) {
        ev.warn(inst.loc, "linear_extrude(): height " + formatNumber(height) +
                              " is not positive; OpenSCAD makes empty geometry");
        return out;
    }
    spec.z0 = center ? -height / 2 : 0;
    spec.z1 = center ? height / 2 : height;
    if ((scale.x == 0) != (scale.y == 0)) {
        (scale.x == 0 ? scale.x : scale.y) = kMinAxisScale;
    }
    spec.scale = scale;
    spec.meshPath = spec.twist != 0 || scale.x != scale.y;
    if (!spec.meshPath) {
        // A prism per outline: its points at both ends
        ev.chargeGeometryWork(inst.loc, "linear_extrude()", 2 * pointCount2d(ev, *children));
        if (ir::NodePtr solid = lift2d(ev, *children, spec, Affine2(), 0))
            out->children.push_back(std::move(solid));
        return out;
    }
    // Twisted or unevenly scaled: OpenSCAD sweeps one polygon set, the union of the children
    // (Clipper), so several outlines are evaluated first and their regions swept; one outline
    // is swept as it is (the same facets, without Clipper's quantisation)
    std::optional<clipper2d::PolygonSet> evaluated;
    if (outlineCount(ev, *children) > 1) evaluated = evaluate2d(ev, *children);
    // One slice count for the whole 2D child, from its farthest points (extrudePolygon)
    double rSqr = 0, deltaSqr = 0;
    if (evaluated) {
        for (const Outline &o : evaluated->outlines)
            for (Vec2 v : o) {
                rSqr = std::max(rSqr, v.x * v.x + v.y * v.y);
                Vec2 d{v.x - v.x * scale.x, v.y - v.y * scale.y};
                deltaSqr = std::max(deltaSqr, d.x * d.x + d.y * d.y);
            }
    } else {
        extentOf2d(ev, *children, Affine2(), scale, rSqr, deltaSqr);
    }
    spec.slices =
        extrudeSlices(spec.sliceArg, height, spec.twist, scale, rSqr, deltaSqr, spec.fragments);
    if (spec.slices > kMaxSlices) {
        ev.warn(inst.loc, "linear_extrude(): " + std::to_string(spec.slices) +
                              " slices are too many; using " + std::to_string(kMaxSlices));
        spec.slices = kMaxSlices;
    }
    // The swept mesh: a ring of the outlines' points at every slice
    double points = 0;
    if (evaluated) {
        for (const Outline &o : evaluated->outlines) points += static_cast<double>(o.size());
    } else {
        points = pointCount2d(ev, *children);
    }
    ev.chargeGeometryWork(inst.loc, "linear_extrude()", points * (spec.slices + 1));
    ir::NodePtr solid =
        evaluated
            ? liftRegions(ev, withClipper(inst.loc, [&] { return clipper2d::regions(*evaluated); }),
                          spec, 0, spec.material, inst.loc)
            : lift2d(ev, *children, spec, Affine2(), 0);
    if (solid) out->children.push_back(std::move(solid));
    return out;
}

ir::NodePtr moduleRotateExtrude(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // 2021.01: positional file, layer, origin, scale (the deprecated DXF form); named
    // convexity and angle
    BoundArgs a = ev.bindBuiltin(inst, {"file", "layer", "origin", "scale", "convexity", "angle"},
                                 f, dollars.get(), 4);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    RevolveSpec spec;
    spec.loc = inst.loc;
    spec.fragments = ev.currentFragments(inst.loc);
    spec.material = resolveMaterial(ev, inst.loc);
    double angle = 360;
    if (a[5].isNumber()) angle = revolveAngle(a[5].toNumber());

    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    children->label = "rotate_extrude children";
    ev.instantiateChildren(inst, f, children->children);
    spec.silentUnion = children.get();
    ir::NodePtr out = ev.newNode(ir::NodeKind::Group, inst.loc);
    out->label = "rotate_extrude";

    if (!a[0].isUndef()) {
        // OpenSCAD reads the file named by any first argument (rotate_extrude(180) opens a
        // DXF file called "180") and ignores the children
        ev.deprecated(a.loc(0),
                      "Support for reading files in rotate_extrude will be removed in "
                      "future releases. Use a child import() instead.",
                      false);
        Dxf2dArgs d = dxfArgs(ev, "rotate_extrude", a[1], a[2], a.loc(2), a[3], a.loc(3));
        children->children.clear();
        children->children.push_back(dxfFileShape(ev, a[0], d, inst));
    }
    if (angle == 0) {
        ev.warn(inst.loc, "rotate_extrude(): angle 0 makes empty geometry, as in OpenSCAD");
        return out;
    }
    // OpenSCAD tests the points of the children's polygon set (Clipper's union of them) for
    // the sides of the axis and counts segments from its largest |x|; the lifted solid
    // below is the same set revolved
    XRange range;
    {
        ++ev.state().quiet;
        struct Restore {
            int &q;
            ~Restore() { --q; }
        } restore{ev.state().quiet};
        clipper2d::PolygonSet polygons = evaluate2d(ev, *children);
        for (const Outline &o : polygons.outlines)
            for (Vec2 p : o) range.add(p.x);
    }
    if (range.empty) {
        // Nothing on OpenSCAD's 2D grid (2^-16): either no area at all, or a profile that
        // small, which OpenSCAD rounds away but the exact revolve below keeps
        // (the points' extent decides: a profile spanning more than a few grid steps that
        // Clipper empties has no area, e.g. two identical outlines under the even-odd rule)
        range = pointRange2d(ev, *children, Affine2());
        if (range.empty || range.min == range.max ||
            range.max - range.min > kBelowGridSteps / clipper2d::kScale)
            return out;
        ev.warn(inst.loc,
                "rotate_extrude(): the 2D profile is smaller than OpenSCAD's 2D grid "
                "(1/65536), where OpenSCAD makes nothing of it; scadray revolves it "
                "exactly");
    }
    if (range.crossesAxis()) {
        ev.diag().report(Severity::Error, inst.loc,
                         "all points for rotate_extrude() must have the same X coordinate sign "
                         "(range is " +
                             rangeText(range.min) + " -> " + rangeText(range.max) +
                             "); OpenSCAD leaves the rotate_extrude() out, and so does scadray");
        return out;
    }
    // A profile on the -X side revolves as its mirror image turned half a turn; a negative
    // angle sweeps clockwise, which is the positive sweep turned back by the angle
    bool negativeSide = range.min < 0;
    spec.angle = std::abs(angle);
    spec.segments = revolveFragments(range, angle, spec.fragments);
    // OpenSCAD's mesh of it: a ring of the profile's points at every segment
    ev.chargeGeometryWork(inst.loc, "rotate_extrude()",
                          pointCount2d(ev, *children) * (static_cast<double>(spec.segments) + 1));
    double turn = (angle < 0 ? angle : 0) + (negativeSide ? 180 : 0);
    Affine2 mirror;
    if (negativeSide) mirror.m00 = -1;
    ir::NodePtr solid = liftRevolve(ev, *children, spec, mirror, false);
    if (!solid) return out;
    if (turn != 0) {
        ir::NodePtr t = ir::Node::makeTransform(Mat4::rotateZ(turn), inst.loc);
        t->children.push_back(std::move(solid));
        solid = std::move(t);
    }
    out->children.push_back(std::move(solid));
    return out;
}

}  // namespace

BuiltinFamily extrusionBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"linear_extrude", moduleLinearExtrude},
        {"rotate_extrude", moduleRotateExtrude},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
