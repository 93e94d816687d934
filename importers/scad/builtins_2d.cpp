// SPDX-License-Identifier: MIT
// 2D primitives (square, circle, polygon) and linear_extrude, lifted to exact 3D CSG: the
// extrusion distributes over 2D booleans and 2D transforms, so each 2D primitive becomes a
// box, cylinder, polytope or planar-faced mesh (OpenSCAD 2021.01 primitives.cc,
// linearextrude.cc, GeometryEvaluator.cc).
#include <algorithm>
#include <cmath>

#include "core/meshing/facets.h"
#include "importers/scad/clipper2d.h"
#include "importers/scad/evaluator.h"
#include "importers/scad/extrude.h"

namespace rt::scad {

namespace {

constexpr int k2d = 1, k3d = 2;

/// Subtrahends of a lifted difference reach this fraction of the height beyond the minuend's
/// caps at each end. The result is the same set (the minuend ends at its caps), but no cap
/// of a subtrahend lies in the plane of a minuend cap, which ray tracers would shade at
/// random. 0.05 of a 1-unit plate is also what OpenSCAD's preview adds to subtracted 2D
/// objects (polyset-gl.cc: differences 1.1 thick).
constexpr double kSubtrahendPad = 0.05;

/// A non-uniform scale with one zero axis flattens the top to a segment, which leaves the
/// swept mesh open; that axis is scaled by this instead (far below any visible size).
constexpr double kMinAxisScale = 1e-9;

/// More slices than this are refused: they would only multiply triangles.
constexpr int kMaxSlices = 100000;

/// Clipper's strictly simple pass (regions()) compares every point of an outline with every
/// other (Clipper 6.4.2 DoSimplePolygons): this many such pairs are charged as one unit of
/// geometry work, so a 100,000-point outline (about 10 s of pairs) is what the default
/// budget allows.
constexpr double kPointPairsPerWork = 100;

/// Plates drawn for top-level 2D objects, as OpenSCAD's preview draws them (polyset-gl.cc).
constexpr double kPlateThickness = 1;

/// The z range an extrusion covers with `pad` more at each end where the scale stays at
/// least half of what it is at the nearer end (scale 0 at the top: no pad there), and the
/// scale at both ends of that range.
struct Range {
    double za, zb, ka, kb;
};

Range paddedRange(const ExtrudeSpec &spec, double pad) {
    double h = spec.z1 - spec.z0, s = spec.scale.x;
    double padBottom = s > 1 ? std::min(pad, 0.5 * h / (s - 1)) : pad;
    double padTop = s < 1 ? std::min(pad, 0.5 * s * h / (1 - s)) : pad;
    auto k = [&](double z) { return 1 + (s - 1) * (z - spec.z0) / h; };
    Range r;
    r.za = spec.z0 - padBottom;
    r.zb = spec.z1 + padTop;
    r.ka = padBottom == 0 ? 1 : k(r.za);
    r.kb = padTop == 0 ? s : k(r.zb);
    return r;
}

}  // namespace

bool getVec2(const Value &v, double &x, double &y) {
    if (!v.isVector() || v.toVector().size() != 2) return false;
    const auto &e = v.toVector();
    if (!e[0].isNumber() || !e[1].isNumber()) return false;
    x = e[0].toNumber();
    y = e[1].toNumber();
    return true;
}

// ---------------------------------------------------------------------------------------------
// 2D shapes in the node tree

ir::NodePtr Evaluator::shape2dNode(Shape2d shape, const ModuleInstantiation &inst) {
    shape.material = resolveMaterial(inst.loc);
    shape.loc = inst.loc;
    ir::NodePtr n = newNode(ir::NodeKind::Group, inst.loc);
    n->shape2d = static_cast<int>(shapes2d_.size());
    shapes2d_.push_back(std::move(shape));
    return n;
}

const Shape2d *Evaluator::shape2dOf(const ir::Node &n) const {
    if (n.shape2d < 0) return nullptr;
    if (n.kind != ir::NodeKind::Group || !n.children.empty() ||
        static_cast<size_t>(n.shape2d) >= shapes2d_.size())
        throw EvalError(n.loc, "malformed 2D shape placeholder (internal error)");
    return &shapes2d_[n.shape2d];
}

int Evaluator::contentsOf(const ir::Node &n) const {
    if (shape2dOf(n)) return k2d;
    if (n.kind == ir::NodeKind::Primitive) return k3d;
    int m = 0;
    for (const auto &c : n.children) m |= contentsOf(*c);
    return m;
}

std::vector<const ir::Node *> Evaluator::children2d(const ir::Node &n, bool warnMixing,
                                                   bool warnIgnored) {
    // OpenSCAD's collectChildren2D: each 3D child is ignored with a warning at it, and the
    // first also draws isValidDim's mixing warning, at the same child
    std::vector<const ir::Node *> out;
    for (const auto &c : n.children) {
        int d = dimensionOf(*c);
        if (d == 2) {
            out.push_back(c.get());
        } else if (d == 3 && warnIgnored) {
            if (warnMixing) warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            warn(c->loc, "Ignoring 3D child object for 2D operation");
        }
    }
    return out;
}

void Evaluator::warnIgnored2d(const ir::Node &n) {
    // The 3D counterpart (collectChildren3D), through the whole 3D subtree
    if (n.kind == ir::NodeKind::Primitive || dimensionOf(n) != 3) return;
    bool warnMixing = true;
    for (const auto &c : n.children) {
        if (dimensionOf(*c) == 2) {
            if (warnMixing) warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            warn(c->loc, "Ignoring 2D child object for 3D operation");
        } else {
            warnIgnored2d(*c);
        }
    }
}

int Evaluator::dimensionOf(const ir::Node &n) const {
    if (shape2dOf(n)) return 2;
    if (n.kind == ir::NodeKind::Primitive) return 3;
    for (const auto &c : n.children)
        if (int d = dimensionOf(*c)) return d;
    return 0;
}

ir::NodePtr Evaluator::moduleSquare(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"size", "center"}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    double x = 1, y = 1;
    const Value &size = a[0];
    if (size.isNumber()) {
        x = y = size.toNumber();
    } else if (!size.isUndef() && !getVec2(size, x, y)) {
        warn(a.loc(0), "Unable to convert square(size=" + size.toEchoString() +
                           ", ...) parameter to a number or a vec2 of numbers");
        x = y = 1;
    }
    bool center = a[1].isBool() && a[1].boolValue();
    if (!(x > 0 && y > 0) || !std::isfinite(x) || !std::isfinite(y))
        return emptyPrimitive(inst, "size [" + formatNumber(x) + ", " + formatNumber(y) +
                                        "] is not positive and finite");
    Shape2d s;
    s.kind = Shape2dKind::Square;
    s.min = center ? Vec2{-x / 2, -y / 2} : Vec2{0, 0};
    s.max = center ? Vec2{x / 2, y / 2} : Vec2{x, y};
    return shape2dNode(std::move(s), inst);
}

