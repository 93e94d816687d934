// SPDX-License-Identifier: MIT
// Geometry pass (closest hits at pixel centres, rows shared among threads) and the masked
// per-pixel comparison of two geometry buffers.
#include "core/render/geometry_buffer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "core/camera/camera.h"
#include "core/system/large_stack.h"

namespace rt {

GeometryBuffer renderGeometry(const RenderScene &scene, int width, int height, int threads) {
    if (width < 1 || height < 1)
        throw std::invalid_argument("geometry buffer size must be positive");
    Camera camera(scene.camera(), width, height);
    GeometryBuffer buf;
    buf.width = width;
    buf.height = height;
    buf.samples.resize(size_t(width) * height);
    int n =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    n = std::min(n, height);
    std::atomic<int> nextRow{0};
    auto worker = [&]() {
        SpanScratch scratch;
        for (int y; (y = nextRow.fetch_add(1)) < height;)
            for (int x = 0; x < width; ++x) {
                Ray ray = camera.generateRay(x + 0.5, y + 0.5);
                SurfaceInteraction si;
                GeometrySample &s = buf.samples[size_t(y) * width + x];
                if (scene.intersect(ray, 0, kInfinity, &si, scratch)) {
                    // Camera rays are unit length, so t is the distance
                    s.depth = si.t;
                    s.point = ray.o + ray.d * si.t;
                    s.direction = ray.d;
                    s.normal = faceForward(si.n, -ray.d);
                }
                s.tie = si.tie;
            }
    };
    std::vector<std::unique_ptr<StackThread>> pool;
    for (int i = 0; i < n; ++i)
        pool.push_back(std::make_unique<StackThread>(kWorkerStackBytes, worker));
    for (auto &t : pool) t->join();
    return buf;
}

Image normalImage(const GeometryBuffer &g) {
    Image img(g.width, g.height);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const GeometrySample &s = g.at(x, y);
            if (s.hit()) {
                Vec3 c = s.normal * 0.5 + Vec3(0.5);
                img.set(x, y, Rgb(c.x, c.y, c.z));
            }
        }
    return img;
}

namespace {

constexpr double kDegrees = 180 / M_PI;

double angleDegrees(const Vec3 &a, const Vec3 &b) {
    return std::atan2(length(cross(a, b)), dot(a, b)) * kDegrees;
}

double relativeDepth(const GeometrySample &a, const GeometrySample &ref) {
    return std::abs(a.depth - ref.depth) / ref.depth;
}

bool agrees(const GeometrySample &a, const GeometrySample &b, const GeometryTolerances &tol) {
    return a.hit() && b.hit() && relativeDepth(a, b) <= tol.depthRel &&
           angleDegrees(a.normal, b.normal) <= tol.normalDegrees;
}

/// A neighbour that differs in hit/miss or whose depth jumps.
bool silhouetteAt(const GeometryBuffer &g, int x, int y, const GeometryTolerances &tol) {
    const GeometrySample &p = g.at(x, y);
    for (int j = std::max(0, y - 1); j <= std::min(g.height - 1, y + 1); ++j)
        for (int i = std::max(0, x - 1); i <= std::min(g.width - 1, x + 1); ++i) {
            const GeometrySample &q = g.at(i, j);
            if (p.hit() != q.hit()) return true;
            if (!p.hit()) continue;
            // Split the step to the neighbour's hit into along and across p's ray
            Vec3 step = q.point - p.point;
            double along = dot(step, p.direction);
            double across = length(step - p.direction * along);
            if (std::abs(along) > tol.jumpSlope * across) return true;
        }
    return false;
}

/// `a` matches `other`'s sample at (x, y) or at one of its neighbours.
bool matchesNear(const GeometrySample &a, const GeometryBuffer &other, int x, int y,
                 const GeometryTolerances &tol) {
    for (int j = std::max(0, y - 1); j <= std::min(other.height - 1, y + 1); ++j)
        for (int i = std::max(0, x - 1); i <= std::min(other.width - 1, x + 1); ++i)
            if (agrees(a, other.at(i, j), tol)) return true;
    return false;
}

}  // namespace

GeometryCompareResult compareGeometry(const GeometryBuffer &test, const GeometryBuffer &ref,
                                      const GeometryTolerances &tol) {
    if (test.width != ref.width || test.height != ref.height || test.samples.empty())
        throw std::invalid_argument("geometry buffers differ in size or are empty");
    GeometryCompareResult r;
    int w = ref.width, h = ref.height;
    r.width = w;
    r.height = h;
    r.heatMap = Image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const GeometrySample &a = test.at(x, y), &b = ref.at(x, y);
            // Context: the reference lit by a headlight
            double grey = b.hit() ? 0.15 + 0.35 * std::abs(b.normal.z * 0.5 + 0.5) : 0.05;
            Rgb out(grey);
            if (!a.hit() && !b.hit()) {
                ++r.bothMiss;
            } else if (silhouetteAt(test, x, y, tol) || silhouetteAt(ref, x, y, tol)) {
                ++r.silhouette;
                out = Rgb(grey, grey, grey + 0.35);
            } else if (a.tie || b.tie) {
                ++r.tied;
                out = Rgb(grey, grey, grey + 0.35);
            } else if (a.hit() != b.hit()) {
                ++r.coverageDiffer;
                out = Rgb(1, 0, 1);
            } else {
                double dRel = relativeDepth(a, b), angle = angleDegrees(a.normal, b.normal);
                r.maxDepthRel = std::max(r.maxDepthRel, dRel);
                r.maxNormalDegrees = std::max(r.maxNormalDegrees, angle);
                if (matchesNear(a, ref, x, y, tol) && matchesNear(b, test, x, y, tol)) {
                    ++r.agreeing;
                } else if (dRel > tol.depthRel) {
                    ++r.depthDiffer;
                    out = Rgb(1, 0, 0);
                } else {
                    ++r.normalDiffer;
                    out = Rgb(1, 1, 0);
                }
            }
            r.heatMap.set(x, y, out);
        }
    r.pass = r.differing() <= tol.maxDiffering;
    return r;
}

std::string GeometryCompareResult::summary(const GeometryTolerances &tol) const {
    char buf[512];
    std::string s;
    long total = long(width) * height;
    std::snprintf(buf, sizeof buf,
                  "geometry: %ld of %ld pixels differ (coverage %ld, depth %ld, normal %ld; "
                  "tolerances depth %g relative, normal %g deg; pass with at most %ld)\n",
                  differing(), total, coverageDiffer, depthDiffer, normalDiffer, tol.depthRel,
                  tol.normalDegrees, tol.maxDiffering);
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "agreeing hits %ld, background in both %ld; worst at the same pixel: depth %.3g "
                  "relative, normal %.3g deg\n",
                  agreeing, bothMiss, maxDepthRel, maxNormalDegrees);
    s += buf;
    std::snprintf(buf, sizeof buf,
                  "masked: %ld silhouette pixels (%.1f%%), %ld tie pixels (coincident surfaces)\n",
                  silhouette, 100.0 * silhouette / std::max(1L, total), tied);
    s += buf;
    return s;
}

}  // namespace rt
