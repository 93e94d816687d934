// SPDX-License-Identifier: MIT
// The statistical comparison itself: identical images pass; a 2% brightness bias on a region
// fails; pure noise at the stated level passes at the stated false-alarm rate over many seeds;
// masks, deterministic thresholds, NaN and size mismatches behave.
#include <gtest/gtest.h>

#include <cmath>

#include "core/image/image_compare.h"
#include "core/image/image_io.h"
#include "core/math/rng.h"

namespace rt {
namespace {

/// A smooth reference: a gradient with values between 0.2 and 0.8.
Image reference(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) img.set(x, y, Rgb(0.2 + 0.6 * x / w, 0.3 + 0.4 * y / h, 0.5));
    return img;
}

double gaussian(Rng &rng) {
    double u1 = std::max(rng.uniform(), 1e-300), u2 = rng.uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
}

/// A Monte Carlo-like estimate of `truth` (+ bias inside the box [x0,x1) x [y0,y1)): each pixel
/// is the mean of `batches` batch values with noise sigma, the variance estimated from them
/// exactly as the renderer does.
ImageEstimate noisyEstimate(const Image &truth, double sigma, int batches, uint64_t seed,
                            double bias = 0, int x0 = 0, int y0 = 0, int x1 = 0, int y1 = 0) {
    Rng rng(seed);
    ImageEstimate e;
    e.mean = Image(truth.width(), truth.height());
    e.variance = Image(truth.width(), truth.height());
    e.batches = batches;
    for (int y = 0; y < truth.height(); ++y)
        for (int x = 0; x < truth.width(); ++x) {
            Rgb t = truth.at(x, y);
            if (x >= x0 && x < x1 && y >= y0 && y < y1) t = t * (1 + bias);
            Rgb mean(0), m2(0);
            for (int b = 0; b < batches; ++b) {
                // Drawn in separate statements: the order of evaluation of constructor arguments
                // is unspecified (GCC goes right to left, clang left to right), and with it
                // which noise each channel got, so the images differed between compilers
                double nr = gaussian(rng);
                double ng = gaussian(rng);
                double nb = gaussian(rng);
                Rgb v(t.r + sigma * nr, t.g + sigma * ng, t.b + sigma * nb);
                Rgb d = v - mean;
                mean += d / double(b + 1);
                m2 += d * (v - mean);
            }
            e.mean.set(x, y, mean);
            e.variance.set(x, y, m2 / double(batches - 1) / double(batches));
        }
    return e;
}

TEST(ImageCompare, IdenticalImagesPass) {
    ImageEstimate ref{reference(64, 48), {}, 0, {}, {}};
    CompareResult r = compareImages(ref, ref);
    EXPECT_TRUE(r.pass);
    EXPECT_EQ(r.rmse, 0);
    EXPECT_EQ(r.tilesFailed, 0);
    EXPECT_EQ(r.tilesTested, 48);
    ImageEstimate noisy = noisyEstimate(ref.mean, 0.02, 8, 3);
    EXPECT_TRUE(compareImages(noisy, noisy).pass);
}

TEST(ImageCompare, TwoPercentBiasOnARegionFails) {
    // Benjamini-Hochberg bounds the false discovery rate, the expected share of failed tiles
    // that are not really different, by alpha; it does not promise that no unbiased tile ever
    // fails. Measured over 400 seeds: 48 biased tile-channels fail every time, and a tile
    // outside the region fails in about 3% of the images (0.04 tiles an image, a false
    // discovery rate near 0.1%). So: every image is caught, every failure inside the region
    // is a positive difference, and the false discoveries stay below alpha of all failures.
    Image truth = reference(96, 64);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    CompareOptions o;
    int fails = 0, inside = 0, outside = 0;
    const int kSeeds = 20;
    for (uint64_t seed = 0; seed < kSeeds; ++seed) {
        ImageEstimate test = noisyEstimate(truth, 0.02, 8, seed, 0.02, 32, 16, 64, 48);
        CompareResult r = compareImages(test, ref, o);
        fails += !r.pass;
        for (const TileTest &t : r.failures) {
            if (t.x * 8 >= 32 && t.x * 8 < 64 && t.y * 8 >= 16 && t.y * 8 < 48) {
                ++inside;
                EXPECT_GT(t.difference, 0) << "seed " << seed;
            } else {
                ++outside;
            }
        }
    }
    EXPECT_EQ(fails, kSeeds) << "a 2% bias must be detected every time at this noise level";
    EXPECT_EQ(inside, kSeeds * 4 * 4 * 3) << "every biased tile and channel fails";
    EXPECT_LE(outside, o.alpha * (inside + outside)) << "false discoveries beyond alpha";
}

TEST(ImageCompare, BiasWithinTheMarginPasses) {
    Image truth = reference(64, 48);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    // 0.5% bias: significant with this little noise, but inside the 1% equivalence margin
    ImageEstimate test = noisyEstimate(truth, 0.002, 16, 9, 0.005, 0, 0, 64, 48);
    CompareResult r = compareImages(test, ref);
    EXPECT_TRUE(r.pass);
}

TEST(ImageCompare, PureNoiseFalseAlarmRateMatchesAlpha) {
    // With no margin, only the t-tests and Benjamini-Hochberg decide: under the global null
    // the chance of any failure is alpha (Simes). 400 seeds give a binomial standard error of
    // 0.011 around 0.05.
    Image truth = reference(48, 32);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    CompareOptions o;
    o.alpha = 0.05;
    o.marginAbs = 0;
    o.marginRel = 0;
    int alarms = 0;
    const int kSeeds = 400;
    for (int seed = 0; seed < kSeeds; ++seed) {
        ImageEstimate test = noisyEstimate(truth, 0.05, 8, 1000 + seed);
        alarms += !compareImages(test, ref, o).pass;
    }
    double rate = double(alarms) / kSeeds;
    EXPECT_GT(rate, 0.015) << "far below alpha: the test would be needlessly weak";
    EXPECT_LT(rate, 0.085) << "above alpha: false alarms";
    // With the default margin, noise at this level never fails
    int marginAlarms = 0;
    for (int seed = 0; seed < 100; ++seed)
        marginAlarms += !compareImages(noisyEstimate(truth, 0.05, 8, 5000 + seed), ref).pass;
    EXPECT_LE(marginAlarms, 1);
}

TEST(ImageCompare, EdgesInTheReferenceAreMasked) {
    Image truth = reference(64, 48);
    ImageEstimate ref{truth, {}, 0, Image(64, 48), {}};
    ImageEstimate test{truth, {}, 0, {}, {}};
    // A vertical edge at x = 20 (large sub-sample spread) where the test differs
    for (int y = 0; y < 48; ++y) {
        ref.spread.set(20, y, Rgb(0.5));
        test.mean.set(20, y, Rgb(0.9));
        test.mean.set(21, y, Rgb(0.9));  // the neighbour is masked by the dilation
    }
    CompareResult r = compareImages(test, ref);
    EXPECT_TRUE(r.pass);
    EXPECT_EQ(r.maskedPixels, 48 * 3);
    EXPECT_GT(r.maskedRmse, 0.1);
    EXPECT_LT(r.maxError, 1e-6);
    // Ties reported by the test image are masked the same way
    ImageEstimate tied = test;
    tied.ties = Image(64, 48);
    for (int y = 0; y < 48; ++y) tied.ties.set(40, y, Rgb(1));
    for (int y = 0; y < 48; ++y) tied.mean.set(40, y, Rgb(0));
    EXPECT_TRUE(compareImages(tied, ref).pass);
}

TEST(ImageCompare, DeterministicPixelThresholdWithErosion) {
    Image truth = reference(64, 48);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    ImageEstimate one{truth, {}, 0, {}, {}};
    one.mean.set(30, 30, Rgb(1, 1, 1));  // an isolated wrong pixel is forgiven
    CompareResult r1 = compareImages(one, ref);
    EXPECT_EQ(r1.failedPixels, 0);
    ImageEstimate blob{truth, {}, 0, {}, {}};
    for (int y = 10; y < 13; ++y)
        for (int x = 50; x < 53; ++x) blob.mean.set(x, y, truth.at(x, y) + Rgb(0.2));
    CompareResult r2 = compareImages(blob, ref);
    EXPECT_FALSE(r2.pass);
    EXPECT_EQ(r2.failedPixels, 1);  // the centre of the 3x3 blob survives erosion
}

TEST(ImageCompare, NanFailsAndSizeMismatchIsBadInput) {
    Image truth = reference(32, 32);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    ImageEstimate bad = noisyEstimate(truth, 0.01, 4, 1);
    for (int y = 8; y < 16; ++y)
        for (int x = 8; x < 16; ++x) bad.mean.set(x, y, Rgb(NAN));
    EXPECT_FALSE(compareImages(bad, ref).pass);
    ImageEstimate small{reference(16, 16), {}, 0, {}, {}};
    EXPECT_THROW(compareImages(small, ref), std::invalid_argument);
}

TEST(ImageCompare, ReportsTheSmallestDetectableBias) {
    Image truth = reference(64, 48);
    ImageEstimate ref{truth, {}, 0, {}, {}};
    CompareResult quiet = compareImages(noisyEstimate(truth, 0.001, 8, 2), ref);
    CompareResult noisy = compareImages(noisyEstimate(truth, 0.2, 8, 2), ref);
    // Low noise: the margin decides; high noise: the standard error does
    EXPECT_NEAR(quiet.detectableMedian, 0.01 * 0.5, 0.003);
    EXPECT_GT(noisy.detectableMedian, 0.02);
    EXPECT_GE(noisy.detectableP95, noisy.detectableMedian);
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

TEST(PlaneResidualSpread, GradientsAreNoEdgesStepsAre) {
    // 3x3 blocks of a steep linear ramp (0.04 per sub-sample, 0.12 per pixel): no edge
    Image ramp(30, 30);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 30; ++x) ramp.set(x, y, Rgb(0.04 * x, 0.01 * y, 0.5));
    Image r = planeResidualSpread(ramp, 3);
    ASSERT_EQ(r.width(), 10);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) EXPECT_LT(r.at(x, y).maxComponent(), 1e-6);  // float pixels
    // The usual range spread calls the same ramp an edge everywhere
    EXPECT_GT(downsample(ramp, 3).spread.at(4, 4).r, 0.05);
    // A step of 0.1 between sub-samples 14 and 15 (inside pixel 4 and beside pixel 5): an edge
    // for both, none far from it
    Image step(30, 30);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 30; ++x) step.set(x, y, Rgb(x < 15 ? 0.2 : 0.3));
    Image s = planeResidualSpread(step, 3);
    EXPECT_GT(s.at(4, 4).r, 0.05);
    EXPECT_GT(s.at(5, 4).r, 0.05);
    EXPECT_LT(s.at(1, 4).r, 1e-6);
    EXPECT_LT(s.at(8, 4).r, 1e-6);
}

}  // namespace
}  // namespace rt
