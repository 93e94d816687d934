// SPDX-License-Identifier: MIT
// Span-list CSG: the lecture's worked example with exact span lists, the coincident-face
// tie-break, pruning, and windowed evaluation against full evaluation on random trees.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

#include "core/csg/csg_shape.h"
#include "core/csg/span_ops.h"
#include "core/math/rng.h"

namespace rt {
namespace {

std::unique_ptr<PrimitiveInstance> sphereAt(const Vec3 &c, double r, int material = 0) {
    return std::make_unique<PrimitiveInstance>(
        std::make_unique<Sphere>(r), *Transform::fromMatrix(Mat4::translate(c)), material);
}

/// z coordinates of the span boundaries along the lecture's ray, which runs up the z axis
/// from z = -10 (so z = t - 10).
std::vector<double> boundaries(const SpanList &l) {
    std::vector<double> z;
    for (const Span &s : l) {
        z.push_back(s.in.t - 10);
        z.push_back(s.out.t - 10);
    }
    return z;
}

class LectureExample : public ::testing::Test {
  protected:
    // Spheres A (centre (0,0,8), r 5), B ((0,0,9), r 3), C ((0,-3,8), r 2); the ray from
    // (0,0,-10) through the origin
    Ray ray{Vec3(0, 0, -10), Vec3(0, 0, 1)};
    SpanScratch scratch;

