// SPDX-License-Identifier: MIT
// Bounding volume hierarchy over world bounds: binned build (Wald 2007; pbrt-v3 section 4.3.2)
// by surface area and volume (kVolumeWeight), flattened depth-first nodes, front-to-back
// traversal with a caller-supplied visitor.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "core/math/bounds3.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SCADRAY_LANE_SLABS 1
#define SCADRAY_LANES_TARGET __attribute__((target("avx2")))
#else
#define SCADRAY_LANE_SLABS 0
#endif

namespace rt {

class Bvh {
  public:
    struct Node {
        Bounds3 bounds;
        uint32_t offset = 0;  ///< leaf: first entry of itemOrder(); interior: second child
        uint32_t count = 0;   ///< items in a leaf; 0 for an interior node
        uint8_t axis = 0;     ///< split axis of an interior node
    };

    static constexpr int kBins = 16;
    static constexpr int kMaxLeafItems = 4;
    /// The build weighs a child's chance of being visited by its share of its parent's surface
    /// area (the SAH: rays from outside, uniformly spread) and, as much, by its share of the
    /// parent's volume: most rays of a ray tracer (shadow rays, reflected and refracted ones)
    /// start on a surface inside the scene, and a box that holds the origin is always visited.
    /// SAH alone splits a floor of tiles with the objects on it into strips, each with its
    /// objects, so every shadow ray from a tile walks the strip; with the volume term the
    /// floor and the objects are split apart, and a shadow ray from the floor leaves the
    /// floor's flat box at once (glass.scad and default.scad: 6.5 % fewer instructions,
    /// mirrors.scad 5.7 %; README). A flat or unbounded node is weighed by its area alone.
    static constexpr double kVolumeWeight = 0.5;

    Bvh() = default;
    struct RaySlabs;
#if SCADRAY_LANE_SLABS
    struct LaneSlabs;
#endif
    explicit Bvh(const std::vector<Bounds3> &itemBounds);

    const std::vector<Node> &nodes() const { return nodes_; }
    /// Item indices in leaf order.
    const std::vector<uint32_t> &itemOrder() const { return order_; }
    bool empty() const { return nodes_.empty(); }
    int depth() const { return depth_; }

    /// Visits the items whose leaves the ray reaches within [tMin, *tMax], nearest nodes first.
    /// visit(itemIndex, tMax) tests one item; it may lower *tMax (closest hit) and returns true to
    /// stop the traversal (any hit).
    template <typename Visit>
    void traverse(const Ray &ray, double tMin, double *tMax, Visit &&visit) const {
        traverseWith(RaySlabs(ray), tMin, tMax, visit);
    }
    /// traverse() with the node test of `Slabs`: RaySlabs (one plane at a time) or LaneSlabs
    /// (the three axes side by side), which visit the same items in the same order. The
    /// caller builds them, so it can share the ray's reciprocal direction with its visitor.
    template <typename Slabs, typename Visit>
    void traverseWith(const Slabs &slabs, double tMin, double *tMax, Visit &&visit) const;

    /// The leaves, in the order traverse() meets them for rays of `octant` (bit a set where the
    /// direction's component on axis a is negative, as its reciprocal is), of the subtrees
    /// whose boxes `keep(bounds)` accepts (a conservative cull: VistaLists).
    template <typename Keep>
    void collectLeaves(int octant, Keep &&keep, std::vector<uint32_t> &leaves) const;

