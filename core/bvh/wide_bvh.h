// SPDX-License-Identifier: MIT
// A four-wide BVH over item boxes (the triangles of a mesh, the operands of a CSG node): four
// children per node with their boxes stored as floats rounded
// outward (so a box only ever grows, and no hit is lost), tested four at a time in float with
// margins that make the test conservative (every box the exact ray meets is visited; rays that
// do not fit in floats take a double-precision test); leaves of up to four items (eight for
// meshes that test a leaf's triangles four at a time); binned SAH build, parallel below the
// top levels and identical for any number of threads.
#pragma once

#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/ir/mesh.h"
#include "core/math/bounds3.h"
#include "core/math/float_round.h"
#include "core/math/float_util.h"
#include "core/math/ray.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rt {

/// Allocates large arrays (2 MiB and more) on 2 MiB boundaries and asks Linux for transparent
/// huge pages there: a BVH of tens of megabytes then costs a few dozen page faults to build
/// instead of thousands, and a ray's random walk through it a few TLB entries. Elsewhere (or
/// where the kernel declines) it is plain memory.
void *allocateLarge(size_t bytes);
void freeLarge(void *p) noexcept;

template <typename T>
struct LargeAllocator {
    using value_type = T;
    LargeAllocator() = default;
    template <typename U>
    LargeAllocator(const LargeAllocator<U> &) {}
    T *allocate(size_t n) { return static_cast<T *>(allocateLarge(n * sizeof(T))); }
    void deallocate(T *p, size_t) noexcept { freeLarge(p); }
    /// Default-initialises (resize() of plain data leaves it unwritten, for the code that fills
    /// it, on whichever threads fill it, to be the first to touch the pages)
    template <typename U>
    void construct(U *p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void *>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U *p, Args &&...args) {
        ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
    }
    friend bool operator==(const LargeAllocator &, const LargeAllocator &) { return true; }
};

template <typename T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

class WideBvh {
  public:
    static constexpr int kWidth = 4;
    /// The most items a leaf holds: 4 by default (CSG operands), 8 where a build asks for it
    /// (meshes whose leaves are tested four triangles at a time).
    static constexpr int kLeafItems = 4;
    static constexpr int kMaxLeafItems = 8;
    /// Items a BVH can index (28 bits of a child reference).
    static constexpr size_t kMaxItems = size_t{1} << 28;
    /// A leaf's child reference, and its first slot and item count.
    static constexpr uint32_t leafRef(uint32_t first, uint32_t count) {
        return kLeaf | first << 3 | (count - 1);
    }
    static constexpr uint32_t leafFirst(uint32_t ref) { return (ref & ~kLeaf) >> 3; }
    static constexpr uint32_t leafCount(uint32_t ref) { return (ref & 7) + 1; }

    struct alignas(64) Node {
        float lo[3][kWidth];  ///< per axis, the lower bound of each child
        float hi[3][kWidth];
        /// leafRef(first, count), an interior node's index, or kEmpty
        uint32_t child[kWidth];
        /// Per child, the cache line where the walk prefetches it: an interior child's node, a
        /// leaf's data (setLeafData; without it, the root). In 8-byte steps, signed, from the
        /// line where the node array starts, so that the prefetch's address is one scaled index;
        /// where some line lies beyond 2^31 steps (16 GiB) of it, in 64-byte steps, unsigned,
        /// from the line where the child's kind starts (fetchesNear()). Read with the child
        /// instead of computed from it with a product by the leaf stride and a select.
        uint32_t fetch[kWidth];
    };
    static_assert(sizeof(Node) == 128);
    static_assert(offsetof(Node, hi) ==
                  3 * kWidth * sizeof(float));  // FloatSlabs indexes the planes
    static constexpr uint32_t kLeaf = 0x80000000u;
    static constexpr uint32_t kEmpty = 0xffffffffu;