    SpanList evaluate(CsgShape &shape) {
        SpanList out;
        shape.spans(ray, -kInfinity, kInfinity, out, scratch);
        return out;
    }
    int addA(CsgShape &s) { return s.addLeaf(sphereAt({0, 0, 8}, 5)); }
    int addB(CsgShape &s) { return s.addLeaf(sphereAt({0, 0, 9}, 3)); }
    int addC(CsgShape &s) { return s.addLeaf(sphereAt({0, -3, 8}, 2)); }
};

TEST_F(LectureExample, UnionOfAllThree) {
    CsgShape s;
    int a = addA(s), b = addB(s), c = addC(s);
    s.addOp(CsgShape::Op::Union, {a, b, c});
    EXPECT_EQ(boundaries(evaluate(s)), (std::vector<double>{3, 13}));
}

TEST_F(LectureExample, AMinusB) {
    CsgShape s;
    int a = addA(s), b = addB(s);
    s.addOp(CsgShape::Op::Difference, {a, b});
    SpanList l = evaluate(s);
    EXPECT_EQ(boundaries(l), (std::vector<double>{3, 6, 12, 13}));
    // The inner boundaries are B's surface
    ASSERT_EQ(l.size(), 2u);
    EXPECT_EQ(l[0].out.leaf, s.leaves()[1].get());
    EXPECT_EQ(l[1].in.leaf, s.leaves()[1].get());
}

TEST_F(LectureExample, BMinusAIntersectCIsEmpty) {
    CsgShape s;
    int a = addA(s), b = addB(s), c = addC(s);
    int bma = s.addOp(CsgShape::Op::Difference, {b, a});
    s.addOp(CsgShape::Op::Intersection, {bma, c});
    EXPECT_TRUE(evaluate(s).empty());
}

TEST_F(LectureExample, AUnionBIntersectC) {
    CsgShape s;
    int a = addA(s), b = addB(s), c = addC(s);
    int bc = s.addOp(CsgShape::Op::Intersection, {b, c});
    s.addOp(CsgShape::Op::Union, {a, bc});
    EXPECT_EQ(boundaries(evaluate(s)), (std::vector<double>{3, 13}));
}

TEST_F(LectureExample, PruningSkipsSubtrahendsOfAnEmptyMinuend) {
    CsgShape s;
    int c = addC(s), a = addA(s), b = addB(s);
    s.addOp(CsgShape::Op::Difference, {c, a, b});  // C misses the ray entirely
    EXPECT_TRUE(evaluate(s).empty());
    EXPECT_EQ(scratch.spanOps, 0);
    EXPECT_GE(scratch.prunedSubtrees, 1);
}

// Span lists for one ray straight along +x, built from intervals with given tie ranks
struct FakeLeaf {
    std::unique_ptr<PrimitiveInstance> leaf;
};

SpanList spansOf(std::initializer_list<std::pair<double, double>> iv,
                 const PrimitiveInstance *leaf) {
    SpanList l;
    for (auto [a, b] : iv) l.push_back({{a, leaf, 0}, {b, leaf, 1}});
    return l;
}

class TieBreak : public ::testing::Test {
  protected:
    void SetUp() override {
        low = std::make_unique<PrimitiveInstance>(std::make_unique<Sphere>(1), Transform(), 0);
        high = std::make_unique<PrimitiveInstance>(std::make_unique<Sphere>(1), Transform(), 1);
        low->tieRank = 0;
        high->tieRank = 1;
    }
    std::unique_ptr<PrimitiveInstance> low, high;
};

TEST_F(TieBreak, TouchingSolidsFuseInAUnion) {
    SpanList out;
    combineSpans(spansOf({{0, 1}}, high.get()), spansOf({{1, 2}}, low.get()), SpanOp::Union, out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].in.t, 0);
    EXPECT_EQ(out[0].out.t, 2);
}

TEST_F(TieBreak, SolidsMeetingInAPlaneIntersectInNothing) {
    SpanList out;
    combineSpans(spansOf({{0, 1}}, high.get()), spansOf({{1, 2}}, low.get()), SpanOp::Intersection,
                 out);
    EXPECT_TRUE(out.empty());
}

TEST_F(TieBreak, DifferenceWithSharedFaces) {
    SpanList out;
    // B shares A's entry face: the result starts where B ends, on B's surface
    combineSpans(spansOf({{0, 2}}, high.get()), spansOf({{0, 1}}, low.get()), SpanOp::Difference,
                 out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].in.t, 1);
    EXPECT_EQ(out[0].in.leaf, low.get());
    EXPECT_EQ(out[0].out.leaf, high.get());
    // B exactly covers A: nothing left
    combineSpans(spansOf({{0, 2}}, high.get()), spansOf({{0, 2}}, low.get()), SpanOp::Difference,
                 out);
    EXPECT_TRUE(out.empty());
    // B ends exactly where A begins, or begins where A ends: A untouched, faces and all
    combineSpans(spansOf({{1, 2}}, high.get()), spansOf({{0, 1}}, low.get()), SpanOp::Difference,
                 out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].in.leaf, high.get());
    combineSpans(spansOf({{0, 1}}, high.get()), spansOf({{1, 2}}, low.get()), SpanOp::Difference,
                 out);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].out.leaf, high.get());
}

TEST_F(TieBreak, FacesRoundingApartCountAsCoincident) {
    // A flush pocket: the subtrahend's exit lands one ulp before the minuend's (the faces are
    // the same plane reached through different transforms). Within the tolerance no sliver of
    // the minuend remains; with exact ties only, a lid 1 ulp thick would close the pocket.
    double t1 = 0.0306, t1b = std::nextafter(t1, 0.0);
    SpanList out;
    combineSpans(spansOf({{-1, t1}}, high.get()), spansOf({{0.01, t1b}}, low.get()),
                 SpanOp::Difference, out, 1e-12);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].out.t, 0.01);
    combineSpans(spansOf({{-1, t1}}, high.get()), spansOf({{0.01, t1b}}, low.get()),
                 SpanOp::Difference, out, 0);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[1].in.t, t1b);  // the sliver
    EXPECT_EQ(out[1].out.t, t1);
}

