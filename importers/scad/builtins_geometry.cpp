// SPDX-License-Identifier: MIT
// Builtin geometry modules: primitives, transforms, color(), CSG operations, and the
// modules this importer skips (OpenSCAD 2021.01 primitives.cc, transform.cc, color.cc, csgops.cc).
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "importers/scad/colors.h"
#include "importers/scad/evaluator.h"

namespace rt::scad {

namespace {

/// Smallest $fa/$fs OpenSCAD accepts (primitives.cc F_MINIMUM).
constexpr double kFragmentMinimum = 0.01;

std::string argText(const Value &v) { return v.toEchoString(); }

bool finite3(double x, double y, double z) {
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

/// OpenSCAD's lookup_radius: a numeric diameter wins over the radius.
Value lookupRadius(Evaluator &ev, const Value &d, const Value &r, const char *dName,
                   const char *rName, const SourceLoc &loc) {
    if (d.isNumber()) {
        if (r.isNumber())
            ev.warn(loc, std::string("Ignoring radius variable '") + rName + "' as diameter '" +
                             dName + "' is defined too.");
        return Value::number(d.toNumber() / 2);
    }
    return r.isNumber() ? r : Value();
}

}  // namespace

ir::Fragments Evaluator::currentFragments(const SourceLoc &loc) {
    static const Symbol kFn = Symbol::intern("$fn"), kFs = Symbol::intern("$fs"),
                        kFa = Symbol::intern("$fa");
    auto special = [&](Symbol name, double dflt) {
        const Value *v = dyn_.lookup(name);
        return v && v->isNumber() ? v->toNumber() : dflt;
    };
    ir::Fragments fr;
    fr.fn = special(kFn, 0);
    fr.fs = special(kFs, 2);
    fr.fa = special(kFa, 12);
    if (!std::isfinite(fr.fn)) fr.fn = 0;
    if (!(fr.fs >= kFragmentMinimum)) {
        warn(loc, "$fs too small - clamping to 0.010000");
        fr.fs = kFragmentMinimum;
    }
    if (!(fr.fa >= kFragmentMinimum)) {
        warn(loc, "$fa too small - clamping to 0.010000");
        fr.fa = kFragmentMinimum;
    }
    return fr;
}

void Evaluator::warnLeafChildren(const ModuleInstantiation &inst) {
    if (!inst.children.empty())
        warn(inst.loc, "module " + inst.name.str() + "() does not support child modules");
}

ir::NodePtr Evaluator::emptyPrimitive(const ModuleInstantiation &inst, const std::string &why) {
    warn(inst.loc, inst.name.str() + "(): " + why + "; OpenSCAD makes empty geometry");
    return newNode(ir::NodeKind::Group, inst.loc);
}

ir::NodePtr Evaluator::primitive(ir::PrimShape shape, const ModuleInstantiation &inst,
                                 const FramePtr &) {
    ir::Fragments fr = currentFragments(inst.loc);
    if (++nodes_ > limits_.maxNodes)
        throw EvalError(inst.loc,
                        "too many geometry nodes: more than " + std::to_string(limits_.maxNodes));
    // A sphere's or cylinder's fragment count: every tessellation of it starts from rings of
    // that many points (hull(), projection() and minkowski() charge the whole tessellation)
    if (const auto *s = std::get_if<ir::SpherePrim>(&shape))
        chargeGeometryWork(inst.loc, inst.name.str() + "()",
                           meshing::openscadFragments(s->radius, fr), "fragments");
    if (const auto *c = std::get_if<ir::CylinderPrim>(&shape))
        chargeGeometryWork(inst.loc, inst.name.str() + "()",
                           meshing::openscadFragments(std::max(c->r1, c->r2), fr), "fragments");
    ir::NodePtr n = ir::Node::makePrimitive(shape, resolveMaterial(inst.loc), inst.loc);
    n->fragments = fr;
    return n;
}

ir::NodePtr Evaluator::moduleCube(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"size", "center"}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    double x = 1, y = 1, z = 1;
    const Value &size = a[0];
    if (size.isNumber()) {
        x = y = z = size.toNumber();
    } else if (!size.isUndef() && !size.getVec3(x, y, z)) {
        // cube([1,2]) and other shapes keep the default 1x1x1 (primitives.cc)
        warn(a.loc(0), "Unable to convert cube(size=" + argText(size) +
                           ", ...) parameter to a number or a vec3 of numbers");
        x = y = z = 1;
    }
    bool center = a[1].isBool() && a[1].boolValue();
    if (!(x > 0 && y > 0 && z > 0) || !finite3(x, y, z))
        return emptyPrimitive(inst, "size [" + formatNumber(x) + ", " + formatNumber(y) + ", " +
                                        formatNumber(z) + "] is not positive and finite");
    ir::BoxPrim box;
    box.min = center ? Vec3(-x / 2, -y / 2, -z / 2) : Vec3(0, 0, 0);
    box.max = center ? Vec3(x / 2, y / 2, z / 2) : Vec3(x, y, z);
    return primitive(box, inst, f);
}

Value Evaluator::radiusArgument(const BoundArgs &a, const ModuleInstantiation &inst) {
    for (size_t i = 0; i < 2; ++i)
        if (!a[i].isUndef() && !a[i].isNumber())
            warn(a.loc(i), inst.name.str() + "(" + (i ? "d" : "r") + "=" + argText(a[i]) +
                               ") is not a number; ignored");
    return lookupRadius(*this, a[1], a[0], "d", "r", inst.loc);
}

ir::NodePtr Evaluator::moduleSphere(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"r", "d"}, f, dollars.get(), 1);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    Value r = radiusArgument(a, inst);
    double radius = r.isNumber() ? r.toNumber() : 1;
    if (!(radius > 0) || !std::isfinite(radius))
        return emptyPrimitive(inst,
                              "radius " + formatNumber(radius) + " is not positive and finite");
    return primitive(ir::SpherePrim{radius}, inst, f);
}

