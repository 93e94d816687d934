// SPDX-License-Identifier: MIT
// Binned SAH build of the four-wide BVH. Item boxes are rounded outward to float once;
// each node splits its range in two by the SAH (16 bins on every axis from 64 items, on the
// longest axis and as many bins as items below) and splits its largest child again until it
// has four, whose interior children are allocated side by side. Below the top levels, subtrees
// are built by separate threads into their own node arrays and appended in a fixed order, so
// the tree is the same for any thread count.
#include "core/bvh/wide_bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <thread>
#include <type_traits>

#include "core/bvh/sah_sweep.h"
#include "core/math/float_round.h"
#include "core/system/parallel_for.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rt {

void *allocateLarge(size_t bytes) {
    constexpr size_t kHuge = size_t{2} << 20;
    void *p = nullptr;
    if (bytes >= kHuge) {
        // aligned_alloc wants a multiple of the alignment
        size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
        p = std::aligned_alloc(kHuge, rounded);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
        // Only advice: the memory works the same without huge pages
        if (p) madvise(p, rounded, MADV_HUGEPAGE);
#endif
    } else {
        p = std::malloc(bytes ? bytes : 1);
    }
    if (!p) throw std::bad_alloc();
    return p;
}

void freeLarge(void *p) noexcept { std::free(p); }

namespace {

/// Four floats: x, y, z and a spare lane, in one SSE register where there is SSE.
struct F4 {
#if defined(__SSE2__)
    __m128 v;
    static F4 of(float x, float y, float z, float w) { return {_mm_setr_ps(x, y, z, w)}; }
    friend F4 operator+(F4 a, F4 b) { return {_mm_add_ps(a.v, b.v)}; }
    friend F4 operator-(F4 a, F4 b) { return {_mm_sub_ps(a.v, b.v)}; }
    friend F4 operator*(F4 a, F4 b) { return {_mm_mul_ps(a.v, b.v)}; }
    friend F4 min(F4 a, F4 b) { return {_mm_min_ps(a.v, b.v)}; }
    friend F4 max(F4 a, F4 b) { return {_mm_max_ps(a.v, b.v)}; }
    void store(float out[4]) const { _mm_storeu_ps(out, v); }
    /// Bit i set where lane i of a is less than that of b.
    friend int lessMask(F4 a, F4 b) { return _mm_movemask_ps(_mm_cmplt_ps(a.v, b.v)); }
    /// The first three lanes truncated to int, taken out of the register one by one (through
    /// memory, each would wait for the whole store).
    void storeBins(int out[3]) const {
        __m128i b = _mm_cvttps_epi32(v);
        out[0] = _mm_cvtsi128_si32(b);
        out[1] = _mm_cvtsi128_si32(_mm_shuffle_epi32(b, 1));
        out[2] = _mm_cvtsi128_si32(_mm_shuffle_epi32(b, 2));
    }
#else
    float v[4];
    static F4 of(float x, float y, float z, float w) { return {{x, y, z, w}}; }
    template <typename Op>
    static F4 zip(F4 a, F4 b, Op op) {
        return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
    }
    friend F4 operator+(F4 a, F4 b) {
        return zip(a, b, [](float x, float y) { return x + y; });
    }
    friend F4 operator-(F4 a, F4 b) {
        return zip(a, b, [](float x, float y) { return x - y; });
    }
    friend F4 operator*(F4 a, F4 b) {
        return zip(a, b, [](float x, float y) { return x * y; });
    }
    friend F4 min(F4 a, F4 b) {
        return zip(a, b, [](float x, float y) { return x < y ? x : y; });
    }
    friend F4 max(F4 a, F4 b) {
        return zip(a, b, [](float x, float y) { return x > y ? x : y; });
    }
    void store(float out[4]) const { std::copy(v, v + 4, out); }
    void storeBins(int out[3]) const {
        for (int i = 0; i < 3; ++i) out[i] = static_cast<int>(v[i]);
    }
    friend int lessMask(F4 a, F4 b) {
        int m = 0;
        for (int i = 0; i < 4; ++i) m |= (a.v[i] < b.v[i]) << i;
        return m;
    }
#endif
};

struct Box {
    F4 lo = F4::of(INFINITY, INFINITY, INFINITY, 0),
       hi = F4::of(-INFINITY, -INFINITY, -INFINITY, 0);
    void grow(F4 l, F4 h) {
        lo = min(lo, l);
        hi = max(hi, h);
    }
    void grow(const Box &b) { grow(b.lo, b.hi); }
    /// Half the surface area; 0 for an empty box.
    float halfArea() const {
#if defined(__SSE2__)
        // xy + yz + zx, summed in that order as the scalar code below
        __m128 d = _mm_sub_ps(hi.v, lo.v);
        if ((_mm_movemask_ps(_mm_cmpge_ps(d, _mm_setzero_ps())) & 7) != 7) return 0;
        __m128 p = _mm_mul_ps(d, _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1)));
        __m128 xyPlusYz = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
        return _mm_cvtss_f32(_mm_add_ss(xyPlusYz, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 2, 2, 2))));
