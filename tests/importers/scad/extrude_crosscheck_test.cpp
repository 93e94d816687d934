// SPDX-License-Identifier: MIT
// Cross-checks linear_extrude against the installed OpenSCAD 2021.01: bounds, volume and
// vertices of its OFF export against the lifted IR (circles drawn with --facets openscad).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/ir/prism.h"
#include "core/math/bounds3.h"
#include "core/meshing/facets.h"
#include "importers/mesh/mesh_reader.h"
#include "importers/scad/test_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

/// OFF files print coordinates with limited digits, and OpenSCAD snaps 2D outlines to a
/// fixed-point grid (Clipper) before extruding them.
constexpr double kVertexTolerance = 1e-5;
constexpr double kVolumeTolerance = 1e-6;  ///< relative

bool haveOpenScad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

double det3(const Mat4 &m) {
    return m.m[0][0] * (m.m[1][1] * m.m[2][2] - m.m[1][2] * m.m[2][1]) -
           m.m[0][1] * (m.m[1][0] * m.m[2][2] - m.m[1][2] * m.m[2][0]) +
           m.m[0][2] * (m.m[1][0] * m.m[2][1] - m.m[1][1] * m.m[2][0]);
}

double triVolume(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return dot(a, cross(b, c)) / 6; }

double meshVolume(const ir::Mesh &m) {
    double v = 0;
    for (const auto &t : m.triangles)
        v += triVolume(m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]);
    return v;
}

/// Volume of a polytope; its faces may be listed either way round (polytopePlanes orients
/// them).
double polytopeVolume(const ir::PolytopePrim &poly) {
    double v = 0;
    for (const auto &f : poly.faces)
        for (size_t i = 1; i + 1 < f.size(); ++i)
            v += triVolume(poly.vertices[f[0]], poly.vertices[f[i]], poly.vertices[f[i + 1]]);
    return std::abs(v);
}

/// World vertices and volume of one primitive (faceted cylinders are polytopes by now).
struct Solid {
    std::vector<Vec3> vertices;
    double volume = 0;
};

Solid solidOf(const ir::Scene &scene, const PlacedPrimitive &p) {
    Solid s;
    const Mat4 &m = p.worldFromObject;
    std::vector<Vec3> local;
    if (const auto *b = std::get_if<ir::BoxPrim>(&p.node->shape)) {
        for (int i = 0; i < 8; ++i)
            local.push_back(Vec3(i & 1 ? b->max.x : b->min.x, i & 2 ? b->max.y : b->min.y,
                                 i & 4 ? b->max.z : b->min.z));
        Vec3 d = b->max - b->min;
        s.volume = d.x * d.y * d.z;
    } else if (const auto *poly = std::get_if<ir::PolytopePrim>(&p.node->shape)) {
        local = poly->vertices;
        s.volume = polytopeVolume(*poly);
    } else if (const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape)) {
        // Its corners; its volume from its mesh, or from its faces when convex
        local = ir::prismPoints(*prism);
        s.volume = prism->mesh >= 0 ? meshVolume(*scene.meshes[prism->mesh])
                                    : polytopeVolume(ir::prismPolytope(*prism));
    } else if (const auto *mp = std::get_if<ir::MeshPrim>(&p.node->shape)) {
        local = scene.meshes[mp->mesh]->positions;
        s.volume = meshVolume(*scene.meshes[mp->mesh]);
    } else {
        ADD_FAILURE() << "unexpected primitive";
    }
    for (const Vec3 &v : local) s.vertices.push_back(m.transformPoint(v));
    s.volume *= std::abs(det3(m));
    return s;
}

double zExtent(const ir::Scene &scene, const ir::Node &n) {
    double lo = 1e300, hi = -1e300;
    for (const auto &p : primitives(n))
        for (const Vec3 &v : solidOf(scene, p).vertices) {
            lo = std::min(lo, v.z);
            hi = std::max(hi, v.z);
        }
    return hi - lo;
}

/// Volume of a lifted tree whose unions are disjoint and whose subtrahends are straight
/// prisms inside their minuend's outline, reaching beyond its caps.
double treeVolume(const ir::Scene &scene, const ir::Node &n, const Mat4 &m) {
    Mat4 here = n.kind == ir::NodeKind::Transform ? m * n.matrix : m;
    if (n.kind == ir::NodeKind::Primitive) return solidOf(scene, {&n, here}).volume;
    double v = 0;
    for (size_t i = 0; i < n.children.size(); ++i) {
        double c = treeVolume(scene, *n.children[i], here);
        if (n.kind == ir::NodeKind::Difference && i > 0)
            c *= -zExtent(scene, *n.children[0]) / zExtent(scene, *n.children[i]);
        v += c;
    }
    return v;
}

