// SPDX-License-Identifier: MIT
// Builds small ir::Scenes in code for tests of the core, without going through an importer.
#pragma once

#include <memory>

#include "core/ir/scene_ir.h"

namespace rt::test {

/// A material with no ambient and no diffuse light unless set: tests state every term they use.
inline ir::Material plainMaterial(const Rgb &color, double ambient = 0, double diffuse = 0) {
    ir::Material m;
    m.color = color;
    m.finish.ambient = ambient;
    m.finish.diffuse = diffuse;
    return m;
}

inline ir::Material glassMaterial(double ior, double transmit = 1, double filter = 0) {
    ir::Material m = plainMaterial(Rgb(1));
    m.transmit = transmit;
    m.filter = filter;
    m.interior.ior = ior;
    return m;
}

inline ir::NodePtr sphere(double r, int material) {
    return ir::Node::makePrimitive(ir::SpherePrim{r}, material, {});
}
inline ir::NodePtr box(const Vec3 &lo, const Vec3 &hi, int material) {
    return ir::Node::makePrimitive(ir::BoxPrim{lo, hi}, material, {});
}
inline ir::NodePtr cylinder(double z0, double z1, double r1, double r2, int material) {
    return ir::Node::makePrimitive(ir::CylinderPrim{z0, z1, r1, r2}, material, {});
}
inline ir::NodePtr transformed(const Mat4 &m, ir::NodePtr child) {
    auto t = ir::Node::makeTransform(m, {});
    t->children.push_back(std::move(child));
    return t;
}
inline ir::NodePtr translated(const Vec3 &v, ir::NodePtr child) {
    return transformed(Mat4::translate(v), std::move(child));
}
inline ir::NodePtr csg(ir::NodeKind kind, ir::NodePtr a, ir::NodePtr b) {
    auto n = ir::Node::makeGroup(kind, {});
    n->children.push_back(std::move(a));
    n->children.push_back(std::move(b));
    return n;
}

inline ir::Light pointLight(const Vec3 &p, const Rgb &c = Rgb(1)) {
    ir::Light l;
    l.position = p;
    l.color = c;
    return l;
}

inline ir::Camera lookAt(const Vec3 &from, const Vec3 &to, double hfov = 40,
                         const Vec3 &sky = Vec3(0, 0, 1)) {
    ir::Camera c;
    c.location = from;
    c.lookAt = to;
    c.sky = sky;
    c.fov = hfov;
    return c;
}

/// Scene with max_trace_level 5, adc_bailout 0 (no weight cut-off), ambient light 1.
inline ir::Scene emptyScene() {
    ir::Scene s;
    s.settings.adcBailout = 0;
    return s;
}

}  // namespace rt::test