ir::NodePtr Evaluator::moduleCircle(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"r", "d"}, f, dollars.get(), 1);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    Value rv = radiusArgument(a, inst);
    double r = rv.isNumber() ? rv.toNumber() : 1;
    if (!(r > 0) || !std::isfinite(r))
        return emptyPrimitive(inst, "radius " + formatNumber(r) + " is not positive and finite");
    Shape2d s;
    s.kind = Shape2dKind::Circle;
    s.radius = r;
    s.fragments = currentFragments(inst.loc);
    // Its points are made whenever the circle is evaluated or extruded
    chargeGeometryWork(inst.loc, "circle()", static_cast<double>(shapePointCount(s)));
    return shape2dNode(std::move(s), inst);
}

ir::NodePtr Evaluator::modulePolygon(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"points", "paths", "convexity"}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    // Points: vec2s of finite numbers; one bad point empties the polygon (an error there)
    Outline points;
    if (a[0].isVector()) {
        const auto &pv = a[0].toVector();
        points.reserve(pv.size());
        for (size_t i = 0; i < pv.size(); ++i) {
            double x, y;
            if (!getVec2(pv[i], x, y) || !std::isfinite(x) || !std::isfinite(y))
                return emptyPrimitive(inst, "Unable to convert points[" + std::to_string(i) +
                                                "] = " + pv[i].toEchoString() +
                                                " to a vec2 of numbers");
            points.push_back({x, y});
        }
    } else if (!a[0].isUndef()) {
        warn(a.loc(0), "polygon(points=" + a[0].toEchoString() + ") is not a list of points");
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
                        warn(a.loc(1), "Point index " + formatNumber(v) +
                                           " is out of bounds (from paths[" + std::to_string(p) +
                                           "][" + std::to_string(k) + "])");
                    }
                }
            }
            s.outlines.push_back(std::move(o));
        }
    }
    return shape2dNode(std::move(s), inst);
}

