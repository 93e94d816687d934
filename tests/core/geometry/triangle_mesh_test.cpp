// SPDX-License-Identifier: MIT
// Triangle meshes: watertight hits through shared edges and vertices, whole-line spans that
// match the analytic box, inside tests, BVH against brute force, no self-intersection of
// spawned rays, smooth and flat shading normals, open meshes.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geometry/triangle_mesh.h"
#include "core/ir/diagnostics.h"
#include "core/math/rng.h"
#include "support/mesh_builder.h"

namespace rt {
namespace {

using namespace rt::test;

double signedVolume(const ir::Mesh &m) {
    double v = 0;
    for (const auto &t : m.triangles)
        v += dot(m.positions[t[0]], cross(m.positions[t[1]], m.positions[t[2]])) / 6;
    return v;
}

Vec3 randomDirection(Rng &rng) {
    double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
    double r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

TEST(TriangleMesh, BuildersAreClosedAndOutward) {
    for (auto m : {cubeMesh(Vec3(-1), Vec3(2)), icosphere(2, 1.5)}) {
        ir::MeshTopology t = ir::analyzeMesh(*m);
        EXPECT_TRUE(t.oriented());
        EXPECT_GT(signedVolume(*m), 0);
    }
}

TEST(TriangleMesh, CubeSpansMatchTheAnalyticBox) {
    Rng rng(3);
    auto mesh = std::make_shared<TriangleMesh>(cubeMesh(Vec3(-1, -0.5, 0), Vec3(2, 1, 0.7)));
    auto place = *Transform::fromMatrix(Mat4::translate(Vec3(1, 2, 3)) *
                                        Mat4::rotateAxis(30, Vec3(1, 1, 0)));
    MeshInstance inst(mesh, place, 0);
    PrimitiveInstance box(std::make_unique<Box>(Vec3(-1, -0.5, 0), Vec3(2, 1, 0.7)), place, 0);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Vec3 target =
            Vec3(1, 2, 3) + Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * 3;
        Vec3 o = Vec3(1, 2, 3) + randomDirection(rng) * 10;
        Ray r(o, normalize(target - o));
        SpanList a, b;
        inst.lineSpans(r, a);
        box.lineSpans(r, b);
        ASSERT_EQ(a.size(), b.size());
        if (a.empty()) continue;
        ++hits;
        EXPECT_NEAR(a[0].in.t, b[0].in.t, 1e-12 * 10);
        EXPECT_NEAR(a[0].out.t, b[0].out.t, 1e-12 * 10);
    }
    EXPECT_GT(hits, 1000);
}

TEST(TriangleMesh, SpansOfRaysStartingInsideSeeTheFacesBehind) {
    // A shadow ray leaving a cut face into a mesh subtrahend starts inside the mesh, a hair
    // above its flat bottom face: the whole-line span must still begin at that face (behind
    // the origin), or the difference() is not cut along the ray and the face looks shadowed
    auto mesh = std::make_shared<TriangleMesh>(cubeMesh(Vec3(-20, -20, 4), Vec3(20, 20, 44)));
    MeshInstance inst(mesh, Transform(), 0);
    PrimitiveInstance box(std::make_unique<Box>(Vec3(-20, -20, 4), Vec3(20, 20, 44)), Transform(),
                          0);
    Rng rng(11);
    for (double above : {1e-12, 1e-9, 1e-6, 1e-3, 1.0}) {
        for (int i = 0; i < 200; ++i) {
            Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, 4 + above);
            Vec3 d = normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, 1));
            Ray r(o, d);
            SpanList a, b;
            inst.lineSpans(r, a);
            box.lineSpans(r, b);
            ASSERT_EQ(a.size(), 1u) << "above " << above;
            ASSERT_EQ(b.size(), 1u);
            EXPECT_LT(a[0].in.t, 0);
            EXPECT_NEAR(a[0].in.t, b[0].in.t, 1e-12 * 50);
            EXPECT_NEAR(a[0].out.t, b[0].out.t, 1e-12 * 50);
        }
    }
}