ir::NodePtr Evaluator::moduleCylinder(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a =
        bindBuiltin(inst, {"h", "r1", "r2", "center", "r", "d", "d1", "d2"}, f, dollars.get(), 4);
    FrameGuard g(dyn_, dollars.get());
    warnLeafChildren(inst);
    static const char *const kNames[] = {"h", "r1", "r2", "center", "r", "d", "d1", "d2"};
    for (size_t i = 0; i < 8; ++i)
        if (i != 3 && !a[i].isUndef() && !a[i].isNumber())
            warn(a.loc(i), std::string("cylinder(") + kNames[i] + "=" + argText(a[i]) +
                               ") is not a number; ignored");
    double h = a[0].isNumber() ? a[0].toNumber() : 1;
    // r (or d) sets both ends, then r1/d1 and r2/d2 override their end (d beats r)
    Value r = lookupRadius(*this, a[5], a[4], "d", "r", inst.loc);
    Value r1 = lookupRadius(*this, a[6], a[1], "d1", "r1", inst.loc);
    Value r2 = lookupRadius(*this, a[7], a[2], "d2", "r2", inst.loc);
    if (r.isNumber() && (r1.isNumber() || r2.isNumber()))
        warn(inst.loc, "Cylinder parameters ambiguous");
    double rb = 1, rt = 1;
    if (r.isNumber()) rb = rt = r.toNumber();
    if (r1.isNumber()) rb = r1.toNumber();
    if (r2.isNumber()) rt = r2.toNumber();
    bool center = a[3].isBool() && a[3].boolValue();
    if (!(h > 0) || !std::isfinite(h))
        return emptyPrimitive(inst, "height " + formatNumber(h) + " is not positive and finite");
    if (!(rb >= 0 && rt >= 0) || !(rb > 0 || rt > 0) || !std::isfinite(rb) || !std::isfinite(rt))
        return emptyPrimitive(inst, "radii " + formatNumber(rb) + " and " + formatNumber(rt) +
                                        " are negative, both zero or not finite");
    ir::CylinderPrim cyl;
    cyl.z0 = center ? -h / 2 : 0;
    cyl.z1 = center ? h / 2 : h;
    cyl.r1 = rb;
    cyl.r2 = rt;
    return primitive(cyl, inst, f);
}

