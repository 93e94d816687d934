// SPDX-License-Identifier: MIT
// The planar faces and points of prisms: closed, outward, with the volumes of prisms,
// frustums and pyramids, and the hull and bounds that follow from them.
#include "core/ir/prism.h"

#include <gtest/gtest.h>

#include <map>

#include "core/ir/scene_ir.h"
#include "core/meshing/facets.h"
#include "core/meshing/hull.h"

namespace rt::ir {
namespace {

using namespace meshing;

/// Volume by the divergence theorem over fan-triangulated faces.
double volume(const PolytopePrim &p) {
    double v = 0;
    for (const auto &f : p.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k)
            v += dot(p.vertices[f[0]], cross(p.vertices[f[k]], p.vertices[f[k + 1]]));
    return v / 6;
}

/// Every directed edge once and its reverse once (closed, consistently oriented), and the
/// centroid behind every face (outward, for a convex outline).
void expectClosedOutward(const PolytopePrim &p) {
    std::map<std::pair<int, int>, int> edges;
    for (const auto &f : p.faces) {
        ASSERT_GE(f.size(), 3u);
        for (size_t k = 0; k < f.size(); ++k) ++edges[{f[k], f[(k + 1) % f.size()]}];
    }
    for (const auto &[e, n] : edges) {
        EXPECT_EQ(n, 1) << e.first << "-" << e.second;
        EXPECT_EQ(edges.count({e.second, e.first}), 1u) << e.first << "-" << e.second;
    }
    Vec3 centroid(0);
    for (const Vec3 &v : p.vertices)
        centroid = centroid + v / static_cast<double>(p.vertices.size());
    for (const FacePlane &pl : polytopePlanes(p)) EXPECT_LT(dot(pl.normal, centroid), pl.offset);
    // Planes as listed (polytopePlanes would orient a face listed the wrong way round)
    for (const auto &f : p.faces) {
        Vec3 a = p.vertices[f[0]], b = p.vertices[f[1]], c = p.vertices[f[2]];
        EXPECT_GT(dot(cross(b - a, c - a), a - centroid), 0);
    }
}

const std::vector<Point2> kPentagon{{0, 0}, {2, 0}, {3, 1}, {1, 3}, {-1, 1}};
// Shoelace area of kPentagon
const double kPentagonArea = 0.5 * (0 + 2 * 1 - 3 * 0 + 3 * 3 - 1 * 1 + 1 * 1 + 1 * 3 - 0);

TEST(Prism, StraightPrismIsClosedWithAreaTimesHeight) {
    PrismPrim p{kPentagon, -1, 2.5, 1, 1, -1};
    PolytopePrim poly = prismPolytope(p);
    EXPECT_EQ(poly.vertices.size(), 10u);
    EXPECT_EQ(poly.faces.size(), 7u);
    expectClosedOutward(poly);
    EXPECT_NEAR(volume(poly), kPentagonArea * 3.5, 1e-12);
}

TEST(Prism, FrustumAndPyramidVolumes) {
    // Frustum: h / 3 (A0 + A1 + sqrt(A0 A1)) with A = k^2 A
    PrismPrim f{kPentagon, 0, 2, 2, 0.5, -1};
    PolytopePrim poly = prismPolytope(f);
    expectClosedOutward(poly);
    EXPECT_NEAR(volume(poly), 2.0 / 3 * kPentagonArea * (4 + 0.25 + 1), 1e-12);
    // Apex on top, then below: one apex vertex, triangles to it, one cap
    for (PrismPrim pyr :
         {PrismPrim{kPentagon, 1, 4, 1, 0, -1}, PrismPrim{kPentagon, 1, 4, 0, 1, -1}}) {
        poly = prismPolytope(pyr);
        EXPECT_EQ(poly.vertices.size(), 6u);
        EXPECT_EQ(poly.faces.size(), 6u);
        expectClosedOutward(poly);
        EXPECT_NEAR(volume(poly), kPentagonArea * 3 / 3, 1e-12);
    }
}

TEST(Prism, PointsAndBoundsAreTheCorners) {
    PrismPrim p{kPentagon, 0, 1, 2, 0, -1};
    std::vector<Vec3> pts = prismPoints(p);
    ASSERT_EQ(pts.size(), 6u);
    EXPECT_EQ(pts[1], Vec3(4, 0, 0));
    EXPECT_EQ(pts[5], Vec3(0, 0, 1));
    Bounds3 b = primitiveBounds(p);
    EXPECT_EQ(b.min, Vec3(-2, 0, 0));
    EXPECT_EQ(b.max, Vec3(6, 6, 1));
}

}  // namespace
}  // namespace rt::ir