    /// The cost of testing one item in a leaf, against one node visit, that the build's SAH
    /// weighs: a leaf of n items costs n times it. CSG operands are tested one at a time (1);
    /// where TriangleMesh tests a leaf's triangles four at a time (TriangleMesh::fourWideLeaves)
    /// a leaf costs little more than one triangle, and a quarter makes almost every range of up
    /// to four triangles a leaf (a ray's tests are the same and the tree depends only on this).
    static constexpr float kItemCost = 1.0f;
    static constexpr float kTriangleCost = 0.25f;

    WideBvh() = default;
    /// threads: 0 for std::thread::hardware_concurrency(). The tree does not depend on it.
    /// Throws std::length_error beyond kMaxItems.
    /// Over the triangles of a mesh.
    /// leafItems: the most items a leaf holds (1 to kMaxLeafItems).
    explicit WideBvh(const ir::Mesh &mesh, int threads = 0, float itemCost = kTriangleCost,
                     int leafItems = kLeafItems);
    /// Over item boxes, which may be empty, infinite or beyond the float range: they are
    /// rounded outward to floats, and their centres clamped to it.
    explicit WideBvh(const std::vector<Bounds3> &items, int threads = 1, float itemCost = kItemCost,
                     int leafItems = kLeafItems);

    const LargeVector<Node> &nodes() const { return nodes_; }
    /// Item (triangle) indices in leaf order; empty after dropItemOrder().
    const LargeVector<uint32_t> &itemOrder() const { return order_; }
    /// Frees the item order, for a caller that keeps it in its own leaf data and only uses
    /// traverseLeaves or traverseSlots; traverse needs it.
    void dropItemOrder() { LargeVector<uint32_t>().swap(order_); }
    size_t bytes() const {
        return nodes_.capacity() * sizeof(Node) + order_.capacity() * sizeof(uint32_t);
    }
    int depth() const { return depth_; }

    bool empty() const { return nodes_.empty(); }

    /// Visits the items whose leaves the ray reaches within [tMin, *tMax], nearest boxes
    /// first. visit(item, tMax) may lower *tMax and returns true to stop.
    template <typename Visit>
    void traverse(const Ray &ray, double tMin, double *tMax, Visit &&visit) const;
    /// As traverse, but visit(slot, tMax) gets the item's position in itemOrder(): a caller
    /// that keeps its own per-item data in leaf order reads it contiguously, without the
    /// dependent load of the item index.
    template <typename Visit>
    void traverseSlots(const Ray &ray, double tMin, double *tMax, Visit &&visit) const;

    /// Per-item data a caller keeps in leaf order (a mesh's leaf vertices): item slot s's data
    /// starts at base + s * stride.
    struct LeafData {
        const void *base;  ///< null: no leaf data
        size_t stride;
    };
    /// Makes the walk prefetch the start of each leaf child's data (four cache lines) while it
    /// tests the node, a level before it visits the leaf. It decides only what is fetched
    /// ahead: without it, or after a copy of the BVH, the hits are the same.
    void setLeafData(LeafData data);
    /// Where the walk prefetches child c of node n: the start of the cache line that holds it.
    const void *fetchLine(const Node &n, int c) const {
        return fetchNear_ ? fetchLine<true>(fetchBases(), n, c)
                          : fetchLine<false>(fetchBases(), n, c);
    }
    /// Whether every child's line counts from the node array's (one base, no select a child,
    /// in 8-byte steps).
    bool fetchesNear() const { return fetchNear_; }
    /// As traverseSlots, a leaf at a time: visit(first, count, tMax) gets the leaf's slots
    /// [first, first + count) (count <= the build's leafItems).
    template <typename Visit>
    void traverseLeaves(const Ray &ray, double tMin, double *tMax, Visit &&visit) const;

  private:
    /// Depth bound of the build; with at most three pushes a level it sizes the traversal stack.
    static constexpr int kMaxDepth = 64;
    static constexpr int kStackSize = 3 * kMaxDepth + 4;
    friend class WideBvhBuilder;

