// SPDX-License-Identifier: MIT
// CSG span evaluation with a window of interest and bounds pruning.
#include "core/csg/csg_shape.h"

#include <algorithm>

namespace rt {

namespace {

SpanOp spanOpOf(CsgShape::Op op) {
    return op == CsgShape::Op::Union          ? SpanOp::Union
           : op == CsgShape::Op::Intersection ? SpanOp::Intersection
                                              : SpanOp::Difference;
}

/// Narrows the window [w0, w1] to a result so far that runs from `in` to `out`, with the tie
/// tolerance as slack, so an operand that only touches it is still merged and its coincident
/// faces are noticed.
void narrowWindow(const Ray &ray, double in, double out, double &w0, double &w1) {
    w0 = std::max(w0, in - tieEpsilon(ray.o, in));
    w1 = std::min(w1, out + tieEpsilon(ray.o, out));
}

}  // namespace

int CsgShape::addLeaf(std::unique_ptr<LeafShape> leaf) {
    Node n;
    n.op = Op::Leaf;
    n.bounds = leaf->worldBounds();
    n.leaf = leaf.get();
    leaves_.push_back(std::move(leaf));
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size()) - 1;
}

int CsgShape::addOp(Op op, std::vector<int> children) {
    Node n;
    n.op = op;
    switch (op) {
        case Op::Union:
            for (int c : children) n.bounds = unionBounds(n.bounds, nodes_[c].bounds);
            break;
        case Op::Intersection:
            n.bounds = Bounds3::infinite();
            for (int c : children) n.bounds = intersectBounds(n.bounds, nodes_[c].bounds);
            if (n.bounds.isEmpty()) n.bounds = Bounds3();
            break;
        case Op::Difference:
            if (!children.empty()) n.bounds = nodes_[children.front()].bounds;
            break;
        case Op::Leaf:
            break;
    }
    n.children = std::move(children);
    if (op != Op::Leaf && n.children.size() == 2) {
        auto convexLeaf = [&](int c) -> const PrimitiveInstance * {
            const auto *p = dynamic_cast<const PrimitiveInstance *>(nodes_[c].leaf);
            return p && p->convex() ? p : nullptr;
        };
        n.convexA = convexLeaf(n.children[0]);
        n.convexB = convexLeaf(n.children[1]);
        if (!n.convexA || !n.convexB) n.convexA = n.convexB = nullptr;
    }
    n.bvhFirst = op == Op::Difference ? 1 : 0;
    if ((op == Op::Union || op == Op::Difference) &&
        n.children.size() >= n.bvhFirst + kCsgBvhMinOperands) {
        std::vector<Bounds3> bounds;
        for (size_t i = n.bvhFirst; i < n.children.size(); ++i)
            bounds.push_back(nodes_[n.children[i]].bounds);
        n.bvh = std::make_unique<WideBvh>(bounds);
    }
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size()) - 1;
}

void CsgShape::reachedOperands(const Node &node, const Ray &ray, double w0, double w1,
                               std::vector<int> &out) const {
    out.clear();
    double tMax = w1;
    node.bvh->traverse(ray, w0, &tMax, [&](uint32_t item, double *) {
        out.push_back(static_cast<int>(item + node.bvhFirst));  // position among the operands
        return false;
    });
    // In operand order, so the result is the one the plain loop gives
    std::sort(out.begin(), out.end());
    for (int &i : out) i = node.children[i];
}

std::unique_ptr<LeafShape> CsgShape::releaseOnlyLeaf() {
    std::unique_ptr<LeafShape> leaf = std::move(leaves_.front());
    leaves_.clear();
    nodes_.clear();
    return leaf;
}