// ---------------------------------------------------------------------------------------------
// linear_extrude

ir::NodePtr Evaluator::moduleLinearExtrude(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    // Positional order of 2021.01: file, layer, height, origin, scale, center, twist, slices
    BoundArgs a = bindBuiltin(inst,
                              {"file", "layer", "height", "origin", "scale", "center", "twist",
                               "slices", "convexity"},
                              f, dollars.get(), 8);
    FrameGuard g(dyn_, dollars.get());
    ExtrudeSpec spec;
    spec.loc = inst.loc;
    spec.fragments = currentFragments(inst.loc);

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
        deprecated(a.loc(0), "Support for reading files in linear_extrude will be removed in "
                             "future releases. Use a child import() instead.",
                   false);
    Dxf2dArgs dxfFile = dxfArgs("linear_extrude", a[1], a[3], a.loc(3), Value(), a.loc(4));
    // Scale: a number or a vec2 (a bad one keeps [1, 1]); negative axes clamp to 0
    Vec2 scale{1, 1};
    if (a[4].isNumber() && std::isfinite(a[4].toNumber())) {
        scale = {a[4].toNumber(), a[4].toNumber()};
    } else if (!a[4].isUndef()) {
        double sx, sy;
        if (getVec2(a[4], sx, sy) && std::isfinite(sx) && std::isfinite(sy))
            scale = {sx, sy};
        else
            warn(a.loc(4), "linear_extrude(..., scale=" + a[4].toEchoString() +
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
    spec.material = resolveMaterial(inst.loc);
    ir::NodePtr children = newNode(ir::NodeKind::Group, inst.loc);
    children->label = "linear_extrude children";
    instantiateChildren(inst, f, children->children);
    if (fromFile) {
        // OpenSCAD reads the file with the x scale and ignores the children
        dxfFile.scale = scale.x;
        children->children.clear();
        children->children.push_back(dxfFileShape(a[0], dxfFile, inst));
    }
    spec.silentUnion = children.get();
    ir::NodePtr out = newNode(ir::NodeKind::Group, inst.loc);
    out->label = "linear_extrude";
    if (!(height > 0)) {
        warn(inst.loc, "linear_extrude(): height " + formatNumber(height) +
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
        chargeGeometryWork(inst.loc, "linear_extrude()", 2 * pointCount2d(*children));
        if (ir::NodePtr solid = lift2d(*children, spec, Affine2(), 0))
            out->children.push_back(std::move(solid));
        return out;
    }
    // Twisted or unevenly scaled: OpenSCAD sweeps one polygon set, the union of the children
    // (Clipper), so several outlines are evaluated first and their regions swept; one outline
    // is swept as it is (the same facets, without Clipper's quantisation)
    std::optional<clipper2d::PolygonSet> evaluated;
    if (outlineCount(*children) > 1) evaluated = evaluate2d(*children);
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
        extentOf2d(*children, Affine2(), scale, rSqr, deltaSqr);
    }
    spec.slices = extrudeSlices(spec.sliceArg, height, spec.twist, scale, rSqr, deltaSqr,
                                spec.fragments);
    if (spec.slices > kMaxSlices) {
        warn(inst.loc, "linear_extrude(): " + std::to_string(spec.slices) +
                           " slices are too many; using " + std::to_string(kMaxSlices));
        spec.slices = kMaxSlices;
    }
    // The swept mesh: a ring of the outlines' points at every slice
    double points = 0;
    if (evaluated) {
        for (const Outline &o : evaluated->outlines) points += static_cast<double>(o.size());
    } else {
        points = pointCount2d(*children);
    }
    chargeGeometryWork(inst.loc, "linear_extrude()", points * (spec.slices + 1));
    ir::NodePtr solid =
        evaluated ? liftRegions(withClipper(inst.loc, [&] { return clipper2d::regions(*evaluated); }),
                                spec, 0, spec.material, inst.loc)
                  : lift2d(*children, spec, Affine2(), 0);
    if (solid) out->children.push_back(std::move(solid));
    return out;
}

double Evaluator::pointCount2d(const ir::Node &n) const {
    if (const Shape2d *s = shape2dOf(n)) return static_cast<double>(shapePointCount(*s));
    double count = 0;
    for (const auto &c : n.children) count += pointCount2d(*c);
    return count;
}

size_t Evaluator::outlineCount(const ir::Node &n) const {
    if (const Shape2d *s = shape2dOf(n)) return shapeOutlines(*s).size();
    size_t count = 0;
    for (const auto &c : n.children) count += outlineCount(*c);
    return count;
}

void Evaluator::extentOf2d(const ir::Node &n, const Affine2 &placed, Vec2 scale, double &rSqr,
                           double &deltaSqr) const {
    if (const Shape2d *s = shape2dOf(n)) {
        for (const Outline &o : shapeOutlines(*s))
            for (Vec2 p : o) {
                Vec2 v = placed.apply(p);
                rSqr = std::max(rSqr, v.x * v.x + v.y * v.y);
                Vec2 d{v.x - v.x * scale.x, v.y - v.y * scale.y};
                deltaSqr = std::max(deltaSqr, d.x * d.x + d.y * d.y);
            }
        return;
    }
    if (n.kind == ir::NodeKind::Primitive || dimensionOf(n) == 3) return;
    Affine2 inner = placed;
    if (n.kind == ir::NodeKind::Transform) inner = placed * Affine2::fromMat4(n.matrix);
    for (const auto &c : n.children) extentOf2d(*c, inner, scale, rSqr, deltaSqr);
}

ir::NodePtr Evaluator::makeLifted(ir::PrimShape shape, int material, const SourceLoc &loc) {
    if (++nodes_ > limits_.maxNodes)
        throw EvalError(loc,
                        "too many geometry nodes: more than " + std::to_string(limits_.maxNodes));
    return ir::Node::makePrimitive(std::move(shape), material, loc);
}

ir::NodePtr Evaluator::lift2d(const ir::Node &n, const ExtrudeSpec &spec, const Affine2 &placed,
                              double pad) {
    if (const Shape2d *s = shape2dOf(n)) return liftShape(*s, spec, placed, pad);
    if (n.kind == ir::NodeKind::Primitive) return nullptr;

    // A transform: in 3D for preview plates; else its 2D part (rows and columns 0, 1, 3),
    // folded into the outlines on the mesh path or lifted to an exact 3D affine map
    Affine2 inner = placed;
    ir::NodePtr out;
    if (n.kind == ir::NodeKind::Transform) {
        Affine2 t = Affine2::fromMat4(n.matrix);
        if (spec.previewTransforms && n.matrix.affineInverse()) {
            out = newNode(ir::NodeKind::Transform, n.loc);
            out->matrix = n.matrix;
        } else if (!(t.det() != 0)) {
            warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return nullptr;
        } else if (spec.meshPath) {
            inner = placed * t;
            out = newNode(ir::NodeKind::Group, n.loc);
        } else {
            // E(A p) = S (M (+) 1) E(p), S(x, y, z) = (x + t k(z), z) with k(z) affine in z
            double beta = (spec.scale.x - 1) / (spec.z1 - spec.z0);
            Mat4 m;
            m.m[0][0] = t.m00;
            m.m[0][1] = t.m01;
            m.m[1][0] = t.m10;
            m.m[1][1] = t.m11;
            m.m[0][2] = t.tx * beta;
            m.m[1][2] = t.ty * beta;
            m.m[0][3] = t.tx * (1 - beta * spec.z0);
            m.m[1][3] = t.ty * (1 - beta * spec.z0);
            out = newNode(ir::NodeKind::Transform, n.loc);
            out->matrix = m;
        }
    } else {
        out = newNode(n.kind, n.loc);
    }
    out->label = n.label;
    out->highlight = n.highlight;

    // Children: 3D ones are ignored, with OpenSCAD's warnings; a difference's subtrahends
    // reach beyond the minuend's caps
    size_t operands = 0;
    double step = kSubtrahendPad * (spec.z1 - spec.z0);
    for (const ir::Node *c : children2d(n, &n != spec.silentUnion)) {
        bool subtrahend = n.kind == ir::NodeKind::Difference && operands > 0;
        ir::NodePtr lifted = lift2d(*c, spec, inner, subtrahend ? pad + step : pad);
        ++operands;
        if (lifted) {
            out->children.push_back(std::move(lifted));
        } else if ((n.kind == ir::NodeKind::Difference && operands == 1) ||
                   n.kind == ir::NodeKind::Intersection) {
            return nullptr;  // nothing to subtract from, or to intersect with
        }
    }
    return out;
}

ir::NodePtr Evaluator::sweptSolid(const Outline &ccw, const ExtrudeSpec &spec, double pad,
                                  int material, const SourceLoc &loc) {
    ir::Mesh mesh;
    mesh.name = "linear_extrude";
    mesh.loc = loc;
    if (spec.meshPath) {
        // Twisted or scaled unevenly: OpenSCAD's slices as a mesh
        Sweep sweep;
        sweep.z0 = spec.z0;
        sweep.z1 = spec.z1;
        sweep.scale1 = spec.scale;
        sweep.rot1 = spec.twist;
        sweep.slices = spec.slices;
        if (!sweepMesh(ccw, sweep, mesh)) {
            warn(loc, "linear_extrude(): an outline of no area is left out");
            return nullptr;
        }
        return makeLifted(ir::MeshPrim{addMesh(std::move(mesh))}, material, loc);
    }
    // Straight: a prism, drawn as its polytope when convex, else as its mesh
    Range r = paddedRange(spec, pad);
    ir::PrismPrim prism = straightPrism(ccw, r.za, r.zb, r.ka, r.kb);
    if (!isConvex(ccw)) {
        if (!prismMesh(prism, mesh)) {
            warn(loc, "linear_extrude(): an outline of no area is left out");
            return nullptr;
        }
        prism.mesh = addMesh(std::move(mesh));
    }
    return makeLifted(prism, material, loc);
}

ir::NodePtr Evaluator::liftShape(const Shape2d &s, const ExtrudeSpec &spec, const Affine2 &placed,
                                 double pad) {
    int material = spec.material >= 0 ? spec.material : s.material;
    if (!spec.meshPath && s.kind == Shape2dKind::Square) {
        Range r = paddedRange(spec, pad);
        if (r.ka == 1 && r.kb == 1) {
            ir::BoxPrim box;
            box.min = Vec3(s.min.x, s.min.y, r.za);
            box.max = Vec3(s.max.x, s.max.y, r.zb);
            return makeLifted(box, material, s.loc);
        }
        return makeLifted(straightPrism(shapeOutlines(s)[0], r.za, r.zb, r.ka, r.kb), material,
                          s.loc);
    }
    if (!spec.meshPath && s.kind == Shape2dKind::Circle) {
        // A cylinder, or a cone when scaled; its polygon has the circle's fragment count
        Range r = paddedRange(spec, pad);
        ir::CylinderPrim c{r.za, r.zb, s.radius * r.ka, s.radius * r.kb};
        // The facets pass counts from the larger radius: $fs grows with it, so that
        // 2 pi r / $fs, and the count, stay the circle's ($fn, when set, does not depend on r)
        ir::Fragments fr = s.fragments;
        if (fr.fn <= 0) fr.fs *= std::max(c.r1, c.r2) / s.radius;
        ir::NodePtr node = makeLifted(c, material, s.loc);
        node->fragments = fr;
        return node;
    }

    // Outlines (placed on the mesh path) as even-odd regions with holes. Outlines that cross
    // themselves or each other are sanitized by Clipper first, as OpenSCAD sanitizes every
    // polygon(); an evaluated polygon set (offset) is nested as Clipper nests it.
    std::vector<Region> regions;
    auto chargePairs = [&] {
        double pairs = 0;
        for (const Outline &o : s.outlines)
            pairs += static_cast<double>(o.size()) * static_cast<double>(o.size());
        chargeGeometryWork(s.loc, "extruding the outline made here",
                           pairs / kPointPairsPerWork,
                           "hundred point pairs (Clipper compares each outline's points with "
                           "one another)");
    };
    if (s.kind == Shape2dKind::Polygon && s.evaluated) {
        chargePairs();
        clipper2d::PolygonSet set{s.outlines, s.sanitized};
        regions = withClipper(s.loc, [&] { return clipper2d::regions(set); });
    } else {
        std::vector<Outline> outlines;
        for (Outline o : shapeOutlines(s)) {
            o = cleanOutline(o);
            if (!o.empty()) outlines.push_back(std::move(o));
        }
        if (s.kind == Shape2dKind::Polygon && outlinesIntersect(outlines)) {
            chargePairs();
            regions = withClipper(s.loc, [&] {
                return clipper2d::regions(clipper2d::sanitize({s.outlines, false}));
            });
        } else {
            regions = evenOddRegions(outlines);
        }
    }
    // Placed on the mesh path (a mirror turns the outlines over: counter-clockwise again)
    if (!placed.isIdentity()) {
        auto place = [&](Outline &o) {
            for (Vec2 &p : o) p = placed.apply(p);
            if (twiceSignedArea(o) < 0) std::reverse(o.begin(), o.end());
        };
        for (Region &r : regions) {
            place(r.outer);
            for (Outline &h : r.holes) place(h);
        }
    }
    if (regions.empty()) {
        warn(s.loc, "polygon(): no outline with area; nothing to extrude");
        return nullptr;
    }
    return liftRegions(regions, spec, pad, material, s.loc);
}

ir::NodePtr Evaluator::liftRegions(const std::vector<Region> &regions, const ExtrudeSpec &spec,
                                   double pad, int material, const SourceLoc &loc) {
    double step = kSubtrahendPad * (spec.z1 - spec.z0);
    ir::NodePtr group = newNode(ir::NodeKind::Group, loc);
    for (const Region &region : regions) {
        ir::NodePtr solid = sweptSolid(region.outer, spec, pad, material, loc);
        if (!solid) continue;
        if (!region.holes.empty()) {
            ir::NodePtr diff = newNode(ir::NodeKind::Difference, loc);
            diff->children.push_back(std::move(solid));
            for (const Outline &hole : region.holes)
                if (ir::NodePtr h = sweptSolid(hole, spec, pad + step, material, loc))
                    diff->children.push_back(std::move(h));
            solid = std::move(diff);
        }
        group->children.push_back(std::move(solid));
    }
    if (group->children.empty()) return nullptr;
    if (group->children.size() == 1) return std::move(group->children[0]);
    return group;
}

// ---------------------------------------------------------------------------------------------
// 2D objects outside any extrusion

int Evaluator::finish2d(ir::Node &n, bool top) {
    if (shape2dOf(n)) return k2d;
    if (n.kind == ir::NodeKind::Primitive) return k3d;
    std::vector<int> masks;
    int all = 0;
    for (auto &c : n.children) {
        masks.push_back(finish2d(*c, false));
        all |= masks.back();
    }
    // Where 3D meets 2D, and at the top, the pure 2D children become plates
    if (all != (k2d | k3d) && !(top && all == k2d)) return all;
    // OpenSCAD's mixing warning (isValidDim) is at the first child whose dimension differs
    // from the first child's
    bool pure2d = std::find(masks.begin(), masks.end(), k2d) != masks.end();
    bool with3d = std::any_of(masks.begin(), masks.end(), [](int m) { return m & k3d; });
    if (pure2d && with3d) {
        auto first = std::find_if(masks.begin(), masks.end(), [](int m) { return m != 0; });
        auto other = std::find_if(first, masks.end(), [&](int m) { return m && m != *first; });
        warn(n.children[other - masks.begin()]->loc, "Mixing 2D and 3D objects is not supported");
    }
    ExtrudeSpec plate;
    plate.z0 = -kPlateThickness / 2;
    plate.z1 = kPlateThickness / 2;
    plate.previewTransforms = true;
    size_t operands = 0;
    for (size_t i = 0; i < n.children.size(); ++i) {
        if (masks[i] == 0) continue;
        bool subtrahend = n.kind == ir::NodeKind::Difference && operands++ > 0;
        if (masks[i] != k2d) continue;
        if (!plateWarned_) {
            warn(n.children[i]->loc,
                 "2D objects outside linear_extrude() are drawn as OpenSCAD's preview draws "
                 "them: plates 1 unit thick, from z = -0.5 to 0.5");
            plateWarned_ = true;
        }
        ir::NodePtr lifted = lift2d(*n.children[i], plate, Affine2(),
                                    subtrahend ? kSubtrahendPad * kPlateThickness : 0);
        n.children[i] = lifted ? std::move(lifted) : newNode(ir::NodeKind::Group, n.loc);
    }
    return all;
}

// ---------------------------------------------------------------------------------------------
// hull() of 2D children (OpenSCAD 2021.01 GeometryEvaluator::applyHull2D)

ir::NodePtr Evaluator::hull2d(const ir::Node &children, const ModuleInstantiation &inst) {
    // OpenSCAD hulls every outline point of its children with CGAL's convex_hull_2
    std::vector<Vec2> points;
    if (!hullPoints2d(children, Affine2(), points)) return newNode(ir::NodeKind::Group, inst.loc);
    size_t count = points.size();
    Hull2d h = convexHull2d(std::move(points));
    if (h.kind != meshing::HullKind::Solid) {
        // OpenSCAD keeps an outline without area, which extrudes and draws as nothing
        if (h.kind != meshing::HullKind::Empty && backgroundDepth_ == 0)
            warn(inst.loc, "hull(): the children's " + std::to_string(count) + " 2D points are " +
                               meshing::hullKindName(h.kind) + ", so the hull has no area; left out");
        return newNode(ir::NodeKind::Group, inst.loc);
    }
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    s.outlines.push_back(std::move(h.ccw));
    s.evaluated = true;  // OpenSCAD's hull is a polygon it does not sanitize
    return shape2dNode(std::move(s), inst);
}

bool Evaluator::hullPoints2d(const ir::Node &n, const Affine2 &placed, std::vector<Vec2> &out) {
    if (const Shape2d *s = shape2dOf(n)) {
        size_t count = shapePointCount(*s);
        if (out.size() + count > meshing::kMaxHullPoints) {
            warn(s->loc, "hull(): this part gives " + std::to_string(count) +
                             " points, more than the " + std::to_string(meshing::kMaxHullPoints) +
                             " a hull may have; the hull is left out");
            return false;
        }
        for (const Outline &o : shapeOutlines(*s))
            for (Vec2 p : o) out.push_back(placed.apply(p));
        return true;
    }
    Affine2 inner = placed;
    if (n.kind == ir::NodeKind::Transform) {
        Affine2 t = Affine2::fromMat4(n.matrix);
        if (!(t.det() != 0)) {
            warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return true;
        }
        inner = placed * t;
    }
    if (n.kind == ir::NodeKind::Intersection || n.kind == ir::NodeKind::Difference) {
        // OpenSCAD hulls the points of the evaluated (Clipper) polygon set
        std::optional<clipper2d::PolygonSet> p = polygons2d(n, nullptr);
        if (!p) return true;
        size_t count = 0;
        for (const Outline &o : p->outlines) count += o.size();
        if (out.size() + count > meshing::kMaxHullPoints) {
            warn(n.loc, "hull(): this part gives " + std::to_string(count) +
                            " points, more than the " + std::to_string(meshing::kMaxHullPoints) +
                            " a hull may have; the hull is left out");
            return false;
        }
        for (const Outline &o : p->outlines)
            for (Vec2 v : o) out.push_back(placed.apply(v));
        return true;
    }
    std::vector<const ir::Node *> operands = children2d(n, true);
    // Groups, unions and transforms: the hull of a union is the hull of its operands' points
    for (const ir::Node *c : operands)
        if (!hullPoints2d(*c, inner, out)) return false;
    return true;
}

}  // namespace rt::scad