TEST_F(TieBreak, CoincidentFacesIgnoreOperandOrder) {
    SpanList ab, ba;
    SpanList a = spansOf({{0, 2}}, high.get()), b = spansOf({{0, 1}}, low.get());
    combineSpans(a, b, SpanOp::Union, ab);
    combineSpans(b, a, SpanOp::Union, ba);
    ASSERT_EQ(ab.size(), 1u);
    ASSERT_EQ(ba.size(), 1u);
    EXPECT_EQ(ab[0].in.leaf, low.get());  // lower rank wins the shared entry face
    EXPECT_EQ(ba[0].in.leaf, low.get());
    EXPECT_EQ(ab[0].out.leaf, ba[0].out.leaf);
    SpanList i1, i2;
    combineSpans(a, b, SpanOp::Intersection, i1);
    combineSpans(b, a, SpanOp::Intersection, i2);
    ASSERT_EQ(i1.size(), 1u);
    EXPECT_EQ(i1[0].in.leaf, i2[0].in.leaf);
    EXPECT_EQ(i1[0].out.leaf, low.get());  // b's exit bounds the intersection
}

// combineSpans takes a shortcut for one span a side whose crossings are all more than tieEps
// apart across the two; it must give the sweep's result crossing for crossing (t, leaf, face,
// tie mark) and the same cancelled ties, for every operation and every order of the four
// crossings, with crossings exactly coincident, within tieEps, just beyond it, and infinite.
TEST_F(TieBreak, OneSpanEachGivesTheSweepsResult) {
    Rng rng(29);
    const double eps = 1e-6;
    // Crossing positions on a coarse grid, nudged by nothing, by less than eps or by a little more
    auto position = [&]() {
        double t = std::floor(rng.uniform() * 6);
        switch (static_cast<int>(rng.uniform() * 5)) {
            case 0:
                return t + 0.5 * eps;
            case 1:
                return t + 1.5 * eps;
            case 2:
                return rng.uniform() < 0.5 ? -kInfinity : kInfinity;
            default:
                return t;
        }
    };
    auto span = [&](const PrimitiveInstance *leaf) -> std::optional<Span> {
        double a = position(), b = position();
        if (a > b) std::swap(a, b);
        if (!(a < b)) return std::nullopt;
        Span s{{a, leaf, static_cast<int>(rng.uniform() * 6)},
               {b, leaf, static_cast<int>(rng.uniform() * 6)}};
        s.in.tie = rng.uniform() < 0.2;
        s.out.tie = rng.uniform() < 0.2;
        return s;
    };
    int shortcut = 0, checked = 0;
    for (int i = 0; i < 20000; ++i) {
        auto sa = span(low.get()), sb = span(rng.uniform() < 0.5 ? high.get() : low.get());
        if (!sa || !sb) continue;
        SpanList a{*sa}, b{*sb};
        for (SpanOp op : {SpanOp::Union, SpanOp::Intersection, SpanOp::Difference}) {
            SpanList got, want;
            double gotTie = kInfinity, wantTie = kInfinity;
            combineSpans(a, b, op, got, eps, &gotTie);
            combineSpansBySweep(a, b, op, want, eps, &wantTie);
            ASSERT_EQ(got.size(), want.size()) << i;
            for (size_t k = 0; k < got.size(); ++k)
                for (auto [g, w] :
                     {std::pair{got[k].in, want[k].in}, std::pair{got[k].out, want[k].out}}) {
                    EXPECT_EQ(g.t, w.t) << i;
                    EXPECT_EQ(g.leaf, w.leaf) << i;
                    EXPECT_EQ(g.face, w.face) << i;
                    EXPECT_EQ(g.tie, w.tie) << i;
                }
            EXPECT_EQ(gotTie, wantTie) << i;
            ++checked;
            bool apart = true;
            for (double s : {sa->in.t, sa->out.t})
                for (double t : {sb->in.t, sb->out.t}) apart = apart && std::abs(s - t) > eps;
            shortcut += apart;
        }
    }
    // Both kinds of pair were met many times
    EXPECT_GT(shortcut, 5000);
    EXPECT_GT(checked - shortcut, 5000);
}