    /// The visits traverse() makes, for a ray that can reach no leaf but `leaves` (node indices
    /// from collectLeaves() for the ray's octant, a superset of the leaves whose boxes the ray
    /// meets). Each leaf's box is tested with the ray's tMax of the moment, as traverse() tests
    /// it when it gets there; where it passes, so did every ancestor's in traverse(): a parent's
    /// box contains the child's and was tested with a tMax no smaller, and the slab test is
    /// monotonic in both (for finite boxes and a direction with no zero component, where no
    /// slab distance is NaN; callers make sure of both). So the same items are visited in the
    /// same order with the same tMax.
    template <typename Visit>
    void traverseLeaves(const uint32_t *leaves, size_t count, const Ray &ray, double tMin,
                        double *tMax, Visit &&visit) const {
        traverseLeavesWith(leaves, count, RaySlabs(ray), tMin, tMax, visit);
    }
    template <typename Slabs, typename Visit>
    void traverseLeavesWith(const uint32_t *leaves, size_t count, const Slabs &slabs, double tMin,
                            double *tMax, Visit &&visit) const;

#if SCADRAY_LANE_SLABS
    /// traverseWith<LaneSlabs> for a visitor that only ever lowers *tMax (a closest-hit
    /// search), testing an interior node's two children side by side (LaneSlabs::hitPair)
    /// instead of one when the walk enters it and the other when it comes back. A child left
    /// for later keeps its near distance t0, and is entered then if t0 <= *tMax: the test it
    /// would have had then gives the same answer, since its far distance does not depend on
    /// *tMax and passed with a *tMax no smaller. So the same nodes pass, the same items are
    /// visited in the same order with the same *tMax, and the two tests' latencies overlap.
    template <typename Visit>
    void traversePairs(const LaneSlabs &slabs, double tMin, double *tMax, Visit &&visit) const;
    /// traverseLeavesWith<LaneSlabs> for such a visitor, testing two leaves side by side; the
    /// second is visited if it passed and its t0 <= *tMax after the first's visits.
    template <typename Visit>
    void traverseLeavesPairs(const uint32_t *leaves, size_t count, const LaneSlabs &slabs,
                             double tMin, double *tMax, Visit &&visit) const;
#endif

    /// What the slab test needs of a ray, computed once per traversal: besides the origin and
    /// the reciprocal direction, where in a box each axis' near and far planes lie (in doubles
    /// from min.x), so a node test loads them without a branch on the direction's sign.
    struct RaySlabs {
        Vec3 o, invDir;
        bool neg[3];
        int nearAt[3], farAt[3];
        explicit RaySlabs(const Ray &ray)
            : RaySlabs(ray, Vec3(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z)) {}
        /// `invDir`: 1 / ray.d, component by component
        RaySlabs(const Ray &ray, const Vec3 &inverseDir)
            : o(ray.o),
              invDir(inverseDir),
              neg{invDir.x < 0, invDir.y < 0, invDir.z < 0},
              nearAt{neg[0] ? 3 : 0, neg[1] ? 4 : 1, neg[2] ? 5 : 2},
              farAt{neg[0] ? 0 : 3, neg[1] ? 1 : 4, neg[2] ? 2 : 5} {}
        bool hit(const Node &node, double tMin, double tMax) const;
    };
#if SCADRAY_LANE_SLABS
    /// The same test with the three axes in the lanes of one AVX register, for walks compiled
    /// for AVX2 (RenderScene::closestHit where the machine has it). Each lane computes what
    /// RaySlabs computes for its axis, with the same operations and roundings; the fourth lane
    /// is NaN, which the NaN-safe selections leave out, as they leave out a NaN slab.
    struct LaneSlabs {
        __m256d o, invDir, negLanes;
        bool neg[3];
        SCADRAY_LANES_TARGET explicit LaneSlabs(const Ray &ray)
            : LaneSlabs(ray, Vec3(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z)) {}
        SCADRAY_LANES_TARGET LaneSlabs(const Ray &ray, const Vec3 &inverseDir);
        SCADRAY_LANES_TARGET bool hit(const Node &node, double tMin, double tMax) const;
        /// hit() for two nodes at once: bit 0 of the result for `a`, bit 1 for `b`, and each
        /// box's near distance t0 (the largest of tMin and its near planes' distances).
        SCADRAY_LANES_TARGET int hitPair(const Node &a, const Node &b, double tMin, double tMax,
                                         double t0[2]) const;

      private:
        /// A box's near and far distances lane by lane, each near one no less than tMin and each
        /// far one no more than infinity (the fourth lane: tMin and infinity).
        SCADRAY_LANES_TARGET void distances(const Node &node, double tMin, __m256d *nearOut,
                                            __m256d *farOut) const;
    };
#endif