    /// The ray's interval [tMin, tMax] as a node test takes it: made once a walk, and again
    /// whenever a leaf lowers *tMax. These tests take it as it is; ForwardSlabs rounds it.
    struct PlainLimits {
        struct Limits {
            double tMin, tMax;
        };
        static Limits limits(double tMin, double tMax) { return {tMin, tMax}; }
        static void lower(Limits &l, double tMax) { l.tMax = tMax; }
    };
    /// The slab test of the four children of a node: the mask of those the ray meets within
    /// [tMin, tMax], and for each a float no greater than its near distance.
    struct DoubleSlabs : PlainLimits {
        /// Whether the test alone culls an empty slot (lo +inf, hi -inf): not here, where the
        /// far distance -inf grown by its error is NaN (and a ray with a NaN direction meets
        /// every box), so the walk masks empty slots out.
        static constexpr bool kCullsEmpty = false;
        double o[3], inv[3];
        int nearHi[3];  ///< the near plane of each axis: hi for a negative direction
        explicit DoubleSlabs(const Ray &ray);
        int test(const Node &n, const Limits &l, float tn[kWidth]) const;
    };
#if defined(__SSE2__)
    /// The origin and planes of a float test: per axis, where in a node (in floats from
    /// lo[0][0]) the near and the far planes lie, and the origin rounded for each.
    struct FloatRay {
        /// The float tests cull an empty slot (lo +inf, hi -inf) without a mask: the ray fits
        /// (its origin is finite, no reciprocal zero or NaN), so on every axis the near plane's
        /// distance is +inf and the far one's -inf, whatever the signs, and no clamp or margin
        /// brings the two ends back in order.
        static constexpr bool kCullsEmpty = true;
        __m128 oNear[3], oFar[3];
        int nearAt[3], farAt[3];
        /// False where the ray does not fit in floats (an origin beyond 1e30, a direction
        /// component beyond 1e30 or below 1e-30 and not zero): DoubleSlabs takes those rays.
        /// inv gets the reciprocal of the direction rounded to floats, x, y and z in lanes 0 to 2.
        bool init(const Ray &ray, __m128 *inv);
        /// Narrows the four children's [t0, t1] to each box's near and far distances, taken with
        /// the near planes' and the far planes' reciprocals.
        void clip(const Node &n, const __m128 invNear[3], const __m128 invFar[3], __m128 &t0,
                  __m128 &t1) const;
    };
    /// The same test in float, conservatively: it meets every child that the exact ray meets
    /// within [tMin, tMax] (and so every child that DoubleSlabs meets), so the hits are the same.
    /// The origin is rounded per plane in the direction that gives the smaller near distance and
    /// the larger far one, so its rounding costs nothing per node; what is left is the rounding
    /// of the reciprocal, of the subtraction and of the product (3 float units in all), covered
    /// by kMargin with room for the margin's own rounding, and results in the denormal range,
    /// covered by kTiny.
    struct FloatSlabs : FloatRay, PlainLimits {
        __m128 inv[3];
        bool init(const Ray &ray);
        int test(const Node &n, const Limits &l, float tn[kWidth]) const;
    };
    /// FloatSlabs for a ray that starts at tMin >= 0 (closest hits and shadow rays: everything
    /// but the whole-line queries of CSG), with the margins folded into the ray. Only distances
    /// at or beyond 0 decide there: a negative near distance gives way to tMin, and a negative far
    /// one culls the child as the exact one does (the origin's rounding keeps the sign of each
    /// plane's distance, and a zero stays zero). So the near planes take the reciprocal shrunk
    /// by kMargin and the far planes the reciprocal grown by it, which makes a positive near
    /// distance no greater and a positive far one no smaller than the exact one whatever the
    /// rounding of the reciprocal, the subtraction and the products (3 float units); kTiny still
    /// covers results in the denormal range, and tMin and tMax are rounded outward to floats
    /// once per leaf visited instead of converted per node. The result is the same set of hits:
    /// a conservative test visits every child the exact ray meets.
    struct ForwardSlabs : FloatRay {
        __m128 invNear[3], invFar[3];
        /// As FloatSlabs::init; tMin >= 0 is the caller's to ensure.
        bool init(const Ray &ray);
        struct Limits {
            __m128 t0, t1;
        };
        static Limits limits(double tMin, double tMax) {
            return {_mm_set1_ps(floatBelow(tMin)), _mm_set1_ps(floatAbove(tMax))};
        }
        static void lower(Limits &l, double tMax) { l.t1 = _mm_set1_ps(floatAbove(tMax)); }
        int test(const Node &n, const Limits &l, float tn[kWidth]) const;
    };
    static constexpr float kMargin = 1.0f / (1 << 20);  ///< 16 float units
    static constexpr float kTiny = 1.17549435e-38f;     ///< the smallest normal float
    static constexpr float kLargest = 3.40282347e38f;   ///< the largest finite float
#endif
    template <typename BoxOf>
    void build(size_t n, BoxOf &&boxOf, int threads, float itemCost, int leafItems);
    template <typename Slabs, typename Visit>
    void walk(const Slabs &slabs, double tMin, double *tMax, Visit &visit) const;
    template <bool Near, typename Slabs, typename Visit>
    void walkFetching(const Slabs &slabs, double tMin, double *tMax, Visit &visit) const;