TEST(CsgShape, TangentSpheres) {
    // Unit spheres at x = 0 and x = 2 touch at (1, 0, 0). Rays through and beside the point of
    // contact: along the line of centres, and across it, exactly and 1e-9 off tangency.
    SpanScratch scratch;
    auto eval = [&](CsgShape::Op op, const Ray &ray) {
        CsgShape s;
        int a = s.addLeaf(sphereAt({0, 0, 0}, 1)), b = s.addLeaf(sphereAt({2, 0, 0}, 1));
        s.addOp(op, {a, b});
        SpanList out;
        s.spans(ray, -kInfinity, kInfinity, out, scratch);
        for (const Span &sp : out) {
            EXPECT_TRUE(std::isfinite(sp.in.t) && std::isfinite(sp.out.t));
            EXPECT_LT(sp.in.t, sp.out.t);
        }
        return out;
    };
    Ray centres(Vec3(-5, 0, 0), Vec3(1, 0, 0));
    // Union: one solid from x = -1 to x = 3, not two spans with a zero-width gap
    SpanList u = eval(CsgShape::Op::Union, centres);
    ASSERT_EQ(u.size(), 1u);
    EXPECT_NEAR(u[0].in.t, 4, 1e-15);
    EXPECT_NEAR(u[0].out.t, 8, 1e-15);
    // Difference: the second sphere only touches the first, which stays whole
    SpanList d = eval(CsgShape::Op::Difference, centres);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_NEAR(d[0].out.t, 6, 1e-15);
    // Intersection: a point, no volume
    EXPECT_TRUE(eval(CsgShape::Op::Intersection, centres).empty());
    // Just beside the contact point the gap between the spheres (y^2 wide) is real
    SpanList beside = eval(CsgShape::Op::Union, Ray(Vec3(-5, 1e-3, 0), Vec3(1, 0, 0)));
    ASSERT_EQ(beside.size(), 2u);
    EXPECT_NEAR(beside[1].in.t - beside[0].out.t, 2 * (1 - std::sqrt(1 - 1e-6)), 1e-12);
    // Across the contact point: the line is tangent to both spheres, so nothing is hit
    Ray across(Vec3(1, -5, 0), Vec3(0, 1, 0));
    for (auto op : {CsgShape::Op::Union, CsgShape::Op::Difference, CsgShape::Op::Intersection})
        EXPECT_TRUE(eval(op, across).empty());
    // 1e-9 inside the first sphere: a chord of 2 sqrt(2e-9) through it alone
    SpanList grazing = eval(CsgShape::Op::Union, Ray(Vec3(1 - 1e-9, -5, 0), Vec3(0, 1, 0)));
    ASSERT_EQ(grazing.size(), 1u);
    double chord = 2 * std::sqrt(1 - (1 - 1e-9) * (1 - 1e-9));
    EXPECT_NEAR(grazing[0].out.t - grazing[0].in.t, chord, 1e-6 * chord);
    EXPECT_TRUE(
        eval(CsgShape::Op::Intersection, Ray(Vec3(1 - 1e-9, -5, 0), Vec3(0, 1, 0))).empty());
}

