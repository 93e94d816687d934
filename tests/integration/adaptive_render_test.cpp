// SPDX-License-Identifier: MIT
// Adaptive antialiasing: the same picture as uniform 64 samples per pixel within
// `compare`, with a fraction of the samples; refined pixels are exactly uniform sampling's; the
// picture is the same for any thread count and tile size; pixels that differ from a neighbour
// (edges, shadow boundaries) are the ones refined.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "core/csg/csg_shape.h"
#include "core/image/image_compare.h"
#include "core/render/render_plan.h"
#include "core/render/renderer.h"
#include "importers/scad/scad_importer.h"
#include "integration/render_test_support.h"

namespace rt {
namespace {

using test::compile;
using test::Compiled;
using test::libraryOptions;
using test::loadScene;
using test::options;

Compiled loadText(const std::string &text) {
    DiagnosticSink diag;
    return compile(scad::importScadSource("use <scadray.scad>\n" + text,
                                          std::string(SCADRAY_SOURCE_DIR) + "/scenes/test.scad",
                                          diag, libraryOptions()));
}

RenderResult uniform(const RenderScene &rs, int w, int h, int spp) {
    RenderOptions o = options(w, h);
    o.samplesPerPixel = spp;
    return renderImage(rs, o);
}

RenderResult adaptive(const RenderScene &rs, int w, int h, RenderOptions o = {}) {
    o.width = w;
    o.height = h;
    if (o.threads == 0) o.threads = 2;
    o.adaptive = true;
    return renderImage(rs, o);
}

/// Root mean square difference of the display values (square root of linear) over every
/// pixel, edges included.
double displayRmse(const Image &a, const Image &b) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int ch = 0; ch < 3; ++ch) {
                double d = std::sqrt(std::clamp(double(a.at(x, y)[ch]), 0.0, 1.0)) -
                           std::sqrt(std::clamp(double(b.at(x, y)[ch]), 0.0, 1.0));
                sum += d * d;
            }
    return std::sqrt(sum / (3.0 * a.width() * a.height()));
}

bool samePixels(const Image &a, const Image &b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (!(a.at(x, y) == b.at(x, y))) return false;
    return true;
}

TEST(AdaptiveRender, SamePictureAsUniform64WithAFractionOfTheSamples) {
    // Edges, CSG holes and shadows
    for (const char *name : {"lecture_csg.scad", "csg_part.scad"}) {
        SCOPED_TRACE(name);
        Compiled c = loadScene(name);
        const int w = 160, h = 120;
        RenderResult a = adaptive(*c.rs, w, h), ref = uniform(*c.rs, w, h, 64),
                     one = uniform(*c.rs, w, h, 1);
        ImageEstimate test{a.image, {}, 0, {}, a.ties}, reference{ref.image, {}, 0, {}, ref.ties};
        CompareResult cmp = compareImages(test, reference);
        EXPECT_TRUE(cmp.pass) << cmp.summary({});
        double fraction = double(a.samples) / (64.0 * w * h);
        double errorAdaptive = displayRmse(a.image, ref.image),
               errorOne = displayRmse(one.image, ref.image);
        std::printf(
            "%s %dx%d: adaptive %.2f spp = %.3f of uniform 64; display RMSE against it %.4f "
            "(1 spp: %.4f)\n",
            name, w, h, meanSamplesPerPixel(a), fraction, errorAdaptive, errorOne);
        EXPECT_LT(fraction, 0.1);
        // Antialiased: the edges are much closer to uniform 64's than the centres are
        EXPECT_LT(errorAdaptive, 0.5 * errorOne);
        // The histogram accounts for every pixel and every sample
        ASSERT_EQ(a.pixelsBySamples.size(), 4u);
        int64_t pixels = 0, samples = w * h, checked = 0;
        for (uint8_t probes : a.pixelChecked) {
            EXPECT_TRUE(probes == 0 || probes == 2 || probes == 3) << int(probes);
            samples += probes;
            checked += probes > 0;
        }
        EXPECT_EQ(checked, a.checkedPixels);
        for (size_t k = 0; k < a.pixelsBySamples.size(); ++k) {
            pixels += a.pixelsBySamples[k];
            if (k) samples += a.pixelsBySamples[k] << (2 * k);
        }
        EXPECT_GT(a.checkedPixels, 0);
        EXPECT_LE(a.checkedPixels, a.pixelsBySamples[0]);
        EXPECT_EQ(pixels, w * h);
        EXPECT_EQ(samples, a.samples);
        EXPECT_EQ(a.stats.camera, a.samples);
    }
}

