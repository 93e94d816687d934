// SPDX-License-Identifier: MIT
// Property and stiff-case tests of the torus and the lathe: span lists sorted and disjoint,
// ends on the surface, spans agree with the inside test, outward unit normals; thin, horn,
// huge and tiny tori, grazing and far rays; lathes with holes, on the axis, partial turns.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/geometry/revolved.h"
#include "core/geometry/shape.h"
#include "core/math/rng.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

ir::ProfileOutline rect(double r0, double r1, double z0, double z1) {
    return {{r0, z0}, {r1, z0}, {r1, z1}, {r0, z1}};
}

ir::TorusPrim torus(double major, double minor, double angle = 360) {
    ir::TorusPrim t;
    t.major = major;
    t.minor = minor;
    t.angle = angle;
    return t;
}

ir::LathePrim lathe(std::vector<ir::ProfileOutline> outlines, double angle = 360) {
    ir::LathePrim l;
    l.outlines = std::move(outlines);
    l.angle = angle;
    return l;
}

struct Case {
    std::string name;
    ir::PrimShape shape;
    Mat4 placement;
};

std::vector<Case> cases() {
    Mat4 rot = Mat4::translate(Vec3(0.3, -2, 1)) * Mat4::rotateAxis(37, Vec3(1, 2, 3));
    Mat4 squash = Mat4::rotateZ(20) * Mat4::scale(Vec3(3, 0.5, 1.5));
    Mat4 far = Mat4::translate(Vec3(1e4, -1e4, 5e3));
    // A vase: not convex in r, with a slanted inside wall, clockwise
    ir::ProfileOutline vase = {{0, 0}, {0.5, 2}, {1, 2}, {0.8, 1}, {1.2, 0.2}, {1, 0}};
    std::vector<std::pair<std::string, ir::PrimShape>> shapes = {
        {"torus", torus(1, 0.3)},
        {"thin_torus", torus(1, 1e-3)},
        {"horn_torus", torus(1, 1)},
        {"torus_90", torus(1, 0.4, 90)},
        {"torus_180", torus(1, 0.4, 180)},
        {"torus_270", torus(1, 0.4, 270)},
        {"torus_359", torus(1, 0.4, 359)},
        {"lathe_square", lathe({rect(1, 2, 0, 1)})},
        {"lathe_hole", lathe({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)})},
        {"lathe_axis", lathe({{{0, 0}, {1, 0.5}, {0, 1}}})},
        {"lathe_vase", lathe({vase})},
        {"lathe_90", lathe({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)}, 90)},
        {"lathe_180", lathe({vase}, 180)},
        {"lathe_270", lathe({rect(0, 2, 0, 1)}, 270)},
        {"lathe_359", lathe({rect(1, 2, 0, 1)}, 359)},
    };
    std::vector<Case> out;
    for (auto &[n, s] : shapes) {
        out.push_back({n, s, Mat4()});
        out.push_back({n + "_rot", s, rot});
        out.push_back({n + "_squash", s, squash});
        out.push_back({n + "_far", s, far});
    }
    return out;
}