    LargeVector<Node> nodes_;
    LargeVector<uint32_t> order_;
    int depth_ = 0;
    uintptr_t leafLines_ = 0;  ///< the line where the leaf data starts; 0: none
    bool fetchNear_ = true;

    /// Where the lines count from: the node array's first line, and where they do not fetch
    /// near, the leaf data's, picked by a child's top bit (kLeaf; an empty slot takes the leaf
    /// data's). In integers: a leaf's data lies in another allocation.
    std::array<uintptr_t, 2> fetchBases() const {
        const uintptr_t nodeLines = reinterpret_cast<uintptr_t>(nodes_.data()) & ~uintptr_t{63};
        return {nodeLines, leafLines_ ? leafLines_ : nodeLines};
    }
    template <bool Near>
    static const char *fetchLine(const std::array<uintptr_t, 2> &bases, const Node &n, int c) {
        if constexpr (Near)  // a sign-extending load, then base + index * 8 in the prefetch itself
            return reinterpret_cast<const char *>(bases[0]) +
                   intptr_t{static_cast<int32_t>(n.fetch[c])} * 8;
        else
            return reinterpret_cast<const char *>(bases[n.child[c] >> 31] +
                                                  uintptr_t{n.fetch[c]} * 64);
    }
};

template <typename Visit>
void WideBvh::traverse(const Ray &ray, double tMin, double *tMax, Visit &&visit) const {
    assert(order_.size() > 0 || nodes_.empty());  // not after dropItemOrder()
    traverseSlots(ray, tMin, tMax,
                  [&](uint32_t slot, double *far) { return visit(order_[slot], far); });
}

template <typename Visit>
void WideBvh::traverseSlots(const Ray &ray, double tMin, double *tMax, Visit &&visit) const {
    traverseLeaves(ray, tMin, tMax, [&](uint32_t first, uint32_t count, double *far) {
        for (uint32_t i = 0; i < count; ++i)
            if (visit(first + i, far)) return true;
        return false;
    });
}

template <typename Visit>
void WideBvh::traverseLeaves(const Ray &ray, double tMin, double *tMax, Visit &&visit) const {
    if (nodes_.empty()) return;
#if defined(__SSE2__)
    if (tMin >= 0) {
        ForwardSlabs f;
        if (f.init(ray)) return walk(f, tMin, tMax, visit);
    } else {
        FloatSlabs f;
        if (f.init(ray)) return walk(f, tMin, tMax, visit);
    }
#endif
    walk(DoubleSlabs(ray), tMin, tMax, visit);
}