ir::NodePtr Evaluator::transformNode(const Mat4 &m, const ModuleInstantiation &inst,
                                     const FramePtr &f, const FramePtr &dollars) {
    // `$` arguments of a transform reach its children
    FrameGuard g(dyn_, dollars.get());
    Mat4 saved = worldFromLocal_;
    worldFromLocal_ = worldFromLocal_ * m;
    ir::NodePtr node = newNode(ir::NodeKind::Transform, inst.loc);
    node->matrix = m;
    instantiateChildren(inst, f, node->children);
    worldFromLocal_ = saved;
    // Inside a hull flattened points still count; a 2D child is judged by the matrix's 2D
    // part when it is extruded or drawn
    if (!m.affineInverse() && hullDepth_ == 0 && contentsOf(*node) != 1) {
        // scale(0) and the like flatten their children to no volume: OpenSCAD's render drops
        // them from 3D results, and a singular matrix cannot be ray traced
        warn(inst.loc, inst.name.str() +
                           "() is singular and flattens its children to no "
                           "volume; they are left out");
        node->children.clear();
        node->kind = ir::NodeKind::Group;
        node->matrix = Mat4();
    }
    return node;
}

ir::NodePtr Evaluator::moduleTranslate(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"v"}, f, dollars.get());
    Mat4 m;
    double x, y, z;
    if (a[0].getVec3(x, y, z, true) && finite3(x, y, z)) {
        m = Mat4::translate(Vec3(x, y, z));
    } else {
        warn(a.loc(0), "Unable to convert translate(" + argText(a[0]) +
                           ") parameter to a vec3 or vec2 of numbers; ignored");
    }
    return transformNode(m, inst, f, dollars);
}

ir::NodePtr Evaluator::moduleRotate(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"a", "v"}, f, dollars.get());
    Mat4 m;
    const Value &angle = a[0];
    if (angle.isVector()) {
        // Rz * Ry * Rx: about world X first. Like transform.cc, components are read from the
        // last to the first, and one that is not a number repeats the previous angle.
        const auto &v = angle.toVector();
        bool ok = v.size() <= 3;
        double deg[3] = {0, 0, 0};
        double last = 0;
        for (int i = 2; i >= 0; --i) {
            if (static_cast<size_t>(i) >= v.size()) continue;
            if (v[i].isNumber() && std::isfinite(v[i].toNumber()))
                last = v[i].toNumber();
            else
                ok = false;
            deg[i] = last;
        }
        if (!ok)
            warn(a.loc(0), "Problem converting rotate(a=" + argText(angle) + ") parameter");
        else if (!a[1].isUndef())
            warn(a.loc(1), "When parameter a is supplied as vector, v is ignored rotate(a=" +
                               argText(angle) + ", v=" + argText(a[1]) + ")");
        m = Mat4::rotateZ(deg[2]) * Mat4::rotateY(deg[1]) * Mat4::rotateX(deg[0]);
    } else if (angle.isNumber() && std::isfinite(angle.toNumber())) {
        // Axis-angle about v (default +Z); only v's direction matters, a zero axis is identity
        Vec3 axis(0, 0, 1);
        double x, y, z;
        if (a[1].getVec3(x, y, z, true) && finite3(x, y, z))
            axis = Vec3(x, y, z);
        else if (!a[1].isUndef())
            warn(a.loc(1), "Problem converting rotate(..., v=" + argText(a[1]) + ") parameter");
        m = Mat4::rotateAxis(angle.toNumber(), axis);
    } else {
        warn(a.loc(0), "Problem converting rotate(a=" + argText(angle) + ") parameter");
    }
    return transformNode(m, inst, f, dollars);
}

