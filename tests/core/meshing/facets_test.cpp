// SPDX-License-Identifier: MIT
// OpenSCAD's fragment counts and tessellation, the polytope planes, and the --facets rule.
#include "core/meshing/facets.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/primitive.h"
#include "core/ir/scene_ir.h"
#include "core/math/rng.h"

namespace rt::meshing {
using namespace ir;
namespace {

Fragments fn(double n) { return Fragments{n, 12, 2}; }

TEST(Facets, FragmentCountsAreOpenScads) {
    Fragments defaults;
    // Defaults $fa=12, $fs=2: 5 up to r = 5/pi, ceil(pi r) up to 30/pi, then 30
    EXPECT_EQ(openscadFragments(1, defaults), 5);
    EXPECT_EQ(openscadFragments(1.59, defaults), 5);
    EXPECT_EQ(openscadFragments(5, defaults), 16);
    EXPECT_EQ(openscadFragments(9.5, defaults), 30);
    EXPECT_EQ(openscadFragments(1000, defaults), 30);
    // $fn truncates in 2021.01 and is at least 3
    EXPECT_EQ(openscadFragments(1, fn(6)), 6);
    EXPECT_EQ(openscadFragments(1, fn(3.5)), 3);
    EXPECT_EQ(openscadFragments(1, fn(6.9)), 6);
    EXPECT_EQ(openscadFragments(1, fn(1)), 3);
    EXPECT_EQ(openscadFragments(1, fn(2)), 3);
    // Below GRID_FINE (2^-20) every circle is a triangle
    EXPECT_EQ(openscadFragments(1e-7, fn(64)), 3);
    EXPECT_EQ(openscadFragments(1, Fragments{0, 30, 0.1}), 12);
    EXPECT_EQ(openscadFragments(1, Fragments{0, 1, 0.5}), 13);
}

TEST(Facets, SphereHasOpenScadsRingsAndNoPoles) {
    // sphere(2, $fn=6): 3 rings at polar angles 30, 90, 150 degrees, each a hexagon from +X
    PolytopePrim p = openscadSphere(2, 6);
    ASSERT_EQ(p.vertices.size(), 18u);
    EXPECT_EQ(p.faces.size(), 2u + 2 * 6);
    EXPECT_NEAR(p.vertices[0].x, 1, 1e-15);
    EXPECT_NEAR(p.vertices[0].z, std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(p.vertices[6].x, 2, 1e-15);
    EXPECT_NEAR(p.vertices[6].z, 0, 1e-15);
    EXPECT_NEAR(p.vertices[17].z, -std::sqrt(3.0), 1e-15);
    // Default sphere(1): 5 fragments, 3 rings, z extent +-cos(30 degrees)
    PolytopePrim d = openscadSphere(1, openscadFragments(1, Fragments{}));
    EXPECT_EQ(d.vertices.size(), 15u);
    Bounds3 b = primitiveBounds(d);
    EXPECT_NEAR(b.max.z, std::cos(M_PI / 6), 1e-15);
    EXPECT_NEAR(b.min.z, -std::cos(M_PI / 6), 1e-15);
}

TEST(Facets, ConeHasOneApexAndTriangularSides) {
    PolytopePrim p = openscadCylinder(CylinderPrim{0, 3, 2, 0}, 5);
    ASSERT_EQ(p.vertices.size(), 6u);
    ASSERT_EQ(p.faces.size(), 6u);  // 5 triangles and the base
    for (int i = 0; i < 5; ++i) EXPECT_EQ(p.faces[i].size(), 3u);
    EXPECT_EQ(p.faces[5].size(), 5u);
    PolytopePrim up = openscadCylinder(CylinderPrim{0, 3, 0, 2}, 4);
    EXPECT_EQ(up.vertices.size(), 5u);
    EXPECT_EQ(up.faces.size(), 5u);
}

TEST(Facets, FacesAreCounterClockwiseFromOutsideAndPlanesPointOut) {
    for (const PolytopePrim &p :
         {openscadSphere(1.5, 7), openscadSphere(3, 30), openscadCylinder({-1, 1, 0.8, 0.8}, 6),
          openscadCylinder({0, 2, 1, 0}, 3), openscadCylinder({0, 2, 0.5, 1.5}, 8)}) {
        Vec3 centroid(0);
        for (const Vec3 &v : p.vertices) centroid += v;
        centroid = centroid / static_cast<double>(p.vertices.size());
        auto planes = polytopePlanes(p);
        ASSERT_EQ(planes.size(), p.faces.size());
        for (size_t i = 0; i < p.faces.size(); ++i) {
            const auto &f = p.faces[i];
            // The IR's winding: (v1 - v0) x (v2 - v0) points out
            Vec3 n =
                cross(p.vertices[f[1]] - p.vertices[f[0]], p.vertices[f[2]] - p.vertices[f[0]]);
            EXPECT_GT(dot(n, p.vertices[f[0]] - centroid), 0) << "face " << i;
            EXPECT_GT(dot(planes[i].normal, n), 0) << "face " << i;
            EXPECT_NEAR(length(planes[i].normal), 1, 1e-15);
            // Every vertex is on or behind every plane; the face's own vertices are on it
            for (const Vec3 &v : p.vertices)
                EXPECT_LE(dot(planes[i].normal, v) - planes[i].offset, 1e-14);
            for (int k : f)
                EXPECT_NEAR(dot(planes[i].normal, p.vertices[k]), planes[i].offset, 1e-14);
        }
    }
}

TEST(Facets, AxisPlanesAreExact) {
    auto planes = polytopePlanes(openscadCylinder({0.1, 0.7, 1, 1}, 6));
    int axisPlanes = 0;
    for (const auto &pl : planes)
        if (pl.axis == 2) {
            ++axisPlanes;
            EXPECT_EQ(pl.normal.z * pl.offset, pl.normal.z > 0 ? 0.7 : 0.1);
        }
    EXPECT_EQ(axisPlanes, 2);
}

TEST(Facets, SquareCylinderIsADiamond) {
    // cylinder(r=1, $fn=4): a square with corners on the axes. (0.6, 0.6) is inside the
    // circle but outside the square; (0.45, 0.45) inside both.
    ConvexPolytope square(openscadCylinder({0, 1, 1, 1}, 4));
    EXPECT_FALSE(square.inside(Vec3(0.6, 0.6, 0.5)));
    EXPECT_TRUE(square.inside(Vec3(0.45, 0.45, 0.5)));
    PrimitiveSpan span;
    EXPECT_FALSE(square.intersect(Ray(Vec3(0.6, 0.6, 5), Vec3(0, 0, -1)), &span));
    ASSERT_TRUE(square.intersect(Ray(Vec3(0.45, 0.45, 5), Vec3(0, 0, -1)), &span));
    EXPECT_EQ(span.t0, 4);
    EXPECT_EQ(span.t1, 5);
    // A ray along x through the middle meets the corners at +-1
    ASSERT_TRUE(square.intersect(Ray(Vec3(-5, 0, 0.5), Vec3(1, 0, 0)), &span));
    EXPECT_NEAR(span.t0, 4, 1e-15);
    EXPECT_NEAR(span.t1, 6, 1e-15);
}

TEST(Facets, ManyFacedPolytopesUseAFaceBvhWithTheSameSpans) {
    // Spans found through the face BVH against the plane-based inside test along random lines
    ConvexPolytope big(openscadSphere(2, 40));
    ASSERT_TRUE(big.usesFaceBvh());
    EXPECT_FALSE(ConvexPolytope(openscadSphere(2, 8)).usesFaceBvh());
    Rng rng(5);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        Vec3 o(rng.uniform() * 8 - 4, rng.uniform() * 8 - 4, rng.uniform() * 8 - 4);
        Vec3 target(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2);
        Ray r(o, normalize(target - o));
        PrimitiveSpan s;
        if (!big.intersect(r, &s)) {
            // A miss: no point of the line near the sphere is inside
            bool anyInside = false;
            for (double t = -8; t <= 8; t += 0.05) anyInside |= big.inside(r.at(t));
            EXPECT_FALSE(anyInside);
            continue;
        }
        ++hits;
        double len = s.t1 - s.t0;
        EXPECT_TRUE(big.inside(r.at(s.t0 + 0.5 * len)));
        EXPECT_FALSE(big.inside(r.at(s.t0 - 1e-6)));
        EXPECT_FALSE(big.inside(r.at(s.t1 + 1e-6)));
        // The span's faces are the planes the ends lie on
        for (auto [t, face] : {std::pair{s.t0, s.face0}, std::pair{s.t1, s.face1}}) {
            ObjectSurface os = big.surface(r.at(t), face);
            EXPECT_LT(length(os.p - r.at(t)), 1e-12);
        }
    }
    EXPECT_GT(hits, 1000);
}

Scene sceneOf(std::vector<std::pair<PrimShape, Fragments>> prims) {
    Scene s;
    for (auto &[shape, fr] : prims) {
        auto n = Node::makePrimitive(shape, s.addMaterial(Material()), {});
        n->fragments = fr;
        s.root->children.push_back(std::move(n));
    }
    return s;
}

bool isPolytope(const Scene &s, size_t i) {
    return std::holds_alternative<PolytopePrim>(s.root->children[i]->shape);
}

TEST(Facets, AutoFacetsSmallExplicitFnOnly) {
    auto make = [] {
        return sceneOf({{SpherePrim{1}, Fragments{}},        // defaults: 5, round
                        {CylinderPrim{0, 1, 1, 1}, fn(6)},   // hexagon
                        {CylinderPrim{0, 1, 2, 2}, fn(12)},  // 12-gon
                        {CylinderPrim{0, 1, 1, 1}, fn(13)},  // round
                        {SpherePrim{1}, fn(64)},             // round
                        {BoxPrim{}, fn(4)}});                // a box is a box
    };
    DiagnosticSink diag;
    Scene a = make();
    applyFacets(a, FacetMode::Auto, diag);
    EXPECT_FALSE(isPolytope(a, 0));
    EXPECT_TRUE(isPolytope(a, 1));
    EXPECT_TRUE(isPolytope(a, 2));
    EXPECT_FALSE(isPolytope(a, 3));
    EXPECT_FALSE(isPolytope(a, 4));
    EXPECT_FALSE(isPolytope(a, 5));
    ASSERT_TRUE(a.stats.facets);
    EXPECT_EQ(a.stats.facets->faceted, 2);
    EXPECT_EQ(a.stats.facets->smooth, 3);
    EXPECT_NE(a.stats.facets->describe().find("at most 12 fragments"), std::string::npos);

    Scene o = make();
    applyFacets(o, FacetMode::OpenScad, diag);
    for (size_t i = 0; i < 5; ++i) EXPECT_TRUE(isPolytope(o, i)) << i;
    Scene s = make();
    applyFacets(s, FacetMode::Smooth, diag);
    for (size_t i = 0; i < 6; ++i) EXPECT_FALSE(isPolytope(s, i)) << i;
    EXPECT_TRUE(diag.all().empty());
}

TEST(Facets, HugeFragmentCountsStayRoundWithAWarning) {
    Scene s = sceneOf({{SpherePrim{1}, fn(1e6)}});
    DiagnosticSink diag;
    applyFacets(s, FacetMode::OpenScad, diag);
    EXPECT_FALSE(isPolytope(s, 0));
    ASSERT_EQ(diag.all().size(), 1u);
    EXPECT_NE(diag.all()[0].message.find("drawn round"), std::string::npos);
}

TEST(Facets, ModeNamesRoundTrip) {
    for (FacetMode m : {FacetMode::Smooth, FacetMode::OpenScad, FacetMode::Auto})
        EXPECT_EQ(parseFacetMode(facetModeName(m)), m);
    EXPECT_FALSE(parseFacetMode("round"));
}

}  // namespace
}  // namespace rt::meshing
