// SPDX-License-Identifier: MIT
// Builtin transforms and color() (OpenSCAD 2021.01 transform.cc, color.cc).
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/builtins/placeholders2d.h"

namespace rt::scad {

namespace {

bool finite3(double x, double y, double z) {
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

ir::NodePtr transformNode(Evaluator &ev, const Mat4 &m, const ModuleInstantiation &inst,
                          const FramePtr &f, const FramePtr &dollars) {
    // `$` arguments of a transform reach its children
    FrameGuard g(ev.dynamicScope(), dollars.get());
    Mat4 saved = ev.state().worldFromLocal;
    ev.state().worldFromLocal = ev.state().worldFromLocal * m;
    ir::NodePtr node = ev.newNode(ir::NodeKind::Transform, inst.loc);
    node->matrix = m;
    ev.instantiateChildren(inst, f, node->children);
    ev.state().worldFromLocal = saved;
    // Inside a hull flattened points still count; a 2D child is judged by the matrix's 2D
    // part when it is extruded or drawn
    if (!m.affineInverse() && ev.state().hullDepth == 0 && contentsOf(ev, *node) != 1) {
        // scale(0) and the like flatten their children to no volume: OpenSCAD's render drops
        // them from 3D results, and a singular matrix cannot be ray traced
        ev.warn(inst.loc, inst.name.str() +
                              "() is singular and flattens its children to no "
                              "volume; they are left out");
        node->children.clear();
        node->kind = ir::NodeKind::Group;
        node->matrix = Mat4();
    }
    return node;
}

ir::NodePtr moduleTranslate(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"v"}, f, dollars.get());
    Mat4 m;
    double x, y, z;
    if (a[0].getVec3(x, y, z, true) && finite3(x, y, z)) {
        m = Mat4::translate(Vec3(x, y, z));
    } else {
        ev.warn(a.loc(0), "Unable to convert translate(" + argText(a[0]) +
                              ") parameter to a vec3 or vec2 of numbers; ignored");
    }
    return transformNode(ev, m, inst, f, dollars);
}

ir::NodePtr moduleRotate(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"a", "v"}, f, dollars.get());
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
            ev.warn(a.loc(0), "Problem converting rotate(a=" + argText(angle) + ") parameter");
        else if (!a[1].isUndef())
            ev.warn(a.loc(1), "When parameter a is supplied as vector, v is ignored rotate(a=" +
                                  argText(angle) + ", v=" + argText(a[1]) + ")");
        m = Mat4::rotateZ(deg[2]) * Mat4::rotateY(deg[1]) * Mat4::rotateX(deg[0]);
    } else if (angle.isNumber() && std::isfinite(angle.toNumber())) {
        // Axis-angle about v (default +Z); only v's direction matters, a zero axis is identity
        Vec3 axis(0, 0, 1);
        double x, y, z;
        if (a[1].getVec3(x, y, z, true) && finite3(x, y, z))
            axis = Vec3(x, y, z);
        else if (!a[1].isUndef())
            ev.warn(a.loc(1), "Problem converting rotate(..., v=" + argText(a[1]) + ") parameter");
        m = Mat4::rotateAxis(angle.toNumber(), axis);
    } else {
        ev.warn(a.loc(0), "Problem converting rotate(a=" + argText(angle) + ") parameter");
    }
    return transformNode(ev, m, inst, f, dollars);
}

ir::NodePtr moduleScale(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"v"}, f, dollars.get());
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
        ev.warn(a.loc(0), "Unable to convert scale(" + argText(a[0]) +
                              ") parameter to a number, a vec3 or vec2 of finite numbers; ignored");
    }
    return transformNode(ev, m, inst, f, dollars);
}

ir::NodePtr moduleMirror(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"v"}, f, dollars.get());
    double x, y, z;
    Vec3 n(1, 0, 0);
    if (a[0].getVec3(x, y, z, true) && finite3(x, y, z)) {
        n = Vec3(x, y, z);
    } else {
        // mirror() without a usable vector mirrors X, with a warning (transform.cc)
        ev.warn(a.loc(0), "Unable to convert mirror(" + argText(a[0]) +
                              ") parameter to a vec3 or vec2 of numbers; mirroring X");
    }
    return transformNode(ev, Mat4::mirror(n), inst, f, dollars);
}

ir::NodePtr moduleMultmatrix(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"m"}, f, dollars.get());
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
        ev.warn(a.loc(0), "multmatrix(" + argText(mv) + ") is not a matrix; ignored");
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
        ev.warn(a.loc(0), "multmatrix() has non-finite entries; ignored");
        m = Mat4();
    } else if (!m.isAffine()) {
        throw EvalError(a.loc(0),
                        "multmatrix() with bottom row " + rowText() +
                            " is a projective (non-affine) transform, which is not supported");
    }
    return transformNode(ev, m, inst, f, dollars);
}

ir::NodePtr moduleColor(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"c", "alpha"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    std::optional<Rgba> c;
    if (a[0].isVector()) {
        c = colorFromValue(a[0]);
    } else if (a[0].isString()) {
        c = parseColorString(a[0].toStr());
        if (!c) ev.warn(a.loc(0), "Unable to parse color " + argText(a[0]) + "; color() ignored");
    }
    if (c && a[1].isNumber()) c->a = a[1].toNumber();
    if (c && c->r == -1 && c->g == -1 && c->b == -1) {
        // OpenSCAD's "no colour" marker, as its .csg export writes an unparsable colour
        c.reset();
    }
    if (c) {
        for (double ch : {c->r, c->g, c->b, c->a})
            if (!(ch >= 0 && ch <= 1))
                ev.warn(inst.loc, "color() expects numbers between 0.0 and 1.0. Value of " +
                                      formatNumber(ch) + " is out of range");
        if (!std::isfinite(c->r) || !std::isfinite(c->g) || !std::isfinite(c->b) ||
            !std::isfinite(c->a)) {
            ev.warn(inst.loc, "color() with non-finite components ignored");
            c.reset();
        } else if (c->r < 0 || c->g < 0 || c->b < 0) {
            // A negative channel marks an invalid colour: OpenSCAD shows the default instead
            c.reset();
        }
    }
    ir::NodePtr node = ev.newNode(ir::NodeKind::Group, inst.loc);
    // The outermost valid colour wins: an inner color() never replaces it
    bool applies = c && !ev.state().color;
    if (applies) {
        ev.state().color = ColorState{c->r, c->g, c->b, c->a, inst.loc};
        ev.state().currentMaterial = -1;
    }
    ev.instantiateChildren(inst, f, node->children);
    if (applies) {
        ev.state().color.reset();
        ev.state().currentMaterial = -1;
    }
    return node;
}

}  // namespace

BuiltinFamily transformBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"translate", moduleTranslate}, {"rotate", moduleRotate},         {"scale", moduleScale},
        {"mirror", moduleMirror},       {"multmatrix", moduleMultmatrix}, {"color", moduleColor},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
