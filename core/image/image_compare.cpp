// SPDX-License-Identifier: MIT
// Tile t-tests with Benjamini-Hochberg, equivalence margins, masks and the heat map.
#include "core/image/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/math/statistics.h"

namespace rt {

namespace {

double clampValue(double v, double hi) {
    if (!std::isfinite(v)) return v;
    return std::clamp(v, 0.0, hi);
}

/// Marks pixels on edges (large sub-sample spread, or a large 3x3 range when the spread is
/// unknown) and pixels where either image met coincident surfaces, and dilates the mark by one
/// pixel.
std::vector<char> edgeMask(const ImageEstimate &test, const ImageEstimate &ref,
                           const CompareOptions &o) {
    int w = ref.mean.width(), h = ref.mean.height();
    std::vector<char> edge(size_t(w) * h, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double range = 0;
            if (!ref.spread.empty()) {
                range = ref.spread.at(x, y).maxComponent();
            } else {
                Rgb lo(1e300), hi(-1e300);
                for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1); ++j)
                    for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1); ++i) {
                        Rgb c = ref.mean.at(i, j);
                        for (int ch = 0; ch < 3; ++ch) {
                            lo[ch] = std::min(lo[ch], clampValue(c[ch], o.clampMax));
                            hi[ch] = std::max(hi[ch], clampValue(c[ch], o.clampMax));
                        }
                    }
                range = (hi - lo).maxComponent();
            }
            bool tied = (!test.ties.empty() && test.ties.at(x, y).r > 0) ||
                        (!ref.ties.empty() && ref.ties.at(x, y).r > 0);
            edge[size_t(y) * w + x] = range > o.edgeSpread || tied;
        }
    std::vector<char> mask(edge.size(), 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!edge[size_t(y) * w + x]) continue;
            for (int j = std::max(0, y - 1); j <= std::min(h - 1, y + 1); ++j)
                for (int i = std::max(0, x - 1); i <= std::min(w - 1, x + 1); ++i)
                    mask[size_t(j) * w + i] = 1;
        }
    return mask;
}

/// Red-yellow ramp for a difference relative to `scale`.
Rgb heat(double d, double scale) {
    double t = std::clamp(d / scale, 0.0, 1.0);
    return {std::min(1.0, 2 * t), std::max(0.0, 2 * t - 1), 0};
}

}  // namespace

Image planeResidualSpread(const Image &fine, int k) {
    int w = fine.width() / k, h = fine.height() / k;
    Image out(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            // The block and the ring of sub-samples around it, as downsample's spread
            int j0 = std::max(0, y * k - 1), j1 = std::min(fine.height() - 1, y * k + k);
            int i0 = std::max(0, x * k - 1), i1 = std::min(fine.width() - 1, x * k + k);
            double n = 0, si = 0, sj = 0, sii = 0, sjj = 0;
            Rgb sc(0), sci(0), scj(0);
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    Rgb c = fine.at(i, j);
                    n += 1;
                    si += i;
                    sj += j;
                    sii += double(i) * i;
                    sjj += double(j) * j;
                    sc += c;
                    sci += c * double(i);
                    scj += c * double(j);
                }
            // Least squares over a rectangle of samples: the two slopes are independent
            double mi = si / n, mj = sj / n;
            double vii = sii - n * mi * mi, vjj = sjj - n * mj * mj;
            Rgb mc = sc / n;
            Rgb gi = vii > 0 ? (sci - mc * si) / vii : Rgb(0);
            Rgb gj = vjj > 0 ? (scj - mc * sj) / vjj : Rgb(0);
            double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    Rgb c = fine.at(i, j);
                    for (int ch = 0; ch < 3; ++ch) {
                        double r = c[ch] - (mc[ch] + gi[ch] * (i - mi) + gj[ch] * (j - mj));
                        lo[ch] = std::min(lo[ch], r);
                        hi[ch] = std::max(hi[ch], r);
                    }
                }
            out.set(x, y, Rgb(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
        }
    return out;
}