ir::NodePtr Evaluator::moduleScale(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"v"}, f, dollars.get());
    Mat4 m;
    double x, y, z;
    bool ok = a[0].getVec3(x, y, z, true, 1);
    if (!ok && a[0].isNumber()) {
        x = y = z = a[0].toNumber();
        ok = true;
    }
    if (ok && finite3(x, y, z)) {
        m = Mat4::scale(Vec3(x, y, z));
    } else {
        warn(a.loc(0), "Unable to convert scale(" + argText(a[0]) +
                           ") parameter to a number, a vec3 or vec2 of finite numbers; ignored");
    }
    return transformNode(m, inst, f, dollars);
}

ir::NodePtr Evaluator::moduleMirror(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"v"}, f, dollars.get());
    double x, y, z;
    Vec3 n(1, 0, 0);
    if (a[0].getVec3(x, y, z, true) && finite3(x, y, z)) {
        n = Vec3(x, y, z);
    } else {
        // mirror() without a usable vector mirrors X, with a warning (transform.cc)
        warn(a.loc(0), "Unable to convert mirror(" + argText(a[0]) +
                           ") parameter to a vec3 or vec2 of numbers; mirroring X");
    }
    return transformNode(Mat4::mirror(n), inst, f, dollars);
}

ir::NodePtr Evaluator::moduleMultmatrix(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"m"}, f, dollars.get());
    Mat4 m;
    const Value &mv = a[0];
    if (mv.isVector()) {
        // Up to 4x4 entries; missing or non-numeric ones keep the identity's value
        const auto &rows = mv.toVector();
        for (size_t i = 0; i < rows.size() && i < 4; ++i) {
            if (!rows[i].isVector()) continue;
            const auto &row = rows[i].toVector();
            for (size_t j = 0; j < row.size() && j < 4; ++j)
                if (row[j].isNumber()) m.m[i][j] = row[j].toNumber();
        }
    } else if (!mv.isUndef()) {
        warn(a.loc(0), "multmatrix(" + argText(mv) + ") is not a matrix; ignored");
    }
    auto rowText = [&m] {
        return "[" + formatNumber(m.m[3][0]) + ", " + formatNumber(m.m[3][1]) + ", " +
               formatNumber(m.m[3][2]) + ", " + formatNumber(m.m[3][3]) + "]";
    };
    if (m.m[3][3] == 0)
        throw EvalError(a.loc(0),
                        "multmatrix() with bottom row " + rowText() +
                            " is a projective (non-affine) transform, which is not supported");
    if (m.m[3][3] != 1 && std::isfinite(m.m[3][3])) {
        double w = m.m[3][3];
        for (auto &row : m.m)
            for (double &e : row) e /= w;
    }
    if (!m.isFinite()) {
        warn(a.loc(0), "multmatrix() has non-finite entries; ignored");
        m = Mat4();
    } else if (!m.isAffine()) {
        throw EvalError(a.loc(0),
                        "multmatrix() with bottom row " + rowText() +
                            " is a projective (non-affine) transform, which is not supported");
    }
    return transformNode(m, inst, f, dollars);
}