int CsgShape::absorb(CsgShape &&other) {
    if (other.nodes_.empty()) return -1;
    int offset = static_cast<int>(nodes_.size());
    for (Node &n : other.nodes_) {
        for (int &c : n.children) c += offset;
        nodes_.push_back(std::move(n));
    }
    for (auto &leaf : other.leaves_) leaves_.push_back(std::move(leaf));
    other.nodes_.clear();
    other.leaves_.clear();
    return static_cast<int>(nodes_.size()) - 1;
}

void CsgShape::spans(const Ray &ray, double tMin, double tMax, SpanList &out,
                     SpanScratch &scratch) const {
    out.clear();
    if (!nodes_.empty())
        evaluate(static_cast<int>(nodes_.size()) - 1, ray,
                 Vec3(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z), tMin, tMax, out, scratch);
}

// Only the state of the ray inside [w0, w1] decides the crossings there, and a boolean result's
// state at t depends only on its operands' states at t. So a subtree whose bounds the ray misses
// within the window contributes nothing, and an intersection or difference can narrow the window
// of later operands to the extent of its result so far.
// Inlined where it is called (GCC 12 left it out of line once it grew the pair's test: 1.4 %
// more instructions on openscad_model); the boolean nodes' merges are the calls
__attribute__((always_inline)) inline void CsgShape::evaluate(int index, const Ray &ray,
                                                              const Vec3 &invDir, double w0,
                                                              double w1, SpanList &out,
                                                              SpanScratch &scratch) const {
    const Node &node = nodes_[index];
    out.clear();
    if (prune_ && !node.bounds.intersectP(ray, invDir, w0, w1)) {
        ++scratch.prunedSubtrees;
        return;
    }
    if (node.op == Op::Leaf) {
        node.leaf->lineSpans(ray, out);
        return;
    }
    if (node.convexA && prune_) {
        evaluateConvexPair(node, ray, invDir, w0, w1, out, scratch);
        return;
    }
    evaluateOperation(node, ray, invDir, w0, w1, out, scratch);
}

// evaluateOperation's steps for two operands with one span each at most, written out: the first
// operand over the window, the window narrowed to it (not for a union), the second operand over
// that, then their merge, with the same bounds tests, pruning rules and counters
void CsgShape::evaluateConvexPair(const Node &node, const Ray &ray, const Vec3 &invDir, double w0,
                                  double w1, SpanList &out, SpanScratch &scratch) const {
    const Node &a = nodes_[node.children[0]], &b = nodes_[node.children[1]];
    Span sa, sb;
    bool hasA = false, hasB = false;
    if (!a.bounds.intersectP(ray, invDir, w0, w1))
        ++scratch.prunedSubtrees;
    else
        hasA = node.convexA->lineSpan(ray, &sa);
    if (node.op != Op::Union) {
        if (!hasA) {
            // Pruning rule: nothing left of the minuend or the intersection so far
            ++scratch.prunedSubtrees;
            return;
        }
        narrowWindow(ray, sa.in.t, sa.out.t, w0, w1);
    }
    if (!b.bounds.intersectP(ray, invDir, w0, w1))
        ++scratch.prunedSubtrees;
    else
        hasB = node.convexB->lineSpan(ray, &sb);
    if (!hasB) {
        // An intersection with nothing is empty; a union or difference with nothing is unchanged
        if (hasA && node.op != Op::Intersection) out.push_back(sa);
        return;
    }
    if (!hasA) {  // only a union gets here
        out.push_back(sb);
        return;
    }
    combineSpans({&sa, 1}, {&sb, 1}, spanOpOf(node.op), out, tieEpsilon(ray.o, sa.in.t),
                 &scratch.cancelledTie);
    ++scratch.spanOps;
}