#if defined(__SSE2__)
inline void WideBvh::FloatRay::clip(const Node &n, const __m128 invNear[3], const __m128 invFar[3],
                                    __m128 &t0, __m128 &t1) const {
    const float *planes = &n.lo[0][0];
    // maxps/minps return their second operand when either is NaN: a NaN distance (the
    // origin's bound on the plane of a flat direction) leaves the interval as it was
    // (three calls, not a loop: GCC's -O2 keeps a loop here, which costs 14 % more instructions)
    auto axis = [&](int a) {
        t0 = _mm_max_ps(
            _mm_mul_ps(_mm_sub_ps(_mm_load_ps(planes + nearAt[a]), oNear[a]), invNear[a]), t0);
        t1 = _mm_min_ps(_mm_mul_ps(_mm_sub_ps(_mm_load_ps(planes + farAt[a]), oFar[a]), invFar[a]),
                        t1);
    };
    axis(0);
    axis(1);
    axis(2);
}

inline int WideBvh::FloatSlabs::test(const Node &n, const Limits &l, float tn[kWidth]) const {
    __m128 t0 = _mm_set1_ps(static_cast<float>(l.tMin)),
           t1 = _mm_set1_ps(static_cast<float>(l.tMax));
    clip(n, inv, inv, t0, t1);
    // A distance that overflowed stands for one beyond the largest float, not for infinity
    const __m128 big = _mm_set1_ps(kLargest);
    t0 = _mm_min_ps(t0, big);
    t1 = _mm_max_ps(t1, _mm_sub_ps(_mm_setzero_ps(), big));
    // Widen both ends by the relative margin and the absolute one. Both widenings are monotonic,
    // so widening the maximum of the near distances (and tMin, rounded to nearest) equals the
    // maximum of the widened ones
    const __m128 down = _mm_set1_ps(1 - kMargin), up = _mm_set1_ps(1 + kMargin);
    const __m128 tiny = _mm_set1_ps(kTiny);
    t0 = _mm_sub_ps(_mm_min_ps(_mm_mul_ps(t0, down), _mm_mul_ps(t0, up)), tiny);
    t1 = _mm_add_ps(_mm_max_ps(_mm_mul_ps(t1, down), _mm_mul_ps(t1, up)), tiny);
    _mm_storeu_ps(tn, t0);
    return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
}

inline int WideBvh::ForwardSlabs::test(const Node &n, const Limits &l, float tn[kWidth]) const {
    __m128 t0 = l.t0, t1 = l.t1;
    clip(n, invNear, invFar, t0, t1);
    // A near distance that overflowed stands for one beyond the largest float (an overflowed
    // far one is beyond it anyway, and a far one below minus the largest float culls as -inf does)
    t0 = _mm_sub_ps(_mm_min_ps(t0, _mm_set1_ps(kLargest)), _mm_set1_ps(kTiny));
    t1 = _mm_add_ps(t1, _mm_set1_ps(kTiny));
    _mm_storeu_ps(tn, t0);
    return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
}
#endif

inline WideBvh::DoubleSlabs::DoubleSlabs(const Ray &ray)
    : o{ray.o.x, ray.o.y, ray.o.z},
      inv{1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z},
      nearHi{inv[0] < 0, inv[1] < 0, inv[2] < 0} {}