struct Case {
    const char *src;
    bool compareVertices;  ///< false where subtrahends reach beyond the caps
};

class ExtrudeCrossCheck : public ::testing::TestWithParam<Case> {};

TEST_P(ExtrudeCrossCheck, BoundsVolumeAndVertices) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const Case &c = GetParam();
    SCOPED_TRACE(c.src);
    fs::path dir = fs::temp_directory_path() / ("scadray_extrude_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::string in = (dir / "case.scad").string(), off = (dir / "case.off").string();
    std::ofstream(in) << c.src << "\n";
    fs::remove(off);
    std::string cmd = "openscad -o '" + off + "' '" + in + "' >/dev/null 2>&1";
    int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << cmd;
    DiagnosticSink offDiag;
    ir::Mesh ref = meshio::readOff(off, offDiag);

    DiagnosticSink diag;
    ir::Scene scene = importScad(in, diag);
    meshing::applyFacets(scene, ir::FacetMode::OpenScad, diag);
    auto prims = primitives(*scene.root);
    ASSERT_FALSE(prims.empty());

    // Volume
    double refVolume = meshVolume(ref);
    double ours = treeVolume(scene, *scene.root, Mat4());
    EXPECT_NEAR(ours, refVolume, kVolumeTolerance * std::abs(refVolume));

    // Bounds (of the minuends only where subtrahends reach beyond them)
    Bounds3 refBounds = ref.bounds(), ourBounds;
    std::vector<Vec3> ourVertices;
    for (const auto &p : prims) {
        Solid s = solidOf(scene, p);
        ourVertices.insert(ourVertices.end(), s.vertices.begin(), s.vertices.end());
        if (!c.compareVertices && &p != &prims.front()) continue;
        for (const Vec3 &v : s.vertices) ourBounds = unionBounds(ourBounds, v);
    }
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(ourBounds.min[a], refBounds.min[a], kVertexTolerance) << "axis " << a;
        EXPECT_NEAR(ourBounds.max[a], refBounds.max[a], kVertexTolerance) << "axis " << a;
    }
    if (!c.compareVertices) return;

    // The same vertex sets, both ways
    auto has = [](const std::vector<Vec3> &set, const Vec3 &v) {
        for (const Vec3 &w : set)
            if (length(w - v) < kVertexTolerance * std::max(1.0, length(v))) return true;
        return false;
    };
    for (const Vec3 &v : ref.positions)
        EXPECT_TRUE(has(ourVertices, v))
            << "OpenSCAD vertex missing: " << v.x << " " << v.y << " " << v.z;
    for (const Vec3 &v : ourVertices)
        EXPECT_TRUE(has(ref.positions, v))
            << "vertex not in OpenSCAD's: " << v.x << " " << v.y << " " << v.z;
}

INSTANTIATE_TEST_SUITE_P(
    Extrusions, ExtrudeCrossCheck,
    ::testing::Values(
        Case{"linear_extrude(3) square([2, 4]);", true},
        Case{"linear_extrude(height=5, center=true, scale=0.5) circle(r=4, $fn=12);", true},
        Case{"linear_extrude(height=2, scale=2) translate([1, 0.5]) rotate(30) "
             "polygon([[0,0],[3,0],[1,2]]);",
             true},
        Case{"linear_extrude(2) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]);", true},
        Case{"linear_extrude(height=3, scale=0) square(2, center=true);", true},
        Case{"linear_extrude(height=10, twist=90, $fn=8) square(2);", true},
        Case{"linear_extrude(height=20, twist=200) square([5, 3]);", true},
        Case{"linear_extrude(height=10, twist=180, scale=0.5) square(4, center=true);", true},
        Case{"linear_extrude(height=6, twist=-120, scale=[1.5, 0.5]) translate([1, 0]) "
             "square([2, 1]);",
             true},
        Case{"linear_extrude(height=4, scale=[2, 0.5]) circle(3, $fn=9);", true},
        Case{"linear_extrude(height=5, twist=60, slices=3) mirror([1, 0]) "
             "polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]);",
             true},
        Case{"linear_extrude(2) difference() { square(10); translate([5, 5]) circle(2, $fn=10); }",
             false},
        Case{"linear_extrude(2) polygon([[0,0],[10,0],[10,10],[0,10],[2,2],[8,2],[8,8],[2,8]], "
             "[[0,1,2,3],[4,5,6,7]]);",
             false},
        // Even-odd: an island inside the hole, paths listed clockwise and counter-clockwise
        Case{"linear_extrude(3) polygon([[0,0],[10,0],[10,10],[0,10],[2,2],[2,8],[8,8],[8,2],"
             "[4,4],[6,4],[6,6],[4,6]], [[0,1,2,3],[4,5,6,7],[8,9,10,11]]);",
             false}));

}  // namespace
}  // namespace rt::scad::test
