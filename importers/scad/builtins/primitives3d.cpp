// SPDX-License-Identifier: MIT
// Builtin 3D primitives: cube, sphere, cylinder, polyhedron (OpenSCAD 2021.01 primitives.cc).
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <unordered_map>
#include <unordered_set>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "core/meshing/triangulate.h"
#include "importers/gltf/gltf_importer.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/module_support.h"

namespace rt::scad {

namespace {

bool finite3(double x, double y, double z) {
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

/// At most this many skipped-face warnings per polyhedron; the rest are counted in a summary.
constexpr int kMaxFaceWarnings = 10;

/// True when the polygon's corners hold at least three different points.
bool hasThreeDistinctPoints(const std::vector<Vec3> &positions,
                            const std::vector<uint32_t> &polygon) {
    const Vec3 *first = nullptr, *second = nullptr;
    for (uint32_t i : polygon) {
        const Vec3 &p = positions[i];
        if (!first) {
            first = &p;
        } else if (!second) {
            if (p != *first) second = &p;
        } else if (p != *first && p != *second) {
            return true;
        }
    }
    return false;
}

/// Removes the triangles that repeat an earlier one (the same corners in the same cyclic
/// order; the reverse is another face) and returns how many. A face listed many times costs
/// the trace as many times over while adding nothing: OpenSCAD's CGAL operations take such
/// a polyhedron as its distinct faces.
size_t dropRepeatedTriangles(ir::Mesh &mesh) {
    struct Hash {
        size_t operator()(const std::array<uint32_t, 3> &t) const {
            uint64_t h = t[0];
            h = h * 0x9E3779B97F4A7C15ull ^ t[1];
            h = h * 0x9E3779B97F4A7C15ull ^ t[2];
            return static_cast<size_t>(h ^ (h >> 29));
        }
    };
    std::unordered_set<std::array<uint32_t, 3>, Hash> seen;
    seen.reserve(mesh.triangles.size());
    size_t kept = 0;
    for (const auto &t : mesh.triangles) {
        // Rotated to start at the smallest index: one key per cyclic order
        int first = t[0] <= t[1] && t[0] <= t[2] ? 0 : t[1] <= t[2] ? 1 : 2;
        std::array<uint32_t, 3> key = {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
        if (seen.insert(key).second) mesh.triangles[kept++] = t;
    }
    size_t dropped = mesh.triangles.size() - kept;
    mesh.triangles.resize(kept);
    return dropped;
}

ir::NodePtr moduleCube(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"size", "center"}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    double x = 1, y = 1, z = 1;
    const Value &size = a[0];
    if (size.isNumber()) {
        x = y = z = size.toNumber();
    } else if (!size.isUndef() && !size.getVec3(x, y, z)) {
        // cube([1,2]) and other shapes keep the default 1x1x1 (primitives.cc)
        ev.warn(a.loc(0), "Unable to convert cube(size=" + argText(size) +
                              ", ...) parameter to a number or a vec3 of numbers");
        x = y = z = 1;
    }
    bool center = a[1].isBool() && a[1].boolValue();
    if (!(x > 0 && y > 0 && z > 0) || !finite3(x, y, z))
        return emptyPrimitive(ev, inst,
                              "size [" + formatNumber(x) + ", " + formatNumber(y) + ", " +
                                  formatNumber(z) + "] is not positive and finite");
    ir::BoxPrim box;
    box.min = center ? Vec3(-x / 2, -y / 2, -z / 2) : Vec3(0, 0, 0);
    box.max = center ? Vec3(x / 2, y / 2, z / 2) : Vec3(x, y, z);
    return primitive(ev, box, inst, f);
}

ir::NodePtr moduleSphere(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"r", "d"}, f, dollars.get(), 1);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    Value r = radiusArgument(ev, a, inst);
    double radius = r.isNumber() ? r.toNumber() : 1;
    if (!(radius > 0) || !std::isfinite(radius))
        return emptyPrimitive(ev, inst,
                              "radius " + formatNumber(radius) + " is not positive and finite");
    return primitive(ev, ir::SpherePrim{radius}, inst, f);
}

ir::NodePtr moduleCylinder(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a = ev.bindBuiltin(inst, {"h", "r1", "r2", "center", "r", "d", "d1", "d2"}, f,
                                 dollars.get(), 4);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    static const char *const kNames[] = {"h", "r1", "r2", "center", "r", "d", "d1", "d2"};
    for (size_t i = 0; i < 8; ++i)
        if (i != 3 && !a[i].isUndef() && !a[i].isNumber())
            ev.warn(a.loc(i), std::string("cylinder(") + kNames[i] + "=" + argText(a[i]) +
                                  ") is not a number; ignored");
    double h = a[0].isNumber() ? a[0].toNumber() : 1;
    // r (or d) sets both ends, then r1/d1 and r2/d2 override their end (d beats r)
    Value r = lookupRadius(ev, a[5], a[4], "d", "r", inst.loc);
    Value r1 = lookupRadius(ev, a[6], a[1], "d1", "r1", inst.loc);
    Value r2 = lookupRadius(ev, a[7], a[2], "d2", "r2", inst.loc);
    if (r.isNumber() && (r1.isNumber() || r2.isNumber()))
        ev.warn(inst.loc, "Cylinder parameters ambiguous");
    double rb = 1, rt = 1;
    if (r.isNumber()) rb = rt = r.toNumber();
    if (r1.isNumber()) rb = r1.toNumber();
    if (r2.isNumber()) rt = r2.toNumber();
    bool center = a[3].isBool() && a[3].boolValue();
    if (!(h > 0) || !std::isfinite(h))
        return emptyPrimitive(ev, inst,
                              "height " + formatNumber(h) + " is not positive and finite");
    if (!(rb >= 0 && rt >= 0) || !(rb > 0 || rt > 0) || !std::isfinite(rb) || !std::isfinite(rt))
        return emptyPrimitive(ev, inst,
                              "radii " + formatNumber(rb) + " and " + formatNumber(rt) +
                                  " are negative, both zero or not finite");
    ir::CylinderPrim cyl;
    cyl.z0 = center ? -h / 2 : 0;
    cyl.z1 = center ? h / 2 : h;
    cyl.r1 = rb;
    cyl.r2 = rt;
    return primitive(ev, cyl, inst, f);
}

ir::NodePtr modulePolyhedron(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr dollars = makeFrame(nullptr);
    BoundArgs a =
        ev.bindBuiltin(inst, {"points", "faces", "convexity", "triangles"}, f, dollars.get(), 3);
    FrameGuard g(ev.dynamicScope(), dollars.get());
    warnLeafChildren(ev, inst);
    // `convexity` only matters for OpenSCAD's preview

    // Points are 3-vectors, or 2-vectors with z = 0 (2021.01 getVec3(..., 0.0))
    const Value &points = a[0];
    if (!points.isVector())
        return emptyPrimitive(ev, inst,
                              "points = " + argText(points) + " is not a vector of coordinates");
    ir::Mesh mesh;
    mesh.name = "polyhedron";
    mesh.loc = inst.loc;
    const auto &pv = points.toVector();
    mesh.positions.reserve(pv.size());
    for (size_t i = 0; i < pv.size(); ++i) {
        double x, y, z;
        if (!pv[i].getVec3(x, y, z, true) || !std::isfinite(x) || !std::isfinite(y) ||
            !std::isfinite(z))
            return emptyPrimitive(ev, inst,
                                  "points[" + std::to_string(i) + "] = " + argText(pv[i]) +
                                      " is not a vector of 3 finite numbers");
        mesh.positions.emplace_back(x, y, z);
    }

    // The deprecated triangles= counts only when faces is undef
    size_t facesArg = 1;
    if (a[1].isUndef() && !a[3].isUndef()) {
        ev.warn(a.loc(3),
                "DEPRECATED: polyhedron(triangles=[]) will be removed in future releases. Use "
                "polyhedron(faces=[]) instead.");
        facesArg = 3;
    }
    const Value &faces = a[facesArg];
    if (faces.isUndef()) return emptyPrimitive(ev, inst, "no faces given");
    if (!faces.isVector())
        return emptyPrimitive(
            ev, inst, "faces = " + argText(faces) + " is not a vector of vectors of point indices");
    const SourceLoc &facesLoc = a.loc(facesArg);
    if (faces.isVector())
        ev.chargeGeometryWork(inst.loc, "polyhedron()",
                              static_cast<double>(faces.toVector().size()), "faces");
    int skipped = 0;
    auto skip = [&](const std::string &why) {
        if (++skipped <= kMaxFaceWarnings) ev.warn(facesLoc, why + "; face skipped");
    };

    std::vector<uint32_t> polygon;
    const auto &fv = faces.toVector();
    for (size_t i = 0; i < fv.size(); ++i) {
        std::string name = "faces[" + std::to_string(i) + "]";
        if (!fv[i].isVector()) {
            skip(name + " = " + argText(fv[i]) + " is not a vector of point indices");
            continue;
        }
        const auto &indices = fv[i].toVector();
        polygon.clear();
        bool valid = true;
        for (size_t j = 0; j < indices.size() && valid; ++j) {
            auto where = [&] { return name + "[" + std::to_string(j) + "]"; };
            double d;
            if (!indices[j].getFiniteNumber(d)) {
                skip(where() + " = " + argText(indices[j]) + " is not a point index");
                valid = false;
            } else if (d < 0 || d >= static_cast<double>(mesh.positions.size())) {
                skip("Point index " + formatNumber(d) + " is out of bounds (from " + where() + ")");
                valid = false;
            } else {
                // A fractional index is truncated, as OpenSCAD converts it to size_t
                polygon.push_back(static_cast<uint32_t>(d));
            }
        }
        if (!valid) continue;
        if (!hasThreeDistinctPoints(mesh.positions, polygon)) {
            skip(name + " has fewer than 3 distinct points");
            continue;
        }
        // OpenSCAD's faces are clockwise seen from outside; the IR's are counter-clockwise
        std::reverse(polygon.begin(), polygon.end());
        if (polygon.size() == 3)
            mesh.triangles.push_back({polygon[0], polygon[1], polygon[2]});
        else if (!meshing::triangulatePolygon(mesh.positions, polygon, mesh.triangles))
            skip(name + " is degenerate (its points enclose no area)");
    }
    if (skipped > kMaxFaceWarnings)
        ev.warn(facesLoc, std::to_string(skipped) + " faces skipped in all");

    meshio::weldMesh(mesh);
    if (size_t repeated = dropRepeatedTriangles(mesh))
        ev.warn(facesLoc, "polyhedron(): " + std::to_string(repeated) +
                              " triangles repeat earlier faces (the same points in the same "
                              "order); each is drawn once, as OpenSCAD's CGAL operations take it");
    if (mesh.triangles.empty()) return emptyPrimitive(ev, inst, "no valid faces");
    std::string problem = meshio::solidProblem(mesh);
    if (!problem.empty())
        ev.warn(inst.loc, "polyhedron() " + problem +
                              "; OpenSCAD needs a closed surface whose faces are listed clockwise "
                              "seen from outside");
    // Left out with its `%` subtree: no mesh without a node placing it
    if (ev.state().backgroundDepth > 0) return ev.newNode(ir::NodeKind::Group, inst.loc);
    int index = addMesh(ev, std::move(mesh));
    return primitive(ev, ir::MeshPrim{index}, inst, f);
}

}  // namespace

BuiltinFamily primitives3dBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"cube", moduleCube},
        {"sphere", moduleSphere},
        {"cylinder", moduleCylinder},
        {"polyhedron", modulePolyhedron},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