ir::NodePtr Evaluator::moduleColor(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = bindBuiltin(inst, {"c", "alpha"}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    std::optional<Rgba> c;
    if (a[0].isVector()) {
        c = colorFromValue(a[0]);
    } else if (a[0].isString()) {
        c = parseColorString(a[0].toStr());
        if (!c) warn(a.loc(0), "Unable to parse color " + argText(a[0]) + "; color() ignored");
    }
    if (c && a[1].isNumber()) c->a = a[1].toNumber();
    if (c && c->r == -1 && c->g == -1 && c->b == -1) {
        // OpenSCAD's "no colour" marker, as its .csg export writes an unparsable colour
        c.reset();
    }
    if (c) {
        for (double ch : {c->r, c->g, c->b, c->a})
            if (!(ch >= 0 && ch <= 1))
                warn(inst.loc, "color() expects numbers between 0.0 and 1.0. Value of " +
                                   formatNumber(ch) + " is out of range");
        if (!std::isfinite(c->r) || !std::isfinite(c->g) || !std::isfinite(c->b) ||
            !std::isfinite(c->a)) {
            warn(inst.loc, "color() with non-finite components ignored");
            c.reset();
        } else if (c->r < 0 || c->g < 0 || c->b < 0) {
            // A negative channel marks an invalid colour: OpenSCAD shows the default instead
            c.reset();
        }
    }
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    // The outermost valid colour wins: an inner color() never replaces it
    bool applies = c && !color_;
    if (applies) {
        color_ = ColorState{c->r, c->g, c->b, c->a, inst.loc};
        currentMaterial_ = -1;
    }
    instantiateChildren(inst, f, node->children);
    if (applies) {
        color_.reset();
        currentMaterial_ = -1;
    }
    return node;
}

ir::NodePtr Evaluator::csgOperation(ir::NodeKind kind, const ModuleInstantiation &inst,
                                    const FramePtr &f) {
    // OpenSCAD 2021.01's CSG modules ignore every argument, `$` ones included
    ir::NodePtr node = newNode(kind, inst.loc);
    instantiateChildren(inst, f, node->children);
    return node;
}

ir::NodePtr Evaluator::moduleUnion(const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ir::NodeKind::Union, inst, f);
}
ir::NodePtr Evaluator::moduleDifference(const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ir::NodeKind::Difference, inst, f);
}
ir::NodePtr Evaluator::moduleIntersection(const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ir::NodeKind::Intersection, inst, f);
}

ir::NodePtr Evaluator::moduleGroup(const ModuleInstantiation &inst, const FramePtr &f) {
    // render(convexity) and group(): pass-through implicit unions
    FramePtr dollars = makeFrame(nullptr);
    if (inst.name.str() == "render")
        bindBuiltin(inst, {"convexity"}, f, dollars.get());
    else
        bindBuiltin(inst, {}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, f, node->children);
    return node;
}

ir::NodePtr Evaluator::moduleHull(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    bindBuiltin(inst, {}, f, dollars.get());
    FrameGuard g(dyn_, dollars.get());
    // The children are only a source of points; their tree is dropped afterwards
    ir::NodePtr children = pointSourceChildren(inst, f);
    // OpenSCAD's hull takes the dimension of its first child with geometry; the other
    // dimension's children are ignored with its warnings
    if (dimensionOf(*children) == 2) return hull2d(*children, inst);
    warnIgnored2d(*children);
    chargeGeometryWork(inst.loc, "hull()", tessellatedFaces(*children, scene_));
    std::vector<Vec3> points;
    if (!meshing::gatherHullPoints(*children, scene_, diag_, points))
        return newNode(ir::NodeKind::Group, inst.loc);
    meshing::HullResult hull = meshing::convexHull(points);
    if (hull.unsettledPoints > 0)
        warn(inst.loc, "hull(): " + std::to_string(hull.unsettledPoints) +
                           " points too close to the hull's surface for the arithmetic to place "
                           "were left out; they lie within rounding of it");
    if (hull.kind == meshing::HullKind::Solid) {
        ir::NodePtr n = primitive(std::move(hull.polytope), inst, f);
        // Its points are fixed: no $fn/$fa/$fs applies to a hull (nor does --facets)
        n->fragments = ir::Fragments{};
        return n;
    }
    // OpenSCAD makes a flat or empty result; a solid renderer has nothing to draw
    if (hull.kind != meshing::HullKind::Empty && backgroundDepth_ == 0)
        warn(inst.loc, "hull(): the children's " + std::to_string(points.size()) +
                           " points are " + meshing::hullKindName(hull.kind) +
                           ", so the hull has no volume; left out");
    return newNode(ir::NodeKind::Group, inst.loc);
}

