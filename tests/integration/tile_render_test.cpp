// SPDX-License-Identifier: MIT
// Rendering a picture in horizontal bands (`render --tile`): every band's pixels,
// ties and adaptive levels are bit for bit those of the whole picture, for uniform sampling,
// sampling adaptive to edges (whose decisions read the neighbours' centres across a band's
// border) and sampling adaptive to Monte Carlo noise.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "core/render/renderer.h"
#include "integration/render_test_support.h"

namespace rt {
namespace {

using test::Compiled;
using test::loadScene;
using test::options;

/// Whether rows [begin, begin + band.height()) of `whole` are `band`, bit for bit.
bool sameRows(const Image &whole, const Image &band, int begin) {
    if (band.width() != whole.width()) return false;
    size_t offset = 3 * size_t(begin) * whole.width();
    return std::memcmp(whole.data().data() + offset, band.data().data(),
                       band.data().size() * sizeof(float)) == 0;
}

/// Renders `o` whole and in `tiles` bands; every band must match its rows of the whole.
void expectBandsMatch(const RenderScene &rs, RenderOptions o, int tiles) {
    RenderResult whole = renderImage(rs, o);
    int64_t samples = 0;
    for (int k = 0; k < tiles; ++k) {
        SCOPED_TRACE("tile " + std::to_string(k + 1) + " of " + std::to_string(tiles));
        RenderOptions bo = o;
        std::tie(bo.rowBegin, bo.rowEnd) = tileRows(k, tiles, o.height);
        RenderResult band = renderImage(rs, bo);
        ASSERT_EQ(band.image.height(), bo.rowEnd - bo.rowBegin);
        EXPECT_TRUE(sameRows(whole.image, band.image, bo.rowBegin));
        EXPECT_TRUE(sameRows(whole.ties, band.ties, bo.rowBegin));
        if (o.adaptive) {
            size_t offset = size_t(bo.rowBegin) * o.width;
            ASSERT_EQ(band.pixelLevels.size(), size_t(o.width) * band.image.height());
            EXPECT_TRUE(std::equal(band.pixelLevels.begin(), band.pixelLevels.end(),
                                   whole.pixelLevels.begin() + offset));
            EXPECT_TRUE(std::equal(band.pixelChecked.begin(), band.pixelChecked.end(),
                                   whole.pixelChecked.begin() + offset));
        }
        samples += band.samples;
    }
    // The bands' samples add up to the picture's (a band's bordering centres are not counted)
    EXPECT_EQ(samples, whole.samples);
}

TEST(TileRender, RowsOfTilesPartitionThePicture) {
    for (int height : {1, 7, 61}) {
        for (int tiles = 1; tiles <= height && tiles <= 9; ++tiles) {
            int next = 0;
            for (int k = 0; k < tiles; ++k) {
                auto [begin, end] = tileRows(k, tiles, height);
                EXPECT_EQ(begin, next);
                EXPECT_GE(end - begin, height / tiles);
                EXPECT_LE(end - begin, height / tiles + 1);
                next = end;
            }
            EXPECT_EQ(next, height);
        }
    }
    EXPECT_THROW(tileRows(0, 8, 7), std::invalid_argument);
    EXPECT_THROW(tileRows(3, 3, 7), std::invalid_argument);
    EXPECT_THROW(tileRows(-1, 3, 7), std::invalid_argument);
    RenderOptions o = options(8, 8);
    o.rowBegin = 4;
    o.rowEnd = 4;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
    o.rowEnd = 9;
    EXPECT_THROW(validateRenderOptions(o), std::invalid_argument);
}

TEST(TileRender, AdaptiveEdgeBandsAreTheWholePicturesRows) {
    // Sharp scene, the default sampling: edge-adaptive decisions at every band border
    Compiled c = loadScene("default.scad");
    RenderOptions o = options(53, 37);
    o.adaptive = true;
    for (int tiles : {1, 3, 7}) expectBandsMatch(*c.rs, o, tiles);
}

TEST(TileRender, UniformBandsAreTheWholePicturesRows) {
    Compiled c = loadScene("default.scad");
    RenderOptions o = options(41, 29);
    o.samplesPerPixel = 4;
    for (int tiles : {1, 3, 7}) expectBandsMatch(*c.rs, o, tiles);
    // With batches: the variance of each band is the whole picture's too
    o.batches = 3;
    RenderResult whole = renderImage(*c.rs, o);
    RenderOptions bo = o;
    std::tie(bo.rowBegin, bo.rowEnd) = tileRows(1, 3, o.height);
    RenderResult band = renderImage(*c.rs, bo);
    EXPECT_TRUE(sameRows(whole.variance, band.variance, bo.rowBegin));
}

TEST(TileRender, AdaptiveNoiseBandsAreTheWholePicturesRows) {
    // Monte Carlo scene: glossy reflection, sampling adaptive to its noise
    Compiled c = loadScene("montecarlo/glossy.scad");
    RenderOptions o = options(37, 23);
    o.adaptive = true;
    o.adaptiveNoise = true;
    o.adaptiveMax = 16;
    o.adaptiveTolerance = kAdaptiveNoiseTolerance;
    for (int tiles : {1, 3, 7}) expectBandsMatch(*c.rs, o, tiles);
}

}  // namespace
}  // namespace rt
