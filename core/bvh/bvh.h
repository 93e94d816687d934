// SPDX-License-Identifier: MIT
// Bounding volume hierarchy over world bounds: binned SAH build (Wald 2007; pbrt-v3 section
// 4.3.2), flattened depth-first nodes, front-to-back traversal with a caller-supplied visitor.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/math/bounds3.h"

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

    Bvh() = default;
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
    void traverse(const Ray &ray, double tMin, double *tMax, Visit &&visit) const;

  private:
    struct BuildItem {
        Bounds3 bounds;
        Vec3 centroid;
        uint32_t index;
    };
    int build(std::vector<BuildItem> &items, size_t begin, size_t end, int depth);
    static bool hitNode(const Bounds3 &b, const Ray &ray, const Vec3 &invDir, const int dirIsNeg[3],
                        double tMin, double tMax);

    std::vector<Node> nodes_;
    std::vector<uint32_t> order_;
    int depth_ = 0;
};

inline bool Bvh::hitNode(const Bounds3 &b, const Ray &ray, const Vec3 &invDir,
                         const int dirIsNeg[3], double tMin, double tMax) {
    // pbrt-v3 Bounds3::IntersectP with precomputed reciprocal; NaN-safe comparisons
    const Vec3 *corners[2] = {&b.min, &b.max};
    double t0 = tMin, t1 = tMax;
    for (int i = 0; i < 3; ++i) {
        double tNear = ((*corners[dirIsNeg[i]])[i] - ray.o[i]) * invDir[i];
        double tFar = ((*corners[1 - dirIsNeg[i]])[i] - ray.o[i]) * invDir[i];
        // Grow the far distance by its rounding error (pbrt's 1 + 2 gamma(3)) away from zero:
        // span queries look behind the origin too (tMin = -inf), and scaling a negative tFar
        // would shrink it, so a flat node (one face of a mesh) behind the origin was missed
        tFar += 2 * gamma(3) * std::abs(tFar);
        t0 = tNear > t0 ? tNear : t0;
        t1 = tFar < t1 ? tFar : t1;
        if (t0 > t1) return false;
    }
    return true;
}

template <typename Visit>
void Bvh::traverse(const Ray &ray, double tMin, double *tMax, Visit &&visit) const {
    if (nodes_.empty()) return;
    Vec3 invDir(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z);
    int dirIsNeg[3] = {invDir.x < 0, invDir.y < 0, invDir.z < 0};
    uint32_t stack[128];
    int top = 0;
    uint32_t current = 0;
    while (true) {
        const Node &node = nodes_[current];
        if (hitNode(node.bounds, ray, invDir, dirIsNeg, tMin, *tMax)) {
            if (node.count > 0) {
                for (uint32_t i = 0; i < node.count; ++i)
                    if (visit(order_[node.offset + i], tMax)) return;
                if (top == 0) return;
                current = stack[--top];
            } else if (dirIsNeg[node.axis]) {
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

}  // namespace rt