TEST(CsgShape, WindowedEvaluationAgreesWithFullEvaluation) {
    Rng rng(5);
    SpanScratch scratch;
    for (int trial = 0; trial < 40; ++trial) {
        // Random tree over 6 spheres and boxes
        CsgShape s;
        std::vector<int> nodes;
        for (int i = 0; i < 6; ++i) {
            Vec3 c(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2);
            if (i % 2)
                nodes.push_back(s.addLeaf(sphereAt(c, 0.5 + rng.uniform() * 1.5, i)));
            else
                nodes.push_back(s.addLeaf(std::make_unique<PrimitiveInstance>(
                    std::make_unique<Box>(Vec3(-1, -0.7, -0.4), Vec3(0.8, 1, 1.2)),
                    *Transform::fromMatrix(Mat4::translate(c) *
                                           Mat4::rotateAxis(30 * i, Vec3(1, 1, 0))),
                    i)));
        }
        while (nodes.size() > 1) {
            int a = nodes.back();
            nodes.pop_back();
            int b = nodes.back();
            nodes.pop_back();
            auto op = static_cast<CsgShape::Op>(1 + static_cast<int>(rng.uniform() * 3));
            nodes.insert(nodes.begin(), s.addOp(op, {b, a}));
        }
        for (int i = 0; i < 300; ++i) {
            Vec3 o(rng.uniform() * 12 - 6, rng.uniform() * 12 - 6, rng.uniform() * 12 - 6);
            Vec3 target(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
            Ray r(o, normalize(target - o));
            double tMin = rng.uniform() * 6;
            SpanList full;
            s.spans(r, -kInfinity, kInfinity, full, scratch);
            Crossing expected;
            bool want = false;
            for (const Span &sp : full) {
                if (sp.in.t > tMin) {
                    expected = sp.in;
                    want = true;
                    break;
                }
                if (sp.out.t > tMin) {
                    expected = sp.out;
                    want = true;
                    break;
                }
            }
            Crossing got;
            bool have = s.firstCrossing(r, tMin, kInfinity, &got, scratch);
            ASSERT_EQ(want, have);
            if (want) {
                EXPECT_EQ(got.t, expected.t);
                EXPECT_EQ(got.leaf, expected.leaf);
            }
            // Inside test agrees with the span classification just past tMin
            double probe = tMin + 1e-3;
            bool inSpan = false;
            for (const Span &sp : full) inSpan |= sp.in.t < probe && probe < sp.out.t;
            bool nearBoundary = false;
            for (const Span &sp : full)
                nearBoundary |=
                    std::abs(sp.in.t - probe) < 1e-9 || std::abs(sp.out.t - probe) < 1e-9;
            if (!nearBoundary) {
                EXPECT_EQ(s.inside(r.at(probe)), inSpan);
            }
        }
    }
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

/// A plate minus a grid of spheres, plus a union of spheres over it: both nodes have enough
/// operands for a BVH. The spans must be those of the plain loop (pruning off), bit for bit.
TEST(CsgShape, ManyOperandsThroughABvhGiveThePlainLoopsSpans) {
    auto build = [](CsgShape &s) {
        std::vector<int> diff{s.addLeaf(std::make_unique<PrimitiveInstance>(
            std::make_unique<Box>(Vec3(0, 0, 0), Vec3(10, 10, 1)), Transform(), 0))};
        std::vector<int> bumps;
        for (int i = 0; i < 10; ++i)
            for (int j = 0; j < 10; ++j) {
                diff.push_back(s.addLeaf(sphereAt({i + 0.5, j + 0.5, 0.5}, 0.3 + 0.01 * j, 1)));
                if ((i + j) % 3 == 0)
                    bumps.push_back(s.addLeaf(sphereAt({i + 0.2, j + 0.7, 1}, 0.45, 2)));
            }
        ASSERT_GE(diff.size(), 1 + kCsgBvhMinOperands);
        ASSERT_GE(bumps.size(), kCsgBvhMinOperands);
        int d = s.addOp(CsgShape::Op::Difference, diff);
        int u = s.addOp(CsgShape::Op::Union, bumps);
        s.addOp(CsgShape::Op::Union, {d, u});
    };
    CsgShape pruned, plain;
    build(pruned);
    build(plain);
    plain.setPruning(false);
    Rng rng(11);
    SpanScratch scratch;
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        Vec3 o(rng.uniform() * 30 - 10, rng.uniform() * 30 - 10, rng.uniform() * 10 - 2);
        Vec3 target(rng.uniform() * 10, rng.uniform() * 10, rng.uniform() * 1.5);
        Ray r(o, normalize(target - o));
        SpanList a, b;
        pruned.spans(r, -kInfinity, kInfinity, a, scratch);
        plain.spans(r, -kInfinity, kInfinity, b, scratch);
        ASSERT_EQ(a.size(), b.size()) << "ray " << i;
        for (size_t k = 0; k < a.size(); ++k) {
            EXPECT_EQ(a[k].in.t, b[k].in.t);
            EXPECT_EQ(a[k].out.t, b[k].out.t);
            EXPECT_EQ(a[k].in.leaf->material(), b[k].in.leaf->material());
        }
        hits += !a.empty();
        // Inside tests through the same tree
        Vec3 p(rng.uniform() * 10, rng.uniform() * 10, rng.uniform() * 1.5);
        EXPECT_EQ(pruned.inside(p), plain.inside(p));
    }
    EXPECT_GT(hits, 1000);
}

/// Points on the faces, edges and corners of the operands' bounds: the BVH's point query must
/// still find every operand whose bounds hold the point, as the plain loop does.
TEST(CsgShape, ManyOperandsInsideTestsOnTheirBoundsFaces) {
    auto cube = [](const Vec3 &lo, const Vec3 &hi, int material) {
        return std::make_unique<PrimitiveInstance>(std::make_unique<Box>(lo, hi), Transform(),
                                                   material);
    };
    auto build = [&](CsgShape &s) {
        // A 4 x 4 x 1 slab minus 16 unit cubes' halves on a grid, united with 20 cubes above
        std::vector<int> diff{s.addLeaf(cube({0, 0, 0}, {4, 4, 1}, 0))};
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                diff.push_back(
                    s.addLeaf(cube({i + 0.25, j + 0.25, 0.5}, {i + 0.75, j + 0.75, 2}, 1)));
        std::vector<int> parts{s.addOp(CsgShape::Op::Difference, diff)};
        for (int k = 0; k < 20; ++k)
            parts.push_back(s.addLeaf(
                cube({k % 5 * 0.75, k / 5 * 1.0, 1}, {k % 5 * 0.75 + 0.5, k / 5 + 0.5, 1.5}, 2)));
        s.addOp(CsgShape::Op::Union, parts);
    };
    CsgShape pruned, plain;
    build(pruned);
    build(plain);
    plain.setPruning(false);
    int inside = 0, points = 0;
    for (double x = -0.25; x <= 4.25; x += 0.125)
        for (double y = -0.25; y <= 4.25; y += 0.125)
            for (double z = -0.25; z <= 2.25; z += 0.25) {
                Vec3 p(x, y, z);
                ASSERT_EQ(pruned.inside(p), plain.inside(p)) << x << " " << y << " " << z;
                inside += plain.inside(p);
                ++points;
            }
    EXPECT_GT(inside, points / 10);
    EXPECT_LT(inside, points / 2);
}

}  // namespace
}  // namespace rt

