// SPDX-License-Identifier: MIT
// What several builtin families share: primitive leaves, argument helpers, meshes.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "core/meshing/triangulate.h"
#include "importers/gltf/gltf_importer.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/module_support.h"
#include "importers/scad/geometry2d/clipper2d.h"
#include "importers/scad/geometry2d/projection.h"

namespace rt::scad {

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

void warnLeafChildren(Evaluator &ev, const ModuleInstantiation &inst) {
    if (!inst.children.empty())
        ev.warn(inst.loc, "module " + inst.name.str() + "() does not support child modules");
}

ir::NodePtr emptyPrimitive(Evaluator &ev, const ModuleInstantiation &inst, const std::string &why) {
    ev.warn(inst.loc, inst.name.str() + "(): " + why + "; OpenSCAD makes empty geometry");
    return ev.newNode(ir::NodeKind::Group, inst.loc);
}

ir::NodePtr primitive(Evaluator &ev, ir::PrimShape shape, const ModuleInstantiation &inst,
                      const FramePtr &) {
    ir::Fragments fr = ev.currentFragments(inst.loc);
    ev.countNodes(1, inst.loc);
    // A sphere's or cylinder's fragment count: every tessellation of it starts from rings of
    // that many points (hull(), projection() and minkowski() charge the whole tessellation)
    if (const auto *s = std::get_if<ir::SpherePrim>(&shape))
        ev.chargeGeometryWork(inst.loc, inst.name.str() + "()",
                              meshing::openscadFragments(s->radius, fr), "fragments");
    if (const auto *c = std::get_if<ir::CylinderPrim>(&shape))
        ev.chargeGeometryWork(inst.loc, inst.name.str() + "()",
                              meshing::openscadFragments(std::max(c->r1, c->r2), fr), "fragments");
    ir::NodePtr n = ir::Node::makePrimitive(shape, resolveMaterial(ev, inst.loc), inst.loc);
    n->fragments = fr;
    return n;
}

Value radiusArgument(Evaluator &ev, const BoundArgs &a, const ModuleInstantiation &inst) {
    for (size_t i = 0; i < 2; ++i)
        if (!a[i].isUndef() && !a[i].isNumber())
            ev.warn(a.loc(i), inst.name.str() + "(" + (i ? "d" : "r") + "=" + argText(a[i]) +
                                  ") is not a number; ignored");
    return lookupRadius(ev, a[1], a[0], "d", "r", inst.loc);
}

ir::NodePtr skipUnsupported(Evaluator &ev, const SourceLoc &loc, const std::string &what) {
    // Inside a `%` part, which is left out of the scene anyway, nothing is lost: no warning
    if (ev.state().backgroundDepth == 0) {
        ev.warn(loc, what + " is not supported yet; skipped");
        ++ev.scene().stats.skippedModules;
    }
    return ev.newNode(ir::NodeKind::Group, loc);
}

ir::NodePtr pointSourceChildren(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    ir::NodePtr children = ev.newNode(ir::NodeKind::Group, inst.loc);
    ++ev.state().hullDepth;
    try {
        ev.instantiateChildren(inst, f, children->children);
    } catch (...) {
        --ev.state().hullDepth;
        throw;
    }
    --ev.state().hullDepth;
    return children;
}

int addMesh(Evaluator &ev, ir::Mesh mesh) {
    // The readers and polyhedron() only make valid meshes; this keeps it so
    ir::validateMesh(mesh);
    ev.scene().meshes.push_back(std::make_shared<const ir::Mesh>(std::move(mesh)));
    return static_cast<int>(ev.scene().meshes.size()) - 1;
}

double tessellatedFaces(const ir::Node &n, const ir::Scene &scene) {
    // Only parameters are read: a sphere of $fn = 1e6 would have 5e11 faces to count
    auto fragments = [&](double r) {
        return static_cast<double>(meshing::openscadFragments(r, n.fragments));
    };
    auto meshTriangles = [&](int index) {
        return index >= 0 && index < static_cast<int>(scene.meshes.size()) && scene.meshes[index]
                   ? static_cast<double>(scene.meshes[index]->triangles.size())
                   : 0.0;
    };
    // rotate_extrude's mesh: two triangles per profile edge and segment, and the end caps
    auto revolved = [](double points, int segments) {
        return 2 * points * std::max(segments, 1) + 2 * points;
    };
    if (n.kind != ir::NodeKind::Primitive) {
        double sum = 0;
        for (const auto &c : n.children) sum += tessellatedFaces(*c, scene);
        return sum;
    }
    if (std::holds_alternative<ir::BoxPrim>(n.shape)) return 6;
    if (const auto *s = std::get_if<ir::SpherePrim>(&n.shape)) {
        double f = fragments(s->radius);
        return f * std::floor((f + 1) / 2) + 2;
    }
    if (const auto *c = std::get_if<ir::CylinderPrim>(&n.shape))
        return fragments(std::max(c->r1, c->r2)) + 2;
    if (const auto *m = std::get_if<ir::MeshPrim>(&n.shape)) return meshTriangles(m->mesh);
    if (const auto *p = std::get_if<ir::PolytopePrim>(&n.shape))
        return static_cast<double>(p->faces.size());
    if (const auto *l = std::get_if<ir::LathePrim>(&n.shape)) {
        double points = 0;
        for (const auto &o : l->outlines) points += static_cast<double>(o.size());
        return revolved(points, l->fragments);
    }
    if (const auto *t = std::get_if<ir::TorusPrim>(&n.shape))
        return revolved(static_cast<double>(t->facetOutline.size()), t->fragments);
    const auto &prism = std::get<ir::PrismPrim>(n.shape);
    return prism.mesh >= 0 ? meshTriangles(prism.mesh)
                           : static_cast<double>(prism.outline.size()) + 2;
}

}  // namespace rt::scad