inline int WideBvh::DoubleSlabs::test(const Node &n, const Limits &l, float tn[kWidth]) const {
    const double tMin = l.tMin, tMax = l.tMax;
    // Far distances grow by their rounding error away from zero, as in Bvh::hitNode
    constexpr double kSlop = 2 * gamma(3);
    alignas(16) double t[4];
    int mask;
#if defined(__SSE2__)
    const __m128d slop = _mm_set1_pd(kSlop);
    const __m128d absMask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    __m128d t0a = _mm_set1_pd(tMin), t0b = t0a;
    // The far distance is the nearest far plane grown by its rounding error, then capped at
    // tMax: growing is monotonic, so growing the minimum equals the minimum of the grown
    __m128d t1a = _mm_set1_pd(kInfinity), t1b = t1a;
    for (int a = 0; a < 3; ++a) {
        const __m128d oa = _mm_set1_pd(o[a]), iv = _mm_set1_pd(inv[a]);
        __m128 nearF = _mm_load_ps(nearHi[a] ? n.hi[a] : n.lo[a]);
        __m128 farF = _mm_load_ps(nearHi[a] ? n.lo[a] : n.hi[a]);
        __m128d na = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(nearF), oa), iv);
        __m128d nb = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(nearF, nearF)), oa), iv);
        __m128d fa = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(farF), oa), iv);
        __m128d fb = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(farF, farF)), oa), iv);
        // maxpd/minpd return their second operand when either is NaN: a NaN distance
        // (origin on the plane of a flat direction) leaves the interval as it was
        t0a = _mm_max_pd(na, t0a);
        t0b = _mm_max_pd(nb, t0b);
        t1a = _mm_min_pd(fa, t1a);
        t1b = _mm_min_pd(fb, t1b);
    }
    const __m128d tMaxV = _mm_set1_pd(tMax);
    t1a = _mm_min_pd(_mm_add_pd(t1a, _mm_mul_pd(slop, _mm_and_pd(t1a, absMask))), tMaxV);
    t1b = _mm_min_pd(_mm_add_pd(t1b, _mm_mul_pd(slop, _mm_and_pd(t1b, absMask))), tMaxV);
    mask = _mm_movemask_pd(_mm_cmple_pd(t0a, t1a)) | _mm_movemask_pd(_mm_cmple_pd(t0b, t1b)) << 2;
    _mm_store_pd(t, t0a);
    _mm_store_pd(t + 2, t0b);
#else
    mask = 0;
    for (int c = 0; c < 4; ++c) {
        double t0 = tMin, t1 = tMax;
        for (int a = 0; a < 3; ++a) {
            double nearB = nearHi[a] ? n.hi[a][c] : n.lo[a][c];
            double farB = nearHi[a] ? n.lo[a][c] : n.hi[a][c];
            double tNear = (nearB - o[a]) * inv[a], tFar = (farB - o[a]) * inv[a];
            tFar += kSlop * std::abs(tFar);
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
        }
        t[c] = t0;
        if (t0 <= t1) mask |= 1 << c;
    }
#endif
    // The stack keeps floats no greater than the near distances
    for (int c = 0; c < 4; ++c) {
        float f = static_cast<float>(t[c]);
        tn[c] = static_cast<double>(f) > t[c] ? std::nextafter(f, -INFINITY) : f;
    }
    return mask;
}

template <typename Slabs, typename Visit>
void WideBvh::walk(const Slabs &slabs, double tMin, double *tMax, Visit &visit) const {
    if (fetchNear_)
        walkFetching<true>(slabs, tMin, tMax, visit);
    else
        walkFetching<false>(slabs, tMin, tMax, visit);
}