#else
        float d[4];
        (hi - lo).store(d);
        if (!(d[0] >= 0 && d[1] >= 0 && d[2] >= 0)) return 0;
        return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
#endif
    }
    float lower(int axis) const {
        float f[4];
        lo.store(f);
        return f[axis];
    }
    float upper(int axis) const {
        float f[4];
        hi.store(f);
        return f[axis];
    }
};

/// An item's box; the spare lanes hold 0 and the item index (as a normal float: bit 30
/// set keeps the exponent away from both denormals and infinities).
struct Item {
    F4 lo, hi;
    /// Twice the centre, spare lane 0 + 0, clamped to +-2^127: the centre of an infinite or
    /// huge box is a finite float, and so is that of an empty box or one infinite both ways
    /// (the NaN of inf - inf gives way to the second operand of max)
    F4 centroid() const {
        const F4 big = F4::of(kBig, kBig, kBig, kBig), small = F4::of(-kBig, -kBig, -kBig, -kBig);
        return min(max(lo + hi, small), big);
    }
    static constexpr float kBig = 1.70141183e38f;  // 2^127
    uint32_t index() const {
        float f[4];
        hi.store(f);
        uint32_t bits;
        std::memcpy(&bits, &f[3], 4);
        return bits & ~kTag;
    }
    static constexpr uint32_t kTag = 0x40000000u;
};

/// A range of items with its bounds, and once decided, whether and where it splits.
struct Range {
    uint32_t begin = 0, end = 0;
    Box box, centroids;
    enum { kUndecided, kLeaf, kSplit } decision = kUndecided;
    int axis = -1, bin = -1;  ///< SAH split: items whose centroid bin is <= bin go left
    int bins = 0;             ///< the number of bins of the split axis
};

}  // namespace

class WideBvhBuilder {
  public:
    static constexpr int kBins = 16;
    static constexpr size_t kTasksFrom = 4096;
    /// Nodes at this depth (the root is at 1) hand their interior children to subtree tasks.
    static constexpr int kTaskDepth = 2;
    static constexpr uint32_t kAllAxesFrom = 64;
    static constexpr size_t kTwoBinSetsFrom = 256;
    /// Item boxes and the bins of ranges from this size on are computed by all threads.
    static constexpr size_t kParallelFrom = 65536;
    /// Ranges up to this size partition without a branch per item.
    static constexpr uint32_t kBranchFreeUpTo = 256;

    /// boxOf(i, lo, hi) gives the double bounds of item i.
    template <typename BoxOf>
    WideBvhBuilder(size_t n, BoxOf &&boxOf, WideBvh &bvh, int threads, float itemCost,
                   int leafItems)
        : bvh_(bvh),
          threads_(threads),
          itemCost_(itemCost),
          leafItems_(static_cast<uint32_t>(leafItems)) {
        items_.resize(n);
        parallelFor(0, n, n >= kParallelFrom ? static_cast<size_t>(threads) : 1,
                    [&](size_t, size_t begin, size_t end) {
                        for (size_t i = begin; i < end; ++i) {
                            double lo[3], hi[3];
                            boxOf(i, lo, hi);
                            uint32_t bits = static_cast<uint32_t>(i) | Item::kTag;
                            float tag;
                            std::memcpy(&tag, &bits, 4);
#if defined(__SSE2__)
                            // x and y two at a time (a third of this pass's time went into the
                            // roundings)
                            __m128 loXY = floatsBelow(_mm_loadu_pd(lo)),
                                   hiXY = floatsAbove(_mm_loadu_pd(hi));
                            items_[i] = {
                                {_mm_movelh_ps(loXY, _mm_set_ss(floatBelow(lo[2])))},
                                {_mm_movelh_ps(hiXY, _mm_setr_ps(floatAbove(hi[2]), tag, 0, 0))}};
#else
                items_[i] = {F4::of(floatBelow(lo[0]), floatBelow(lo[1]), floatBelow(lo[2]), 0),
                             F4::of(floatAbove(hi[0]), floatAbove(hi[1]), floatAbove(hi[2]), tag)};
#endif
                        }
                    });
    }