  private:
    struct BuildItem {
        Bounds3 bounds;
        Vec3 centroid;
        uint32_t index;
    };
    int build(std::vector<BuildItem> &items, size_t begin, size_t end, int depth);
    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;
    int depth_ = 0;
};

inline bool Bvh::RaySlabs::hit(const Node &node, double tMin, double tMax) const {
    const RaySlabs &r = *this;
    const Bounds3 &b = node.bounds;
    static_assert(
        sizeof(Bounds3) == 6 * sizeof(double) && offsetof(Bounds3, max) == 3 * sizeof(double),
        "RaySlabs indexes a box's six planes");
    // The planes are read as the box's bytes (memcpy of a double: one load)
    const char *planes = reinterpret_cast<const char *>(&b);
    auto plane = [planes](int at) {
        double v;
        std::memcpy(&v, planes + at * sizeof(double), sizeof v);
        return v;
    };
    // pbrt-v3 Bounds3::IntersectP with precomputed reciprocal, written without a loop or an early
    // exit so the three slabs are computed side by side (the result is the same: t0 only grows
    // and t1 only shrinks). The comparisons are NaN-safe: a NaN slab leaves t0/t1 unchanged.
    double nearX = (plane(r.nearAt[0]) - r.o.x) * r.invDir.x;
    double nearY = (plane(r.nearAt[1]) - r.o.y) * r.invDir.y;
    double nearZ = (plane(r.nearAt[2]) - r.o.z) * r.invDir.z;
    double farX = (plane(r.farAt[0]) - r.o.x) * r.invDir.x;
    double farY = (plane(r.farAt[1]) - r.o.y) * r.invDir.y;
    double farZ = (plane(r.farAt[2]) - r.o.z) * r.invDir.z;
    double t0 = tMin;
    t0 = nearX > t0 ? nearX : t0;
    t0 = nearY > t0 ? nearY : t0;
    t0 = nearZ > t0 ? nearZ : t0;
    // The nearest far plane, grown by its rounding error (pbrt's 1 + 2 gamma(3)) away from zero:
    // span queries look behind the origin too (tMin = -inf), and scaling a negative tFar
    // would shrink it, so a flat node (one face of a mesh) behind the origin was missed.
    // Growing is monotonic, so growing the nearest equals the nearest of the grown (where a
    // far distance is -inf, growing it gives NaN and the slabs' far ends are then all left out:
    // more nodes are visited, never fewer)
    double far = kInfinity;
    far = farX < far ? farX : far;
    far = farY < far ? farY : far;
    far = farZ < far ? farZ : far;
    far += 2 * gamma(3) * std::abs(far);
    double t1 = far < tMax ? far : tMax;
    return t0 <= t1;
}

#if SCADRAY_LANE_SLABS
SCADRAY_LANES_TARGET inline Bvh::LaneSlabs::LaneSlabs(const Ray &ray, const Vec3 &inverseDir) {
    double ix = inverseDir.x, iy = inverseDir.y, iz = inverseDir.z;
    o = _mm256_setr_pd(ray.o.x, ray.o.y, ray.o.z, 0);
    invDir = _mm256_setr_pd(ix, iy, iz, std::numeric_limits<double>::quiet_NaN());
    negLanes = _mm256_cmp_pd(invDir, _mm256_setzero_pd(), _CMP_LT_OQ);  // the NaN lane: false
    neg[0] = ix < 0, neg[1] = iy < 0, neg[2] = iz < 0;
}

SCADRAY_LANES_TARGET inline void Bvh::LaneSlabs::distances(const Node &node, double tMin,
                                                           __m256d *nearOut,
                                                           __m256d *farOut) const {
    static_assert(offsetof(Node, bounds) == 0 && sizeof(Node) >= 7 * sizeof(double),
                  "LaneSlabs reads 7 doubles from a node: its box, then a word of the node");
    // min.xyz and max.x; max.xyz and the node's offset and count, whose lane takes max.x
    // instead (as a double it is subnormal, which costs an arithmetic operation a microcode
    // assist); the NaN lane of invDir turns both into NaN
    const double *planes = &node.bounds.min.x;
    __m256d lo = _mm256_loadu_pd(planes);
    __m256d hi = _mm256_blend_pd(_mm256_loadu_pd(planes + 3), lo, 0b1000);
    __m256d tLo = _mm256_mul_pd(_mm256_sub_pd(lo, o), invDir);
    __m256d tHi = _mm256_mul_pd(_mm256_sub_pd(hi, o), invDir);
    __m256d nearV = _mm256_blendv_pd(tLo, tHi, negLanes),
            farV = _mm256_blendv_pd(tHi, tLo, negLanes);
    // RaySlabs::hit's selections lane by lane (max and min give their second operand where
    // the first is NaN)
    *nearOut = _mm256_max_pd(nearV, _mm256_set1_pd(tMin));
    *farOut = _mm256_min_pd(farV, _mm256_set1_pd(kInfinity));
}

SCADRAY_LANES_TARGET inline bool Bvh::LaneSlabs::hit(const Node &node, double tMin,
                                                     double tMax) const {
    __m256d t0V, farL;
    distances(node, tMin, &t0V, &farL);
    // Then across the lanes: the same largest near distance and smallest far one as
    // RaySlabs::hit, up to the sign of a zero, which t0 <= t1 does not see
    __m128d t0xy = _mm256_castpd256_pd128(t0V), farxy = _mm256_castpd256_pd128(farL);
    __m128d t0m =
        _mm_max_sd(_mm_max_sd(t0xy, _mm_unpackhi_pd(t0xy, t0xy)), _mm256_extractf128_pd(t0V, 1));
    __m128d farm = _mm_min_sd(_mm_min_sd(farxy, _mm_unpackhi_pd(farxy, farxy)),
                              _mm256_extractf128_pd(farL, 1));
    double t0 = _mm_cvtsd_f64(t0m), far = _mm_cvtsd_f64(farm);
    far += 2 * gamma(3) * std::abs(far);
    double t1 = far < tMax ? far : tMax;
    return t0 <= t1;
}

SCADRAY_LANES_TARGET inline int Bvh::LaneSlabs::hitPair(const Node &a, const Node &b, double tMin,
                                                        double tMax, double t0[2]) const {
    // hit()'s lane operations for each box; the selections across the lanes are made for both
    // boxes at once, in another order, which gives the same largest and smallest values: after
    // the lane-by-lane selections against tMin and infinity no lane is NaN (where tMin is not)
    __m256d nearA, farA, nearB, farB;
    distances(a, tMin, &nearA, &farA);
    distances(b, tMin, &nearB, &farB);
    // [a0 b0 a2 b2] against [a1 b1 a3 b3], then the halves: [a's, b's]
    __m256d nearM =
        _mm256_max_pd(_mm256_unpacklo_pd(nearA, nearB), _mm256_unpackhi_pd(nearA, nearB));
    __m256d farM = _mm256_min_pd(_mm256_unpacklo_pd(farA, farB), _mm256_unpackhi_pd(farA, farB));
    __m128d near = _mm_max_pd(_mm256_castpd256_pd128(nearM), _mm256_extractf128_pd(nearM, 1));
    __m128d far = _mm_min_pd(_mm256_castpd256_pd128(farM), _mm256_extractf128_pd(farM, 1));
    // far += 2 gamma(3) |far|; then t1 = far < tMax ? far : tMax (minpd's rule)
    __m128d absFar = _mm_andnot_pd(_mm_set1_pd(-0.0), far);
    far = _mm_add_pd(far, _mm_mul_pd(_mm_set1_pd(2 * gamma(3)), absFar));
    __m128d t1 = _mm_min_pd(far, _mm_set1_pd(tMax));
    _mm_storeu_pd(t0, near);
    return _mm_movemask_pd(_mm_cmp_pd(near, t1, _CMP_LE_OQ));
}
#endif

template <typename Slabs, typename Visit>
void Bvh::traverseWith(const Slabs &slabs, double tMin, double *tMax, Visit &&visit) const {
    if (nodes_.empty()) return;
    uint32_t stack[128];
    int top = 0;
    uint32_t current = 0;
    while (true) {
        const Node &node = nodes_[current];
        if (slabs.hit(node, tMin, *tMax)) {
            if (node.count > 0) {
                for (uint32_t i = 0; i < node.count; ++i)
                    if (visit(order_[node.offset + i], tMax)) return;
                if (top == 0) return;
                current = stack[--top];
            } else if (slabs.neg[node.axis]) {
                stack[top++] = current + 1;
                current = node.offset;
            } else {
                stack[top++] = node.offset;
                current = current + 1;
            }
        } else {
            if (top == 0) return;
            current = stack[--top];
        }
    }
}

template <typename Keep>
void Bvh::collectLeaves(int octant, Keep &&keep, std::vector<uint32_t> &leaves) const {
    if (nodes_.empty()) return;
    // traverse()'s order: at a node split on an axis where the rays run negative, the second
    // child first (the tree is at most 100 deep)
    auto collect = [&](auto &self, uint32_t index) -> void {
        const Node &node = nodes_[index];
        if (!keep(node.bounds)) return;
        if (node.count > 0) {
            leaves.push_back(index);
            return;
        }
        bool secondFirst = octant >> node.axis & 1;
        self(self, secondFirst ? node.offset : index + 1);
        self(self, secondFirst ? index + 1 : node.offset);
    };
    collect(collect, 0);
}

template <typename Slabs, typename Visit>
void Bvh::traverseLeavesWith(const uint32_t *leaves, size_t count, const Slabs &slabs, double tMin,
                             double *tMax, Visit &&visit) const {
    for (size_t l = 0; l < count; ++l) {
        const Node &node = nodes_[leaves[l]];
        if (!slabs.hit(node, tMin, *tMax)) continue;
        for (uint32_t i = 0; i < node.count; ++i)
            if (visit(order_[node.offset + i], tMax)) return;
    }
}

#if SCADRAY_LANE_SLABS
template <typename Visit>
void Bvh::traversePairs(const LaneSlabs &slabs, double tMin, double *tMax, Visit &&visit) const {
    if (nodes_.empty()) return;
    if (!slabs.hit(nodes_[0], tMin, *tMax)) return;
    uint32_t stack[128];
    double stackT0[128];  // the near distance of each node left for later
    int top = 0;
    uint32_t current = 0;  // a node whose box passed
    while (true) {
        const Node &node = nodes_[current];
        if (node.count > 0) {
            for (uint32_t i = 0; i < node.count; ++i)
                if (visit(order_[node.offset + i], tMax)) return;
        } else {
            uint32_t first = current + 1, second = node.offset;
            if (slabs.neg[node.axis]) std::swap(first, second);
            double t0[2];
            int pass = slabs.hitPair(nodes_[first], nodes_[second], tMin, *tMax, t0);
            if (pass & 1) {
                if (pass & 2) {
                    stack[top] = second;
                    stackT0[top++] = t0[1];
                }
                current = first;
                continue;
            }
            if (pass & 2) {
                current = second;
                continue;
            }
        }
        // The nearest node left for later that still passes
        do {
            if (top == 0) return;
            --top;
        } while (!(stackT0[top] <= *tMax));
        current = stack[top];
    }
}

template <typename Visit>
void Bvh::traverseLeavesPairs(const uint32_t *leaves, size_t count, const LaneSlabs &slabs,
                              double tMin, double *tMax, Visit &&visit) const {
    size_t l = 0;
    for (; l + 1 < count; l += 2) {
        double t0[2];
        int pass = slabs.hitPair(nodes_[leaves[l]], nodes_[leaves[l + 1]], tMin, *tMax, t0);
        for (int k = 0; k < 2; ++k) {
            if (!(pass >> k & 1) || !(t0[k] <= *tMax)) continue;
            const Node &node = nodes_[leaves[l + k]];
            for (uint32_t i = 0; i < node.count; ++i)
                if (visit(order_[node.offset + i], tMax)) return;
        }
    }
    if (l < count) {
        const Node &node = nodes_[leaves[l]];
        if (!slabs.hit(node, tMin, *tMax)) return;
        for (uint32_t i = 0; i < node.count; ++i)
            if (visit(order_[node.offset + i], tMax)) return;
    }
}
#endif

}  // namespace rt