TEST(AdaptiveRender, RefinedPixelsAreUniformSamplingsAndTheRestAreCentres) {
    // With no tolerance every refined pixel takes all adaptiveMax samples: it is then exactly
    // the pixel of uniform sampling at adaptiveMax, and every other pixel that of 1 spp
    Compiled c = loadScene("lecture_csg.scad");
    const int w = 64, h = 48;
    RenderOptions o;
    o.adaptiveMax = 16;
    o.adaptiveTolerance = 0;
    RenderResult a = adaptive(*c.rs, w, h, o), one = uniform(*c.rs, w, h, 1),
                 sixteen = uniform(*c.rs, w, h, 16);
    ASSERT_EQ(a.pixelLevels.size(), size_t(w) * h);
    int refined = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int n = 1 << (2 * a.pixelLevels[size_t(y) * w + x]);
            ASSERT_TRUE(n == 1 || n == 16) << n;
            const Image &expected = n == 1 ? one.image : sixteen.image;
            EXPECT_TRUE(a.image.at(x, y) == expected.at(x, y)) << x << "," << y << ": " << n;
            refined += n == 16;
        }
    EXPECT_GT(refined, 0);
    EXPECT_EQ(a.pixelsBySamples[2], refined);
    EXPECT_EQ(a.pixelsBySamples[1], 0);
}

TEST(AdaptiveRender, SameForAnyThreadCountAndTileSize) {
    Compiled c = loadScene("csg_part.scad");
    RenderOptions o;
    o.threads = 1;
    RenderResult base = adaptive(*c.rs, 80, 60, o);
    for (auto [threads, tile] : {std::pair{2, 7}, std::pair{3, 32}, std::pair{2, 1}}) {
        o.threads = threads;
        o.tileSize = tile;
        RenderResult r = adaptive(*c.rs, 80, 60, o);
        EXPECT_TRUE(samePixels(base.image, r.image)) << threads << " threads, tile " << tile;
        EXPECT_EQ(base.samples, r.samples);
        EXPECT_EQ(base.pixelLevels, r.pixelLevels);
    }
}

TEST(AdaptiveRender, EdgesShadowsAndSameColouredNeighboursAreRefined) {
    // A floor, a box casting a shadow on it, and two boxes of one colour side by side, lit
    // alike: their seam has no contrast, but the primitives differ
    Compiled c = loadText(R"(
camera(location=[0, -12, 6], look_at=[0, 0, 0], fov=40);
point_light(position=[4, -6, 10]);
material(color="white") translate([-8, -8, -1]) cube([16, 16, 1]);
material(color="red") translate([-3, -1, 0]) cube([2, 2, 2]);
material(color="green") translate([1, -1, 0]) cube([1, 2, 1]);
material(color="green") translate([2, -1, 0]) cube([1, 2, 1]);
)");
    const int w = 96, h = 72;
    RenderResult a = adaptive(*c.rs, w, h), one = uniform(*c.rs, w, h, 1);
    RenderOptions o;
    double threshold = o.adaptiveThreshold + 1.0 / 255;  // the renderer keeps 1/255 steps
    auto display = [&](int x, int y, int ch) {
        return std::sqrt(std::clamp(double(one.image.at(x, y)[ch]), 0.0, 1.0));
    };
    // Every pixel that differs from a neighbour beyond the threshold is refined or checked
    // (two probe samples on the neighbour's side saw its centre's colour), and the contrast is
    // refined on at least one side of nearly every such pair
    auto examined = [&](int x, int y) {
        size_t p = size_t(y) * w + x;
        return a.pixelLevels[p] > 0 || a.pixelChecked[p];
    };
    auto refined = [&](int x, int y) { return a.pixelLevels[size_t(y) * w + x] > 0; };
    int contrasted = 0, refinedPairs = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x + 1 < w; ++x) {
            bool differs = false;
            for (int ch = 0; ch < 3; ++ch)
                differs |= std::abs(display(x, y, ch) - display(x + 1, y, ch)) > threshold;
            if (!differs) continue;
            ++contrasted;
            EXPECT_TRUE(examined(x, y)) << x << "," << y;
            EXPECT_TRUE(examined(x + 1, y)) << x + 1 << "," << y;
            refinedPairs += refined(x, y) || refined(x + 1, y);
        }
    EXPECT_GT(contrasted, 20);
    // A pair is left unrefined where every probe of both pixels fell on its own pixel's side
    // of the edge: for straight edges evenly spread between the centres, a third of the pairs,
    // those where the edge covers little of the pixel it crosses
    EXPECT_GT(refinedPairs, 0.6 * contrasted) << refinedPairs << " of " << contrasted;
    EXPECT_GT(a.checkedPixels, 0);
    // Most of the picture keeps its centre sample
    EXPECT_GT(a.pixelsBySamples[0], w * h / 2);
    // The seam between the two green boxes: found as the column where the 1 spp picture's
    // green faces meet, refined although the colour does not change across it
    RenderOptions noContrast;
    noContrast.adaptiveThreshold = 1;  // only primitive changes refine
    RenderResult seams = adaptive(*c.rs, w, h, noContrast);
    int64_t examinedSeams = w * h - seams.pixelsBySamples[0] + seams.checkedPixels;
    EXPECT_LT(examinedSeams, w * h);
    EXPECT_GT(examinedSeams, contrasted / 4);
    EXPECT_GT(w * h - seams.pixelsBySamples[0], 0);
}