    void build() {
        Range root = measure(0, static_cast<uint32_t>(items_.size()));
        // The root is always a node, so traversal starts at node 0
        bvh_.nodes_.reserve(items_.size() >= kTasksFrom ? 32 : items_.size() / 2 + 8);
        bvh_.nodes_.emplace_back();
        std::vector<Pending> pending;
        // Subtrees below the second level are separate tasks whatever the thread count, so the
        // node layout is the same too
        int taskDepth = items_.size() >= kTasksFrom ? kTaskDepth : -1;
        int depth = fillNode(0, root, bvh_.nodes_, 1, taskDepth, &pending);
        bvh_.depth_ = std::max(bvh_.depth_, depth);
        runPending(pending);
        bvh_.order_.resize(items_.size());
        for (size_t i = 0; i < items_.size(); ++i) bvh_.order_[i] = items_[i].index();
    }

  private:
    /// A subtree left for a worker: its range and the slot that will point to it.
    struct Pending {
        Range range;
        uint32_t node;
        int slot;
        int depth;
        LargeVector<WideBvh::Node> nodes;
        int maxDepth = 0;
    };

    /// Per axis and bin, the box of the items whose centroid falls in it and their count; only
    /// the bins in use are initialised (a small range uses few).
    struct Bins {
        Box boxes[3][kBins];
        uint32_t counts[3][kBins];
        Bins() {}  // left uninitialised: clear() sets what is used
        /// Clears the first `bins` bins of the axes in `axes` (bit a for axis a).
        void clear(int bins, int axes) {
            for (int a = 0; a < 3; ++a)
                for (int k = 0; k < bins && (axes >> a & 1); ++k) {
                    boxes[a][k] = Box();
                    counts[a][k] = 0;
                }
        }
        /// Adds the items of `o`: boxes merge by min and max and counts by sums, both exact,
        /// so the bins do not depend on how the items were shared out.
        void merge(const Bins &o, int bins, int axes) {
            for (int a = 0; a < 3; ++a)
                for (int k = 0; k < bins && (axes >> a & 1); ++k) {
                    boxes[a][k].grow(o.boxes[a][k]);
                    counts[a][k] += o.counts[a][k];
                }
        }
    };

    /// Bins per unit of centroid extent (the last centroid falls just inside the last bin).
    static float binScale(int bins, float extent) {
        return static_cast<float>(bins) / extent * (1 - 1e-6f);
    }

    Range measure(uint32_t begin, uint32_t end) const {
        Range r;
        r.begin = begin;
        r.end = end;
        for (uint32_t i = begin; i < end; ++i) {
            r.box.grow(items_[i].lo, items_[i].hi);
            F4 c = items_[i].centroid();
            r.centroids.grow(c, c);
        }
        return r;
    }