template <bool Near, typename Slabs, typename Visit>
void WideBvh::walkFetching(const Slabs &slabs, double tMin, double *tMax, Visit &visit) const {
    struct Entry {
        uint32_t ref;
        float tNear;  ///< no greater than the child's near distance
    };
    Entry stack[kStackSize];
    int top = 0;
    uint32_t current = 0;  // the root is always a node
    typename Slabs::Limits limits = slabs.limits(tMin, *tMax);
    auto push = [&](uint32_t ref, float tNear) { stack[top++] = {ref, tNear}; };
#if defined(__SSE2__)
    const std::array<uintptr_t, 2> bases = fetchBases();
#endif
    while (true) {
        if (current & kLeaf) {
            if (visit(leafFirst(current), leafCount(current), tMax)) return;
            slabs.lower(limits, *tMax);
        } else {
            const Node &n = nodes_[current];
#if defined(__SSE2__)
            // Every child's node or leaf data is fetched while this node is tested, so the walk
            // waits on memory about once a level instead of once a node: four lines a child, a
            // node's two and its neighbour's (often a sibling the walk visits next), or the
            // first 256 bytes of a leaf's data (a float leaf of up to eight triangles takes 40
            // bytes each). Written out: GCC 12 at -O2 dropped these prefetches from a lambda
            // called for each child, and kept a loop with a branch per child
            const char *p0 = fetchLine<Near>(bases, n, 0), *p1 = fetchLine<Near>(bases, n, 1);
            const char *p2 = fetchLine<Near>(bases, n, 2), *p3 = fetchLine<Near>(bases, n, 3);
            _mm_prefetch(p0, _MM_HINT_T0);
            _mm_prefetch(p0 + 64, _MM_HINT_T0);
            _mm_prefetch(p1, _MM_HINT_T0);
            _mm_prefetch(p1 + 64, _MM_HINT_T0);
            _mm_prefetch(p2, _MM_HINT_T0);
            _mm_prefetch(p2 + 64, _MM_HINT_T0);
            _mm_prefetch(p3, _MM_HINT_T0);
            _mm_prefetch(p3 + 64, _MM_HINT_T0);
            _mm_prefetch(p0 + 128, _MM_HINT_T0);
            _mm_prefetch(p0 + 192, _MM_HINT_T0);
            _mm_prefetch(p1 + 128, _MM_HINT_T0);
            _mm_prefetch(p1 + 192, _MM_HINT_T0);
            _mm_prefetch(p2 + 128, _MM_HINT_T0);
            _mm_prefetch(p2 + 192, _MM_HINT_T0);
            _mm_prefetch(p3 + 128, _MM_HINT_T0);
            _mm_prefetch(p3 + 192, _MM_HINT_T0);
#endif
            alignas(16) float tn[4];
            int mask = slabs.test(n, limits, tn);
            // Without the empty slots, where the test does not cull their inverted infinite boxes
            if constexpr (!Slabs::kCullsEmpty) {
#if defined(__SSE2__)
                mask &= ~_mm_movemask_ps(_mm_castsi128_ps(
                    _mm_cmpeq_epi32(_mm_load_si128(reinterpret_cast<const __m128i *>(n.child)),
                                    _mm_set1_epi32(-1))));
#else
                for (int c = 0; c < 4; ++c)
                    if (n.child[c] == kEmpty) mask &= ~(1 << c);
#endif
            }
            // Go on with the nearest child met and push the others, farthest first
            if (mask != 0) {
                int c0 = __builtin_ctz(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    current = n.child[c0];
                    continue;
                }
                int c1 = __builtin_ctz(mask);
                mask &= mask - 1;
                if (mask == 0) {
                    if (tn[c1] < tn[c0]) std::swap(c0, c1);
                    push(n.child[c1], tn[c1]);
                    current = n.child[c0];
                    continue;
                }
                Entry hit[4] = {{n.child[c0], tn[c0]}, {n.child[c1], tn[c1]}};
                int k = 2;
                for (; mask != 0; mask &= mask - 1)
                    hit[k++] = {n.child[__builtin_ctz(mask)], tn[__builtin_ctz(mask)]};
                // Farthest first (insertion sort of at most four)
                for (int i = 1; i < k; ++i) {
                    Entry x = hit[i];
                    int j = i;
                    for (; j > 0 && hit[j - 1].tNear < x.tNear; --j) hit[j] = hit[j - 1];
                    hit[j] = x;
                }
                for (int j = 0; j < k - 1; ++j) push(hit[j].ref, hit[j].tNear);
                current = hit[k - 1].ref;
                continue;
            }
        }
        // Next: the nearest pushed entry still within reach
        do {
            if (top == 0) return;
            --top;
        } while (stack[top].tNear > *tMax);
        current = stack[top].ref;
    }
}

}  // namespace rt