ir::NodePtr Evaluator::pointSourceChildren(const ModuleInstantiation &inst, const FramePtr &f) {
    ir::NodePtr children = newNode(ir::NodeKind::Group, inst.loc);
    ++hullDepth_;
    try {
        instantiateChildren(inst, f, children->children);
    } catch (...) {
        --hullDepth_;
        throw;
    }
    --hullDepth_;
    return children;
}

ir::NodePtr Evaluator::skipUnsupported(const SourceLoc &loc, const std::string &what) {
    // Inside a `%` part, which is left out of the scene anyway, nothing is lost: no warning
    if (backgroundDepth_ == 0) {
        warn(loc, what + " is not supported yet; skipped");
        ++scene_.stats.skippedModules;
    }
    return newNode(ir::NodeKind::Group, loc);
}

ir::NodePtr Evaluator::moduleUnsupported(const ModuleInstantiation &inst, const FramePtr &) {
    return skipUnsupported(inst.loc, inst.name.str() + "()");
}

const std::unordered_map<Symbol, Evaluator::ModuleHandler, SymbolHash>
    &Evaluator::builtinModules() {
    static const std::unordered_map<Symbol, ModuleHandler, SymbolHash> kTable = [] {
        std::unordered_map<Symbol, ModuleHandler, SymbolHash> t;
        auto add = [&t](const char *name, ModuleHandler h) { t[Symbol::intern(name)] = h; };
        add("cube", &Evaluator::moduleCube);
        add("sphere", &Evaluator::moduleSphere);
        add("cylinder", &Evaluator::moduleCylinder);
        add("translate", &Evaluator::moduleTranslate);
        add("rotate", &Evaluator::moduleRotate);
        add("scale", &Evaluator::moduleScale);
        add("mirror", &Evaluator::moduleMirror);
        add("multmatrix", &Evaluator::moduleMultmatrix);
        add("color", &Evaluator::moduleColor);
        add("union", &Evaluator::moduleUnion);
        add("difference", &Evaluator::moduleDifference);
        add("intersection", &Evaluator::moduleIntersection);
        add("render", &Evaluator::moduleGroup);
        add("group", &Evaluator::moduleGroup);
        add("hull", &Evaluator::moduleHull);
        add("for", &Evaluator::moduleFor);
        add("intersection_for", &Evaluator::moduleIntersectionFor);
        add("let", &Evaluator::moduleLet);
        add("echo", &Evaluator::moduleEcho);
        add("assert", &Evaluator::moduleAssert);
        add("children", &Evaluator::moduleChildren);
        add("child", &Evaluator::moduleChild);
        add("assign", &Evaluator::moduleAssign);
        add("polyhedron", &Evaluator::modulePolyhedron);
        add("import", &Evaluator::moduleImport);
        for (const char *name : {"import_stl", "import_off", "import_dxf"})
            add(name, &Evaluator::moduleImportDeprecated);
        add("square", &Evaluator::moduleSquare);
        add("circle", &Evaluator::moduleCircle);
        add("polygon", &Evaluator::modulePolygon);
        add("linear_extrude", &Evaluator::moduleLinearExtrude);
        add("rotate_extrude", &Evaluator::moduleRotateExtrude);
        add("offset", &Evaluator::moduleOffset);
        add("text", &Evaluator::moduleText);
        add("surface", &Evaluator::moduleSurface);
        add("resize", &Evaluator::moduleResize);
        add("minkowski", &Evaluator::moduleMinkowski);
        add("projection", &Evaluator::moduleProjection);
        return t;
    }();
    return kTable;
}

}  // namespace rt::scad
