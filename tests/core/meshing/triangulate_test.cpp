// SPDX-License-Identifier: MIT
// Triangulation tests: OpenSCAD's own diagonals on recorded faces, area and orientation
// preserved for concave polygons in any plane, degenerate polygons rejected.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/math/mat4.h"
#include "core/meshing/triangulate.h"

namespace rt::meshing::test {
namespace {

using Tris = std::vector<std::array<uint32_t, 3>>;

/// Sum of the triangles' areas, each signed by how its normal faces `n`.
double projectedArea(const std::vector<Vec3> &pos, const std::vector<std::array<uint32_t, 3>> &tris,
                     const Vec3 &n) {
    double sum = 0;
    for (const auto &t : tris)
        sum += dot(cross(pos[t[1]] - pos[t[0]], pos[t[2]] - pos[t[0]]), n) / 2;
    return sum;
}

/// Twice the signed area of a 2D polygon (shoelace).
double shoelace(const std::vector<std::array<double, 2>> &p) {
    double s = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        const auto &a = p[i], &b = p[(i + 1) % p.size()];
        s += a[0] * b[1] - b[0] * a[1];
    }
    return s;
}

struct Placed {
    std::vector<Vec3> positions;
    std::vector<uint32_t> polygon;
    Vec3 normal;  ///< unit normal of the plane the 2D polygon was placed in
};

/// Places a 2D polygon in 3D with a rotation and an offset; the polygon's indices start at
/// `first` (a few unused positions before it).
Placed place(const std::vector<std::array<double, 2>> &p, const Mat4 &m, uint32_t first = 3) {
    Placed out;
    for (uint32_t i = 0; i < first; ++i) out.positions.push_back(Vec3(100 + i, 0, 0));
    for (const auto &q : p) {
        out.positions.push_back(m.transformPoint(Vec3(q[0], q[1], 0)));
        out.polygon.push_back(static_cast<uint32_t>(out.positions.size() - 1));
    }
    out.normal = normalize(m.transformVector(Vec3(0, 0, 1)));
    return out;
}

/// Checks a triangulation of a simple polygon: n - 2 triangles over its corners, all facing
/// the polygon's side, whose areas add up to the polygon's (so none overlap or stick out).
void expectGoodTriangulation(const Placed &pl, const Tris &tris, double area) {
    EXPECT_EQ(tris.size(), pl.polygon.size() - 2);
    double sum = 0;
    for (const auto &t : tris) {
        for (uint32_t v : t)
            EXPECT_NE(std::find(pl.polygon.begin(), pl.polygon.end(), v), pl.polygon.end());
        const Vec3 &a = pl.positions[t[0]], &b = pl.positions[t[1]], &c = pl.positions[t[2]];
        double signedArea = dot(cross(b - a, c - a), pl.normal) / 2;
        EXPECT_GT(signedArea, 0) << "triangle " << t[0] << " " << t[1] << " " << t[2];
        sum += std::abs(signedArea);
    }
    EXPECT_NEAR(sum, area, 1e-9 * std::max(1.0, area));
    EXPECT_NEAR(projectedArea(pl.positions, tris, pl.normal), area, 1e-9 * std::max(1.0, area));
}

const std::vector<std::array<double, 2>> kLShape = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
const std::vector<std::array<double, 2>> kComb = {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1},
                                                  {5, 3}, {4, 3}, {4, 1}, {3, 1}, {3, 3}, {2, 3},
                                                  {2, 1}, {1, 1}, {1, 3}, {0, 3}};
/// A five-pointed star, counter-clockwise
const std::vector<std::array<double, 2>> kStar = {{-1, 1},   {-3, 1}, {-1.5, -0.5}, {-2, -3},
                                                  {0, -1.5}, {2, -3}, {1.5, -0.5},  {3, 1},
                                                  {1, 1},    {0, 3}};
/// Collinear corners along the bottom and a notch
const std::vector<std::array<double, 2>> kCollinear = {{0, 0}, {1, 0},   {2, 0}, {3, 0}, {3, 2},
                                                       {2, 2}, {1.5, 1}, {1, 2}, {0, 2}, {0, 1}};

/// A polygon face and the triangles OpenSCAD 2021.01 makes of it. Recorded with
/// `openscad -o x.stl` on polyhedron(points = P + [apex], faces = [[0..n-1], sides to the apex]),
/// keeping the STL triangles without the apex (indices into P). OpenSCAD reverses the face first.
struct OpenScadCase {
    const char *name;
    std::vector<Vec3> points;
    std::vector<std::array<uint32_t, 3>> triangles;
};