void CsgShape::evaluateOperation(const Node &node, const Ray &ray, const Vec3 &invDir, double w0,
                                 double w1, SpanList &out, SpanScratch &scratch) const {
    ScratchList operand(scratch), merged(scratch);
    bool first = true;
    // Merges one operand into `out`; false when the result is settled (pruned)
    auto merge = [&](int child) {
        if (prune_ && !first && node.op != Op::Union) {
            if (out.empty()) {
                // Pruning rule: nothing left of the minuend or the intersection so far
                ++scratch.prunedSubtrees;
                return false;
            }
            // narrowWindow() written out: called here, GCC 12 compiles the operand loop into
            // 3.5 % more instructions on openscad_model and 1.7 % on csg_part (callgrind)
            w0 = std::max(w0, out.front().in.t - tieEpsilon(ray.o, out.front().in.t));
            w1 = std::min(w1, out.back().out.t + tieEpsilon(ray.o, out.back().out.t));
        }
        if (first) {
            evaluate(child, ray, invDir, w0, w1, out, scratch);
            first = false;
            return true;
        }
        evaluate(child, ray, invDir, w0, w1, *operand, scratch);
        if (operand->empty()) {
            if (node.op == Op::Intersection) {
                out.clear();
                if (prune_) return false;
            }
            return true;  // union or difference with nothing: unchanged
        }
        if (out.empty()) {
            // Only without pruning does an emptied intersection or difference get here
            if (node.op == Op::Union) out.swap(*operand);
            return true;
        }
        combineSpans(out, *operand, spanOpOf(node.op), *merged, tieEpsilon(ray.o, out.front().in.t),
                     &scratch.cancelledTie);
        ++scratch.spanOps;
        out.swap(*merged);
        return true;
    };
    if (!node.bvh || !prune_) {
        for (int child : node.children)
            if (!merge(child)) return;
        return;
    }
    // Many operands: a difference's minuend first, then only the operands whose bounds the
    // ray reaches within the window (narrowed by the minuend), in their order
    for (size_t k = 0; k < node.bvhFirst; ++k)
        if (!merge(node.children[k])) return;
    if (node.op == Op::Difference) {
        if (out.empty()) {
            ++scratch.prunedSubtrees;
            return;
        }
        narrowWindow(ray, out.front().in.t, out.back().out.t, w0, w1);
    }
    // From the scratch pool: an allocation per ray and node cost 4 to 11 % of the hit time
    // of plates and unions (csg_bench)
    ScratchIndices reached(scratch);
    reachedOperands(node, ray, w0, w1, *reached);
    for (int child : *reached)
        if (!merge(child)) return;
}

bool CsgShape::inside(const Vec3 &p) const {
    return !nodes_.empty() && insideNode(static_cast<int>(nodes_.size()) - 1, p);
}

bool CsgShape::insideNode(int index, const Vec3 &p) const {
    const Node &node = nodes_[index];
    if (!node.bounds.contains(p)) return false;
    switch (node.op) {
        case Op::Leaf:
            return node.leaf->inside(p);
        case Op::Union:
            if (node.bvh && prune_) return anyOperandInside(node, p);
            return std::any_of(node.children.begin(), node.children.end(),
                               [&](int c) { return insideNode(c, p); });
        case Op::Intersection:
            return !node.children.empty() && std::all_of(node.children.begin(), node.children.end(),
                                                         [&](int c) { return insideNode(c, p); });
        case Op::Difference: {
            if (node.children.empty() || !insideNode(node.children.front(), p)) return false;
            if (node.bvh && prune_) return !anyOperandInside(node, p);
            for (size_t i = 1; i < node.children.size(); ++i)
                if (insideNode(node.children[i], p)) return false;
            return true;
        }
    }
    return false;
}

bool CsgShape::anyOperandInside(const Node &node, const Vec3 &p) const {
    // The operands whose bounds contain p are among those a ray from p reaches at t = 0 (a zero
    // direction component gives an infinite or NaN slab distance, which the node test passes)
    bool found = false;
    double tMax = 0;
    node.bvh->traverse(Ray(p, Vec3(1, 0, 0)), 0, &tMax, [&](uint32_t item, double *) {
        found = insideNode(node.children[item + node.bvhFirst], p);
        return found;
    });
    return found;
}

}  // namespace rt
