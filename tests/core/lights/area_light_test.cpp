// SPDX-License-Identifier: MIT
// POV-Ray's area light grid: target positions, the recursive average (its weights differ from
// a plain mean), adaptive subdivision, circular and orient, and seeded jitter.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/lights/area_light.h"

namespace rt {
namespace {

ir::Light areaLight(int n1, int n2) {
    ir::Light l;
    l.position = Vec3(0, 0, 10);
    l.area = true;
    l.areaLight.axis1 = Vec3(4, 0, 0);
    l.areaLight.axis2 = Vec3(0, 2, 0);
    l.areaLight.n1 = n1;
    l.areaLight.n2 = n2;
    return l;
}

TEST(AreaLight, GridSpansTheAxesAboutTheCentre) {
    ir::Light l = areaLight(5, 3);
    Rng rng(1);
    AreaLightSampler s(l, Vec3(0, 0, 0), rng);
    EXPECT_EQ(s.gridTarget(0, 0), Vec3(-2, -1, 10));
    EXPECT_EQ(s.gridTarget(4, 2), Vec3(2, 1, 10));
    EXPECT_EQ(s.gridTarget(2, 1), Vec3(0, 0, 10));
    EXPECT_EQ(s.gridTarget(1, 0), Vec3(-1, -1, 10));
    // An axis with a single sample contributes nothing
    ir::Light line = areaLight(1, 3);
    AreaLightSampler t(line, Vec3(0, 0, 0), rng);
    EXPECT_EQ(t.gridTarget(0, 2), Vec3(0, 1, 10));
}

TEST(AreaLight, CentreBlockedInNineByNineGivesPovRaysWeightedAverage) {
    // docs/design/povray-semantics.md section 5.3: a 9x9 light with only the centre blocked
    // gives 1 - 1/64, not the plain mean 1 - 1/81
    ir::Light l = areaLight(9, 9);
    Rng rng(1);
    AreaLightSampler s(l, Vec3(0, 0, 0), rng);
    Vec3 centre = s.gridTarget(4, 4);
    Rgb r = s.average([&](const Vec3 &t) { return t == centre ? Rgb(0) : Rgb(1); });
    EXPECT_NEAR(r.r, 1 - 1.0 / 64, 1e-15);
    EXPECT_EQ(s.evaluated(), 81);
}

TEST(AreaLight, FullSubdivisionIsTheTrapezoidRuleOnPowerOfTwoPlusOneGrids) {
    // On a (2^k + 1)^2 grid the recursion weights every cell's four corners equally
    ir::Light l = areaLight(5, 5);
    Rng rng(1);
    AreaLightSampler s(l, Vec3(0, 0, 0), rng);
    auto f = [](const Vec3 &t) { return Rgb(t.x * t.x + 3 * t.y + 1); };
    Rgb got = s.average(f);
    double want = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int di = 0; di < 2; ++di)
                for (int dj = 0; dj < 2; ++dj) want += f(s.gridTarget(i + di, j + dj)).r / 64;
    EXPECT_NEAR(got.r, want, 1e-12);
}

TEST(AreaLight, AdaptiveZeroStopsAtTheCornersUnlessTheyDiffer) {
    ir::Light l = areaLight(17, 17);
    l.areaLight.adaptive = 0;
    Rng rng(1);
    AreaLightSampler s(l, Vec3(0, 0, 0), rng);
    Rgb flat = s.average([](const Vec3 &) { return Rgb(0.5); });
    EXPECT_EQ(flat, Rgb(0.5));
    EXPECT_EQ(s.evaluated(), 4);
    // A shadow edge between corners forces subdivision down to single cells near the edge
    AreaLightSampler e(l, Vec3(0, 0, 0), rng);
    Rgb edge = e.average([](const Vec3 &t) { return t.x < 0.3 ? Rgb(0) : Rgb(1); });
    EXPECT_GT(e.evaluated(), 4);
    EXPECT_LT(e.evaluated(), 17 * 17);
    EXPECT_GT(edge.r, 0.3);
    EXPECT_LT(edge.r, 0.6);
}

TEST(AreaLight, CircularTargetsLieOnADisc) {
    ir::Light l = areaLight(9, 9);
    l.areaLight.axis2 = Vec3(0, 4, 0);
    l.areaLight.circular = true;
    Rng rng(1);
    AreaLightSampler s(l, Vec3(0, 0, 0), rng);
    double maxRadius = 0;
    for (int u = 0; u < 9; ++u)
        for (int v = 0; v < 9; ++v) {
            Vec3 d = s.gridTarget(u, v) - l.position;
            maxRadius = std::max(maxRadius, std::hypot(d.x, d.y));
        }
    // The disc of diameter |axis|, moved out by POV-Ray's 0.001 nudge (of the axis length)
    EXPECT_NEAR(maxRadius, 2, 4 * 0.0011);
}

TEST(AreaLight, OrientFacesTheShadedPoint) {
    ir::Light l = areaLight(5, 5);
    l.areaLight.orient = true;
    Rng rng(1);
    Vec3 p(7, 3, -2);
    AreaLightSampler s(l, p, rng);
    Vec3 toLight = normalize(l.position - p);
    for (int u = 0; u < 5; ++u)
        for (int v = 0; v < 5; ++v) {
            Vec3 d = s.gridTarget(u, v) - l.position;
            EXPECT_NEAR(dot(d, toLight), 0, 1e-12);  // the grid is square to the light ray
            EXPECT_LE(length(d), 2 + 4 * 0.0011);    // both axes as long as axis1 (4)
        }
}

TEST(AreaLight, JitterStaysWithinHalfACellAndRepeatsForTheSameSeed) {
    ir::Light l = areaLight(5, 3);
    l.areaLight.jitter = true;
    Rng a(42), b(42);
    AreaLightSampler sa(l, Vec3(0, 0, 0), a), sb(l, Vec3(0, 0, 0), b);
    std::set<double> xs;
    for (int u = 0; u < 5; ++u)
        for (int v = 0; v < 3; ++v) {
            Vec3 ta = sa.gridTarget(u, v), tb = sb.gridTarget(u, v);
            EXPECT_EQ(ta, tb);
            xs.insert(ta.x);
            // Cells are axis / (n - 1): 1 x 1 here; jitter moves by at most half of one
            EXPECT_LE(std::abs(ta.x - (-2 + u)), 0.5);
            EXPECT_LE(std::abs(ta.y - (-1 + v)), 0.5);
        }
    EXPECT_EQ(xs.size(), 15u);  // really jittered
}

TEST(AreaLightWeights, FixedWeightsReproduceTheRecursiveAverage) {
    for (auto [n1, n2] : {std::pair{9, 9}, {5, 3}, {6, 6}, {1, 4}, {2, 2}, {17, 5}}) {
        ir::Light l = areaLight(n1, n2);
        AreaLightWeights w(l.areaLight);
        ASSERT_TRUE(w.fixed());
        Rng rng(1);
        AreaLightSampler s(l, Vec3(0, 0, 0), rng);
        // Any values: the average is the weighted sum
        auto value = [](const Vec3 &t) { return Rgb(std::sin(3 * t.x) + t.y * t.y + 2); };
        double sum = 0, total = 0;
        for (int u = 0; u < n1; ++u)
            for (int v = 0; v < n2; ++v) {
                sum += w.weight(u, v) * value(s.gridTarget(u, v)).r;
                total += w.weight(u, v);
            }
        EXPECT_NEAR(total, 1, 1e-15);
        EXPECT_NEAR(s.average(value).r, sum, 1e-14) << n1 << "x" << n2;
    }
    EXPECT_DOUBLE_EQ(AreaLightWeights(areaLight(9, 9).areaLight).weight(4, 4), 1.0 / 64);
}

TEST(AreaLightWeights, PicksGridPointsInProportionToTheirWeights) {
    ir::Light l = areaLight(5, 3);
    AreaLightWeights w(l.areaLight);
    std::vector<int> counts(15, 0);
    Rng rng(2);
    constexpr int n = 200000;
    for (int i = 0; i < n; ++i) {
        int u, v;
        w.pick(rng.uniform(), u, v);
        ++counts[u * 3 + v];
    }
    for (int u = 0; u < 5; ++u)
        for (int v = 0; v < 3; ++v) {
            double p = w.weight(u, v);
            double sd = std::sqrt(n * p * (1 - p));
            EXPECT_NEAR(counts[u * 3 + v], n * p, 5 * sd + 1) << u << "," << v;
        }
}

TEST(AreaLightWeights, AnAdaptingGridHasNoFixedWeights) {
    ir::Light l = areaLight(17, 17);
    l.areaLight.adaptive = 2;  // 17 x 17 needs 4 levels to reach single cells
    EXPECT_FALSE(AreaLightWeights(l.areaLight).fixed());
    l.areaLight.adaptive = 4;
    EXPECT_TRUE(AreaLightWeights(l.areaLight).fixed());
}

}  // namespace
}  // namespace rt
