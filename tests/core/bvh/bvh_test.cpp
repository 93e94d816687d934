// SPDX-License-Identifier: MIT
// The BVH finds exactly the closest hit that a brute-force loop over all objects finds.
#include <gtest/gtest.h>

#include <memory>

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
    empty.traverse(Ray(Vec3(0), Vec3(1, 0, 0)), 0, &t, [&](uint32_t, double *) { ++visits; return false; });
    EXPECT_EQ(visits, 0);
}

}  // namespace
}  // namespace rt
