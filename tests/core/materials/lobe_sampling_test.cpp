// SPDX-License-Identifier: MIT
// Each lobe sampler against its own density: chi-square goodness of fit over (theta, phi) bins
// whose expected counts come from integrating pdfLocal, the normalisation of the density, and
// a deliberately wrong sampler that the same test must reject.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "core/materials/lobe_sampling.h"
#include "core/math/rng.h"
#include "core/math/statistics.h"

namespace rt {
namespace {

constexpr double kPi = 3.14159265358979323846;

double deg(double d) { return d * kPi / 180; }

/// Integral of the lobe's density over theta in [t0, t1], phi in [p0, p1] (composite Simpson,
/// fine enough that quadrature error is far below the test's sampling noise).
double binProbability(const Lobe &lobe, double t0, double t1, double p0, double p1) {
    constexpr int kT = 64, kP = 8;
    double ht = (t1 - t0) / kT, hp = (p1 - p0) / kP, sum = 0;
    for (int i = 0; i <= kT; ++i) {
        double wt = (i == 0 || i == kT) ? 1 : (i % 2 ? 4 : 2);
        double t = t0 + i * ht;
        for (int j = 0; j <= kP; ++j) {
            double wp = (j == 0 || j == kP) ? 1 : (j % 2 ? 4 : 2);
            double p = p0 + j * hp;
            Vec3 w(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
            sum += wt * wp * lobe.pdfLocal(w) * std::sin(t);
        }
    }
    return sum * ht * hp / 9;
}

struct ChiSquare {
    double statistic = 0;
    int dof = 0;
    double pValue = 1;
};

/// Bins samples over theta in [0, thetaMax] (plus one bin for the rest of the hemisphere) and
/// phi, pools bins expected to hold fewer than 5 samples, and tests against the density.
ChiSquare chiSquareTest(const Lobe &lobe, const std::function<Vec3(double, double)> &sampler,
                        int samples, uint64_t seed) {
    constexpr int kThetaBins = 24, kPhiBins = 12;
    double thetaMax = std::min(kPi / 2, 6 * lobe.sigma());
    int bins = kThetaBins * kPhiBins + 1;
    std::vector<double> observed(bins, 0), expected(bins, 0);
    Rng rng(seed);
    for (int i = 0; i < samples; ++i) {
        Vec3 w = sampler(rng.uniform(), rng.uniform());
        double theta = std::acos(std::clamp(w.z, -1.0, 1.0));
        double phi = std::atan2(w.y, w.x);
        if (phi < 0) phi += 2 * kPi;
        int ti = static_cast<int>(theta / thetaMax * kThetaBins);
        int pi = std::min(kPhiBins - 1, static_cast<int>(phi / (2 * kPi) * kPhiBins));
        observed[ti >= kThetaBins ? bins - 1 : ti * kPhiBins + pi] += 1;
    }
    double inside = 0;
    for (int ti = 0; ti < kThetaBins; ++ti)
        for (int pi = 0; pi < kPhiBins; ++pi) {
            double p =
                binProbability(lobe, thetaMax * ti / kThetaBins, thetaMax * (ti + 1) / kThetaBins,
                               2 * kPi * pi / kPhiBins, 2 * kPi * (pi + 1) / kPhiBins);
            expected[ti * kPhiBins + pi] = p * samples;
            inside += p;
        }
    expected[bins - 1] = std::max(0.0, 1 - inside) * samples;
    // Pool sparse bins (in order) so every tested cell expects at least 5 samples
    ChiSquare r;
    double pooledObs = 0, pooledExp = 0;
    int cells = 0;
    for (int i = 0; i < bins; ++i) {
        pooledObs += observed[i];
        pooledExp += expected[i];
        if (pooledExp >= 5 || i == bins - 1) {
            if (pooledExp > 0) {
                r.statistic += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
                ++cells;
            }
            pooledObs = pooledExp = 0;
        }
    }
    r.dof = cells - 1;
    r.pValue = chiSquareSf(r.statistic, r.dof);
    return r;
}

struct LobeCase {
    LobeShape shape;
    double degrees;
};

class LobeSamplerTest : public ::testing::TestWithParam<LobeCase> {};

TEST_P(LobeSamplerTest, DensityIntegratesToOne) {
    Lobe lobe(GetParam().shape, deg(GetParam().degrees));
    double total = 0;
    // Split at 8 sigma, where narrow lobes have all their mass
    double split = std::min(kPi / 2, 8 * lobe.sigma());
    total += binProbability(lobe, 0, split, 0, 2 * kPi);
    if (split < kPi / 2) total += binProbability(lobe, split, kPi / 2, 0, 2 * kPi);
    // A Phong exponent below 1 has an infinite slope at 90 degrees, which Simpson's rule
    // integrates less well
    bool steepEdge = lobe.shape() == LobeShape::Phong && lobe.exponent() < 1;
    EXPECT_NEAR(total, 1, steepEdge ? 2e-3 : 2e-4);
    // The polar density alone integrates to one as well
    double sum = 0, h = split / 4000;
    for (int i = 0; i < 4000; ++i) sum += lobe.pdfTheta((i + 0.5) * h) * h;
    EXPECT_NEAR(sum, 1, 2e-3);
}

TEST_P(LobeSamplerTest, SamplesFollowTheDensity) {
    Lobe lobe(GetParam().shape, deg(GetParam().degrees));
    ChiSquare r = chiSquareTest(
        lobe, [&](double u1, double u2) { return lobe.sampleLocal(u1, u2); }, 200000, 7);
    // One test per case at a fixed seed: p below 1e-4 would mean a wrong sampler
    EXPECT_GT(r.pValue, 1e-4) << "chi2 " << r.statistic << " with " << r.dof << " dof";
    EXPECT_GT(r.dof, 20);
}

TEST_P(LobeSamplerTest, AMisScaledSamplerIsRejected) {
    // The same test must fail when sampler and density disagree: 5 % wider, or where the lobe
    // is already as wide as it goes (and nearly flat), 15 % narrower
    double sigma = deg(GetParam().degrees);
    Lobe lobe(GetParam().shape, sigma);
    Lobe wider(GetParam().shape, sigma * 1.05 <= kMaxLobeSigma ? sigma * 1.05 : sigma * 0.85);
    ChiSquare r = chiSquareTest(
        lobe, [&](double u1, double u2) { return wider.sampleLocal(u1, u2); }, 200000, 7);
    EXPECT_LT(r.pValue, 1e-6) << "chi2 " << r.statistic << " with " << r.dof << " dof";
}

TEST_P(LobeSamplerTest, SamplesAreUnitAndInTheHemisphere) {
    Lobe lobe(GetParam().shape, deg(GetParam().degrees));
    Rng rng(3);
    for (int i = 0; i < 10000; ++i) {
        Vec3 w = lobe.sampleLocal(rng.uniform(), rng.uniform());
        ASSERT_NEAR(length(w), 1, 1e-12);
        ASSERT_GE(w.z, 0);
    }
    // The extremes of the unit square stay finite
    for (double u : {0.0, 0.5, 1 - 0x1p-53}) {
        Vec3 w = lobe.sampleLocal(u, u);
        EXPECT_TRUE(w.isFinite());
        EXPECT_TRUE(std::isfinite(lobe.pdfLocal(w)));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Lobes, LobeSamplerTest,
    ::testing::Values(LobeCase{LobeShape::Normal, 1}, LobeCase{LobeShape::Normal, 10},
                      LobeCase{LobeShape::Normal, 45}, LobeCase{LobeShape::Normal, 90},
                      LobeCase{LobeShape::Phong, 1}, LobeCase{LobeShape::Phong, 10},
                      LobeCase{LobeShape::Phong, 45}, LobeCase{LobeShape::Phong, 90}),
    [](const auto &param) {
        return std::string(param.param.shape == LobeShape::Normal ? "Normal" : "Phong") +
               std::to_string(static_cast<int>(param.param.degrees)) + "deg";
    });

TEST(LobeSampling, SmallSpreadsOfBothShapesAgree) {
    // For small angles both are a 2-D normal distribution of the tangent offset: E[theta^2] = 2
    // sigma^2
    for (LobeShape shape : {LobeShape::Normal, LobeShape::Phong}) {
        Lobe lobe(shape, deg(2));
        Rng rng(11);
        double sum = 0;
        constexpr int n = 100000;
        for (int i = 0; i < n; ++i) {
            Vec3 w = lobe.sampleLocal(rng.uniform(), rng.uniform());
            double t = std::acos(std::min(1.0, w.z));
            sum += t * t;
        }
        EXPECT_NEAR(sum / n / (2 * deg(2) * deg(2)), 1, 0.02);
    }
}

TEST(LobeSampling, LatticePointsFillEveryStratumOfBothDimensions) {
    for (int n = 1; n <= 256; ++n) {
        int g = latticeGenerator(n);
        std::vector<bool> seen(n, false);
        for (int i = 0; i < n; ++i) seen[(int64_t(i) * g) % n] = true;
        EXPECT_EQ(std::count(seen.begin(), seen.end(), true), n) << n << " points, generator " << g;
    }
    EXPECT_EQ(latticeGenerator(8), 5);    // Fibonacci: 8, 5
    EXPECT_EQ(latticeGenerator(89), 55);  // 89, 55
    EXPECT_EQ(latticeGenerator(16), 11);  // 10 shares the factor 2 with 16
}

TEST(LobeSampling, FrameIsOrthonormalEverywhere) {
    Rng rng(5);
    std::vector<Vec3> axes = {Vec3(0, 0, 1), Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0, -1, 0),
                              normalize(Vec3(1e-9, 0, -1))};
    for (int i = 0; i < 1000; ++i) {
        double z = 2 * rng.uniform() - 1, p = 2 * kPi * rng.uniform(), r = std::sqrt(1 - z * z);
        axes.push_back(Vec3(r * std::cos(p), r * std::sin(p), z));
    }
    for (const Vec3 &n : axes) {
        Frame f = Frame::fromZ(n);
        EXPECT_NEAR(length(f.s), 1, 1e-12);
        EXPECT_NEAR(length(f.t), 1, 1e-12);
        EXPECT_NEAR(dot(f.s, f.t), 0, 1e-12);
        EXPECT_NEAR(dot(f.s, n), 0, 1e-12);
        EXPECT_NEAR(dot(cross(f.s, f.t), n), 1, 1e-12);  // right-handed
        Vec3 v(0.3, -0.4, 0.5);
        Vec3 back = f.toLocal(f.toWorld(v));
        EXPECT_NEAR(length(back - v), 0, 1e-12);
    }
}

TEST(LobeSampling, FoldingKeepsEveryDirectionOnItsSide) {
    // A grazing centre: half the lobe would go below the surface; folded, none does, and the
    // folded directions stay unit
    Lobe lobe(LobeShape::Normal, deg(20));
    Vec3 side(0, 0, 1), centre = normalize(Vec3(1, 0, 0.05));
    Rng rng(9);
    int folded = 0;
    for (int i = 0; i < 20000; ++i) {
        double u1 = rng.uniform(), u2 = rng.uniform();
        Vec3 raw = Frame::fromZ(centre).toWorld(lobe.sampleLocal(u1, u2));
        Vec3 d = sampleLobeAbout(lobe, centre, side, u1, u2);
        ASSERT_GE(dot(d, side), 0);
        ASSERT_NEAR(length(d), 1, 1e-12);
        folded += dot(raw, side) <= 0;
    }
    EXPECT_GT(folded, 5000);  // the case is really grazing
}

TEST(LobeSampling, InvalidSpreadsAreRejected) {
    EXPECT_THROW(Lobe(LobeShape::Normal, 0), std::invalid_argument);
    EXPECT_THROW(Lobe(LobeShape::Phong, -1), std::invalid_argument);
    EXPECT_THROW(Lobe(LobeShape::Normal, 2), std::invalid_argument);
    EXPECT_THROW(Lobe(LobeShape::Normal, std::nan("")), std::invalid_argument);
    EXPECT_NO_THROW(Lobe(LobeShape::Normal, 90 * kPi / 180));
}

TEST(Statistics, ChiSquareSurvivalMatchesTables) {
    // Critical values from standard tables
    EXPECT_NEAR(chiSquareSf(3.841, 1), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSf(18.307, 10), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSf(23.209, 10), 0.01, 1e-4);
    EXPECT_NEAR(chiSquareSf(124.342, 100), 0.05, 1e-4);
    EXPECT_NEAR(chiSquareSf(0, 5), 1, 1e-15);
    EXPECT_NEAR(chiSquareSf(2, 2), std::exp(-1.0), 1e-14);
    EXPECT_LT(chiSquareSf(1000, 10), 1e-100);
}

}  // namespace
}  // namespace rt