// The decisions compare display values in 1/255 steps; the inline rounding must be std::lround's
// at every step's halfway point and its neighbours, and everywhere else
TEST(AdaptiveRender, DisplayStepRoundsAsLround) {
    auto expectLround = [](double d) {
        ASSERT_EQ(int(displayStep(d)), int(std::lround(d * 255))) << "display value " << d;
    };
    for (int k = 0; k <= 255; ++k)
        for (double base : {double(k) / 255, (k + 0.5) / 255}) {
            double d = base;
            for (int i = 0; i < 64 && d <= 1; ++i, d = std::nextafter(d, 2.0)) expectLround(d);
            d = base;
            for (int i = 0; i < 64 && d >= 0; ++i, d = std::nextafter(d, -1.0))
                if (d <= 1) expectLround(d);
        }
    uint64_t state = 12345;
    for (int i = 0; i < 1000000; ++i) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        expectLround(double(state >> 11) * 0x1.0p-53);
    }
    EXPECT_EQ(displayStep(std::nan("")), 0);
    EXPECT_EQ(displayStep(0.5 / 255), 1);
    EXPECT_EQ(displayStep(1), 255);
}

// The adaptive pass tells primitives apart by their index in the compiled scene, which every
// process (every tile) gives them alike, where a hash of their addresses could differ between
// processes and could collide: every leaf has its own index, from 1.
TEST(AdaptiveRender, EveryLeafHasItsOwnSceneIndex) {
    Compiled c = loadScene("print_plate.scad");
    std::vector<uint32_t> seen;
    for (const auto &o : c.rs->objects()) {
        if (const auto *csg = dynamic_cast<const CsgShape *>(o.get())) {
            for (const auto &l : csg->leaves()) seen.push_back(l->sceneIndex);
        } else {
            seen.push_back(static_cast<const LeafShape &>(*o).sceneIndex);
        }
    }
    std::sort(seen.begin(), seen.end());
    ASSERT_GT(seen.size(), 100u);
    for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], i + 1);
}

TEST(AdaptiveRender, OptionsAreValidated) {
    RenderOptions o;
    o.adaptive = true;
    EXPECT_NO_THROW(validateRenderOptions(o));
    for (int max : {4, 16, 256, kMaxAdaptiveSamples}) {
        o.adaptiveMax = max;
        EXPECT_NO_THROW(validateRenderOptions(o)) << max;
    }
    for (int max : {0, 1, 2, 8, 32, 100, kMaxAdaptiveSamples * 4}) {
        o.adaptiveMax = max;
        EXPECT_THROW(validateRenderOptions(o), std::invalid_argument) << max;
    }
    o.adaptiveMax = 64;
    o.adaptiveThreshold = -1;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.adaptiveThreshold = 0.1;
    o.adaptiveTolerance = std::nan("");
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.adaptiveTolerance = 0.1;
    o.batches = 2;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
}

