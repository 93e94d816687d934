// SPDX-License-Identifier: MIT
// 2D shapes in the node tree: placeholders, their Clipper evaluation, their lifting into 3D.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/ir/facet_mode.h"
#include "core/math/degree_trig.h"
#include "core/math/float_util.h"
#include "core/meshing/facets.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/extrude.h"
#include "importers/scad/geometry2d/revolve.h"

namespace rt::scad {

namespace {

constexpr int k2d = 1, k3d = 2;

/// Subtrahends of a lifted difference reach this fraction of the height beyond the minuend's
/// caps at each end. The result is the same set (the minuend ends at its caps), but no cap
/// of a subtrahend lies in the plane of a minuend cap, which ray tracers would shade at
/// random. 0.05 of a 1-unit plate is also what OpenSCAD's preview adds to subtracted 2D
/// objects (polyset-gl.cc: differences 1.1 thick).
constexpr double kSubtrahendPad = 0.05;

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

ir::NodePtr shape2dNode(Evaluator &ev, Shape2d shape, const ModuleInstantiation &inst) {
    shape.material = resolveMaterial(ev, inst.loc);
    shape.loc = inst.loc;
    ir::NodePtr n = ev.newNode(ir::NodeKind::Group, inst.loc);
    n->shape2d = static_cast<int>(ev.state().shapes2d.size());
    ev.state().shapes2d.push_back(std::move(shape));
    return n;
}

const Shape2d *shape2dOf(Evaluator &ev, const ir::Node &n) {
    if (n.shape2d < 0) return nullptr;
    if (n.kind != ir::NodeKind::Group || !n.children.empty() ||
        static_cast<size_t>(n.shape2d) >= ev.state().shapes2d.size())
        throw EvalError(n.loc, "malformed 2D shape placeholder (internal error)");
    return &ev.state().shapes2d[n.shape2d];
}

int contentsOf(Evaluator &ev, const ir::Node &n) {
    if (shape2dOf(ev, n)) return k2d;
    if (n.kind == ir::NodeKind::Primitive) return k3d;
    int m = 0;
    for (const auto &c : n.children) m |= contentsOf(ev, *c);
    return m;
}

std::vector<const ir::Node *> children2d(Evaluator &ev, const ir::Node &n, bool warnMixing,
                                         bool warnIgnored) {
    // OpenSCAD's collectChildren2D: each 3D child is ignored with a warning at it, and the
    // first also draws isValidDim's mixing warning, at the same child
    std::vector<const ir::Node *> out;
    for (const auto &c : n.children) {
        int d = dimensionOf(ev, *c);
        if (d == 2) {
            out.push_back(c.get());
        } else if (d == 3 && warnIgnored) {
            if (warnMixing) ev.warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            ev.warn(c->loc, "Ignoring 3D child object for 2D operation");
        }
    }
    return out;
}

void warnIgnored2d(Evaluator &ev, const ir::Node &n) {
    // The 3D counterpart (collectChildren3D), through the whole 3D subtree
    if (n.kind == ir::NodeKind::Primitive || dimensionOf(ev, n) != 3) return;
    bool warnMixing = true;
    for (const auto &c : n.children) {
        if (dimensionOf(ev, *c) == 2) {
            if (warnMixing) ev.warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            ev.warn(c->loc, "Ignoring 2D child object for 3D operation");
        } else {
            warnIgnored2d(ev, *c);
        }
    }
}

int dimensionOf(Evaluator &ev, const ir::Node &n) {
    if (shape2dOf(ev, n)) return 2;
    if (n.kind == ir::NodeKind::Primitive) return 3;
    for (const auto &c : n.children)
        if (int d = dimensionOf(ev, *c)) return d;
    return 0;
}

ir::NodePtr polygonSetNode(Evaluator &ev, clipper2d::PolygonSet set,
                           const ModuleInstantiation &inst) {
    if (set.empty()) return ev.newNode(ir::NodeKind::Group, inst.loc);
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    s.outlines = std::move(set.outlines);
    s.evaluated = true;
    s.sanitized = set.sanitized;
    return shape2dNode(ev, std::move(s), inst);
}

clipper2d::PolygonSet evaluate2d(Evaluator &ev, const ir::Node &n) {
    if (std::optional<clipper2d::PolygonSet> p = polygons2d(ev, n, &n)) return std::move(*p);
    return {};
}

std::optional<clipper2d::PolygonSet> polygons2d(Evaluator &ev, const ir::Node &n,
                                                const ir::Node *silent) {
    // A leaf: squares and circles are made sanitized, a polygon() is sanitized even-odd
    if (const Shape2d *s = shape2dOf(ev, n)) {
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
        int d = dimensionOf(ev, *c);
        if (d == 3) {
            if (warnMixing) ev.warn(c->loc, "Mixing 2D and 3D objects is not supported");
            warnMixing = false;
            ev.warn(c->loc, "Ignoring 3D child object for 2D operation");
        }
        std::optional<clipper2d::PolygonSet> p;
        if (d == 2) p = polygons2d(ev, *c, silent);
        operands.push_back(p ? std::move(*p) : clipper2d::PolygonSet{});
    }
    // One child is taken as it is, several are combined by Clipper
    std::optional<clipper2d::PolygonSet> result;
    if (operands.size() == 1) {
        if (!operands[0].empty()) result = std::move(operands[0]);
    } else if (operands.size() > 1) {
        clipper2d::BoolOp op = n.kind == ir::NodeKind::Intersection
                                   ? clipper2d::BoolOp::Intersection
                               : n.kind == ir::NodeKind::Difference ? clipper2d::BoolOp::Difference
                                                                    : clipper2d::BoolOp::Union;
        result = withClipper(n.loc, [&] { return clipper2d::apply(operands, op); });
    }
    if (n.kind != ir::NodeKind::Transform || !result) return result;

    // A transform acts on the points (rows and columns 0, 1, 3 of its matrix); one that turns
    // the outlines over makes a sanitized set sanitized again
    Affine2 t = Affine2::fromMat4(n.matrix);
    if (!(t.det() != 0)) {
        ev.warn(n.loc, "Scaling a 2D object with 0 - removing object");
        return clipper2d::PolygonSet{};
    }
    for (Outline &o : result->outlines)
        for (Vec2 &v : o) v = t.apply(v);
    if (result->sanitized && t.det() <= 0)
        result = withClipper(n.loc, [&] { return clipper2d::sanitize(*result); });
    return result;
}

double pointCount2d(Evaluator &ev, const ir::Node &n) {
    if (const Shape2d *s = shape2dOf(ev, n)) return static_cast<double>(shapePointCount(*s));
    double count = 0;
    for (const auto &c : n.children) count += pointCount2d(ev, *c);
    return count;
}

size_t outlineCount(Evaluator &ev, const ir::Node &n) {
    if (const Shape2d *s = shape2dOf(ev, n)) return shapeOutlines(*s).size();
    size_t count = 0;
    for (const auto &c : n.children) count += outlineCount(ev, *c);
    return count;
}

void extentOf2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed, Vec2 scale, double &rSqr,
                double &deltaSqr) {
    if (const Shape2d *s = shape2dOf(ev, n)) {
        for (const Outline &o : shapeOutlines(*s))
            for (Vec2 p : o) {
                Vec2 v = placed.apply(p);
                rSqr = std::max(rSqr, v.x * v.x + v.y * v.y);
                Vec2 d{v.x - v.x * scale.x, v.y - v.y * scale.y};
                deltaSqr = std::max(deltaSqr, d.x * d.x + d.y * d.y);
            }
        return;
    }
    if (n.kind == ir::NodeKind::Primitive || dimensionOf(ev, n) == 3) return;
    Affine2 inner = placed;
    if (n.kind == ir::NodeKind::Transform) inner = placed * Affine2::fromMat4(n.matrix);
    for (const auto &c : n.children) extentOf2d(ev, *c, inner, scale, rSqr, deltaSqr);
}

ir::NodePtr makeLifted(Evaluator &ev, ir::PrimShape shape, int material, const SourceLoc &loc) {
    ev.countNodes(1, loc);
    return ir::Node::makePrimitive(std::move(shape), material, loc);
}

ir::NodePtr sweptSolid(Evaluator &ev, const Outline &ccw, const ExtrudeSpec &spec, double pad,
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
            ev.warn(loc, "linear_extrude(): an outline of no area is left out");
            return nullptr;
        }
        return makeLifted(ev, ir::MeshPrim{addMesh(ev, std::move(mesh))}, material, loc);
    }
    // Straight: a prism, drawn as its polytope when convex, else as its mesh
    Range r = paddedRange(spec, pad);
    ir::PrismPrim prism = straightPrism(ccw, r.za, r.zb, r.ka, r.kb);
    if (!isConvex(ccw)) {
        if (!prismMesh(prism, mesh)) {
            ev.warn(loc, "linear_extrude(): an outline of no area is left out");
            return nullptr;
        }
        prism.mesh = addMesh(ev, std::move(mesh));
    }
    return makeLifted(ev, prism, material, loc);
}

