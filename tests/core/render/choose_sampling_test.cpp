// SPDX-License-Identifier: MIT
// The render plan, not its caller, decides the sampling a caller leaves open.
#include <gtest/gtest.h>

#include "core/render/render_plan.h"

namespace rt {
namespace {

RenderPlan sharpPlan() {
    RenderPlan p;
    p.defaultSamples = 1;
    p.adaptive = true;
    return p;
}

RenderPlan monteCarloPlan() {
    RenderPlan p;
    p.monteCarlo = true;
    p.defaultSamples = 4;
    p.adaptive = false;
    return p;
}

TEST(ChooseSampling, SharpSceneIsAdaptiveFromOneSample) {
    RenderOptions ro;
    chooseSampling(sharpPlan(), SamplingRequest{}, ro);
    EXPECT_EQ(ro.samplesPerPixel, 1);
    EXPECT_TRUE(ro.adaptive);
    EXPECT_FALSE(ro.adaptiveNoise);
}

TEST(ChooseSampling, MonteCarloSceneTakesUniformSamplesUnlessAdaptiveIsAsked) {
    RenderOptions ro;
    chooseSampling(monteCarloPlan(), SamplingRequest{}, ro);
    EXPECT_EQ(ro.samplesPerPixel, 4);
    EXPECT_FALSE(ro.adaptive);

    RenderOptions asked;
    asked.adaptiveTolerance = 0.5;
    SamplingRequest req;
    req.adaptiveGiven = true;
    chooseSampling(monteCarloPlan(), req, asked);
    EXPECT_TRUE(asked.adaptive);
    EXPECT_TRUE(asked.adaptiveNoise);
    EXPECT_EQ(asked.adaptiveTolerance, kAdaptiveNoiseTolerance);

    RenderOptions tolerance;
    tolerance.adaptiveTolerance = 0.5;
    req.toleranceGiven = true;
    chooseSampling(monteCarloPlan(), req, tolerance);
    EXPECT_EQ(tolerance.adaptiveTolerance, 0.5);
    EXPECT_FALSE(req.planChooses());
}

TEST(ChooseSampling, GivenSamplesAndRefusedAdaptiveAreKept) {
    RenderOptions ro;
    ro.samplesPerPixel = 9;
    ro.adaptive = false;
    SamplingRequest req;
    req.samplesGiven = true;
    chooseSampling(sharpPlan(), req, ro);
    EXPECT_EQ(ro.samplesPerPixel, 9);
    EXPECT_FALSE(ro.adaptive);

    RenderOptions refused;
    SamplingRequest no;
    no.noAdaptive = true;
    chooseSampling(sharpPlan(), no, refused);
    EXPECT_FALSE(refused.adaptive);
    EXPECT_EQ(refused.samplesPerPixel, 1);
    EXPECT_TRUE(no.planChooses());
}

}  // namespace
}  // namespace rt
