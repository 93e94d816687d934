// SPDX-License-Identifier: MIT
// Binned SAH construction of the flattened BVH.
#include "core/bvh/bvh.h"

#include <algorithm>
#include <array>

#include "core/bvh/sah_sweep.h"

namespace rt {

namespace {

/// The volume of a box (0 for an empty or flat one).
double boxVolume(const Bounds3 &b) {
    Vec3 d = b.diagonal();
    return d.x > 0 && d.y > 0 && d.z > 0 ? d.x * d.y * d.z : 0;
}

}  // namespace

Bvh::Bvh(const std::vector<Bounds3> &itemBounds) {
    std::vector<BuildItem> items;
    items.reserve(itemBounds.size());
    for (size_t i = 0; i < itemBounds.size(); ++i)
        items.push_back({itemBounds[i], itemBounds[i].centroid(), static_cast<uint32_t>(i)});
    if (items.empty()) return;
    nodes_.reserve(2 * items.size());
    order_.reserve(items.size());
    build(items, 0, items.size(), 1);
}

int Bvh::build(std::vector<BuildItem> &items, size_t begin, size_t end, int depth) {
    depth_ = std::max(depth_, depth);
    int nodeIndex = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Bounds3 bounds, centroidBounds;
    for (size_t i = begin; i < end; ++i) {
        bounds = unionBounds(bounds, items[i].bounds);
        centroidBounds = unionBounds(centroidBounds, items[i].centroid);
    }
    nodes_[nodeIndex].bounds = bounds;
    size_t n = end - begin;

    auto makeLeaf = [&]() {
        nodes_[nodeIndex].offset = static_cast<uint32_t>(order_.size());
        nodes_[nodeIndex].count = static_cast<uint32_t>(n);
        for (size_t i = begin; i < end; ++i) order_.push_back(items[i].index);
        return nodeIndex;
    };
    // The traversal stack (128) bounds the depth; a degenerate split sequence ends in a leaf
    constexpr int kMaxDepth = 100;
    if (n <= 1 || depth >= kMaxDepth) return makeLeaf();

    // Bin the centroids on all three axes in one pass over the items; small nodes, where the
    // fixed cost of the bins dominates, only on the axis of largest extent
    Vec3 extent = centroidBounds.diagonal();
    Vec3 binScale;
    constexpr size_t kAllAxesFrom = 64;
    int longest = maxDimension(extent);
    for (int axis = 0; axis < 3; ++axis)
        binScale[axis] =
            extent[axis] > 0 && (n >= kAllAxesFrom || axis == longest) ? kBins / extent[axis] : 0;
    // Clamped before the conversion: an unbounded item's centroid is NaN or infinite, whose
    // conversion to int is undefined (NaN goes to bin 0)
    auto binOf = [&](const Vec3 &c, int axis) {
        double b = (c[axis] - centroidBounds.min[axis]) * binScale[axis];
        return b >= kBins - 1 ? kBins - 1 : (b > 0 ? static_cast<int>(b) : 0);
    };
    std::array<std::array<int, kBins>, 3> counts{};
    std::array<std::array<Bounds3, kBins>, 3> binBounds;
    for (size_t i = begin; i < end; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            if (binScale[axis] == 0) continue;
            int b = binOf(items[i].centroid, axis);
            ++counts[axis][b];
            binBounds[axis][b] = unionBounds(binBounds[axis][b], items[i].bounds);
        }
    // Evaluate the cost (the items times each side's chance of a visit) at kBins-1 planes on each
    // axis
    int bestAxis = -1, bestSplit = -1;
    double bestCost = kInfinity;
    // A child's chance of a visit: its shares of the parent's area and volume (kVolumeWeight),
    // or of its area alone where the parent is flat or unbounded
    double area = bounds.surfaceArea(), volume = boxVolume(bounds);
    bool byVolume = volume > 0 && volume < kInfinity && area > 0 && area < kInfinity;
    auto chance = [&](const Bounds3 &b) {
        return byVolume ? (1 - kVolumeWeight) * b.surfaceArea() / area +
                              kVolumeWeight * boxVolume(b) / volume
                        : b.surfaceArea();
    };
    for (int axis = 0; axis < 3; ++axis) {
        if (binScale[axis] == 0) continue;
        sweepBins<kBins>(
            binBounds[axis].data(), counts[axis].data(), kBins,
            [](const Bounds3 &a, const Bounds3 &b) { return unionBounds(a, b); }, chance, &bestCost,
            [&](int b) {
                bestAxis = axis;
                bestSplit = b;
            });
    }
    // Relative cost: one traversal step (1/8 of an item test) plus the expected item tests
    double parentChance = byVolume ? 1.0 : area;
    double leafCost = static_cast<double>(n);
    double splitCost = parentChance > 0 ? 0.125 + bestCost / parentChance : kInfinity;
    if (n <= static_cast<size_t>(kMaxLeafItems) && (bestAxis < 0 || splitCost >= leafCost))
        return makeLeaf();
    size_t mid;
    if (bestAxis >= 0) {
        auto pivot = std::partition(
            items.begin() + begin, items.begin() + end,
            [&](const BuildItem &it) { return binOf(it.centroid, bestAxis) <= bestSplit; });
        mid = static_cast<size_t>(pivot - items.begin());
    } else {
        // All centroids coincide: split by count so leaves stay small
        bestAxis = 0;
        mid = begin + n / 2;
    }
    nodes_[nodeIndex].axis = static_cast<uint8_t>(bestAxis);
    build(items, begin, mid, depth + 1);
    nodes_[nodeIndex].offset = static_cast<uint32_t>(build(items, mid, end, depth + 1));
    return nodeIndex;
}

}  // namespace rt