ir::NodePtr liftRegions(Evaluator &ev, const std::vector<Region> &regions, const ExtrudeSpec &spec,
                        double pad, int material, const SourceLoc &loc) {
    double step = kSubtrahendPad * (spec.z1 - spec.z0);
    ir::NodePtr group = ev.newNode(ir::NodeKind::Group, loc);
    for (const Region &region : regions) {
        ir::NodePtr solid = sweptSolid(ev, region.outer, spec, pad, material, loc);
        if (!solid) continue;
        if (!region.holes.empty()) {
            ir::NodePtr diff = ev.newNode(ir::NodeKind::Difference, loc);
            diff->children.push_back(std::move(solid));
            for (const Outline &hole : region.holes)
                if (ir::NodePtr h = sweptSolid(ev, hole, spec, pad + step, material, loc))
                    diff->children.push_back(std::move(h));
            solid = std::move(diff);
        }
        group->children.push_back(std::move(solid));
    }
    if (group->children.empty()) return nullptr;
    if (group->children.size() == 1) return std::move(group->children[0]);
    return group;
}

ir::NodePtr liftShape(Evaluator &ev, const Shape2d &s, const ExtrudeSpec &spec,
                      const Affine2 &placed, double pad) {
    int material = spec.material >= 0 ? spec.material : s.material;
    if (!spec.meshPath && s.kind == Shape2dKind::Square) {
        Range r = paddedRange(spec, pad);
        if (r.ka == 1 && r.kb == 1) {
            ir::BoxPrim box;
            box.min = Vec3(s.min.x, s.min.y, r.za);
            box.max = Vec3(s.max.x, s.max.y, r.zb);
            return makeLifted(ev, box, material, s.loc);
        }
        return makeLifted(ev, straightPrism(shapeOutlines(s)[0], r.za, r.zb, r.ka, r.kb), material,
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
        ir::NodePtr node = makeLifted(ev, c, material, s.loc);
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
        ev.chargeGeometryWork(s.loc, "extruding the outline made here", pairs / kPointPairsPerWork,
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
        ev.warn(s.loc, "polygon(): no outline with area; nothing to extrude");
        return nullptr;
    }
    return liftRegions(ev, regions, spec, pad, material, s.loc);
}

ir::NodePtr lift2d(Evaluator &ev, const ir::Node &n, const ExtrudeSpec &spec, const Affine2 &placed,
                   double pad) {
    if (const Shape2d *s = shape2dOf(ev, n)) return liftShape(ev, *s, spec, placed, pad);
    if (n.kind == ir::NodeKind::Primitive) return nullptr;

    // A transform: in 3D for preview plates; else its 2D part (rows and columns 0, 1, 3),
    // folded into the outlines on the mesh path or lifted to an exact 3D affine map
    Affine2 inner = placed;
    ir::NodePtr out;
    if (n.kind == ir::NodeKind::Transform) {
        Affine2 t = Affine2::fromMat4(n.matrix);
        if (spec.previewTransforms && n.matrix.affineInverse()) {
            out = ev.newNode(ir::NodeKind::Transform, n.loc);
            out->matrix = n.matrix;
        } else if (!(t.det() != 0)) {
            ev.warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return nullptr;
        } else if (spec.meshPath) {
            inner = placed * t;
            out = ev.newNode(ir::NodeKind::Group, n.loc);
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
            out = ev.newNode(ir::NodeKind::Transform, n.loc);
            out->matrix = m;
        }
    } else {
        out = ev.newNode(n.kind, n.loc);
    }
    out->label = n.label;
    out->highlight = n.highlight;

    // Children: 3D ones are ignored, with OpenSCAD's warnings; a difference's subtrahends
    // reach beyond the minuend's caps
    size_t operands = 0;
    double step = kSubtrahendPad * (spec.z1 - spec.z0);
    for (const ir::Node *c : children2d(ev, n, &n != spec.silentUnion)) {
        bool subtrahend = n.kind == ir::NodeKind::Difference && operands > 0;
        ir::NodePtr lifted = lift2d(ev, *c, spec, inner, subtrahend ? pad + step : pad);
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

// ---------------------------------------------------------------------------------------------
// 2D objects outside any extrusion

int finish2d(Evaluator &ev, ir::Node &n, bool top) {
    if (shape2dOf(ev, n)) return k2d;
    if (n.kind == ir::NodeKind::Primitive) return k3d;
    std::vector<int> masks;
    int all = 0;
    for (auto &c : n.children) {
        masks.push_back(finish2d(ev, *c, false));
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
        ev.warn(n.children[other - masks.begin()]->loc,
                "Mixing 2D and 3D objects is not supported");
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
        if (!ev.state().plateWarned) {
            ev.warn(n.children[i]->loc,
                    "2D objects outside linear_extrude() are drawn as OpenSCAD's preview draws "
                    "them: plates 1 unit thick, from z = -0.5 to 0.5");
            ev.state().plateWarned = true;
        }
        ir::NodePtr lifted = lift2d(ev, *n.children[i], plate, Affine2(),
                                    subtrahend ? kSubtrahendPad * kPlateThickness : 0);
        n.children[i] = lifted ? std::move(lifted) : ev.newNode(ir::NodeKind::Group, n.loc);
    }
    return all;
}

bool hullPoints2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed, std::vector<Vec2> &out) {
    if (const Shape2d *s = shape2dOf(ev, n)) {
        size_t count = shapePointCount(*s);
        if (out.size() + count > meshing::kMaxHullPoints) {
            ev.warn(s->loc, "hull(): this part gives " + std::to_string(count) +
                                " points, more than the " +
                                std::to_string(meshing::kMaxHullPoints) +
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
            ev.warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return true;
        }
        inner = placed * t;
    }
    if (n.kind == ir::NodeKind::Intersection || n.kind == ir::NodeKind::Difference) {
        // OpenSCAD hulls the points of the evaluated (Clipper) polygon set
        std::optional<clipper2d::PolygonSet> p = polygons2d(ev, n, nullptr);
        if (!p) return true;
        size_t count = 0;
        for (const Outline &o : p->outlines) count += o.size();
        if (out.size() + count > meshing::kMaxHullPoints) {
            ev.warn(n.loc, "hull(): this part gives " + std::to_string(count) +
                               " points, more than the " + std::to_string(meshing::kMaxHullPoints) +
                               " a hull may have; the hull is left out");
            return false;
        }
        for (const Outline &o : p->outlines)
            for (Vec2 v : o) out.push_back(placed.apply(v));
        return true;
    }
    std::vector<const ir::Node *> operands = children2d(ev, n, true);
    // Groups, unions and transforms: the hull of a union is the hull of its operands' points
    for (const ir::Node *c : operands)
        if (!hullPoints2d(ev, *c, inner, out)) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// hull() of 2D children (OpenSCAD 2021.01 GeometryEvaluator::applyHull2D)

ir::NodePtr hull2d(Evaluator &ev, const ir::Node &children, const ModuleInstantiation &inst) {
    // OpenSCAD hulls every outline point of its children with CGAL's convex_hull_2
    std::vector<Vec2> points;
    if (!hullPoints2d(ev, children, Affine2(), points))
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    size_t count = points.size();
    Hull2d h = convexHull2d(std::move(points));
    if (h.kind != meshing::HullKind::Solid) {
        // OpenSCAD keeps an outline without area, which extrudes and draws as nothing
        if (h.kind != meshing::HullKind::Empty && ev.state().backgroundDepth == 0)
            ev.warn(inst.loc, "hull(): the children's " + std::to_string(count) +
                                  " 2D points are " + meshing::hullKindName(h.kind) +
                                  ", so the hull has no area; left out");
        return ev.newNode(ir::NodeKind::Group, inst.loc);
    }
    Shape2d s;
    s.kind = Shape2dKind::Polygon;
    s.outlines.push_back(std::move(h.ccw));
    s.evaluated = true;  // OpenSCAD's hull is a polygon it does not sanitize
    return shape2dNode(ev, std::move(s), inst);
}

XRange pointRange2d(Evaluator &ev, const ir::Node &n, const Affine2 &placed) {
    XRange r;
    if (const Shape2d *s = shape2dOf(ev, n)) {
        for (const Outline &o : shapeOutlines(*s))
            for (Vec2 p : o) r.add(placed.apply(p).x);
        return r;
    }
    Affine2 inner = placed;
    if (n.kind == ir::NodeKind::Transform) inner = placed * Affine2::fromMat4(n.matrix);
    for (const ir::Node *c : children2d(ev, n, false, false)) r.add(pointRange2d(ev, *c, inner));
    return r;
}

ir::NodePtr revolveShape(Evaluator &ev, const Shape2d &s, const RevolveSpec &spec,
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
        for (Vec2 p : outlines[0])
            t.facetOutline.push_back({std::max(p.x, 0.0), p.y - circle->centre.y});
        shiftZ = circle->centre.y;
        leaf = makeLifted(ev, std::move(t), material, s.loc);
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
        leaf = makeLifted(ev, std::move(l), material, s.loc);
    }
    leaf->fragments = spec.fragments;
    if (turn == 0 && shiftZ == 0) return leaf;
    ir::NodePtr t =
        ir::Node::makeTransform(Mat4::translate(Vec3(0, 0, shiftZ)) * Mat4::rotateZ(turn), s.loc);
    t->children.push_back(std::move(leaf));
    return t;
}

ir::NodePtr liftRevolve(Evaluator &ev, const ir::Node &n, const RevolveSpec &spec,
                        const Affine2 &placed, bool subtracted) {
    if (const Shape2d *s = shape2dOf(ev, n)) return revolveShape(ev, *s, spec, placed, subtracted);
    if (n.kind == ir::NodeKind::Primitive) return nullptr;
    // 2D transforms fold into the profile: only a shift along y is a 3D map of the solid
    Affine2 inner = placed;
    ir::NodePtr out;
    if (n.kind == ir::NodeKind::Transform) {
        Affine2 t = Affine2::fromMat4(n.matrix);
        if (!(t.det() != 0)) {
            ev.warn(n.loc, "Scaling a 2D object with 0 - removing object");
            return nullptr;
        }
        inner = placed * t;
        out = ev.newNode(ir::NodeKind::Group, n.loc);
    } else {
        out = ev.newNode(n.kind, n.loc);
    }
    out->label = n.label;
    out->highlight = n.highlight;
    size_t operands = 0;
    for (const ir::Node *c : children2d(ev, n, &n != spec.silentUnion)) {
        bool subtrahend = n.kind == ir::NodeKind::Difference && operands > 0;
        ir::NodePtr lifted = liftRevolve(ev, *c, spec, inner, subtracted || subtrahend);
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

void finish2dPass(Evaluator &ev, const SourceFile &) {
    if (!ev.state().shapes2d.empty()) finish2d(ev, *ev.scene().root, true);
}

}  // namespace rt::scad
