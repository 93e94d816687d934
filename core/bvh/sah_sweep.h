// SPDX-License-Identifier: MIT
// The sweep of the binned surface area heuristic over the bins of one axis, shared by the
// scene's BVH (double boxes, core/bvh/bvh.cpp) and the four-wide one (float boxes,
// core/bvh/wide_bvh.cpp).
#pragma once

namespace rt {

/// For each plane after bin k (0 <= k < bins - 1) with items on both sides, the cost
/// count(left) * area(left) + count(right) * area(right), where a side's box is the union of its
/// bins' boxes (unite(a, b) gives it, area(box) its area, in Real). A cost below *bestCost
/// replaces it and calls onBetter(k): the first plane of equal costs wins. Box() is empty.
template <int kMaxBins, typename Real, typename Box, typename Count, typename Unite, typename Area,
          typename OnBetter>
void sweepBins(const Box *boxes, const Count *counts, int bins, Unite &&unite, Area &&area,
               Real *bestCost, OnBetter &&onBetter) {
    // From the right: the area and count of every right side
    Real rightArea[kMaxBins];
    Count rightCount[kMaxBins];
    Box acc = Box();
    Count cnt = 0;
    for (int k = bins - 1; k > 0; --k) {
        acc = unite(acc, boxes[k]);
        cnt += counts[k];
        rightArea[k] = area(acc);
        rightCount[k] = cnt;
    }
    acc = Box();
    cnt = 0;
    for (int k = 0; k < bins - 1; ++k) {
        acc = unite(acc, boxes[k]);
        cnt += counts[k];
        if (cnt == 0 || rightCount[k + 1] == 0) continue;
        Real cost = cnt * area(acc) + rightCount[k + 1] * rightArea[k + 1];
        if (cost < *bestCost) {
            *bestCost = cost;
            onBetter(k);
        }
    }
}

}  // namespace rt
