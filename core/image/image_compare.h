// SPDX-License-Identifier: MIT
// Statistical comparison of a rendered image with a reference (docs/design/conventions.md,
// "Comparing images"): per-tile t-tests of the mean difference, Benjamini-Hochberg control of
// false alarms across tiles and channels, an equivalence margin, and masks for silhouettes and
// coplanar faces.
#pragma once

#include <string>
#include <vector>

#include "core/image/image.h"

namespace rt {

struct CompareOptions {
    int tileSize = 8;
    /// False-alarm rate: with no real difference anywhere, the chance of declaring one.
    double alpha = 0.01;
    /// A tile fails only when its mean differs by more than max(marginAbs, marginRel * ref).
    double marginAbs = 0.002;
    double marginRel = 0.01;
    /// A reference pixel whose sub-samples spread more than this (any channel) is on an edge:
    /// a silhouette, a shadow boundary or coplanar speckle. It and its 8 neighbours are masked.
    double edgeSpread = 0.05;
    /// Tiles with fewer unmasked pixels than this are not tested.
    int minPixelsPerTile = 16;
    /// Both images are clamped to [0, clampMax] first (8/16-bit references clip at 1).
    double clampMax = 1.0;
    /// Deterministic comparisons (no variance on either side): a pixel differing by more than
    /// this fails, after a 1-pixel erosion that forgives isolated pixels and thin lines.
    double pixelThreshold = 0.05;
};

struct TileTest {
    int x = 0, y = 0, channel = 0;  ///< tile position in tiles
    int pixels = 0;
    double reference = 0, difference = 0, standardError = 0, pValue = 1;
    bool significant = false, failed = false;
};

struct CompareResult {
    bool pass = true;
    int width = 0, height = 0;
    // Unmasked pixels
    double rmse = 0, psnr = 0, maxError = 0;
    int maxX = 0, maxY = 0;
    long comparedPixels = 0;
    // Masked pixels (silhouettes, shadow edges, coplanar faces), counted separately
    long maskedPixels = 0;
    double maskedRmse = 0;
    // Tile tests
    int tilesTested = 0, tilesSkipped = 0, tilesFailed = 0;
    std::vector<TileTest> failures;
    /// The smallest mean difference a tile test could have flagged, median and 95th percentile
    /// over tested tiles: max(margin, critical t * standard error).
    double detectableMedian = 0, detectableP95 = 0;
    /// Deterministic mode: pixels beyond pixelThreshold that survive erosion.
    long failedPixels = 0;
    bool deterministic = false;
    /// Grey reference, difference in red-yellow, masked pixels blue, failed tiles magenta.
    Image heatMap;

    std::string summary(const CompareOptions &o) const;
};

/// Spread of each k x k block of a supersampled `fine` image (and the ring of sub-samples
/// around it) about the block's least-squares plane, per channel: near 0 where the picture
/// varies smoothly at the sub-sample scale (shading, a magnified bilinear texture: the
/// block's mean is then the pixel's mean), large at steps and thin lines (silhouettes, texel
/// edges, texture detail smaller than a pixel), where the k x k grid misses the pixel's mean.
Image planeResidualSpread(const Image &fine, int k);

/// Compares `test` with `reference` (same size, else std::invalid_argument). Statistics use
/// test.variance when present (independent pixels: tile variance is the sum of pixel variances
/// over n^2, degrees of freedom by Welch-Satterthwaite from the batch count); otherwise the
/// comparison is deterministic. Masks come from reference.spread, or when it is absent from
/// the reference's 3x3 neighbourhood range, plus every pixel whose samples met coincident
/// surfaces in either image (ImageEstimate::ties).
CompareResult compareImages(const ImageEstimate &test, const ImageEstimate &reference,
                            const CompareOptions &opts = {});

}  // namespace rt