const OpenScadCase kOpenScadCases[] = {
    {"skew_square", {{0, 0, 1}, {2, 0, 1.5}, {2, 2, 1}, {0, 2, 1.25}}, {{0, 2, 1}, {2, 0, 3}}},
    {"skew_kite", {{0, 0, 0}, {3, 0, 0.5}, {4, 2, 0}, {0, 1, 0.75}}, {{3, 1, 0}, {1, 3, 2}}},
    {"pentagon_concave",
     {{0, 0, 0}, {4, 0, 0}, {4, 3, 0}, {2, 1, 0}, {0, 3, 0}},
     {{1, 3, 2}, {0, 3, 1}, {3, 0, 4}}},
    {"pentagon_skew",
     {{0, 0, 0}, {4, 0, 1}, {4, 3, 0}, {2, 1, 0.5}, {0, 3, 1}},
     {{1, 3, 2}, {0, 3, 1}, {3, 0, 4}}},
    {"hexagon_cocircular",
     {{2, 0, 0}, {1, 1.75, 0.25}, {-1, 1.75, 0}, {-2, 0, 0.25}, {-1, -1.75, 0}, {1, -1.75, 0.25}},
     {{4, 0, 5}, {3, 0, 4}, {0, 3, 1}, {1, 3, 2}}},
    {"comb_yz",
     {{0, 0, 0},
      {0, 7, 0},
      {0, 7, 3},
      {0, 6, 3},
      {0, 6, 1},
      {0, 5, 1},
      {0, 5, 3},
      {0, 4, 3},
      {0, 4, 1},
      {0, 3, 1},
      {0, 3, 3},
      {0, 0, 3}},
     {{1, 4, 2},
      {1, 5, 4},
      {5, 8, 6},
      {1, 8, 5},
      {1, 9, 8},
      {0, 9, 1},
      {11, 9, 0},
      {9, 11, 10},
      {2, 4, 3},
      {6, 8, 7}}},
    {"l_tilted",
     {{0, 0, 0}, {3, 0, 1}, {3, 1, 1.5}, {1, 1, 0.5}, {1, 3, 1.5}, {0, 3, 1.25}},
     {{1, 3, 2}, {0, 3, 1}, {5, 3, 0}, {3, 5, 4}}},
};

/// A triangle as its sorted corners: the diagonals chosen, whatever the corner order.
std::array<uint32_t, 3> sorted(std::array<uint32_t, 3> t) {
    std::sort(t.begin(), t.end());
    return t;
}

TEST(Triangulate, ChoosesTheDiagonalsOpenScadChooses) {
    for (const OpenScadCase &c : kOpenScadCases) {
        SCOPED_TRACE(c.name);
        std::vector<uint32_t> face;
        for (uint32_t i = 0; i < c.points.size(); ++i) face.push_back(i);
        std::reverse(face.begin(), face.end());  // as polyhedron() and OpenSCAD do
        Tris tris;
        ASSERT_TRUE(triangulatePolygon(c.points, face, tris));
        std::vector<std::array<uint32_t, 3>> ours, theirs;
        for (const auto &t : tris) ours.push_back(sorted(t));
        for (const auto &t : c.triangles) theirs.push_back(sorted(t));
        std::sort(ours.begin(), ours.end());
        std::sort(theirs.begin(), theirs.end());
        EXPECT_EQ(ours, theirs);
    }
}

TEST(Triangulate, KeepsTheFaceOrientationOnOpenScadCases) {
    // Every triangle turns the way the (reversed) face does about its Newell normal
    for (const OpenScadCase &c : kOpenScadCases) {
        SCOPED_TRACE(c.name);
        std::vector<uint32_t> face;
        for (uint32_t i = c.points.size(); i-- > 0;) face.push_back(i);
        Vec3 normal(0);
        for (size_t i = 0; i < face.size(); ++i)
            normal += cross(c.points[face[i]], c.points[face[(i + 1) % face.size()]]);
        Tris tris;
        ASSERT_TRUE(triangulatePolygon(c.points, face, tris));
        for (const auto &t : tris) {
            const Vec3 &a = c.points[t[0]], &b = c.points[t[1]], &d = c.points[t[2]];
            EXPECT_GT(dot(cross(b - a, d - a), normal), 0);
        }
    }
}

