// SPDX-License-Identifier: MIT
// A CSG tree as one solid: span lists of the leaves merged bottom-up, with subtrees skipped by
// their bounds and by the pruning rules (empty intersection operand, empty difference minuend).
#pragma once

#include <memory>
#include <vector>

#include "core/bvh/wide_bvh.h"
#include "core/csg/span_ops.h"
#include "core/geometry/shape.h"

namespace rt {

/// A union or difference with at least this many operands finds the ones a ray reaches
/// through a BVH over their bounds; below it, testing each operand's bounds is as fast.
/// Intersections have none: a ray that hits needs every operand's spans, and one that misses
/// inside the common part of the operands' bounds (the node's bounds, tested first) is inside
/// every operand's bounds too, so bounds cannot find the operand that empties the result;
/// taking operands out of order would change which coincident face wins a tie.
constexpr size_t kCsgBvhMinOperands = 16;

class CsgShape final : public Shape {
  public:
    enum class Op { Leaf, Union, Intersection, Difference };

    /// Builder: add nodes bottom-up; the last node added is the root.
    int addLeaf(std::unique_ptr<LeafShape> leaf);
    int addOp(Op op, std::vector<int> children);

    Bounds3 worldBounds() const override {
        return nodes_.empty() ? Bounds3() : nodes_.back().bounds;
    }
    void spans(const Ray &ray, double tMin, double tMax, SpanList &out,
               SpanScratch &scratch) const override;
    bool inside(const Vec3 &p) const override;
    size_t primitiveCount() const override { return leaves_.size(); }

    const std::vector<std::unique_ptr<LeafShape>> &leaves() const { return leaves_; }
    /// Hands over the primitive of a tree that has exactly one; the shape is empty afterwards.
    std::unique_ptr<LeafShape> releaseOnlyLeaf();
    /// Moves another tree's nodes and primitives into this one; returns the index of its root
    /// (-1 for an empty tree).
    int absorb(CsgShape &&other);

    /// Off: every subtree is evaluated over the whole ray, for checking that pruning by bounds
    /// and by the rules never changes a picture.
    void setPruning(bool on) { prune_ = on; }

  private:
    struct Node {
        Op op = Op::Leaf;
        Bounds3 bounds;
        std::vector<int> children;
        const LeafShape *leaf = nullptr;
        /// Unions and differences of many operands: a BVH over the bounds of the operands
        /// after `bvhFirst` (all of a union's, a difference's subtrahends), so a ray visits
        /// only those it reaches instead of testing every operand's bounds.
        std::unique_ptr<WideBvh> bvh;
        size_t bvhFirst = 0;
        /// A boolean node of exactly two operands, each a convex primitive (a chamfer, a
        /// boss, a hole through a plate): their one span each, merged without span lists.
        const PrimitiveInstance *convexA = nullptr, *convexB = nullptr;
    };

    /// `invDir`: the reciprocal of ray.d, computed once per ray for every bounds test.
    void evaluate(int node, const Ray &ray, const Vec3 &invDir, double w0, double w1, SpanList &out,
                  SpanScratch &scratch) const;
    /// evaluate() for a boolean node whose bounds the ray meets within [w0, w1]: its operands
    /// merged. Out of line, so a leaf's evaluation (most calls) does not set up its frame.
    void evaluateOperation(const Node &node, const Ray &ray, const Vec3 &invDir, double w0,
                           double w1, SpanList &out, SpanScratch &scratch) const;
    /// evaluateOperation() for a node with convexA and convexB, with pruning on: the same
    /// steps, bounds tests, counters and result, from the operands' single spans.
    void evaluateConvexPair(const Node &node, const Ray &ray, const Vec3 &invDir, double w0,
                            double w1, SpanList &out, SpanScratch &scratch) const;
    bool insideNode(int node, const Vec3 &p) const;
    /// Whether p is inside any operand in the BVH of `node` (only those whose bounds hold p
    /// are tested).
    bool anyOperandInside(const Node &node, const Vec3 &p) const;
    /// The operands (node indices) of a node with a BVH that the ray may reach within
    /// [w0, w1], in the node's order.
    void reachedOperands(const Node &node, const Ray &ray, double w0, double w1,
                         std::vector<int> &out) const;

    std::vector<Node> nodes_;
    std::vector<std::unique_ptr<LeafShape>> leaves_;
    bool prune_ = true;
};

}  // namespace rt