namespace rt {
namespace {

/// A boolean node of two convex primitives takes a shortcut (CsgShape::evaluateConvexPair). The
/// same node with its second operand behind a one-operand union takes the general merge: the
/// spans (distances, leaves, faces, tie flags), the cancelled ties, the counters and the first
/// crossings must be the same, bit for bit, over windows that prune. Boxes on a half-unit grid
/// share and touch faces, so the merge sweep's coincident cases are met as well as the
/// well-separated ones.
TEST(CsgShape, TwoConvexOperandsGiveTheGeneralMergesResult) {
    Rng rng(23);
    SpanScratch scratch;
    auto grid = [&](double lo, double hi) {
        return lo + std::floor(rng.uniform() * ((hi - lo) * 2 + 1)) / 2;
    };
    auto convex = [&](int kind, int material) -> std::unique_ptr<PrimitiveInstance> {
        Vec3 lo(grid(-1, 1), grid(-1, 1), grid(-1, 1));
        Vec3 hi = lo + Vec3(grid(0.5, 2), grid(0.5, 2), grid(0.5, 2));
        switch (kind) {
            case 0:
                return std::make_unique<PrimitiveInstance>(std::make_unique<Box>(lo, hi),
                                                           Transform(), material);
            case 1:
                return std::make_unique<PrimitiveInstance>(
                    std::make_unique<Box>(lo, hi),
                    *Transform::fromMatrix(Mat4::rotateAxis(45, Vec3(0, 0, 1))), material);
            case 2:
                return sphereAt(lo, grid(0.5, 1.5), material);
            default:
                return std::make_unique<PrimitiveInstance>(
                    std::make_unique<Cone>(lo.z, hi.z, 1, grid(0, 1)),
                    *Transform::fromMatrix(Mat4::translate(Vec3(lo.x, lo.y, 0))), material);
        }
    };
    int separate = 0, coincident = 0, pruned = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        auto op = static_cast<CsgShape::Op>(1 + trial % 3);
        int kindA = static_cast<int>(rng.uniform() * 4),
            kindB = static_cast<int>(rng.uniform() * 4);
        uint64_t seed = rng.uniformU32();
        // The same two primitives in both trees
        auto build = [&](CsgShape &s, bool wrap) {
            Rng local(seed);
            std::swap(rng, local);
            int a = s.addLeaf(convex(kindA, 1));
            int b = s.addLeaf(convex(kindB, 2));
            std::swap(rng, local);
            if (wrap) b = s.addOp(CsgShape::Op::Union, {b});
            s.addOp(op, {a, b});
        };
        CsgShape shortcut, general;
        build(shortcut, false);
        build(general, true);
        for (int i = 0; i < 120; ++i) {
            Vec3 o(rng.uniform() * 10 - 5, rng.uniform() * 10 - 5, rng.uniform() * 10 - 5);
            Vec3 target(grid(-1, 2), grid(-1, 2), rng.uniform() * 3 - 1);
            // Half the rays along a grid axis, through shared faces end-on
            Vec3 d = i % 2 ? normalize(target - o) : Vec3(0, 0, o.z < 0 ? 1 : -1);
            if (i % 2 == 0) o = Vec3(target.x, target.y, o.z);
            Ray r(o, d);
            double w0 = i % 3 ? -kInfinity : rng.uniform() * 8,
                   w1 = i % 5 ? kInfinity : w0 + rng.uniform() * 4;
            SpanList a, b;
            SpanScratch sa, sb;
            sa.cancelledTie = sb.cancelledTie = kInfinity;
            shortcut.spans(r, w0, w1, a, sa);
            general.spans(r, w0, w1, b, sb);
            ASSERT_EQ(a.size(), b.size()) << "trial " << trial << " ray " << i;
            for (size_t k = 0; k < a.size(); ++k)
                for (auto [x, y] : {std::pair{a[k].in, b[k].in}, std::pair{a[k].out, b[k].out}}) {
                    EXPECT_EQ(x.t, y.t);
                    EXPECT_EQ(x.leaf->material(), y.leaf->material());  // which operand
                    EXPECT_EQ(x.face, y.face);
                    EXPECT_EQ(x.tie, y.tie);
                }
            EXPECT_EQ(sa.cancelledTie, sb.cancelledTie);
            EXPECT_EQ(sa.spanOps, sb.spanOps);
            EXPECT_EQ(sa.prunedSubtrees, sb.prunedSubtrees);
            bool tied = sa.cancelledTie < kInfinity;
            for (const Span &s : a) tied = tied || s.in.tie || s.out.tie;
            coincident += tied;
            separate += sa.spanOps > 0 && !tied;
            pruned += sa.prunedSubtrees > 0;
            Crossing ca, cb;
            double tMin = rng.uniform() * 6;
            bool ha = shortcut.firstCrossing(r, tMin, kInfinity, &ca, scratch);
            bool hb = general.firstCrossing(r, tMin, kInfinity, &cb, scratch);
            ASSERT_EQ(ha, hb);
            if (ha) {
                EXPECT_EQ(ca.t, cb.t);
                EXPECT_EQ(ca.leaf->material(), cb.leaf->material());
                EXPECT_EQ(ca.tie, cb.tie);
            }
        }
    }
    // Every path was met many times
    EXPECT_GT(separate, 2000);
    EXPECT_GT(coincident, 400);
    EXPECT_GT(pruned, 1000);
}

}  // namespace
}  // namespace rt
