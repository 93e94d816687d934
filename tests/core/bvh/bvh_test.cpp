// SPDX-License-Identifier: MIT
// The BVH finds exactly the closest hit that a brute-force loop over all objects finds.
#include <gtest/gtest.h>

#include <memory>
#include <utility>
#include <vector>

#include "core/bvh/bvh.h"
#include "core/geometry/shape.h"
#include "core/math/rng.h"

namespace rt {
namespace {

TEST(Bvh, MatchesBruteForceOnRandomScenes) {
    Rng rng(11);
    SpanScratch scratch;
    for (int n : {1, 2, 3, 7, 50, 500}) {
        SCOPED_TRACE(n);
        std::vector<std::unique_ptr<PrimitiveInstance>> objects;
        std::vector<Bounds3> bounds;
        for (int i = 0; i < n; ++i) {
            Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
            double r = 0.1 + rng.uniform();
            objects.push_back(std::make_unique<PrimitiveInstance>(
                std::make_unique<Sphere>(r), *Transform::fromMatrix(Mat4::translate(c)), i));
            bounds.push_back(objects.back()->worldBounds());
        }
        Bvh bvh(bounds);
        ASSERT_EQ(bvh.itemOrder().size(), static_cast<size_t>(n));
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 30 - 15);
            Vec3 d = normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
            Ray r(o, d);
            double bruteT = kInfinity;
            int bruteIdx = -1;
            for (int k = 0; k < n; ++k) {
                Crossing c;
                if (objects[k]->firstCrossing(r, 0, bruteT, &c, scratch)) {
                    bruteT = c.t;
                    bruteIdx = k;
                }
            }
            double tMax = kInfinity;
            int bvhIdx = -1;
            bvh.traverse(r, 0, &tMax, [&](uint32_t k, double *far) {
                Crossing c;
                if (objects[k]->firstCrossing(r, 0, *far, &c, scratch)) {
                    *far = c.t;
                    bvhIdx = static_cast<int>(k);
                }
                return false;
            });
            ASSERT_EQ(bvhIdx, bruteIdx);
            if (bruteIdx >= 0) {
                EXPECT_EQ(tMax, bruteT);
                ++hits;
            }
        }
        if (n >= 50) {
            EXPECT_GT(hits, 40);
        }
    }
}

// The node test may visit more than it must, never less: every box that the exact ray meets within
// [tMin, tMax] is visited. The boxes are built around points of the ray (o + t d rounded, each
// axis widened by 0 to 2 relative steps, so some are flat or points in one axis) at t before and
// behind the origin, among random others; directions include zero and negative-zero components,
// and the scales run from 1e-6 to 1e6.
TEST(Bvh, VisitsEveryBoxTheRayMeets) {
    Rng rng(29);
    for (double scale : {1e-6, 1.0, 1e6}) {
        SCOPED_TRACE(scale);
        for (int i = 0; i < 600; ++i) {
            Vec3 o =
                Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * (20 * scale);
            Vec3 d = normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
            // One ray in three runs parallel to one or two axes, some with a -0.0 component
            if (i % 3 == 1) d[i % 2] = (i & 4) ? -0.0 : 0.0;
            if (i % 9 == 1) d[2] = (i & 8) ? -0.0 : 0.0;
            if (d == Vec3(0)) d.z = 1;
            d = normalize(d);
            bool behind = i % 2 == 0;
            double tMin = behind ? -kInfinity : 0;
            std::vector<Bounds3> boxes;
            std::vector<bool> mustVisit;
            for (int k = 0; k < 24; ++k) {
                double t = (rng.uniform() * 20 - (behind ? 10 : 0)) * scale;
                Vec3 p = o + d * t;
                Vec3 lo = p, hi = p;
                int flatAxis = static_cast<int>(rng.uniform() * 3);
                for (int a = 0; a < 3; ++a) {
                    if (a == flatAxis && k % 2 == 0) continue;  // flat in this axis
                    double w = (1e-9 + rng.uniform() * 0.5) * scale;
                    lo[a] -= w;
                    hi[a] += w;
                }
                boxes.push_back(Bounds3(lo, hi));
                mustVisit.push_back(true);
            }
            for (int k = 0; k < 24; ++k) {
                Vec3 c = Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) *
                         (30 * scale);
                Vec3 size = Vec3(rng.uniform(), rng.uniform(), rng.uniform()) * scale;
                boxes.push_back(Bounds3(c, c + size));
                mustVisit.push_back(false);
            }
            Bvh bvh(boxes);
            std::vector<bool> visited(boxes.size(), false);
            double tMax = kInfinity;
            bvh.traverse(Ray(o, d), tMin, &tMax, [&](uint32_t k, double *) {
                visited[k] = true;
                return false;
            });
            for (size_t k = 0; k < boxes.size(); ++k)
                if (mustVisit[k]) {
                    ASSERT_TRUE(visited[k]) << "ray " << i << " box " << k;
                }
        }
    }
}

