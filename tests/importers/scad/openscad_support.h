// SPDX-License-Identifier: MIT
// Header-only helpers of the cross-checks against the installed OpenSCAD 2021.01: running it to
// an OFF export and comparing vertex sets and volumes at the precision OFF files keep.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/mesh.h"
#include "core/ir/prism.h"
#include "core/math/float_util.h"
#include "core/meshing/facets.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {

/// OFF export writes 6 significant digits.
constexpr double kOffDigits = 1e-5;

inline bool haveOpenScad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

/// Signed volume of a closed triangle mesh (divergence theorem).
inline double meshVolume(const ir::Mesh &m) {
    double v = 0;
    for (const auto &t : m.triangles)
        v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]]));
    return v / 6;
}

/// Volume of a polytope with faces counter-clockwise seen from outside.
inline double polytopeVolume(const std::vector<Vec3> &verts,
                             const std::vector<std::vector<int>> &faces) {
    double v = 0;
    for (const auto &f : faces)
        for (size_t k = 1; k + 1 < f.size(); ++k)
            v += dot(verts[f[0]], cross(verts[f[k]], verts[f[k + 1]]));
    return v / 6;
}

/// Every point of `a` has one of `b` within OFF's rounding (`digits`, relative above 1).
inline void expectCovered(const std::vector<Vec3> &a, const std::vector<Vec3> &b, const char *what,
                          double digits = kOffDigits) {
    for (const Vec3 &v : a) {
        double best = kInfinity;
        for (const Vec3 &w : b) best = std::min(best, length(v - w));
        EXPECT_LT(best, digits * std::max(1.0, length(v))) << what << " " << v.toString();
    }
}

/// World points of every primitive (circles already faceted as OpenSCAD facets them).
inline std::vector<Vec3> worldPoints(const ir::Scene &scene) {
    std::vector<Vec3> out;
    for (const auto &p : primitives(*scene.root)) {
        std::vector<Vec3> local;
        if (const auto *b = std::get_if<ir::BoxPrim>(&p.node->shape)) {
            for (int i = 0; i < 8; ++i)
                local.push_back(Vec3(i & 1 ? b->max.x : b->min.x, i & 2 ? b->max.y : b->min.y,
                                     i & 4 ? b->max.z : b->min.z));
        } else if (const auto *poly = std::get_if<ir::PolytopePrim>(&p.node->shape)) {
            local = poly->vertices;
        } else if (const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape)) {
            local = ir::prismPoints(*prism);
        } else if (const auto *mp = std::get_if<ir::MeshPrim>(&p.node->shape)) {
            local = scene.meshes[mp->mesh]->positions;
        } else {
            ADD_FAILURE() << "unexpected primitive";
        }
        for (const Vec3 &v : local) out.push_back(p.worldFromObject.transformPoint(v));
    }
    return out;
}

/// OpenSCAD's OFF export of `src`, written through files in `dir` (a failed run fails the
/// test and gives an empty mesh).
inline ir::Mesh openscadOff(const std::string &src, const std::filesystem::path &dir) {
    std::string scad = (dir / "case.scad").string(), off = (dir / "case.off").string();
    std::ofstream(scad) << src << "\n";
    std::string cmd = "openscad -o '" + off + "' '" + scad + "' >/dev/null 2>&1";
    int status = std::system(cmd.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    DiagnosticSink diag;
    return meshio::readMeshFile(off, diag);
}

/// The scene's one primitive, a polytope or a prism of a convex outline (as its polytope),
/// with its vertices in world coordinates (an empty polytope, after a test failure, when the
/// scene holds anything else).
inline ir::PolytopePrim worldPolytope(const ir::Scene &scene) {
    auto prims = primitives(*scene.root);
    EXPECT_EQ(prims.size(), 1u);
    std::optional<ir::PolytopePrim> poly;
    if (prims.size() == 1) {
        const ir::PrimShape &shape = prims[0].node->shape;
        if (const auto *p = std::get_if<ir::PolytopePrim>(&shape)) poly = *p;
        const auto *prism = std::get_if<ir::PrismPrim>(&shape);
        if (prism && prism->mesh < 0) poly = ir::prismPolytope(*prism);
    }
    EXPECT_TRUE(poly) << "not a polytope";
    if (!poly) return {};
    ir::PolytopePrim world = *poly;
    for (Vec3 &v : world.vertices) v = prims[0].worldFromObject.transformPoint(v);
    return world;
}

/// Every point of `a` lies on the surface of the polytope.
inline void expectOnSurface(const std::vector<Vec3> &a, const ir::PolytopePrim &p) {
    std::vector<meshing::FacePlane> planes = meshing::polytopePlanes(p);
    for (const Vec3 &v : a) {
        double outside = -kInfinity;
        for (const auto &pl : planes) outside = std::max(outside, dot(pl.normal, v) - pl.offset);
        EXPECT_LT(std::abs(outside), kOffDigits * std::max(1.0, length(v))) << v.toString();
    }
}

/// The scene `src` imports to is one polytope with the vertices (OFF's 6 digits) and the volume
/// of OpenSCAD's export. Where OpenSCAD's exact arithmetic leaves points on straight hull
/// edges (extraCollinearVertices), its vertices need only lie on our polytope's surface.
inline void expectSamePolytope(const std::string &src, const std::filesystem::path &dir,
                               bool extraCollinearVertices = false) {
    ir::Mesh theirs = openscadOff(src, dir);
    ASSERT_FALSE(theirs.positions.empty());
    Imported ours = importText(src);
    EXPECT_TRUE(ours.warnings().empty()) << ours.warnings().front();
    ir::PolytopePrim placed = worldPolytope(ours.scene);
    const std::vector<Vec3> &world = placed.vertices;
    ASSERT_FALSE(world.empty());
    expectCovered(world, theirs.positions, "our vertex missing from OpenSCAD's:");
    if (extraCollinearVertices) {
        expectOnSurface(theirs.positions, placed);
        EXPECT_GT(theirs.positions.size(), world.size());
    } else {
        EXPECT_EQ(world.size(), theirs.positions.size());
        expectCovered(theirs.positions, world, "OpenSCAD's vertex missing from ours:");
    }
    double vo = polytopeVolume(world, placed.faces), vt = meshVolume(theirs);
    EXPECT_NEAR(vo, vt, kOffDigits * 10 * std::abs(vt));
}

/// Point comparisons at OFF's 6 significant digits; Clipper's grid (2^-16 = 1.5e-5) is
/// coarser, so a point off by one grid step fails where coordinates are below 1.
constexpr double kOffPointDigits = 6e-6;

/// Every point of `a` has one of `b` within kOffPointDigits (relative above 1).
inline void expectPointsCovered(const std::vector<Vec3> &a, const std::vector<Vec3> &b,
                                const char *what) {
    expectCovered(a, b, what, kOffPointDigits);
}

/// The distinct points, projected on the plane z = 0 first when `flatten`, sorted.
inline std::vector<Vec3> distinctPoints(std::vector<Vec3> v, bool flatten) {
    if (flatten)
        for (Vec3 &p : v) p.z = 0;
    auto less = [](const Vec3 &a, const Vec3 &b) {
        return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
    };
    std::sort(v.begin(), v.end(), less);
    v.erase(
        std::unique(v.begin(), v.end(),
                    [&less](const Vec3 &a, const Vec3 &b) { return !less(a, b) && !less(b, a); }),
        v.end());
    return v;
}

}  // namespace rt::scad::test
