// SPDX-License-Identifier: MIT
// Builtin operations over their children's points: hull, minkowski, resize.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/projection.h"

namespace rt::scad {

namespace {

/// Most convex parts a 3D minkowski() builds (the product of its operands' part counts):
/// each part is a hull of pairwise sums, so this bounds the work and the primitives made.
constexpr size_t kMaxMinkowskiParts = 100'000;

/// Gives every primitive of the subtree the material.
void recolour(ir::Node &n, int material) {
    if (n.kind == ir::NodeKind::Primitive) n.material = material;
    for (auto &c : n.children) recolour(*c, material);
}

/// 2021.01's resize scale per axis (CGALUtils / PolySet / Polygon2d resize): an axis with a
/// positive new size is scaled to it; one without, when `autosize` is set for it, takes the
/// scale of the axis with the largest new size; the rest keep 1. Sizes that are not positive
/// (0, negative, NaN) count as not given [verified with 2021.01: resize([-10, 5, 0],
/// auto = true) scales x by 5/4].
std::array<double, 3> resizeScale(const double newsize[3], const bool autosize[3],
                                  const double size[3], int dims) {
    std::array<double, 3> scale{1, 1, 1};
    int largest = 0;
    for (int i = 0; i < dims; ++i) {
        if (newsize[i] > 0 && size[i] > 0) scale[i] = newsize[i] / size[i];
        if (newsize[i] > newsize[largest]) largest = i;
    }
    double autoscale =
        newsize[largest] > 0 && size[largest] > 0 ? newsize[largest] / size[largest] : 1;
    for (int i = 0; i < dims; ++i)
        if (autosize[i] && !(newsize[i] > 0)) scale[i] = autoscale;
    return scale;
}

ir::NodePtr moduleHull(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    ev.bindBuiltin(inst, {}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    // The children are only a source of points; their tree is dropped afterwards
    ir::NodePtr children = pointSourceChildren(ev, inst, f);
    // OpenSCAD's hull takes the dimension of its first child with geometry; the other
    // dimension's children are ignored with its warnings
    if (dimensionOf(ev, *children) == 2) return hull2d(ev, *children, inst);
    warnIgnored2d(ev, *children);
    ev.chargeGeometryWork(inst.loc, "hull()", tessellatedFaces(*children, ev.scene()));
    std::vector<Vec3> points;
    if (!meshing::gatherHullPoints(*children, ev.scene(), ev.diag(), points))
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    meshing::HullResult hull = meshing::convexHull(points);
    if (hull.unsettledPoints > 0)
        ev.warn(inst.loc, "hull(): " + std::to_string(hull.unsettledPoints) +
                              " points too close to the hull's surface for the arithmetic to place "
                              "were left out; they lie within rounding of it");
    if (hull.kind == meshing::HullKind::Solid) {
        ir::NodePtr n = primitive(ev, std::move(hull.polytope), inst, f);
        // Its points are fixed: no $fn/$fa/$fs applies to a hull (nor does --facets)
        n->fragments = ir::Fragments{};
        return n;
    }
    // OpenSCAD makes a flat or empty result; a solid renderer has nothing to draw
    if (hull.kind != meshing::HullKind::Empty && ev.state().backgroundDepth == 0)
        ev.warn(inst.loc, "hull(): the children's " + std::to_string(points.size()) +
                              " points are " + meshing::hullKindName(hull.kind) +
                              ", so the hull has no volume; left out");
    return ev.newNode(ir::NodeKind::Group, inst.loc);
}

ir::NodePtr moduleMinkowski(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    ev.bindBuiltin(inst, {"convexity"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    // The children are only a source of points, as under hull()
    ir::NodePtr children = pointSourceChildren(ev, inst, f);
    int dims = dimensionOf(ev, *children);
    if (dims == 0) return ev.newNode(ir::NodeKind::Group, inst.loc);

    if (dims == 2) {
        // 2021.01: the 2D children with geometry, each as its polygon set, folded by
        // ClipperUtils::applyMinkowski (3D children ignored with OpenSCAD's warnings)
        std::vector<clipper2d::PolygonSet> operands;
        for (const ir::Node *c : children2d(ev, *children, true))
            if (std::optional<clipper2d::PolygonSet> set = polygons2d(ev, *c, nullptr))
                operands.push_back(std::move(*set));
        if (operands.empty()) return ev.newNode(ir::NodeKind::Group, inst.loc);
        // Every outline point of one operand meets every point of the next (a quad each)
        double points = 0, quads = 0;
        for (const clipper2d::PolygonSet &set : operands) {
            double n = 0;
            for (const Outline &o : set.outlines) n += static_cast<double>(o.size());
            quads += points * n;
            points += n;
        }
        ev.chargeGeometryWork(inst.loc, "minkowski()", quads, "quads");
        return polygonSetNode(
            ev, withClipper(inst.loc, [&] { return clipper2d::minkowski(operands); }), inst);
    }

    // The children as OpenSCAD tessellates them, before any point is gathered
    ev.chargeGeometryWork(inst.loc, "minkowski()", tessellatedFaces(*children, ev.scene()),
                          "faces");

    // 3D: the sum distributes over unions; the sum of two convex parts is the hull of the
    // pairwise sums of their points (OpenSCAD's minkowski3 does the same on its convex parts).
    // A part that is not convex (a solid S: a difference, a non-convex mesh, ...) sums with a
    // convex part K as S moved by a point of K together with the hulls of K and each convex
    // piece of S's boundary: a point of S + K whose copy of -K meets S's boundary is in one of
    // those hulls, and one whose copy lies inside S is in the moved S.
    warnIgnored2d(ev, *children);
    struct Part {
        const ir::Node *solid = nullptr;  ///< a solid, placed by `placement`; null: convex
        Mat4 placement;
        /// A convex part: one piece, the points it is the hull of; a solid: convex pieces that
        /// lie in it and cover its boundary
        std::vector<std::vector<Vec3>> pieces;
    };
    auto partsOf = [&](const ir::Node &c, std::vector<Part> &out) {
        std::vector<std::vector<Vec3>> convex;
        std::vector<Part> solids;
        bool ok = meshing::gatherConvexParts(
            c, ev.scene(), ev.diag(), convex, [&](const ir::Node &n, const Mat4 &m) {
                Part p;
                p.solid = &n;
                p.placement = m;
                double faces = tessellatedFaces(n, ev.scene());
                ev.chargeGeometryWork(inst.loc, "minkowski()", faces * faces, "face pairs");
                Tessellation tess(n, m, ev.scene());
                p.pieces = withClipper(n.loc, [&] { return solidBoundary(tess, n); });
                if (!p.pieces.empty()) solids.push_back(std::move(p));
            });
        for (auto &pts : convex) out.push_back(Part{nullptr, Mat4(), {std::move(pts)}});
        for (auto &p : solids) out.push_back(std::move(p));
        return ok;
    };
    auto hullOfSums = [&](const std::vector<Vec3> &p, const std::vector<Vec3> &q,
                          std::vector<Part> &out) {
        if (p.size() * q.size() > meshing::kMaxHullPoints) {
            ev.warn(inst.loc, "minkowski(): a sum of " + std::to_string(p.size()) + " and " +
                                  std::to_string(q.size()) + " points is more than the " +
                                  std::to_string(meshing::kMaxHullPoints) +
                                  " a hull may have; left out");
            return false;
        }
        ev.chargeGeometryWork(inst.loc, "minkowski()", static_cast<double>(p.size() * q.size()));
        std::vector<Vec3> pts;
        pts.reserve(p.size() * q.size());
        for (const Vec3 &a : p)
            for (const Vec3 &b : q) pts.push_back(a + b);
        meshing::HullResult h = meshing::convexHull(pts);
        if (h.kind == meshing::HullKind::Solid)
            out.push_back(Part{nullptr, Mat4(), {std::move(h.polytope.vertices)}});
        return true;
    };
    auto moved = [](const Part &s, const Vec3 &by) {
        Part p;
        p.solid = s.solid;
        p.placement = Mat4::translate(by) * s.placement;
        for (const auto &piece : s.pieces) {
            p.pieces.push_back(piece);
            for (Vec3 &v : p.pieces.back()) v = v + by;
        }
        return p;
    };
    std::vector<Part> sum;
    bool first = true;
    for (const auto &c : children->children) {
        if (dimensionOf(ev, *c) != 3) continue;
        std::vector<Part> parts;
        if (!partsOf(*c, parts)) return ev.newNode(ir::NodeKind::Group, inst.loc);
        if (parts.empty()) continue;  // an empty child is passed over, as in 2021.01
        if (first) {
            sum = std::move(parts);
            first = false;
            continue;
        }
        // How many hulls the next sum makes, before making any
        size_t count = 0;
        for (const Part &a : sum)
            for (const Part &b : parts) count += a.pieces.size() * b.pieces.size();
        if (count > kMaxMinkowskiParts) {
            ev.warn(inst.loc, "minkowski(): " + std::to_string(count) +
                                  " convex parts would be summed, "
                                  "more than the " +
                                  std::to_string(kMaxMinkowskiParts) + " allowed; left out");
            return ev.newNode(ir::NodeKind::Group, inst.loc);
        }
        std::vector<Part> next;
        for (const Part &a : sum)
            for (const Part &b : parts) {
                if (a.solid) next.push_back(moved(a, b.pieces[0][0]));
                if (b.solid) next.push_back(moved(b, a.pieces[0][0]));
                for (const auto &p : a.pieces)
                    for (const auto &q : b.pieces)
                        if (!hullOfSums(p, q, next))
                            return ev.newNode(ir::NodeKind::Group, inst.loc);
            }
        sum = std::move(next);
    }
    ir::NodePtr result = ev.newNode(ir::NodeKind::Union, inst.loc);
    int material = resolveMaterial(ev, inst.loc);
    for (Part &p : sum) {
        if (p.solid) {
            // The solid itself, moved, in the minkowski()'s material (as OpenSCAD's result is
            // one object)
            ir::NodePtr placed = ev.newNode(ir::NodeKind::Transform, inst.loc);
            placed->matrix = p.placement;
            ir::NodePtr copy = p.solid->clone();
            recolour(*copy, material);
            placed->children.push_back(std::move(copy));
            result->children.push_back(std::move(placed));
            continue;
        }
        // A single part may still be flat (a sum of flat children): no volume to draw
        meshing::HullResult h = meshing::convexHull(p.pieces[0]);
        if (h.kind != meshing::HullKind::Solid) continue;
        ir::NodePtr n = primitive(ev, std::move(h.polytope), inst, f);
        n->fragments = ir::Fragments{};  // fixed points: no $fn/$fa/$fs (nor --facets) applies
        result->children.push_back(std::move(n));
    }
    if (result->children.size() == 1) return std::move(result->children[0]);
    if (result->children.empty()) result->kind = ir::NodeKind::Group;
    return result;
}

ir::NodePtr moduleResize(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"newsize", "auto", "convexity"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    // 2021.01 (cgaladv.cc): up to three numbers of a vector (anything else counts as 0);
    // `auto` as one bool for every axis or a vector of truthy values
    double newsize[3] = {0, 0, 0};
    if (a[0].isVector()) {
        const auto &v = a[0].toVector();
        for (size_t i = 0; i < 3 && i < v.size(); ++i)
            if (v[i].isNumber()) newsize[i] = v[i].toNumber();
    }
    bool autosize[3] = {false, false, false};
    if (a[1].isVector()) {
        const auto &v = a[1].toVector();
        for (size_t i = 0; i < 3 && i < v.size(); ++i) autosize[i] = v[i].toBool();
    } else if (a[1].isBool()) {
        autosize[0] = autosize[1] = autosize[2] = a[1].boolValue();
    }

    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    ev.instantiateChildren(inst, f, children->children);
    int dims = dimensionOf(ev, *children);
    if (dims == 0) return children;

    // The bounding box of what OpenSCAD evaluates: the Clipper polygon set in 2D, the
    // tessellated points in 3D
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (dims == 2) {
        clipper2d::PolygonSet set = evaluate2d(ev, *children);
        if (set.empty()) return ev.newNode(ir::NodeKind::Group, inst.loc);
        lo[0] = lo[1] = std::numeric_limits<double>::infinity();
        hi[0] = hi[1] = -lo[0];
        for (const Outline &o : set.outlines)
            for (Vec2 p : o) {
                lo[0] = std::min(lo[0], p.x), hi[0] = std::max(hi[0], p.x);
                lo[1] = std::min(lo[1], p.y), hi[1] = std::max(hi[1], p.y);
            }
    } else {
        warnIgnored2d(ev, *children);
        ev.chargeGeometryWork(inst.loc, "resize()", tessellatedFaces(*children, ev.scene()));
        std::vector<Vec3> points;
        if (!meshing::gatherHullPoints(*children, ev.scene(), ev.diag(), points, "resize()"))
            return ev.newNode(ir::NodeKind::Group, inst.loc);
        if (points.empty()) return children;
        Bounds3 b;
        for (const Vec3 &p : points) b = unionBounds(b, p);
        for (int i = 0; i < 3; ++i) lo[i] = b.min[i], hi[i] = b.max[i];
    }
    double size[3];
    for (int i = 0; i < 3; ++i) size[i] = hi[i] - lo[i];
    for (int i = 0; i < dims; ++i)
        if (newsize[i] > 0 && !(size[i] > 0))
            ev.warn(inst.loc, "Resize in direction " + std::to_string(i) + " has no effect");
    std::array<double, 3> s = resizeScale(newsize, autosize, size, dims);
    if (!std::isfinite(s[0] * s[1] * s[2]) || s[0] * s[1] * s[2] == 0) {
        // An infinite new size (or one so small its scale underflows) flattens or blows up
        // the geometry: OpenSCAD's result has no volume
        ev.warn(inst.loc, "resize(" + a[0].toEchoString() + ") scales by [" + formatNumber(s[0]) +
                              ", " + formatNumber(s[1]) + ", " + formatNumber(s[2]) +
                              "], which leaves no finite volume; left out");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }
    // Scaled about the origin, not the box's corner
    ir::NodePtr node = ev.newNode(ir::NodeKind::Transform, inst.loc);
    node->matrix = Mat4::scale(Vec3(s[0], s[1], s[2]));
    node->children = std::move(children->children);
    return node;
}

}  // namespace

BuiltinFamily hullMinkowskiBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"hull", moduleHull},
        {"minkowski", moduleMinkowski},
        {"resize", moduleResize},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