TEST(AdaptiveRender, PlanChoosesAdaptiveForSharpScenesAndSaysWhereSamplesWent) {
    Compiled sharp = loadScene("lecture_csg.scad");
    RenderPlan plan = makePlan(*sharp.rs);
    EXPECT_TRUE(plan.adaptive);
    RenderOptions o;
    o.adaptive = true;
    std::string text = describePlan(*sharp.rs, sharp.scene.stats, plan, o, true);
    EXPECT_NE(text.find("samples: adaptive, each pixel's centre; where a neighbour differs"),
              std::string::npos);
    EXPECT_NE(text.find("then 4, 16 ... up to 64 stratified samples"), std::string::npos) << text;
    RenderResult r = adaptive(*sharp.rs, 32, 24);
    std::string where = describeSampling(r);
    EXPECT_EQ(where.rfind("adaptive, pixels by samples: 1: ", 0), 0u) << where;
    EXPECT_NE(where.find(", 64: "), std::string::npos) << where;
    EXPECT_NE(where.find(" per pixel"), std::string::npos) << where;
    EXPECT_EQ(describeSampling(uniform(*sharp.rs, 8, 6, 4)), "4.00 per pixel");
    // Monte Carlo scenes keep uniform sampling
    Compiled mc = loadScene("montecarlo/glossy.scad");
    EXPECT_FALSE(makePlan(*mc.rs).adaptive);
    o.adaptiveNoise = true;
    o.adaptiveTolerance = kAdaptiveNoiseTolerance;
    text = describePlan(*mc.rs, mc.scene.stats, makePlan(*mc.rs), o, false);
    EXPECT_NE(
        text.find(
            "samples: adaptive to Monte Carlo noise, every pixel 4, 16 ... up to 64 stratified "
            "samples until the standard error is below 0.02 (given)"),
        std::string::npos)
        << text;
}

// Sampling adaptive to Monte Carlo noise: every pixel starts from the 4 cells of round 1 and
// goes on while its error estimate is above the tolerance; the samples are uniform sampling's
TEST(AdaptiveRender, NoiseModeRefinesEveryPixelFromFourSamplesWithUniformSamplingsSamples) {
    Compiled c = loadScene("montecarlo/glossy.scad");
    const int w = 32, h = 24;
    RenderOptions o;
    o.adaptiveNoise = true;
    o.adaptiveMax = 16;
    o.adaptiveTolerance = 0;  // every pixel to the maximum: exactly uniform 16
    RenderResult all = adaptive(*c.rs, w, h, o), sixteen = uniform(*c.rs, w, h, 16);
    EXPECT_TRUE(samePixels(all.image, sixteen.image));
    EXPECT_EQ(all.samples, int64_t(w) * h * 16);
    EXPECT_EQ(all.pixelsBySamples[2], int64_t(w) * h);
    // At the noise tolerance pixels stop at 4 where the estimate allows and go on where not;
    // each is the mean of 4 stratified samples or exactly uniform 16's pixel
    o.adaptiveTolerance = kAdaptiveNoiseTolerance;
    RenderResult a = adaptive(*c.rs, w, h, o);
    EXPECT_EQ(a.pixelsBySamples[0], 0);
    EXPECT_GT(a.pixelsBySamples[1], 0);
    EXPECT_GT(a.pixelsBySamples[2], 0);
    EXPECT_EQ(a.pixelsBySamples[1] + a.pixelsBySamples[2], int64_t(w) * h);
    EXPECT_EQ(a.samples, a.pixelsBySamples[1] * 4 + a.pixelsBySamples[2] * 16);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (a.pixelLevels[size_t(y) * w + x] == 2) {
                EXPECT_TRUE(a.image.at(x, y) == sixteen.image.at(x, y));
            }
    EXPECT_EQ(describeSampling(a).rfind("adaptive, pixels by samples: 4: ", 0), 0u)
        << describeSampling(a);
    // The same picture for any thread count and tile size
    for (auto [threads, tile] : {std::pair{1, 16}, std::pair{3, 5}}) {
        o.threads = threads;
        o.tileSize = tile;
        RenderResult r = adaptive(*c.rs, w, h, o);
        EXPECT_TRUE(samePixels(a.image, r.image)) << threads << " threads, tile " << tile;
        EXPECT_EQ(a.pixelLevels, r.pixelLevels);
    }
}

}  // namespace
}  // namespace rt