    /// Decides whether r becomes a leaf or splits, and on which bin plane.
    void decide(Range &r, int depth) const {
        uint32_t n = r.end - r.begin;
        if (n <= 1) {
            r.decision = Range::kLeaf;
            return;
        }
        int bestAxis = -1, bestSplit = -1;
        float bestCost = INFINITY;
        float lo[4], hi[4], scale[4] = {0, 0, 0, 0};
        r.centroids.lo.store(lo);
        r.centroids.hi.store(hi);
        // Past the depth bound, split by count only: the depth then grows as log4 of the items
        bool sah = depth < WideBvh::kMaxDepth - 16;
        // Small ranges, where the fixed cost of the bins dominates, bin on their longest axis
        // only, and into about as many bins as they have items
        const int nBins = static_cast<int>(std::min<uint32_t>(kBins, std::max<uint32_t>(n, 2)));
        int longest = 0;
        for (int a = 1; a < 3; ++a)
            if (hi[a] - lo[a] > hi[longest] - lo[longest]) longest = a;
        for (int a = 0; a < 3; ++a) {
            float extent = hi[a] - lo[a];
            if (sah && extent > 0 && (n >= kAllAxesFrom || a == longest))
                scale[a] = binScale(nBins, extent);
        }
        if (scale[0] > 0 || scale[1] > 0 || scale[2] > 0) {
            const F4 origin = r.centroids.lo, scale4 = F4::of(scale[0], scale[1], scale[2], 0);
            const float lastBin = static_cast<float>(nBins - 1);
            const F4 zero = F4::of(0, 0, 0, 0), last = F4::of(lastBin, lastBin, lastBin, 0);
            int axes = 0;
            for (int a = 0; a < 3; ++a) axes |= (scale[a] > 0) << a;
            // One axis (the longest, for a small range): only its bins
            const int only = axes == 1 ? 0 : axes == 2 ? 1 : axes == 4 ? 2 : -1;
            if (only < 0) axes = 7;
            // Bins of an item on the three axes (0 on an axis not binned)
            auto binsOf = [&](const Item &it, int b[3]) {
                min(max((it.centroid() - origin) * scale4, zero), last).storeBins(b);
            };
            if (only >= 0 && n <= leafItems_) {
                // Two to four items, as many bins: the sweep of the bins, done over the items
                // themselves (the items of bins 0..k have the union of those bins' boxes). These
                // are most of the decisions, and filling bins on the stack for sweepBins made
                // the whole build 7 to 9 % slower
                int bin[WideBvh::kMaxLeafItems];
                for (uint32_t i = 0; i < n; ++i) {
                    int b[3];
                    binsOf(items_[r.begin + i], b);
                    bin[i] = b[only];
                }
                for (int k = 0; k < nBins - 1; ++k) {
                    Box leftBox, rightBox;
                    uint32_t leftCount = 0;
                    for (uint32_t i = 0; i < n; ++i) {
                        const Item &it = items_[r.begin + i];
                        bool toLeft = bin[i] <= k;
                        (toLeft ? leftBox : rightBox).grow(it.lo, it.hi);
                        leftCount += toLeft;
                    }
                    uint32_t rightCount = n - leftCount;
                    if (leftCount == 0 || rightCount == 0) continue;
                    float cost = leftCount * leftBox.halfArea() + rightCount * rightBox.halfArea();
                    if (cost < bestCost) {
                        bestCost = cost;
                        bestAxis = only;
                        bestSplit = k;
                    }
                }
            } else {
                // Instantiated for one axis and for all three, so the choice is made once per range
                auto binOne = [&](auto oneAxis, const Item &it, Bins &out)
                    __attribute__((always_inline)) {
                    int b[3];
                    binsOf(it, b);
                    const F4 itemLo = it.lo, itemHi = it.hi;
                    if constexpr (decltype(oneAxis)::value) {
                        ++out.counts[only][b[only]];
                        out.boxes[only][b[only]].grow(itemLo, itemHi);
                    } else {
                        ++out.counts[0][b[0]];
                        out.boxes[0][b[0]].grow(itemLo, itemHi);
                        ++out.counts[1][b[1]];
                        out.boxes[1][b[1]].grow(itemLo, itemHi);
                        ++out.counts[2][b[2]];
                        out.boxes[2][b[2]].grow(itemLo, itemHi);
                    }
                };
                auto binRange = [&](auto oneAxis, size_t begin, size_t end, Bins &out) {
                    out.clear(nBins, axes);
                    if (end - begin < kTwoBinSetsFrom) {
                        for (size_t i = begin; i < end; ++i) binOne(oneAxis, items_[i], out);
                        return;
                    }
                    // Neighbouring items mostly fall in the same bins: alternate between two sets
                    // of bins, so that one item's update need not wait for the previous one's
                    Bins other;
                    other.clear(nBins, axes);
                    size_t i = begin;
                    for (; i + 1 < end; i += 2) {
                        binOne(oneAxis, items_[i], out);
                        binOne(oneAxis, items_[i + 1], other);
                    }
                    if (i < end) binOne(oneAxis, items_[i], out);
                    out.merge(other, nBins, axes);
                };
                auto binItems = [&](size_t begin, size_t end, Bins &out) {
                    if (only >= 0)
                        binRange(std::true_type(), begin, end, out);
                    else
                        binRange(std::false_type(), begin, end, out);
                };
                // The top levels bin in parallel: boxes merge by min and max and counts by sums,
                // both exact, so the bins are the same for any number of threads
                // (the levels above the subtree tasks, which run one at a time)
                Bins merged;
                if (depth <= kTaskDepth && n >= kParallelFrom && threads_ > 1) {
                    std::vector<Bins> parts(static_cast<size_t>(threads_));
                    parallelFor(r.begin, r.end, parts.size(),
                                [&](size_t part, size_t begin, size_t end) {
                                    binItems(begin, end, parts[part]);
                                });
                    merged = parts[0];
                    for (size_t p = 1; p < parts.size(); ++p) merged.merge(parts[p], nBins, axes);
                } else {
                    binItems(r.begin, r.end, merged);
                }
                for (int a = 0; a < 3; ++a) {
                    if (scale[a] == 0) continue;
                    sweepBins<kBins>(
                        merged.boxes[a], merged.counts[a], nBins,
                        [](Box acc, const Box &b) {
                            acc.grow(b);
                            return acc;
                        },
                        [](const Box &b) { return b.halfArea(); }, &bestCost,
                        [&](int k) {
                            bestAxis = a;
                            bestSplit = k;
                        });
                }
            }
        }
        // In units of a node visit (a cache miss, mostly): a split costs a visit and the items'
        // tests weighted by the children's areas, a leaf its items' tests
        float area = r.box.halfArea();
        float splitCost = area > 0 && bestAxis >= 0 ? 1.0f + itemCost_ * bestCost / area : INFINITY;
        if (n <= leafItems_ && splitCost >= itemCost_ * n) {
            r.decision = Range::kLeaf;
            return;
        }
        r.decision = Range::kSplit;
        r.axis = bestAxis;
        r.bin = bestSplit;
        r.bins = nBins;
    }