CompareResult compareImages(const ImageEstimate &test, const ImageEstimate &reference,
                            const CompareOptions &o) {
    const Image &a = test.mean, &b = reference.mean;
    if (a.empty() || b.empty()) throw std::invalid_argument("cannot compare an empty image");
    if (a.width() != b.width() || a.height() != b.height())
        throw std::invalid_argument("images differ in size: " + std::to_string(a.width()) + "x" +
                                    std::to_string(a.height()) + " and " +
                                    std::to_string(b.width()) + "x" + std::to_string(b.height()));
    if (o.tileSize < 1 || !(o.alpha > 0 && o.alpha < 1))
        throw std::invalid_argument("tile size must be positive and alpha in (0, 1)");
    int w = a.width(), h = a.height();
    bool haveVariance = !test.variance.empty() && test.batches > 1 && test.variance.width() == w &&
                        test.variance.height() == h;
    CompareResult r;
    r.width = w;
    r.height = h;
    r.deterministic = !haveVariance;
    std::vector<char> mask = edgeMask(test, reference, o);

    // Pixel metrics
    double sumSq = 0, maskedSq = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rgb p = a.at(x, y), q = b.at(x, y);
            double worst = 0, sq = 0;
            for (int c = 0; c < 3; ++c) {
                double d = clampValue(p[c], o.clampMax) - clampValue(q[c], o.clampMax);
                if (!std::isfinite(d)) d = o.clampMax;  // a NaN pixel is as wrong as can be
                worst = std::max(worst, std::abs(d));
                sq += d * d;
            }
            if (mask[size_t(y) * w + x]) {
                ++r.maskedPixels;
                maskedSq += sq;
                continue;
            }
            ++r.comparedPixels;
            sumSq += sq;
            if (worst > r.maxError) {
                r.maxError = worst;
                r.maxX = x;
                r.maxY = y;
            }
        }
    r.rmse = r.comparedPixels ? std::sqrt(sumSq / (3.0 * r.comparedPixels)) : 0;
    r.maskedRmse = r.maskedPixels ? std::sqrt(maskedSq / (3.0 * r.maskedPixels)) : 0;
    r.psnr =
        r.rmse > 0 ? 20 * std::log10(o.clampMax / r.rmse) : std::numeric_limits<double>::infinity();

    // Tile tests of the mean difference per channel
    std::vector<TileTest> tests;
    std::vector<double> pValues, dofs;
    int tilesX = (w + o.tileSize - 1) / o.tileSize, tilesY = (h + o.tileSize - 1) / o.tileSize;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx) {
            for (int c = 0; c < 3; ++c) {
                TileTest t;
                t.x = tx;
                t.y = ty;
                t.channel = c;
                double sumA = 0, sumB = 0, sumVar = 0, sumVar2 = 0;
                for (int y = ty * o.tileSize; y < std::min(h, (ty + 1) * o.tileSize); ++y)
                    for (int x = tx * o.tileSize; x < std::min(w, (tx + 1) * o.tileSize); ++x) {
                        if (mask[size_t(y) * w + x]) continue;
                        ++t.pixels;
                        sumA += clampValue(a.at(x, y)[c], o.clampMax);
                        sumB += clampValue(b.at(x, y)[c], o.clampMax);
                        if (haveVariance) {
                            double v = std::max(0.0, double(test.variance.at(x, y)[c]));
                            sumVar += v;
                            sumVar2 += v * v;
                        }
                    }
                if (t.pixels < o.minPixelsPerTile) {
                    if (c == 0) ++r.tilesSkipped;
                    continue;
                }
                double n = t.pixels;
                t.reference = sumB / n;
                t.difference = (sumA - sumB) / n;
                t.standardError = std::sqrt(sumVar) / n;
                double dof = std::numeric_limits<double>::infinity();
                if (haveVariance && sumVar2 > 0)
                    dof = (sumVar * sumVar) / (sumVar2 / (test.batches - 1));  // Satterthwaite
                if (!std::isfinite(t.difference))
                    t.pValue = 0;  // NaN or Inf pixels: certainly different
                else if (t.standardError > 0)
                    t.pValue = twoSidedPValue(t.difference / t.standardError, dof);
                else
                    t.pValue = t.difference != 0 ? 0 : 1;
                tests.push_back(t);
                pValues.push_back(t.pValue);
                dofs.push_back(dof);
            }
        }
    r.tilesTested = static_cast<int>(tests.size() / 3);
    std::vector<bool> significant = benjaminiHochberg(pValues, o.alpha);
    std::vector<double> detectable;
    double m = std::max<double>(1, tests.size());
    std::vector<char> tileFailed(size_t(tilesX) * tilesY, 0);
    for (size_t i = 0; i < tests.size(); ++i) {
        TileTest &t = tests[i];
        double margin = std::max(o.marginAbs, o.marginRel * std::abs(t.reference));
        t.significant = significant[i];
        t.failed = t.significant && !(std::abs(t.difference) <= margin);
        // Bonferroni's critical value: what BH needs of a single isolated difference
        double crit = std::isinf(dofs[i]) ? studentTQuantile(1 - o.alpha / (2 * m), 1e9)
                                          : studentTQuantile(1 - o.alpha / (2 * m), dofs[i]);
        detectable.push_back(std::max(margin, crit * t.standardError));
        if (t.failed) {
            r.failures.push_back(t);
            tileFailed[size_t(t.y) * tilesX + t.x] = 1;
        }
    }
    r.tilesFailed = static_cast<int>(std::count(tileFailed.begin(), tileFailed.end(), 1));
    if (!detectable.empty()) {
        std::sort(detectable.begin(), detectable.end());
        r.detectableMedian = detectable[detectable.size() / 2];
        r.detectableP95 = detectable[std::min(detectable.size() - 1, detectable.size() * 95 / 100)];
    }

    // Deterministic images: large single-pixel differences, forgiving isolated ones
    std::vector<char> bad(size_t(w) * h, 0);
    if (r.deterministic) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                if (mask[size_t(y) * w + x]) continue;
                Rgb p = a.at(x, y), q = b.at(x, y);
                for (int c = 0; c < 3; ++c) {
                    double d = clampValue(p[c], o.clampMax) - clampValue(q[c], o.clampMax);
                    if (!(std::abs(d) <= o.pixelThreshold)) bad[size_t(y) * w + x] = 1;
                }
            }
        for (int y = 1; y + 1 < h; ++y)
            for (int x = 1; x + 1 < w; ++x) {
                size_t i = size_t(y) * w + x;
                if (bad[i] && bad[i - 1] && bad[i + 1] && bad[i - w] && bad[i + w])
                    ++r.failedPixels;
            }
    }
    r.pass = r.tilesFailed == 0 && r.failedPixels == 0;

    // Heat map
    double scale = 10 * o.marginAbs;
    r.heatMap = Image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rgb q = b.at(x, y);
            double grey = 0.25 * std::clamp((q.r + q.g + q.b) / 3, 0.0, 1.0);
            Rgb p = a.at(x, y);
            double d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d,
                             std::abs(clampValue(p[c], o.clampMax) - clampValue(q[c], o.clampMax)));
            Rgb out = Rgb(grey) + heat(d, scale) * 0.75;
            if (mask[size_t(y) * w + x]) out = Rgb(grey, grey, grey + 0.35);
            int tx = x / o.tileSize, ty = y / o.tileSize;
            bool border = x % o.tileSize == 0 || y % o.tileSize == 0 ||
                          x % o.tileSize == o.tileSize - 1 || y % o.tileSize == o.tileSize - 1;
            if (tileFailed[size_t(ty) * tilesX + tx] && border) out = Rgb(1, 0, 1);
            r.heatMap.set(x, y, out);
        }
    return r;
}