Vec3 randomDirection(Rng &rng) {
    double z = 2 * rng.uniform() - 1, phi = 2 * M_PI * rng.uniform();
    double r = std::sqrt(std::max(0.0, 1 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

Ray randomRay(Rng &rng, const Bounds3 &b) {
    Vec3 c = b.centroid();
    double radius = length(b.diagonal());
    Vec3 target =
        c + Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * radius * 0.6;
    Vec3 o = c + randomDirection(rng) * (radius * 2);
    return Ray(o, normalize(target - o));
}

TEST(Revolved, SpansAreSortedOnTheSurfaceAndAgreeWithInside) {
    Rng rng(77);
    for (const Case &c : cases()) {
        SCOPED_TRACE(c.name);
        auto t = Transform::fromMatrix(c.placement);
        ASSERT_TRUE(t);
        PrimitiveInstance inst(Primitive::create(c.shape), *t, 0);
        Bounds3 b = inst.worldBounds();
        double scale = length(b.diagonal()) + length(b.centroid());
        int hits = 0, multi = 0, mismatches = 0, samples = 0;
        for (int i = 0; i < 1500; ++i) {
            Ray r = randomRay(rng, b);
            SpanList spans;
            inst.lineSpans(r, spans);
            if (spans.empty()) continue;
            ++hits;
            if (spans.size() > 1) ++multi;
            for (size_t k = 0; k < spans.size(); ++k) {
                const Span &s = spans[k];
                ASSERT_TRUE(std::isfinite(s.in.t) && std::isfinite(s.out.t));
                ASSERT_LT(s.in.t, s.out.t);
                if (k) {
                    ASSERT_LT(spans[k - 1].out.t, s.in.t);
                }
                // Both ends lie on the face they name, and its normal is unit and outward
                for (const Crossing *x : {&s.in, &s.out}) {
                    SurfaceInteraction si = inst.surfaceAt(r, *x);
                    EXPECT_LT(length(si.p - r.at(x->t)), 1e-8 * scale) << "t " << x->t;
                    EXPECT_NEAR(length(si.n), 1, 1e-12);
                    double along = dot(si.n, r.d);
                    if (std::abs(along) > 1e-3) {
                        if (x == &s.in) {
                            EXPECT_LT(along, 0) << "entry normal points in";
                        } else {
                            EXPECT_GT(along, 0) << "exit normal points in";
                        }
                    }
                }
            }
            // Points along the ray are inside exactly when they are in a span
            double t0 = spans.front().in.t, t1 = spans.back().out.t;
            double len = t1 - t0;
            for (int j = 0; j < 20; ++j) {
                double tt = t0 - 0.1 * len + 1.2 * len * rng.uniform();
                bool inSpan = false, nearEnd = false;
                for (const Span &s : spans) {
                    inSpan = inSpan || (tt > s.in.t && tt < s.out.t);
                    nearEnd = nearEnd || std::abs(tt - s.in.t) < 1e-7 * scale ||
                              std::abs(tt - s.out.t) < 1e-7 * scale;
                }
                if (nearEnd) continue;
                ++samples;
                if (inst.inside(r.at(tt)) != inSpan) ++mismatches;
            }
        }
        // Random rays seldom meet the thin torus (ThinTorusFoundFromEveryDirection aims at it)
        bool thin = c.name.find("thin") != std::string::npos;
        EXPECT_GT(hits, thin ? 0 : 100);
        EXPECT_EQ(mismatches, 0) << "of " << samples;
        if (c.placement.isIdentity() && !thin && c.name.find("square") == std::string::npos &&
            c.name.find("axis") == std::string::npos) {
            EXPECT_GT(multi, 0) << "no ray crossed the solid twice";
        }
    }
}

TEST(Revolved, SpawnedRaysDoNotSelfIntersect) {
    // A ray spawned off a crossing, either way, must not find the surface it leaves again
    // (a solid that is not convex may be met again further on)
    Rng rng(78);
    SpanScratch scratch;
    for (const Case &c : cases()) {
        SCOPED_TRACE(c.name);
        PrimitiveInstance inst(Primitive::create(c.shape), *Transform::fromMatrix(c.placement), 0);
        Bounds3 b = inst.worldBounds();
        double size = length(b.diagonal());
        int tested = 0;
        for (int i = 0; i < 2000; ++i) {
            Ray r = randomRay(rng, b);
            SpanList spans;
            inst.lineSpans(r, spans);
            for (const Span &s : spans)
                for (const Crossing &x : {s.in, s.out}) {
                    SurfaceInteraction si = inst.surfaceAt(r, x);
                    Vec3 w = randomDirection(rng);
                    double cosine = dot(w, si.n);
                    if (std::abs(cosine) < 0.05) continue;  // leave grazing directions out
                    ++tested;
                    Crossing next;
                    if (inst.firstCrossing(spawnRay(si, w), 0, kInfinity, &next, scratch)) {
                        EXPECT_GT(next.t, 1e-7 * size) << "re-hit the surface it left";
                    }
                    // Entering, the ray is inside just past its origin
                    if (cosine < 0) {
                        ASSERT_TRUE(
                            inst.firstCrossing(spawnRay(si, w), 0, kInfinity, &next, scratch));
                    }
                }
        }
        EXPECT_GT(tested, c.name.find("thin") != std::string::npos ? 0 : 300);
    }
}

TEST(Revolved, FirstCrossingMatchesSpans) {
    Rng rng(5);
    PrimitiveInstance inst(Primitive::create(lathe({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)})),
                           Transform(), 0);
    SpanScratch scratch;
    for (int i = 0; i < 500; ++i) {
        Ray r = randomRay(rng, inst.worldBounds());
        SpanList spans;
        inst.lineSpans(r, spans);
        double tMin = 0;
        while (true) {
            Crossing c;
            bool hit = inst.firstCrossing(r, tMin, kInfinity, &c, scratch);
            const Crossing *expect = nullptr;
            for (const Span &s : spans) {
                if (s.in.t > tMin) {
                    expect = &s.in;
                } else if (s.out.t > tMin) {
                    expect = &s.out;
                }
                if (expect) break;
            }
            ASSERT_EQ(hit, expect != nullptr);
            if (!hit) break;
            EXPECT_EQ(c.t, expect->t);
            tMin = c.t;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Torus: stiff cases

std::vector<PrimitiveSpan> spansOf(const Primitive &p, const Ray &r) {
    std::vector<PrimitiveSpan> s;
    p.intersectAll(r, s);
    return s;
}

TEST(Revolved, TorusAlongTheAxisAtEveryScale) {
    for (double scale : {1e-6, 1.0, 1e6})
        for (double ratio : {0.25, 1e-3, 1.0}) {
            SCOPED_TRACE("scale " + std::to_string(scale) + " ratio " + std::to_string(ratio));
            double R = scale, a = ratio * scale;
            Torus t(torus(R, a));
            // Along the x axis from far away: [-R-a, -R+a] and [R-a, R+a] (one span through
            // the horn torus' centre)
            Ray r(Vec3(-1e3 * scale, 0, 0), Vec3(1, 0, 0));
            auto s = spansOf(t, r);
            double o = 1e3 * scale, tol = 1e-12 * o;
            if (ratio == 1.0) {
                ASSERT_EQ(s.size(), 1u);
                EXPECT_NEAR(s[0].t0, o - 2 * R, tol);
                EXPECT_NEAR(s[0].t1, o + 2 * R, tol);
            } else {
                ASSERT_EQ(s.size(), 2u);
                EXPECT_NEAR(s[0].t0, o - R - a, tol);
                EXPECT_NEAR(s[0].t1, o - R + a, tol);
                EXPECT_NEAR(s[1].t0, o + R - a, tol);
                EXPECT_NEAR(s[1].t1, o + R + a, tol);
            }
        }
}

TEST(Revolved, ThinTorusFoundFromEveryDirection) {
    // minor / major = 1e-3: rays aimed at random points of the tube's centre circle always
    // cross the tube, both ends on it
    Rng rng(11);
    double R = 1, a = 1e-3;
    Torus t(torus(R, a));
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        double phi = 2 * M_PI * rng.uniform();
        Vec3 target(R * std::cos(phi), R * std::sin(phi), 0);
        Vec3 d = randomDirection(rng);
        Ray r(target - d * (5 + 100 * rng.uniform()), d);
        auto s = spansOf(t, r);
        ASSERT_FALSE(s.empty()) << i;
        for (const auto &span : s)
            for (double tt : {span.t0, span.t1}) {
                Vec3 p = r.at(tt);
                double dist = std::hypot(std::hypot(p.x, p.y) - R, p.z) - a;
                worst = std::max(worst, std::abs(dist));
            }
    }
    std::printf("thin torus: worst distance of a span end from the tube %.3g (minor 1e-3)\n",
                worst);
    EXPECT_LT(worst, 1e-12);
}

TEST(Revolved, TorusGrazingRaysKeepTheirChord) {
    // A line x = c < R + a in the plane z = 0 cuts a chord of half-length
    // sqrt((R + a - c)(R + a + c)) off the outer side of the tube. With R + a exact in binary
    // and c near it the reference is exact. A point of the line is rounded to an ulp of its
    // coordinates across the surface, which the grazing angle (sine half / c) stretches along
    // the ray: the tolerance is a few ulps over that sine
    double worst = 0;
    for (double ratio : {0.25, 1.0 / 1024})
        for (double delta : {1e-2, 1e-5, 1e-8}) {
            double R = 1, a = ratio;
            Torus t(torus(R, a));
            double c = R + a * (1 - delta);
            Ray r(Vec3(c, -10, 0), Vec3(0, 1, 0));
            auto s = spansOf(t, r);
            double half = std::sqrt((R + a - c) * (R + a + c));
            SCOPED_TRACE("ratio " + std::to_string(ratio) + " delta " + std::to_string(delta));
            double tol = 4 * kMachineEpsilon * c / half * c;
            ASSERT_EQ(s.size(), 1u);
            EXPECT_NEAR(s[0].t0, 10 - half, tol);
            EXPECT_NEAR(s[0].t1, 10 + half, tol);
            worst = std::max(worst, std::abs(s[0].t0 - (10 - half)) / tol);
        }
    std::printf("grazing torus chords: worst error %.2f of the tolerance\n", worst);
    // Just outside: no span; tangent to the top of the tube from above: none either
    Torus t(torus(1, 0.25));
    EXPECT_TRUE(spansOf(t, Ray(Vec3(1.25 + 1e-12, -10, 0), Vec3(0, 1, 0))).empty());
    EXPECT_TRUE(spansOf(t, Ray(Vec3(-10, 0, 0.25 + 1e-12), Vec3(1, 0, 0))).empty());
}

TEST(Revolved, TorusIsInvariantUnderScaling) {
    // The same rays against the same torus at 1e-6, 1 and 1e6: the spans scale exactly
    // (up to rounding), also from origins a million sizes away
    Rng rng(3);
    double worst = 0, worstFar = 0;
    for (double ratio : {0.3, 1e-3, 1.0}) {
        Torus unit(torus(1, ratio));
        for (int i = 0; i < 3000; ++i) {
            Ray r = randomRay(rng, unit.objectBounds());
            auto ref = spansOf(unit, r);
            for (double scale : {1e-6, 1e6}) {
                Torus scaled(torus(scale, ratio * scale));
                auto s = spansOf(scaled, Ray(r.o * scale, r.d));
                ASSERT_EQ(s.size(), ref.size()) << "ray " << i << " scale " << scale;
                for (size_t k = 0; k < s.size(); ++k) {
                    worst = std::max(worst, std::abs(s[k].t0 / scale - ref[k].t0));
                    worst = std::max(worst, std::abs(s[k].t1 / scale - ref[k].t1));
                }
            }
            // The same line from a million sizes back
            double back = 1e6;
            auto f = spansOf(unit, Ray(r.o - r.d * back, r.d));
            if (f.size() != ref.size()) continue;  // a grazing pair may go either way
            for (size_t k = 0; k < f.size(); ++k) {
                worstFar = std::max(worstFar, std::abs(f[k].t0 - back - ref[k].t0));
                worstFar = std::max(worstFar, std::abs(f[k].t1 - back - ref[k].t1));
            }
        }
    }
    std::printf(
        "torus at 1e-6 and 1e6: worst relative difference of span ends %.3g; "
        "from 1e6 away: %.3g of the major radius\n",
        worst, worstFar);
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(worstFar, 1e-8);
}

TEST(Revolved, HornTorusThroughItsCentre) {
    Torus t(torus(1, 1));
    // Along z through the centre: the only point is the origin, no span
    EXPECT_TRUE(spansOf(t, Ray(Vec3(0, 0, -5), Vec3(0, 0, 1))).empty());
    // Slanted through the centre: one span through the pinch point
    auto s = spansOf(t, Ray(Vec3(-5, 0, -1), normalize(Vec3(5, 0, 1))));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_TRUE(t.inside(Vec3(0, 0, 0)));
    for (int i = 0; i < 100; ++i) {
        auto r = Ray(Vec3(-5, 0.01 * i, 0), Vec3(1, 0, 0));
        for (const auto &span : spansOf(t, r)) EXPECT_LT(span.t0, span.t1);
    }
}

TEST(Revolved, NoNanForDegenerateRays) {
    Torus t(torus(1, 0.25));
    Lathe l(lathe({rect(0, 1, 0, 1)}));
    for (const Primitive *p :
         {static_cast<const Primitive *>(&t), static_cast<const Primitive *>(&l)}) {
        EXPECT_TRUE(spansOf(*p, Ray(Vec3(0, 0, 0), Vec3(0, 0, 0))).empty());
        for (const Ray &r :
             {Ray(Vec3(0, 0, -5), Vec3(0, 0, 1)), Ray(Vec3(1, 0, -5), Vec3(0, 0, 1)),
              Ray(Vec3(-5, 0, 0), Vec3(1, 0, 0)), Ray(Vec3(-5, 0, 0.25), Vec3(1, 0, 0))})
            for (const auto &s : spansOf(*p, r)) {
                EXPECT_TRUE(std::isfinite(s.t0) && std::isfinite(s.t1));
                EXPECT_LT(s.t0, s.t1);
            }
    }
}

// ---------------------------------------------------------------------------------------------
// Lathe

TEST(Revolved, LatheWithHoleGivesFourSpans) {
    Lathe l(lathe({rect(1, 3, 0, 2), rect(1.5, 2.5, 0.5, 1.5)}));
    auto s = spansOf(l, Ray(Vec3(-10, 0, 1), Vec3(1, 0, 0)));
    ASSERT_EQ(s.size(), 4u);
    double expect[4][2] = {{7, 7.5}, {8.5, 9}, {11, 11.5}, {12.5, 13}};
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(s[k].t0, expect[k][0], 1e-12);
        EXPECT_NEAR(s[k].t1, expect[k][1], 1e-12);
    }
    // Outside the hole's height: two spans
    EXPECT_EQ(spansOf(l, Ray(Vec3(-10, 0, 0.25), Vec3(1, 0, 0))).size(), 2u);
}

TEST(Revolved, LatheMatchesTheConeItRevolves) {
    // Profiles touching the axis that revolve to a cylinder, a cone and a frustum agree with
    // the analytic Cone, crossing for crossing
    struct Pair {
        ir::ProfileOutline profile;
        ir::CylinderPrim cone;
    };
    std::vector<Pair> pairs = {
        {rect(0, 0.8, -1, 1), {-1, 1, 0.8, 0.8}},
        {{{0, 0}, {1, 0}, {0, 2}}, {0, 2, 1, 0}},
        {{{0, 0}, {1.5, 0}, {0.4, 1.5}, {0, 1.5}}, {0, 1.5, 1.5, 0.4}},
    };
    Rng rng(9);
    for (const Pair &p : pairs) {
        Lathe l(lathe({p.profile}));
        auto cone = Primitive::create(p.cone);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            Ray r = randomRay(rng, l.objectBounds());
            auto s = spansOf(l, r);
            PrimitiveSpan c;
            bool hit = cone->intersect(r, &c);
            // Grazing a rim may go either way in both
            if (hit != !s.empty()) {
                EXPECT_LT(hit ? c.t1 - c.t0 : s[0].t1 - s[0].t0, 1e-6);
                continue;
            }
            if (!hit) continue;
            ++hits;
            ASSERT_EQ(s.size(), 1u);
            EXPECT_NEAR(s[0].t0, c.t0, 1e-9);
            EXPECT_NEAR(s[0].t1, c.t1, 1e-9);
        }
        EXPECT_GT(hits, 500);
    }
}

TEST(Revolved, LatheInsideIsTheEvenOddRuleAtEveryHeight) {
    // A star with 40 points and a hole (its height table has many slabs, several edges each)
    // against a plain even-odd count over every edge, including heights of vertices
    Rng rng(21);
    ir::ProfileOutline star, hole = rect(2.8, 3.2, -0.2, 0.2);
    for (int i = 0; i < 40; ++i) {
        double phi = 2 * M_PI * i / 40, rad = i % 2 ? 1 : 2.5;
        star.push_back({3 + rad * std::cos(phi), rad * std::sin(phi)});
    }
    std::vector<ir::ProfileOutline> outlines = {star, hole};
    Lathe l(lathe(outlines));
    auto evenOdd = [&](double r, double z) {
        bool in = false;
        for (const auto &o : outlines)
            for (size_t i = 0; i < o.size(); ++i) {
                const ir::ProfilePoint &a = o[i], &b = o[(i + 1) % o.size()];
                if ((a.z > z) == (b.z > z)) continue;
                if (r < a.r + (z - a.z) * (b.r - a.r) / (b.z - a.z)) in = !in;
            }
        return in;
    };
    int in = 0;
    for (int i = 0; i < 20000; ++i) {
        double r = 6 * rng.uniform(), z = i % 10 ? 6 * rng.uniform() - 3 : star[i / 10 % 40].z;
        double phi = 2 * M_PI * rng.uniform();
        bool want = evenOdd(r, z);
        in += want;
        ASSERT_EQ(l.inside(Vec3(r * std::cos(phi), r * std::sin(phi), z)), want) << r << " " << z;
    }
    EXPECT_GT(in, 2000);
}

TEST(Revolved, PartialTurnsCutAtTheirEndPlanes) {
    Lathe l90(lathe({rect(1, 2, 0, 1)}, 90));
    // y = 0.5 inside the quarter: entry through r = 1, exit through r = 2
    auto s = spansOf(l90, Ray(Vec3(-5, 0.5, 0.5), Vec3(1, 0, 0)));
    ASSERT_EQ(s.size(), 1u);
    EXPECT_NEAR(s[0].t0, 5 + std::sqrt(0.75), 1e-12);
    EXPECT_NEAR(s[0].t1, 5 + std::sqrt(3.75), 1e-12);
    // Along -y at x = 1.5: in through the end plane y = 0... no: start plane y = 0 at azimuth 0
    auto e = spansOf(l90, Ray(Vec3(1.5, 5, 0.5), Vec3(0, -1, 0)));
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0].t1, 5, 1e-12);
    EXPECT_EQ(e[0].face1, RevolvedSolid::kStartFace);
    ObjectSurface os = l90.surface(Vec3(1.5, 0, 0.5), RevolvedSolid::kStartFace);
    EXPECT_EQ(os.normal.y, -1);
    // 270: at y = -0.5 only x <= 0 is in
    Lathe l270(lathe({rect(1, 2, 0, 1)}, 270));
    auto w = spansOf(l270, Ray(Vec3(-5, -0.5, 0.5), Vec3(1, 0, 0)));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NEAR(w[0].t0, 5 - std::sqrt(3.75), 1e-12);
    EXPECT_NEAR(w[0].t1, 5 - std::sqrt(0.75), 1e-12);
    // 180 through the axis along y: in at y = 2 ... r = 1, out of the plane? no: the half
    // turn keeps y >= 0, so [y = 2 .. 1] only
    Lathe l180(lathe({rect(1, 2, 0, 1)}, 180));
    auto h = spansOf(l180, Ray(Vec3(0, 5, 0.5), Vec3(0, -1, 0)));
    ASSERT_EQ(h.size(), 1u);
    EXPECT_NEAR(h[0].t0, 3, 1e-12);
    EXPECT_NEAR(h[0].t1, 4, 1e-12);
    // A torus wedge: a ray along x at y = -0.1 misses a quarter torus and hits a 359 one
    EXPECT_TRUE(spansOf(Torus(torus(1, 0.25, 90)), Ray(Vec3(-5, -0.1, 0), Vec3(1, 0, 0))).empty());
    EXPECT_EQ(spansOf(Torus(torus(1, 0.25, 359)), Ray(Vec3(-5, -0.1, 0), Vec3(1, 0, 0))).size(),
              2u);
}