    /// Splits r as decided into two measured ranges (by the SAH plane, or by count where all
    /// centroids coincide or past the depth bound).
    void split(const Range &r, Range *left, Range *right) {
        if (r.axis < 0) {
            uint32_t mid = r.begin + (r.end - r.begin) / 2;
            *left = measure(r.begin, mid);
            *right = measure(mid, r.end);
            return;
        }
        const int axis = r.axis;
        const float lo = r.centroids.lower(axis);
        const float scale = binScale(r.bins, r.centroids.upper(axis) - lo);
        // The binning clamps (c - lo) * scale to [0, bins - 1] and truncates it, and the split
        // bin is below bins - 1, so an item goes left exactly when (c - lo) * scale < bin + 1
        // (c >= lo, and the product is finite or +inf). All lanes are computed, as the binning
        // computes them, and the axis' lane decides
        const F4 lo4 = F4::of(lo, lo, lo, lo), scale4 = F4::of(scale, scale, scale, scale);
        const float limit = static_cast<float>(r.bin + 1);
        const F4 limit4 = F4::of(limit, limit, limit, limit);
        const int axisBit = 1 << axis;
        auto goesLeft = [&](F4 centroid) {
            return (lessMask((centroid - lo4) * scale4, limit4) & axisBit) != 0;
        };
        if (r.end - r.begin <= kBranchFreeUpTo) return splitSmall(r, goesLeft, left, right);
        // Partition and measure both sides in the same pass, the bounds kept in registers
        Box lBox, lCent, rBox, rCent;
        Item *items = items_.data();
        uint32_t i = r.begin, j = r.end;
        while (true) {
            while (i < j) {
                F4 c = items[i].centroid();
                if (!goesLeft(c)) break;
                lBox.grow(items[i].lo, items[i].hi);
                lCent.grow(c, c);
                ++i;
            }
            while (i < j) {
                F4 c = items[j - 1].centroid();
                if (goesLeft(c)) break;
                rBox.grow(items[j - 1].lo, items[j - 1].hi);
                rCent.grow(c, c);
                --j;
            }
            if (i >= j) break;
            std::swap(items[i], items[j - 1]);
        }
        Range l, rt;
        l.box = lBox;
        l.centroids = lCent;
        rt.box = rBox;
        rt.centroids = rCent;
        l.begin = r.begin;
        l.end = rt.begin = i;
        rt.end = r.end;
        *left = l;
        *right = rt;
    }

    /// The partition of split for a small range, item for item the same, without a branch on
    /// the items. In a small range the sides alternate at random, and the partition with a
    /// branch per item took 26 to 29 cycles an item from 5 to 64 items, against 6 to 8 in large
    /// ranges, whose neighbouring items mostly go the same way. The serial
    /// partition swaps the k-th item from the left that goes right with the k-th item from the
    /// right that goes left, until the scans meet where the left side ends: here one pass finds
    /// each item's side and grows that side's bounds (chosen by index), a second lists the items
    /// on the wrong side of the end of the left side, and the pairs swap.
    template <typename GoesLeft>
    void splitSmall(const Range &r, const GoesLeft &goesLeft, Range *left, Range *right) {
        const uint32_t begin = r.begin, end = r.end;
        Item *items = items_.data();
        uint8_t toLeft[kBranchFreeUpTo];
        Box bounds[2], centroids[2];  // [1]: the left side
        uint32_t lefts = 0;
        for (uint32_t i = begin; i < end; ++i) {
            F4 c = items[i].centroid();
            uint32_t side = goesLeft(c);
            toLeft[i - begin] = static_cast<uint8_t>(side);
            lefts += side;
            bounds[side].grow(items[i].lo, items[i].hi);
            centroids[side].grow(c, c);
        }
        const uint32_t mid = begin + lefts;
        uint32_t wrongLeft[kBranchFreeUpTo], wrongRight[kBranchFreeUpTo];
        uint32_t pairs = 0, count = 0;
        for (uint32_t i = begin; i < mid; ++i) {
            wrongLeft[pairs] = i;
            pairs += 1u - toLeft[i - begin];
        }
        for (uint32_t i = end; i-- > mid;) {
            wrongRight[count] = i;
            count += toLeft[i - begin];
        }
        for (uint32_t k = 0; k < pairs; ++k) std::swap(items[wrongLeft[k]], items[wrongRight[k]]);
        Range l, rt;
        l.box = bounds[1];
        l.centroids = centroids[1];
        rt.box = bounds[0];
        rt.centroids = centroids[0];
        l.begin = begin;
        l.end = rt.begin = mid;
        rt.end = end;
        *left = l;
        *right = rt;
    }

