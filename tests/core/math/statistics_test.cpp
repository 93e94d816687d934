// SPDX-License-Identifier: MIT
// Student t distribution against tabulated values, and Benjamini-Hochberg on known p-values.
#include <gtest/gtest.h>

#include <cmath>

#include "core/math/statistics.h"

namespace rt {
namespace {

TEST(Statistics, StudentTMatchesTables) {
    // Two-sided 5% critical values: dof 1 -> 12.706, 10 -> 2.228, 30 -> 2.042
    EXPECT_NEAR(twoSidedPValue(12.706, 1), 0.05, 1e-4);
    EXPECT_NEAR(twoSidedPValue(2.228, 10), 0.05, 1e-4);
    EXPECT_NEAR(twoSidedPValue(2.042, 30), 0.05, 2e-4);
    EXPECT_NEAR(studentTCdf(2.0, 10), 0.963306, 1e-6);
    EXPECT_NEAR(studentTCdf(-1.0, 5), 0.181609, 1e-6);
    EXPECT_DOUBLE_EQ(studentTCdf(0, 7), 0.5);
    // Normal limit
    EXPECT_NEAR(twoSidedPValue(1.959964, INFINITY), 0.05, 1e-6);
    EXPECT_NEAR(studentTQuantile(0.975, 10), 2.228139, 1e-5);
    EXPECT_NEAR(studentTQuantile(0.995, 1e9), 2.575829, 1e-5);
}

TEST(Statistics, IncompleteBetaEdgesAndSymmetry) {
    EXPECT_EQ(incompleteBeta(2, 3, 0), 0);
    EXPECT_EQ(incompleteBeta(2, 3, 1), 1);
    EXPECT_NEAR(incompleteBeta(2, 3, 0.4), 1 - incompleteBeta(3, 2, 0.6), 1e-14);
    EXPECT_NEAR(incompleteBeta(1, 1, 0.3), 0.3, 1e-14);  // uniform
}

TEST(Statistics, BenjaminiHochbergStepUp) {
    // m = 5, q = 0.05: thresholds 0.01, 0.02, 0.03, 0.04, 0.05; the 3rd smallest (0.025) passes
    // its threshold, so the three smallest are rejected, though 0.021 exceeds 0.02; 0.045
    // exceeds 0.04
    std::vector<double> p = {0.045, 0.001, 0.021, 0.025, 0.5};
    std::vector<bool> r = benjaminiHochberg(p, 0.05);
    EXPECT_EQ(r, (std::vector<bool>{false, true, true, true, false}));
    EXPECT_EQ(benjaminiHochberg({0.2, 0.3}, 0.05), (std::vector<bool>{false, false}));
    EXPECT_TRUE(benjaminiHochberg({}, 0.05).empty());
}

}  // namespace
}  // namespace rt