#if SCADRAY_LANE_SLABS
// The node test in AVX lanes decides every node as the one-plane-at-a-time test does: on boxes
// around points of the ray and random ones, flat and infinite boxes, origins exactly on a box's
// planes with zero and negative-zero direction components (where a slab distance is 0 * inf,
// NaN), subnormal components (whose reciprocals are infinite), and tMin and tMax from -inf to
// inf, at scales 1e-6 to 1e6. The node's offset and count, which the lanes load with the box,
// are set to words that read as NaN, infinity and subnormals.
TEST(Bvh, LaneSlabsDecideEveryNodeAsRaySlabs) {
    if (!__builtin_cpu_supports("avx2"))
        GTEST_SKIP() << "this machine has no AVX2: the lanes are not used";
    Rng rng(41);
    const uint32_t words[][2] = {{0, 0},          {1, 0},          {0, 0x7ff00000},
                                 {1, 0x7ff80000}, {0, 0x80000001}, {7, 3}};
    auto pick = [&](std::initializer_list<double> values) {
        return *(values.begin() + static_cast<size_t>(rng.uniform() * values.size()));
    };
    long long tested = 0, hits = 0, laterTested = 0;
    for (double scale : {1e-6, 1.0, 1e6}) {
        for (int i = 0; i < 4000; ++i) {
            Vec3 o =
                Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * (20 * scale);
            Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
            for (int a = 0; a < 3; ++a) {
                double u = rng.uniform();
                if (u < 0.15)
                    d[a] = 0.0;
                else if (u < 0.3)
                    d[a] = -0.0;
                else if (u < 0.35)
                    d[a] = (u < 0.325 ? 1 : -1) * 1e-310;
            }
            Ray ray(o, d);
            Bvh::RaySlabs one(ray);
            Bvh::LaneSlabs lanes(ray);
            Bvh::Node previous;
            previous.bounds = Bounds3(o - Vec3(scale), o + Vec3(scale));
            for (int k = 0; k < 16; ++k) {
                Bvh::Node node;
                Vec3 lo, hi;
                for (int a = 0; a < 3; ++a) {
                    double u = rng.uniform();
                    if (u < 0.3) {
                        // a plane through the origin, the box on either side or flat
                        lo[a] = hi[a] = o[a];
                        if (rng.uniform() < 0.5) lo[a] -= rng.uniform() * scale;
                        if (rng.uniform() < 0.5) hi[a] += rng.uniform() * scale;
                    } else if (u < 0.4) {
                        lo[a] = -kInfinity;
                        hi[a] = pick({-kInfinity, o[a], kInfinity});
                    } else {
                        double c = (rng.uniform() - 0.5) * 30 * scale,
                               w = rng.uniform() * 10 * scale;
                        lo[a] = c;
                        hi[a] = c + w;
                    }
                }
                node.bounds = Bounds3();
                node.bounds.min = lo;
                node.bounds.max = hi;
                const uint32_t *w = words[k % 6];
                node.offset = w[0];
                node.count = w[1];
                double tMin = pick({-kInfinity, 0.0, -0.0, rng.uniform() * scale});
                double tMax = pick({kInfinity, rng.uniform() * 40 * scale, 0.0, -kInfinity});
                bool expected = one.hit(node, tMin, tMax);
                ASSERT_EQ(lanes.hit(node, tMin, tMax), expected)
                    << "box " << lo.toString() << " " << hi.toString() << " ray " << o.toString()
                    << " " << d.toString() << " tMin " << tMin << " tMax " << tMax;
                ++tested;
                hits += expected;
                // Two nodes side by side: the same answers, and a passing node's t0 gives the
                // answer of its test with any smaller tMax (the paired walks' later entry)
                double t0[2];
                int pair = lanes.hitPair(previous, node, tMin, tMax, t0);
                ASSERT_EQ(pair, int(one.hit(previous, tMin, tMax)) | int(expected) << 1)
                    << "box " << lo.toString() << " " << hi.toString() << " tMin " << tMin
                    << " tMax " << tMax;
                const Bvh::Node *pairNodes[2] = {&previous, &node};
                for (int p = 0; p < 2; ++p) {
                    if (!(pair >> p & 1)) continue;
                    for (double later : {tMax, t0[p], std::nextafter(t0[p], -kInfinity),
                                         std::nextafter(t0[p], kInfinity), tMin,
                                         t0[p] + (tMax - t0[p]) * rng.uniform()}) {
                        if (!(later <= tMax)) continue;
                        ASSERT_EQ(t0[p] <= later, one.hit(*pairNodes[p], tMin, later))
                            << "tMin " << tMin << " tMax " << tMax << " later " << later;
                        ++laterTested;
                    }
                }
                previous = node;
            }
            for (int a = 0; a < 3; ++a) ASSERT_EQ(lanes.neg[a], one.neg[a]);
        }
    }
    // Both answers occur often
    EXPECT_GT(hits, tested / 10);
    EXPECT_LT(hits, tested - tested / 10);
    EXPECT_GT(laterTested, tested);
}