    /// Fills node `index` of `nodes` with up to four children made from r (already measured),
    /// recursing into interior children; returns the depth reached.
    int fillNode(uint32_t index, Range r, LargeVector<WideBvh::Node> &nodes, int depth,
                 int taskDepth, std::vector<Pending> *pending) {
        if (r.decision == Range::kUndecided) decide(r, depth);
        std::array<Range, 4> kids;
        int count = 1;
        kids[0] = r;
        while (count < 4) {
            int best = -1;
            float bestArea = -1;
            for (int i = 0; i < count; ++i)
                if (kids[i].decision == Range::kSplit && kids[i].box.halfArea() > bestArea) {
                    best = i;
                    bestArea = kids[i].box.halfArea();
                }
            if (best < 0) break;
            Range left, right;
            split(kids[best], &left, &right);
            decide(left, depth);
            decide(right, depth);
            // Keep the children in item order, so the layout follows the partition
            for (int i = count; i > best + 1; --i) kids[i] = kids[i - 1];
            kids[best] = left;
            kids[best + 1] = right;
            ++count;
        }
        WideBvh::Node node;
        for (int c = 0; c < 4; ++c) {
            for (int a = 0; a < 3; ++a) {
                node.lo[a][c] = c < count ? kids[c].box.lower(a) : INFINITY;
                node.hi[a][c] = c < count ? kids[c].box.upper(a) : -INFINITY;
            }
            node.child[c] = WideBvh::kEmpty;
        }
        int reached = depth;
        // The interior children lie side by side, so the siblings a ray visits next share
        // cache lines and pages with the one it visits first
        for (int c = 0; c < count; ++c) {
            const Range &k = kids[c];
            if (k.decision == Range::kLeaf) {
                node.child[c] = WideBvh::leafRef(k.begin, k.end - k.begin);
            } else if (depth == taskDepth) {
                pending->push_back({k, index, c, depth + 1, {}, 0});
            } else {
                node.child[c] = static_cast<uint32_t>(nodes.size());
                nodes.emplace_back();
            }
        }
        nodes[index] = node;
        for (int c = 0; c < count; ++c)
            if (kids[c].decision != Range::kLeaf && depth != taskDepth)
                reached = std::max(reached, fillNode(node.child[c], kids[c], nodes, depth + 1,
                                                     taskDepth, pending));
        return reached;
    }

    void runPending(std::vector<Pending> &pending) {
        std::atomic<size_t> next{0};
        auto work = [&] {
            for (size_t i; (i = next++) < pending.size();) {
                Pending &p = pending[i];
                p.nodes.reserve((p.range.end - p.range.begin) / 2 + 8);
                p.nodes.emplace_back();
                p.maxDepth = fillNode(0, p.range, p.nodes, p.depth, -1, nullptr);
            }
        };
        std::vector<std::thread> workers;
        for (int i = 1; i < threads_ && static_cast<size_t>(i) < pending.size(); ++i)
            workers.emplace_back(work);
        work();
        for (auto &w : workers) w.join();
        // Subtrees go after the top levels in task order; each is copied (its child indices
        // moved by its base) by the threads in parallel, so the new pages are first touched,
        // and zeroed by the kernel, on all threads
        auto &nodes = bvh_.nodes_;
        std::vector<uint32_t> bases(pending.size());
        size_t total = nodes.size();
        for (size_t i = 0; i < pending.size(); ++i) {
            bases[i] = static_cast<uint32_t>(total);
            total += pending[i].nodes.size();
        }
        nodes.resize(total);
        next = 0;
        auto copy = [&] {
            for (size_t i; (i = next++) < pending.size();) {
                Pending &p = pending[i];
                WideBvh::Node *out = nodes.data() + bases[i];
                for (const auto &n : p.nodes) {
                    *out = n;
                    for (auto &c : out->child)
                        if (c != WideBvh::kEmpty && !(c & WideBvh::kLeaf)) c += bases[i];
                    ++out;
                }
                LargeVector<WideBvh::Node>().swap(p.nodes);
            }
        };
        workers.clear();
        for (int i = 1; i < threads_ && static_cast<size_t>(i) < pending.size(); ++i)
            workers.emplace_back(copy);
        copy();
        for (auto &w : workers) w.join();
        for (size_t i = 0; i < pending.size(); ++i) {
            nodes[pending[i].node].child[pending[i].slot] = bases[i];
            bvh_.depth_ = std::max(bvh_.depth_, pending[i].maxDepth);
        }
    }