TEST(Triangulate, ConcavePolygonsInTiltedPlanesKeepAreaAndOrientation) {
    Mat4 tilt = Mat4::translate(Vec3(5, -2, 7)) * Mat4::rotateAxis(37, Vec3(1, 2, 3));
    for (const auto *poly : {&kLShape, &kComb, &kStar, &kCollinear}) {
        double area = shoelace(*poly) / 2;
        ASSERT_GT(area, 0);
        Placed pl = place(*poly, tilt);
        Tris tris;
        ASSERT_TRUE(triangulatePolygon(pl.positions, pl.polygon, tris)) << poly->size();
        expectGoodTriangulation(pl, tris, area);
    }
}

TEST(Triangulate, ClockwisePolygonGivesTrianglesFacingTheOtherWay) {
    auto reversed = kComb;
    std::reverse(reversed.begin(), reversed.end());
    Placed pl = place(reversed, Mat4::rotateX(90));
    Tris tris;
    ASSERT_TRUE(triangulatePolygon(pl.positions, pl.polygon, tris));
    // Counter-clockwise about -normal
    pl.normal = -pl.normal;
    expectGoodTriangulation(pl, tris, shoelace(kComb) / 2);
}

TEST(Triangulate, AppendsWithoutTouchingExistingTriangles) {
    Placed pl = place(kLShape, Mat4());
    Tris tris = {{0, 1, 2}};
    ASSERT_TRUE(triangulatePolygon(pl.positions, pl.polygon, tris));
    EXPECT_EQ(tris.size(), 1u + 4u);
    EXPECT_EQ(tris[0], (std::array<uint32_t, 3>{0, 1, 2}));
}

TEST(Triangulate, RepeatedCornersAreIgnored) {
    Placed pl = place(kLShape, Mat4());
    std::vector<uint32_t> doubled;
    for (uint32_t v : pl.polygon) {
        doubled.push_back(v);
        if (v % 2) doubled.push_back(v);
    }
    doubled.push_back(pl.polygon[0]);  // closing corner repeated
    Tris tris;
    ASSERT_TRUE(triangulatePolygon(pl.positions, doubled, tris));
    expectGoodTriangulation(pl, tris, shoelace(kLShape) / 2);
}

TEST(Triangulate, DegeneratePolygonsAreRejectedAndLeaveTheOutputAlone) {
    std::vector<Vec3> pos = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {0, 0, 0}};
    Tris tris = {{7, 8, 9}};
    // Collinear corners
    EXPECT_FALSE(triangulatePolygon(pos, {0, 1, 2, 3}, tris));
    // Fewer than three distinct points
    EXPECT_FALSE(triangulatePolygon(pos, {0, 1, 4}, tris));
    EXPECT_FALSE(triangulatePolygon(pos, {0, 1}, tris));
    // Zero area: there and back again
    EXPECT_FALSE(triangulatePolygon(pos, {0, 1, 2, 1}, tris));
    // Index out of range
    EXPECT_FALSE(triangulatePolygon(pos, {0, 1, 9}, tris));
    EXPECT_EQ(tris.size(), 1u);
}

TEST(Triangulate, RandomStarShapedPolygonsProperty) {
    // Star-shaped polygons about the origin with random radii: concave, but simple
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> radius(0.2, 5), unit(-1, 1);
    for (int trial = 0; trial < 200; ++trial) {
        int n = 3 + trial % 40;
        std::vector<std::array<double, 2>> p;
        for (int i = 0; i < n; ++i) {
            double a = 2 * M_PI * (i + 0.3 * unit(rng) + 0.5) / n;
            double r = radius(rng);
            p.push_back({r * std::cos(a), r * std::sin(a)});
        }
        Vec3 axis(unit(rng), unit(rng), unit(rng));
        if (lengthSquared(axis) < 1e-3) axis = Vec3(0, 0, 1);
        Mat4 m = Mat4::translate(Vec3(unit(rng), unit(rng), unit(rng)) * 10) *
                 Mat4::rotateAxis(180 * unit(rng), axis);
        Placed pl = place(p, m, static_cast<uint32_t>(trial % 5));
        Tris tris;
        SCOPED_TRACE("trial " + std::to_string(trial));
        ASSERT_TRUE(triangulatePolygon(pl.positions, pl.polygon, tris));
        expectGoodTriangulation(pl, tris, shoelace(p) / 2);
    }
}

}  // namespace
}  // namespace rt::meshing::test
