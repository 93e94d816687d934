// SPDX-License-Identifier: MIT
// Property tests of the analytic primitives with random rays and transforms: crossings lie on
// the surface, spans classify inside/outside, spawned rays never re-hit the surface they leave.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/geometry/shape.h"
#include "core/math/rng.h"

namespace rt {
namespace {

struct Case {
    const char *name;
    ir::PrimShape shape;
    Mat4 placement;
};

std::vector<Case> cases() {
    Mat4 rot = Mat4::translate(Vec3(0.3, -2, 1)) * Mat4::rotateAxis(37, Vec3(1, 2, 3));
    Mat4 squash = Mat4::rotateZ(20) * Mat4::scale(Vec3(3, 0.5, 1.5));
    Mat4 mirror = Mat4::mirror(Vec3(1, 0, 1)) * Mat4::translate(Vec3(1, 1, 1));
    Mat4 far = Mat4::translate(Vec3(1e4, -1e4, 5e3));
    std::vector<Case> out;
    std::vector<std::pair<const char *, ir::PrimShape>> shapes = {
        {"sphere", ir::SpherePrim{1.5}},
        {"box", ir::BoxPrim{Vec3(-1, -0.5, 0), Vec3(2, 1, 0.7)}},
        {"cylinder", ir::CylinderPrim{-1, 1, 0.8, 0.8}},
        {"cone", ir::CylinderPrim{0, 2, 1, 0}},
        {"cone_up", ir::CylinderPrim{-0.5, 1, 0, 1.2}},
        {"frustum", ir::CylinderPrim{0, 1.5, 1.5, 0.4}},
        // OpenSCAD's faceted solids (--facets openscad): convex polytopes
        {"polytope_sphere", meshing::openscadSphere(1.5, 7)},
        {"polytope_hexagon", meshing::openscadCylinder(ir::CylinderPrim{-1, 1, 0.8, 0.8}, 6)},
        {"polytope_pyramid", meshing::openscadCylinder(ir::CylinderPrim{0, 2, 1, 0}, 4)},
        {"polytope_frustum", meshing::openscadCylinder(ir::CylinderPrim{0, 1.5, 1.5, 0.4}, 5)},
        // 422 faces: entry and exit found through the BVH over its faces
        {"polytope_many_faces", meshing::openscadSphere(1.5, 30)},
    };
    for (auto &[n, s] : shapes) {
        out.push_back({n, s, Mat4()});
        out.push_back({n, s, rot});
        out.push_back({n, s, squash});
        out.push_back({n, s, mirror});
        out.push_back({n, s, far});
    }
    return out;
}

Vec3 randomDirection(Rng &rng) {
    double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
    double r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A random ray aimed near the object's centre from a random point outside its bounds.
Ray randomRay(Rng &rng, const Bounds3 &b) {
    Vec3 c = b.centroid();
    double radius = length(b.diagonal());
    // One draw per statement: the order of a call's arguments is unspecified (gcc and clang
    // differ), and the test must see the same rays under every compiler
    double x = rng.uniform(), y = rng.uniform(), z = rng.uniform();
    Vec3 target = c + Vec3(x - 0.5, y - 0.5, z - 0.5) * radius * 0.6;
    Vec3 o = c + randomDirection(rng) * (radius * 2);
    return Ray(o, normalize(target - o));
}

TEST(Primitives, CrossingsLieOnTheSurfaceAndSpansClassify) {
    Rng rng(2024);
    for (const Case &c : cases()) {
        SCOPED_TRACE(c.name);
        auto t = Transform::fromMatrix(c.placement);
        ASSERT_TRUE(t);
        PrimitiveInstance inst(Primitive::create(c.shape), *t, 0);
        Bounds3 b = inst.worldBounds();
        double scale = length(b.diagonal()) + length(b.centroid());
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            Ray r = randomRay(rng, b);
            Span s;
            if (!inst.lineSpan(r, &s)) continue;
            ++hits;
            ASSERT_LT(s.in.t, s.out.t);
            for (const Crossing &x : {s.in, s.out}) {
                SurfaceInteraction si = inst.surfaceAt(r, x);
                // The refined point stays next to the ray's own point
                EXPECT_LT(length(si.p - r.at(x.t)), 1e-9 * scale);
                EXPECT_NEAR(length(si.n), 1, 1e-12);
                EXPECT_TRUE(b.contains(si.p) || length(si.p - b.centroid()) < scale);
            }
            // Inside in the middle, outside just beyond both ends
            double len = s.out.t - s.in.t;
            EXPECT_TRUE(inst.inside(r.at(s.in.t + 0.5 * len)));
            double eps = 1e-6 * scale;
            if (len > 4 * eps) {
                EXPECT_FALSE(inst.inside(r.at(s.in.t - eps)));
                EXPECT_FALSE(inst.inside(r.at(s.out.t + eps)));
            }
            // Outward normals at entry face against the ray, at exit along it
            EXPECT_LT(dot(inst.surfaceAt(r, s.in).n, r.d), 1e-9);
            EXPECT_GT(dot(inst.surfaceAt(r, s.out).n, r.d), -1e-9);
        }
        EXPECT_GT(hits, 200);
    }
}

TEST(Primitives, SpawnedRaysDoNotSelfIntersect) {
    Rng rng(77);
    SpanScratch scratch;
    for (const Case &c : cases()) {
        SCOPED_TRACE(c.name);
        PrimitiveInstance inst(Primitive::create(c.shape), *Transform::fromMatrix(c.placement), 0);
        Bounds3 b = inst.worldBounds();
        double size = length(b.diagonal());
        int tested = 0;
        for (int i = 0; i < 3000; ++i) {
            Ray r = randomRay(rng, b);
            Span s;
            if (!inst.lineSpan(r, &s) || s.in.t <= 0) continue;
            for (const Crossing &x : {s.in, s.out}) {
                SurfaceInteraction si = inst.surfaceAt(r, x);
                Vec3 w = randomDirection(rng);
                double cosine = dot(w, si.n);
                if (std::abs(cosine) < 0.05) continue;  // leave grazing directions out
                ++tested;
                Ray spawned = spawnRay(si, w);
                Crossing next;
                bool hit = inst.firstCrossing(spawned, 0, kInfinity, &next, scratch);
                if (cosine > 0) {
                    // Leaving a convex solid: it can never be met again
                    EXPECT_FALSE(hit) << "outward ray re-hit at t=" << next.t;
                } else {
                    // Entering: the next crossing is the far side, not the surface just left.
                    // Near an edge of a polytope the far side may itself be close (the ray
                    // leaves through the neighbouring facet): it is where the whole line
                    // through the point leaves the solid
                    Span line;
                    double exit = inst.lineSpan(Ray(si.p, w), &line) ? line.out.t : 0;
                    if (exit > 1e-5 * size) {
                        ASSERT_TRUE(hit);
                        EXPECT_GT(next.t, 1e-7 * size);
                        EXPECT_NEAR(next.t, exit, 1e-6 * size);
                    }
                }
            }
        }
        EXPECT_GT(tested, 500);
    }
}

TEST(Primitives, RayStartingInsideSeesItsExit) {
    PrimitiveInstance inst(std::make_unique<Sphere>(2), Transform(), 0);
    SpanScratch scratch;
    Crossing c;
    ASSERT_TRUE(inst.firstCrossing(Ray(Vec3(0.5, 0, 0), Vec3(1, 0, 0)), 0, kInfinity, &c, scratch));
    EXPECT_NEAR(c.t, 1.5, 1e-15);
    EXPECT_FALSE(inst.firstCrossing(Ray(Vec3(0.5, 0, 0), Vec3(1, 0, 0)), 0, 1.0, &c, scratch));
}

TEST(Primitives, TangentRayHasNoSpan) {
    PrimitiveInstance inst(std::make_unique<Sphere>(1), Transform(), 0);
    Span s;
    EXPECT_FALSE(inst.lineSpan(Ray(Vec3(-5, 1, 0), Vec3(1, 0, 0)), &s));
    EXPECT_TRUE(inst.lineSpan(Ray(Vec3(-5, 1 - 1e-9, 0), Vec3(1, 0, 0)), &s));
}

TEST(Primitives, GrazingChordsAreAccurateAtEveryScale) {
    // A ray from a thousand radii away passing (1 - delta) radii from the centre. Its chord,
    // 2 R sqrt(delta (2 - delta)), must be exact for a line within a few roundings of the
    // given one; the textbook discriminant b^2 - 4ac is |o| / 2R = 500 times worse (~10%
    // error at delta = 1e-9 and random misses beyond).
    for (double radius : {1e-6, 1.0, 1e6}) {
        Sphere sphere(radius);
        for (double delta : {1e-3, 1e-6, 1e-9, 1e-12}) {
            SCOPED_TRACE(::testing::Message() << "radius " << radius << ", delta " << delta);
            double h = radius * (1 - delta);
            // Along x, and along a skew direction in a skew plane
            Vec3 u2 = normalize(Vec3(3, 1, 2)), v2 = normalize(cross(u2, Vec3(0, 0, 1)));
            for (auto [u, v] : {std::pair(Vec3(1, 0, 0), Vec3(0, 1, 0)), std::pair(u2, v2)}) {
                Ray r(u * (-1000 * radius) + v * h, u);
                PrimitiveSpan ps;
                ASSERT_TRUE(sphere.intersect(r, &ps));
                // The exact chord for the line as rounded, in long double
                long double o[3] = {r.o.x, r.o.y, r.o.z}, dd[3] = {r.d.x, r.d.y, r.d.z};
                long double od = o[0] * dd[0] + o[1] * dd[1] + o[2] * dd[2];
                long double d2 = dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2];
                long double dist2 = 0;
                for (int i = 0; i < 3; ++i) {
                    long double c = o[i] - dd[i] * od / d2;
                    dist2 += c * c;
                }
                long double rr = radius;
                double chord = static_cast<double>(2 * std::sqrt(rr * rr - dist2));
                // Backward error bound: the chord of a line moved by a few roundings of the
                // origin's coordinates (|o| eps), through d chord / d dist = 4 R / chord
                double moved = 8 * length(r.o) * kMachineEpsilon;
                double tolerance = moved * 4 * radius / chord + 1e-12 * chord;
                EXPECT_NEAR((ps.t1 - ps.t0) * length(r.d), chord, tolerance);
            }
            // The same line moved out by 2 delta misses
            PrimitiveSpan ps;
            EXPECT_FALSE(sphere.intersect(
                Ray(Vec3(-1000 * radius, radius * (1 + delta), 0), Vec3(1, 0, 0)), &ps));
        }
    }
}

TEST(Primitives, BoxFacesAndAxisParallelRays) {
    Box box(Vec3(0, 0, 0), Vec3(1, 2, 3));
    PrimitiveSpan ps;
    ASSERT_TRUE(box.intersect(Ray(Vec3(0.5, -1, 1), Vec3(0, 1, 0)), &ps));
    EXPECT_EQ(ps.t0, 1);
    EXPECT_EQ(ps.t1, 3);
    EXPECT_EQ(ps.face0, 2);  // -y face
    EXPECT_EQ(ps.face1, 3);  // +y face
    EXPECT_FALSE(box.intersect(Ray(Vec3(1.5, -1, 1), Vec3(0, 1, 0)), &ps));
    ObjectSurface os = box.surface(Vec3(0.5, 2.0000001, 1), 3);
    EXPECT_EQ(os.p.y, 2);
    EXPECT_EQ(os.normal, Vec3(0, 1, 0));
}

TEST(Primitives, ConeCapsAndSide) {
    Cone cone(0, 2, 1, 0);  // apex at z = 2
    PrimitiveSpan ps;
    // Straight down the axis: top is the apex (side), bottom is the cap
    ASSERT_TRUE(cone.intersect(Ray(Vec3(0, 0, 5), Vec3(0, 0, -1)), &ps));
    EXPECT_NEAR(ps.t0, 3, 1e-12);
    EXPECT_EQ(ps.t1, 5);
    EXPECT_EQ(ps.face1, 1);
    // Horizontal at z = 1: radius 0.5
    ASSERT_TRUE(cone.intersect(Ray(Vec3(-3, 0, 1), Vec3(1, 0, 0)), &ps));
    EXPECT_NEAR(ps.t0, 2.5, 1e-12);
    EXPECT_NEAR(ps.t1, 3.5, 1e-12);
    EXPECT_EQ(ps.face0, 0);
    // Above the apex: the other nappe does not count
    EXPECT_FALSE(cone.intersect(Ray(Vec3(-3, 0, 3), Vec3(1, 0, 0)), &ps));
    EXPECT_TRUE(cone.inside(Vec3(0.2, 0.2, 1)));
    EXPECT_FALSE(cone.inside(Vec3(0.2, 0.2, 1.9)));
}

}  // namespace
}  // namespace rt