std::string CompareResult::summary(const CompareOptions &o) const {
    char buf[1024];
    std::string s;
    std::snprintf(buf, sizeof buf,
                  "error: RMSE %.3g, PSNR %.1f dB, max %.3g at (%d, %d) over %ld pixels\n", rmse,
                  psnr, maxError, maxX, maxY, comparedPixels);
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "tiles: %d of %dx%d tested (x3 channels, %s), %d skipped, %d failed "
                  "(alpha %g with Benjamini-Hochberg; margin max(%g, %g%% of reference))\n",
                  tilesTested, o.tileSize, o.tileSize,
                  deterministic ? "deterministic" : "t-tests on batch variance", tilesSkipped,
                  tilesFailed, o.alpha, o.marginAbs, 100 * o.marginRel);
    s += buf;
    std::snprintf(buf, sizeof buf, "smallest detectable tile bias: median %.3g, 95%% %.3g\n",
                  detectableMedian, detectableP95);
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "masked: %ld pixels (%.1f%%) on silhouettes, shadow edges and coplanar faces, "
                  "RMSE there %.3g\n",
                  maskedPixels, 100.0 * maskedPixels / std::max(1, width * height), maskedRmse);
    s += buf;
    if (deterministic) {
        std::snprintf(buf, sizeof buf, "pixels beyond %g after 1-pixel erosion: %ld\n",
                      o.pixelThreshold, failedPixels);
        s += buf;
    }
    for (size_t i = 0; i < failures.size() && i < 5; ++i) {
        const TileTest &t = failures[i];
        std::snprintf(
            buf, sizeof buf,
            "  failed tile (%d, %d) %c: reference %.4g, difference %+.4g, SE %.2g, p %.2g\n",
            t.x * o.tileSize, t.y * o.tileSize, "RGB"[t.channel], t.reference, t.difference,
            t.standardError, t.pValue);
        s += buf;
    }
    return s;
}

}  // namespace rt