// And a whole walk with the lanes makes the same visits, in the same order, with the same tMax;
// so does the walk that tests two children at once (for visitors that only lower tMax).
TEST(Bvh, LaneSlabsWalkVisitsAsTheOnePlaneWalk) {
    if (!__builtin_cpu_supports("avx2"))
        GTEST_SKIP() << "this machine has no AVX2: the lanes are not used";
    Rng rng(43);
    for (int scene = 0; scene < 40; ++scene) {
        std::vector<Bounds3> boxes;
        for (int k = 0; k < 200; ++k) {
            Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 2 - 1);
            Vec3 size(rng.uniform() * 3, rng.uniform() * 3, k % 5 == 0 ? 0 : rng.uniform());
            boxes.push_back(Bounds3(c, c + size));
        }
        Bvh bvh(boxes);
        for (int i = 0; i < 200; ++i) {
            Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 10 - 5);
            Vec3 d = normalize(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5));
            if (i % 7 == 0) d.z = i % 2 ? 0.0 : -0.0;
            Ray ray(o, d);
            // The visitor shortens the ray at some items, as a closest-hit search does
            auto walk = [&](auto traverse) {
                std::vector<std::pair<uint32_t, double>> visits;
                double tMax = kInfinity;
                traverse(ray, &tMax, [&](uint32_t k, double *far) {
                    visits.emplace_back(k, *far);
                    if (k % 3 == 0) *far = std::min(*far, 5.0 + k % 11);
                    return false;
                });
                return visits;
            };
            auto one = walk([&](const Ray &r, double *tMax, auto &&v) {
                bvh.traverse(r, -kInfinity, tMax, v);
            });
            auto lanes = walk([&](const Ray &r, double *tMax, auto &&v) {
                bvh.traverseWith(Bvh::LaneSlabs(r), -kInfinity, tMax, v);
            });
            ASSERT_EQ(lanes, one) << "scene " << scene << " ray " << i;
            // The walk that tests two children side by side
            auto pairs = walk([&](const Ray &r, double *tMax, auto &&v) {
                bvh.traversePairs(Bvh::LaneSlabs(r), -kInfinity, tMax, v);
            });
            ASSERT_EQ(pairs, one) << "scene " << scene << " ray " << i;
        }
    }
}
#endif

/// A floor of tiles with a few objects standing on it (glass.scad, default.scad): surface area
/// alone splits it into strips, each with its objects, so a shadow ray leaving a tile walks
/// its strip; weighed by volume as well, the build puts the floor and the objects in the
/// root's two subtrees, and upward rays from the floor leave the floor's subtree at once.
TEST(Bvh, SplitsAFloorFromTheObjectsOnIt) {
    std::vector<Bounds3> bounds;
    for (int i = -7; i < 7; ++i)
        for (int j = -5; j < 6; ++j)
            bounds.push_back(Bounds3(Vec3(2 * i, 2 * j, -0.5), Vec3(2 * i + 2, 2 * j + 2, 0)));
    size_t tiles = bounds.size();
    bounds.push_back(Bounds3(Vec3(-7.5, -2.5, 0), Vec3(-2.5, 2.5, 5)));
    bounds.push_back(Bounds3(Vec3(1, -1, 0), Vec3(5, 3, 4)));
    bounds.push_back(Bounds3(Vec3(6, 1, 0), Vec3(8, 6, 4)));
    Bvh bvh(bounds);
    const auto &nodes = bvh.nodes();
    ASSERT_EQ(nodes[0].count, 0u);
    const Bvh::Node &a = nodes[1], &b = nodes[nodes[0].offset];
    const Bvh::Node &floor = a.bounds.max.z <= 0 ? a : b, &objects = a.bounds.max.z <= 0 ? b : a;
    EXPECT_EQ(floor.bounds.max.z, 0);
    EXPECT_EQ(objects.bounds.min.z, 0);
    EXPECT_EQ(objects.bounds.max.z, 5);
    // Every item under the floor's node is a tile
    std::vector<uint32_t> under;
    auto collect = [&](auto &self, const Bvh::Node &n) -> void {
        if (n.count > 0) {
            for (uint32_t i = 0; i < n.count; ++i) under.push_back(bvh.itemOrder()[n.offset + i]);
            return;
        }
        self(self, nodes[&n - nodes.data() + 1]);
        self(self, nodes[n.offset]);
    };
    collect(collect, floor);
    EXPECT_EQ(under.size(), tiles);
    for (uint32_t item : under) EXPECT_LT(item, tiles);
}

TEST(Bvh, HandlesCoincidentCentroidsAndEmptyInput) {
    std::vector<Bounds3> same(40, Bounds3(Vec3(-1), Vec3(1)));
    Bvh bvh(same);
    EXPECT_EQ(bvh.itemOrder().size(), 40u);
    for (const auto &node : bvh.nodes())
        if (node.count) {
            EXPECT_LE(node.count, static_cast<uint32_t>(Bvh::kMaxLeafItems));
        }
    Bvh empty(std::vector<Bounds3>{});
    double t = kInfinity;
    int visits = 0;
    empty.traverse(Ray(Vec3(0), Vec3(1, 0, 0)), 0, &t, [&](uint32_t, double *) {
        ++visits;
        return false;
    });
    EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace rt