    WideBvh &bvh_;
    int threads_;
    float itemCost_;
    uint32_t leafItems_;
    LargeVector<Item> items_;
};

#if defined(__SSE2__)
namespace {
/// Lanes 0, 1 and 2 of v, each in all four lanes of its own vector
void broadcastLanes(__m128 v, __m128 out[3]) {
    out[0] = _mm_shuffle_ps(v, v, _MM_SHUFFLE(0, 0, 0, 0));
    out[1] = _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 1, 1, 1));
    out[2] = _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 2, 2, 2));
}
}  // namespace

bool WideBvh::FloatRay::init(const Ray &ray, __m128 *inv) {
    const __m128d one = _mm_set1_pd(1);
    const __m128d oXY = _mm_loadu_pd(&ray.o.x), oZZ = _mm_set1_pd(ray.o.z);
    const __m128d invXY = _mm_div_pd(one, _mm_loadu_pd(&ray.d.x)),
                  invZZ = _mm_div_pd(one, _mm_set1_pd(ray.d.z));
    // Both lanes fit: |o| <= 1e30 and 1e-30 <= |inv| <= 1e30 or inv infinite (a NaN fails
    // every comparison)
    auto fits = [](__m128d o, __m128d i) {
        const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffff));
        const __m128d big = _mm_set1_pd(1e30), small = _mm_set1_pd(1e-30);
        __m128d ao = _mm_and_pd(o, magnitude), ai = _mm_and_pd(i, magnitude);
        __m128d finite = _mm_and_pd(_mm_cmpge_pd(ai, small), _mm_cmple_pd(ai, big));
        __m128d ok = _mm_and_pd(_mm_cmple_pd(ao, big),
                                _mm_or_pd(finite, _mm_cmpeq_pd(ai, _mm_set1_pd(kInfinity))));
        return _mm_movemask_pd(ok) == 3;
    };
    if (!(static_cast<int>(fits(oXY, invXY)) & static_cast<int>(fits(oZZ, invZZ)))) return false;
    // The reciprocals rounded to nearest floats in lanes 0 to 2 (an infinite one stays infinite,
    // and each keeps its sign, as none is below 1e-30)
    *inv = _mm_movelh_ps(_mm_cvtpd_ps(invXY), _mm_cvtpd_ps(invZZ));
    const __m128 negative = _mm_cmplt_ps(*inv, _mm_setzero_ps());
    // For a positive direction the near distance (b - o) * inv is smallest for the largest
    // origin: the float above o; the far distance is largest for the float below. A plane b
    // is a float, so b - oNear has the sign of b - o or is zero (a NaN distance where inv is
    // infinite, which the tests ignore)
    const __m128 up = _mm_movelh_ps(floatsAbove(oXY), floatsAbove(oZZ));
    const __m128 down = _mm_movelh_ps(floatsBelow(oXY), floatsBelow(oZZ));
    broadcastLanes(_mm_or_ps(_mm_and_ps(negative, down), _mm_andnot_ps(negative, up)), oNear);
    broadcastLanes(_mm_or_ps(_mm_and_ps(negative, up), _mm_andnot_ps(negative, down)), oFar);
    // Per sign pattern, where the near and the far planes lie: a negative direction meets the
    // hi plane first
    static constexpr auto kPlanes = [] {
        std::array<std::array<int, 6>, 8> t{};
        for (int signs = 0; signs < 8; ++signs)
            for (int a = 0; a < 3; ++a) {
                int hiNear = (signs >> a) & 1;
                t[signs][a] = (a + 3 * hiNear) * kWidth;
                t[signs][3 + a] = (3 + a - 3 * hiNear) * kWidth;
            }
        return t;
    }();
    // Element by element: std::copy of the three ints was a call to memmove
    const auto &planes = kPlanes[_mm_movemask_ps(negative) & 7];
    for (int a = 0; a < 3; ++a) {
        nearAt[a] = planes[a];
        farAt[a] = planes[3 + a];
    }
    return true;
}

bool WideBvh::FloatSlabs::init(const Ray &ray) {
    __m128 f;
    if (!FloatRay::init(ray, &f)) return false;
    broadcastLanes(f, inv);
    return true;
}