TEST(TriangleMesh, RaysThroughVerticesAndEdgesNeverSlipThrough) {
    // Watertightness: a ray aimed exactly at a vertex or an edge midpoint of a closed convex
    // mesh, from outside towards the centre, enters and leaves exactly once
    auto ir = icosphere(2, 1);
    auto mesh = std::make_shared<TriangleMesh>(ir);
    MeshInstance inst(mesh, Transform(), 0);
    Rng rng(8);
    int tested = 0;
    std::vector<Vec3> targets = ir->positions;
    for (const auto &t : ir->triangles)
        targets.push_back((ir->positions[t[0]] + ir->positions[t[1]]) * 0.5);
    for (const Vec3 &target : targets) {
        for (int k = 0; k < 3; ++k) {
            Vec3 o = target * 3 + randomDirection(rng) * 0.7;
            Ray r(o, normalize(target * 0.2 - o));
            // Steer exactly through the target point: origin on the line through it
            r = Ray(target - r.d * 5, r.d);
            SpanList spans;
            inst.lineSpans(r, spans);
            ASSERT_EQ(spans.size(), 1u) << "ray through " << target.toString();
            EXPECT_NEAR(spans[0].in.t, 5, 1e-9);
            ++tested;
        }
    }
    EXPECT_GT(tested, 500);
}

TEST(TriangleMesh, InsideTest) {
    auto mesh = std::make_shared<TriangleMesh>(icosphere(3, 2));
    MeshInstance inst(mesh, *Transform::fromMatrix(Mat4::translate(Vec3(5, 0, 0))), 0);
    Rng rng(4);
    for (int i = 0; i < 2000; ++i) {
        Vec3 p = randomDirection(rng) * (rng.uniform() * 4);
        double r = length(p);
        if (r < 1.9) {
            EXPECT_TRUE(inst.inside(p + Vec3(5, 0, 0)));
        } else if (r > 2.01) {
            EXPECT_FALSE(inst.inside(p + Vec3(5, 0, 0)));
        }
    }
}

TEST(TriangleMesh, BvhClosestMatchesBruteForce) {
    Rng rng(21);
    auto soup = std::make_shared<ir::Mesh>();
    for (int i = 0; i < 3000; ++i) {
        Vec3 c(rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5);
        for (int k = 0; k < 3; ++k)
            soup->positions.push_back(c + Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * 0.6);
        uint32_t b = static_cast<uint32_t>(3 * i);
        soup->triangles.push_back({b, b + 1, b + 2});
    }
    TriangleMesh mesh(soup);
    for (int i = 0; i < 2000; ++i) {
        Ray r(Vec3(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10),
              randomDirection(rng));
        double best = kInfinity;
        uint32_t bestTri = 0;
        for (uint32_t t = 0; t < soup->triangles.size(); ++t) {
            TriangleMesh::Hit h;
            if (mesh.intersectTriangle(r, t, &h) && h.t > h.tError && h.t < best) {
                best = h.t;
                bestTri = t;
            }
        }
        TriangleMesh::Hit hit;
        bool found = mesh.closest(r, 0, kInfinity, &hit);
        ASSERT_EQ(found, best < kInfinity);
        if (found) {
            EXPECT_EQ(hit.t, best);
            EXPECT_EQ(hit.triangle, bestTri);
        }
    }
}

TEST(TriangleMesh, SpawnedRaysDoNotSelfIntersect) {
    auto mesh = std::make_shared<TriangleMesh>(icosphere(3, 1.3));
    Rng rng(5);
    SpanScratch scratch;
    for (auto place :
         {Mat4(), Mat4::translate(Vec3(1e3, -2e3, 500)) * Mat4::scale(Vec3(2, 0.5, 1))}) {
        MeshInstance inst(mesh, *Transform::fromMatrix(place), 0);
        int tested = 0;
        for (int i = 0; i < 3000; ++i) {
            Vec3 centre = place.transformPoint(Vec3(0));
            Vec3 o = centre + randomDirection(rng) * 20;
            Ray r(o, normalize(centre + randomDirection(rng) * 0.5 - o));
            Crossing c;
            if (!inst.firstCrossing(r, 0, kInfinity, &c, scratch)) continue;
            SurfaceInteraction si = inst.surfaceAt(r, c);
            Vec3 w = randomDirection(rng);
            double cosine = dot(w, si.n);
            if (std::abs(cosine) < 0.05) continue;
            ++tested;
            Crossing next;
            bool hit = inst.firstCrossing(spawnRay(si, w), 0, kInfinity, &next, scratch);
            if (cosine > 0) {
                EXPECT_FALSE(hit) << "outward ray re-hit the convex mesh at t=" << next.t;
            } else if (hit) {
                EXPECT_GT(next.t, 1e-6);
            } else {
                ADD_FAILURE() << "inward ray found no exit";
            }
        }
        EXPECT_GT(tested, 1000);
    }
}

