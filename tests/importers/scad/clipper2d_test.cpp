// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's Clipper conventions: fixed-point scaling by 2^16 with truncation,
// even-odd sanitizing, non-zero booleans, offsets and the regions of a polygon set.
#include "importers/scad/geometry2d/clipper2d.h"

#include <gtest/gtest.h>

#include <cmath>

namespace rt::scad::clipper2d {
namespace {

/// Every coordinate is a whole number of Clipper units.
void expectOnGrid(const PolygonSet &p) {
    for (const Outline &o : p.outlines)
        for (Vec2 v : o) {
            EXPECT_EQ(v.x * kScale, std::trunc(v.x * kScale)) << v.x;
            EXPECT_EQ(v.y * kScale, std::trunc(v.y * kScale)) << v.y;
        }
}

double area(const PolygonSet &p) {
    double a = 0;
    for (const Outline &o : p.outlines) a += twiceSignedArea(o) / 2;
    return a;
}

TEST(Clipper2d, ScalesBy2To16AndTruncatesTowardZero) {
    // 0.3 * 65536 = 19660.8: truncated, not rounded (OpenSCAD exports 0.299988 and -0.299988)
    EXPECT_EQ(toFixed(0.3), 19660);
    EXPECT_EQ(toFixed(-0.3), -19660);
    EXPECT_EQ(toFixed(1), 65536);
    EXPECT_EQ(fromFixed(19660), 19660.0 / 65536);
    EXPECT_EQ(kScale, 65536.0);
}

TEST(Clipper2d, SanitizeSplitsABowTieEvenOdd) {
    PolygonSet bowTie{{{{0, 0}, {4, 4}, {4, 0}, {0, 4}}}, false};
    PolygonSet s = sanitize(bowTie);
    EXPECT_TRUE(s.sanitized);
    ASSERT_EQ(s.outlines.size(), 2u);
    for (const Outline &o : s.outlines) {
        EXPECT_EQ(o.size(), 3u);
        EXPECT_GT(twiceSignedArea(o), 0);  // both are outer outlines: counter-clockwise
    }
    EXPECT_DOUBLE_EQ(area(s), 8);
    expectOnGrid(s);
}

TEST(Clipper2d, SanitizeQuantisesEachPoint) {
    PolygonSet p{{{{0, 0}, {1, 0}, {1, 0.3}, {0, -0.3}}}, false};
    PolygonSet s = sanitize(p);
    expectOnGrid(s);
    bool found = false;
    for (const Outline &o : s.outlines)
        for (Vec2 v : o) found = found || v.y == 19660.0 / 65536;
    EXPECT_TRUE(found);
}

TEST(Clipper2d, DifferenceMakesAClockwiseHole) {
    PolygonSet outer{{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}}, true};
    PolygonSet inner{{{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, true};
    PolygonSet d = apply({outer, inner}, BoolOp::Difference);
    ASSERT_EQ(d.outlines.size(), 2u);
    int holes = 0;
    for (const Outline &o : d.outlines) holes += twiceSignedArea(o) < 0;
    EXPECT_EQ(holes, 1);
    EXPECT_DOUBLE_EQ(area(d), 12);
    std::vector<Region> r = regions(d);
    ASSERT_EQ(r.size(), 1u);
    ASSERT_EQ(r[0].holes.size(), 1u);
    EXPECT_GT(twiceSignedArea(r[0].outer), 0);
    EXPECT_GT(twiceSignedArea(r[0].holes[0]), 0);  // regions list every outline counter-clockwise
    EXPECT_DOUBLE_EQ(twiceSignedArea(r[0].holes[0]), 8);
}

TEST(Clipper2d, UnionIntersectionAndEmptyOperands) {
    PolygonSet a{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, true};
    PolygonSet b{{{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, true};
    EXPECT_DOUBLE_EQ(area(apply({a, b}, BoolOp::Union)), 7);
    EXPECT_DOUBLE_EQ(area(apply({a, b}, BoolOp::Intersection)), 1);
    EXPECT_DOUBLE_EQ(area(apply({a, b, PolygonSet{}}, BoolOp::Intersection)), 0);
    EXPECT_DOUBLE_EQ(area(apply({PolygonSet{}, a}, BoolOp::Difference)), 0);
    EXPECT_DOUBLE_EQ(area(apply({a, PolygonSet{}}, BoolOp::Union)), 4);
}

TEST(Clipper2d, OffsetJoins) {
    PolygonSet sq{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, true};
    // delta: mitred corners, 1.1 quantised to 72090 / 65536 (OpenSCAD exports 1.10001)
    PolygonSet m = offset(sq, 0.1, JoinType::Miter, 1e6, 0);
    ASSERT_EQ(m.outlines.size(), 1u);
    ASSERT_EQ(m.outlines[0].size(), 4u);
    for (Vec2 v : m.outlines[0]) {
        EXPECT_TRUE(v.x == 72090.0 / 65536 || v.x == -6554.0 / 65536) << v.x;
        EXPECT_TRUE(v.y == 72090.0 / 65536 || v.y == -6554.0 / 65536) << v.y;
    }
    // chamfer: each corner cut, 8 points
    EXPECT_EQ(offset(sq, 0.5, JoinType::Square, 1e6, 0).outlines[0].size(), 8u);
    // round with a fine tolerance: many points, area near 1 + 4 * 0.5 + pi / 4
    PolygonSet r = offset(sq, 0.5, JoinType::Round, 1e6, 0.5 * (1 - std::cos(M_PI / 64)));
    EXPECT_GT(r.outlines[0].size(), 40u);
    EXPECT_NEAR(area(r), 3 + M_PI / 4, 2e-3);
    // shrinking past the middle leaves nothing
    EXPECT_TRUE(offset(sq, -0.6, JoinType::Round, 1e6, 0.01).empty());
}

TEST(Clipper2d, RegionsKeepTouchingOutlinesApart) {
    // The bow tie's two triangles meet at (2, 2); an island inside a hole is a region too
    std::vector<Region> bt = regions(sanitize({{{{0, 0}, {4, 4}, {4, 0}, {0, 4}}}, false}));
    EXPECT_EQ(bt.size(), 2u);
    for (const Region &r : bt) EXPECT_TRUE(r.holes.empty());
    PolygonSet nested{{{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                       {{2, 2}, {8, 2}, {8, 8}, {2, 8}},
                       {{4, 4}, {6, 4}, {6, 6}, {4, 6}}},
                      false};
    std::vector<Region> n = regions(nested);
    ASSERT_EQ(n.size(), 2u);
    size_t holes = n[0].holes.size() + n[1].holes.size();
    EXPECT_EQ(holes, 1u);
}

TEST(Clipper2d, XRange) {
    PolygonSet p{{{{-1, 0}, {2, 0}, {0, 1}}}, true};
    double lo, hi;
    p.xRange(lo, hi);
    EXPECT_EQ(lo, -1);
    EXPECT_EQ(hi, 2);
    PolygonSet{}.xRange(lo, hi);
    EXPECT_GT(lo, hi);
}

}  // namespace
}  // namespace rt::scad::clipper2d