bool WideBvh::ForwardSlabs::init(const Ray &ray) {
    __m128 f;
    if (!FloatRay::init(ray, &f)) return false;
    // The float reciprocal (within half a unit of the exact one) shrunk and grown by the
    // margin: with the rounding of the margin's product, the subtraction and the node test's
    // product, the near planes' distances are no greater than the exact ones and the far
    // planes' no smaller (16 units of margin against 3 of rounding); an infinite reciprocal (a
    // zero direction component) stays infinite
    broadcastLanes(_mm_mul_ps(f, _mm_set1_ps(1 - kMargin)), invNear);
    broadcastLanes(_mm_mul_ps(f, _mm_set1_ps(1 + kMargin)), invFar);
    return true;
}
#endif

template <typename BoxOf>
void WideBvh::build(size_t n, BoxOf &&boxOf, int threads, float itemCost, int leafItems) {
    if (n >= kMaxItems)
        throw std::length_error("a BVH indexes at most 2^28 items (triangles or CSG operands)");
    if (leafItems < 1 || leafItems > kMaxLeafItems)
        throw std::invalid_argument("a BVH leaf holds 1 to 8 items");
    if (n == 0) return;
    if (threads <= 0) threads = std::max(1u, std::thread::hardware_concurrency());
    WideBvhBuilder builder(n, boxOf, *this, threads, itemCost, leafItems);
    builder.build();
    nodes_.shrink_to_fit();
    setLeafData({nullptr, 0});
}

void WideBvh::setLeafData(LeafData data) {
    static_assert(kLeaf == 0x80000000u &&
                  kEmpty >> 31 == 1);  // the far walk picks a base by the top bit
    // Lines count from the line an array starts in (a small array may start within one)
    const uintptr_t nodeStart = reinterpret_cast<uintptr_t>(nodes_.data());
    const uintptr_t leafStart = reinterpret_cast<uintptr_t>(data.base);
    const uintptr_t nodeLines = nodeStart & ~uintptr_t{63};
    leafLines_ = data.base ? leafStart & ~uintptr_t{63} : 0;
    // Each child's line from its own kind's first line: a node's, or a leaf's data (an empty
    // slot: the leaf data's first line; a leaf without data: the root). At most 2^28 slots of a
    // few hundred bytes, far below 2^32 lines
    auto ownLine = [&](uint32_t r) -> uint64_t {
        if (!(r & kLeaf)) return (nodeStart % 64 + uint64_t{r} * sizeof(Node)) / 64;
        if (r != kEmpty && data.base)
            return (leafStart % 64 + uint64_t{leafFirst(r)} * data.stride) / 64;
        return 0;
    };
    // Near: each line counted from the nodes' first line, in 8-byte steps (a line is 8 of
    // them), fits in 31 bits and a sign; without leaf data, wherever the nodes take less than
    // 16 GiB (2^27 nodes)
    const int64_t shift = data.base ? (int64_t(leafLines_) - int64_t(nodeLines)) / 64 : 0;
    auto nearSteps = [&](uint32_t r) {
        return (int64_t(ownLine(r)) + (r & kLeaf ? shift : 0)) * 8;
    };
    fetchNear_ = true;
    for (const Node &n : nodes_)
        for (int c = 0; c < kWidth && fetchNear_; ++c) {
            int64_t steps = nearSteps(n.child[c]);
            fetchNear_ = steps >= INT32_MIN && steps <= INT32_MAX;
        }
    for (Node &n : nodes_)
        for (int c = 0; c < kWidth; ++c)
            n.fetch[c] = static_cast<uint32_t>(fetchNear_ ? nearSteps(n.child[c])
                                                          : int64_t(ownLine(n.child[c])));
}

WideBvh::WideBvh(const ir::Mesh &mesh, int threads, float itemCost, int leafItems) {
    build(
        mesh.triangles.size(),
        [&](size_t i, double lo[3], double hi[3]) {
            const auto &t = mesh.triangles[i];
            const Vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]],
                       &p2 = mesh.positions[t[2]];
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min({p0[a], p1[a], p2[a]});
                hi[a] = std::max({p0[a], p1[a], p2[a]});
            }
        },
        threads, itemCost, leafItems);
}

WideBvh::WideBvh(const std::vector<Bounds3> &items, int threads, float itemCost, int leafItems) {
    build(
        items.size(),
        [&](size_t i, double lo[3], double hi[3]) {
            for (int a = 0; a < 3; ++a) {
                lo[a] = items[i].min[a];
                hi[a] = items[i].max[a];
            }
        },
        threads, itemCost, leafItems);
}

}  // namespace rt