TEST(Revolved, TorusCutFromABoxShowsItsFarSide) {
    // difference() { box; torus }, seen from above with flat colours: over the hole the box
    // top (red); over the tube the line runs box top, torus (removed), torus far side, so the
    // cut face is the torus' (green) 0.5 below the centre plane. Every line through the tube
    // has two torus spans: CSG must take all of them
    using namespace rt::test;
    ir::Scene s = emptyScene();
    int red = s.addMaterial(plainMaterial(Rgb(1, 0, 0), 1, 0));
    int green = s.addMaterial(plainMaterial(Rgb(0, 1, 0), 1, 0));
    s.root->children.push_back(csg(ir::NodeKind::Difference,
                                   box(Vec3(-3, -3, -1), Vec3(3, 3, 0.25), red),
                                   ir::Node::makePrimitive(torus(1.5, 0.5), green, {})));
    s.camera = lookAt(Vec3(0, 0, 10), Vec3(0, 0, 0), 40, Vec3(0, 1, 0));
    DiagnosticSink diag;
    auto rs = RenderScene::compile(s, diag);
    RenderOptions o;
    o.width = o.height = 33;
    o.threads = 2;
    Image img = renderImage(*rs, o).image;
    EXPECT_EQ(img.at(16, 16).r, 1);
    // 7 pixels off centre the ray meets z = -0.5 about 1.58 from the axis: in the tube
    for (auto [x, y] : {std::pair{9, 16}, std::pair{23, 16}, std::pair{16, 9}, std::pair{16, 23}}) {
        EXPECT_EQ(img.at(x, y).g, 1) << x << " " << y;
        EXPECT_EQ(img.at(x, y).r, 0) << x << " " << y;
    }
}

TEST(Revolved, WedgeBoundsAreTight) {
    Bounds3 b = Torus(torus(1, 0.25, 90)).objectBounds();
    EXPECT_NEAR(b.min.x, 0, 1e-15);
    EXPECT_NEAR(b.min.y, 0, 1e-15);
    EXPECT_EQ(b.max.x, 1.25);
    EXPECT_EQ(b.max.y, 1.25);
    EXPECT_EQ(b.min.z, -0.25);
    Bounds3 f = Lathe(lathe({rect(1, 2, 0, 1)})).objectBounds();
    EXPECT_EQ(f.min, Vec3(-2, -2, 0));
    EXPECT_EQ(f.max, Vec3(2, 2, 1));
}

}  // namespace
}  // namespace rt