TEST(TriangleMesh, SmoothNormalsInterpolateAndFlatTrianglesUseGeometry) {
    auto smooth = icosphere(1, 1, true);
    MeshInstance s(std::make_shared<TriangleMesh>(smooth), Transform(), 0);
    SpanScratch scratch;
    Ray r(Vec3(0.3, 0.2, 5), Vec3(0, 0, -1));
    Crossing c;
    ASSERT_TRUE(s.firstCrossing(r, 0, kInfinity, &c, scratch));
    SurfaceInteraction si = s.surfaceAt(r, c);
    // The interpolated normal is close to the sphere's normal, unlike the facet's
    Vec3 sphereNormal = normalize(si.p);
    EXPECT_GT(dot(si.ns, sphereNormal), dot(si.n, sphereNormal));
    EXPECT_NEAR(length(si.ns), 1, 1e-12);
    // Equal vertex normals: POV-Ray uses the facet normal
    auto flat = cubeMesh(Vec3(-1), Vec3(1));
    flat->normals.assign(flat->positions.size(), Vec3(0, 0, 1));
    MeshInstance f(std::make_shared<TriangleMesh>(flat), Transform(), 0);
    Ray side(Vec3(5, 0.1, 0.2), Vec3(-1, 0, 0));
    ASSERT_TRUE(f.firstCrossing(side, 0, kInfinity, &c, scratch));
    EXPECT_EQ(f.surfaceAt(side, c).ns, Vec3(1, 0, 0));
}

TEST(TriangleMesh, OpenMeshesBoundNothing) {
    auto open = cubeMesh(Vec3(-1), Vec3(1));
    open->triangles.pop_back();
    open->triangles.pop_back();
    TriangleMesh mesh(open);
    EXPECT_FALSE(mesh.closed());
    EXPECT_EQ(mesh.topology().boundaryEdges, 4u);
    MeshInstance inst(std::make_shared<TriangleMesh>(open), Transform(), 0);
    SpanList spans;
    inst.lineSpans(Ray(Vec3(-5, 0.1, 0.2), Vec3(1, 0, 0)), spans);
    EXPECT_TRUE(spans.empty());
    EXPECT_FALSE(inst.inside(Vec3(0)));
    // But its surfaces are still hit
    SpanScratch scratch;
    Crossing c;
    EXPECT_TRUE(inst.firstCrossing(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), 0, kInfinity, &c, scratch));
}

TEST(TriangleMesh, SplitVerticesStillCloseTheMesh) {
    // Every triangle with its own three vertices, as glTF files with flat normals and STL
    // files store them: closedness is judged by position
    auto shared = cubeMesh(Vec3(0), Vec3(1));
    auto split = std::make_shared<ir::Mesh>();
    for (const auto &t : shared->triangles) {
        uint32_t b = static_cast<uint32_t>(split->positions.size());
        for (uint32_t v : t) split->positions.push_back(shared->positions[v]);
        split->triangles.push_back({b, b + 1, b + 2});
    }
    ir::MeshTopology t = ir::analyzeMesh(*split);
    EXPECT_TRUE(t.closed());
    EXPECT_TRUE(t.oriented());
    // A gap is still a gap
    split->positions[0].x += 1e-9;
    EXPECT_FALSE(ir::analyzeMesh(*split).closed());
}

TEST(TriangleMesh, ValidationRejectsBadIndicesAndNaN) {
    auto m = cubeMesh(Vec3(0), Vec3(1));
    m->triangles[3][1] = 99;
    EXPECT_THROW(ir::validateMesh(*m), SceneError);
    auto n = cubeMesh(Vec3(0), Vec3(1));
    n->positions[2].y = NAN;
    EXPECT_THROW(ir::validateMesh(*n), SceneError);
    EXPECT_NO_THROW(ir::validateMesh(*cubeMesh(Vec3(0), Vec3(1))));
}

}  // namespace
}  // namespace rt
