// SPDX-License-Identifier: MIT
// resize(), minkowski() and projection() against the installed OpenSCAD 2021.01: bounding boxes
// of resized solids, the vertices and volume of convex Minkowski sums, and the outline points
// of 2D sums and projections (OFF's 6 digits, Clipper's 2^-16 grid).
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/meshing/facets.h"
#include "importers/scad/openscad_support.h"

namespace rt::scad::test {
namespace {

namespace fs = std::filesystem;

/// Clipper's grid (2^-16) at OFF's 6 significant digits.
constexpr double kGrid = 2e-5;

fs::path scratchDir(const char *what) {
    fs::path dir = fs::temp_directory_path() /
                   (std::string("scadray_") + what + "_" + std::to_string(getpid()));
    fs::create_directories(dir);
    return dir;
}

Bounds3 boundsOf(const std::vector<Vec3> &pts) {
    Bounds3 b;
    for (const Vec3 &p : pts) b = unionBounds(b, p);
    return b;
}

/// Our scene's points, with spheres and cylinders as OpenSCAD's polytopes.
std::vector<Vec3> ourPoints(const std::string &src, bool expectQuiet = true) {
    Imported ours = importText(src);
    if (expectQuiet) {
        EXPECT_TRUE(ours.warnings().empty()) << ours.warnings().front();
    }
    meshing::applyFacets(ours.scene, ir::FacetMode::OpenScad, ours.diag);
    return worldPoints(ours.scene);
}

class ResizeCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(ResizeCrossCheck, BoundingBoxMatchesOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const char *src = GetParam();
    SCOPED_TRACE(src);
    fs::path dir = scratchDir("resize");
    ir::Mesh theirs = openscadOff(src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());
    Bounds3 t = boundsOf(theirs.positions), o = boundsOf(ourPoints(src));
    for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(o.min[a], t.min[a], 1e-5 * std::max(1.0, std::abs(t.min[a]))) << "axis " << a;
        EXPECT_NEAR(o.max[a], t.max[a], 1e-5 * std::max(1.0, std::abs(t.max[a]))) << "axis " << a;
    }
}

INSTANTIATE_TEST_SUITE_P(
    Resize, ResizeCrossCheck,
    ::testing::Values(
        // The tessellated box: a $fn=8 sphere is narrower than its radius says
        "resize([10, 0, 0], auto=true) sphere(1, $fn=8);", "resize([10, 0, 0]) cube([2, 4, 6]);",
        // auto per axis, from the largest new size; scaled about the origin, not the corner
        "resize([10, 20, 0], auto=[false, false, true]) cube([2, 4, 6]);",
        "resize([0, 5, 0], auto=[1, 0, 1]) cube([2, 4, 6]);",
        "resize([3, 5, 0], auto=true) translate([1, 1, 1]) cube([2, 4, 6]);",
        // Sizes that are not positive count as not given
        "resize([-10, 5, 0], auto=true) cube([2, 4, 6]);",
        "resize([1, 2, 0], auto=true) cube([2, 4, 6]);",
        // Several children, nested resizes, a rotated hexagonal prism, 2D under an extrusion
        "resize([3, 0, 0]) { cube(1); translate([5, 0, 0]) sphere(1, $fn=7); }",
        "resize([2, 0, 0]) resize([0, 3, 0]) cube([2, 4, 6]);",
        "resize([10, 0, 0], auto=true) rotate([0, 0, 30]) cylinder(r=1, h=1, $fn=6);",
        "linear_extrude(1) resize([10, 0], auto=true) circle(1, $fn=5);"));

TEST(MinkowskiCrossCheck, ConvexSumsAreOpenScadsPolytope) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const char *cases[] = {
        "minkowski() { cube([10, 10, 2]); sphere(1, $fn=12); }",
        "minkowski() { cube([10, 10, 2], center=true); cylinder(r=2, h=1, $fn=16); }",
        "minkowski() { cube(2); rotate([0, 0, 45]) cube(1); translate([3, 0, 0]) sphere(1, $fn=6); "
        "}",
        ("minkowski() { polyhedron([[0,0,0],[2,0,0],[0,2,0],[0,0,2]], "
         "[[0,1,2],[0,3,1],[0,2,3],[1,3,2]]); sphere(0.3, $fn=8); }"),  // one case on two lines
    };
    fs::path dir = scratchDir("minkowski");
    for (const char *src : cases) {
        SCOPED_TRACE(src);
        expectSamePolytope(src, dir);
    }
    fs::remove_all(dir);
}

TEST(MinkowskiCrossCheck, UnionsSumPartByPart) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    // The sum of a union is the union of the parts' hulls: OpenSCAD's vertices are among ours,
    // and both span the same box
    const char *src =
        "minkowski() { union() { cube(3); translate([5, 0, 0]) cube(2); } sphere(0.5, $fn=8); }";
    fs::path dir = scratchDir("minkowski_union");
    ir::Mesh theirs = openscadOff(src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());
    std::vector<Vec3> mine = ourPoints(src);
    expectCovered(theirs.positions, mine, "OpenSCAD's vertex missing from ours:");
    Bounds3 t = boundsOf(theirs.positions), o = boundsOf(mine);
    EXPECT_LT(length(t.min - o.min) + length(t.max - o.max), 1e-5);
}

TEST(MinkowskiCrossCheck, NonConvexSumsSpanOpenScadsBox) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    // A plate with a hole and an L-shaped extrusion: OpenSCAD splits them into convex parts;
    // ours are the moved solid and hulls of its boundary pieces, and the hulls reach as far as
    // the sum does (an extreme point of the sum is a boundary point plus one of the sphere)
    const char *cases[] = {
        "minkowski() { difference() { cube([10, 10, 1]); translate([5, 5, -1]) "
        "cylinder(r=2, h=3, $fn=12); } sphere(0.5, $fn=8); }",
        "minkowski() { linear_extrude(1) polygon([[0,0],[4,0],[4,1],[1,1],[1,4],[0,4]]); "
        "sphere(0.3, $fn=8); }",
    };
    fs::path dir = scratchDir("minkowski_nonconvex");
    for (const char *src : cases) {
        SCOPED_TRACE(src);
        ir::Mesh theirs = openscadOff(src, dir);
        ASSERT_FALSE(theirs.positions.empty());
        Imported ours = importText(src);
        EXPECT_TRUE(ours.warnings().empty()) << ours.warnings().front();
        Bounds3 o;
        for (const auto &p : primitives(*ours.scene.root))
            if (const auto *poly = std::get_if<ir::PolytopePrim>(&p.node->shape))
                for (const Vec3 &v : poly->vertices)
                    o = unionBounds(o, p.worldFromObject.transformPoint(v));
        Bounds3 t = boundsOf(theirs.positions);
        for (int a = 0; a < 3; ++a) {  // OFF's 6 digits
            EXPECT_NEAR(o.min[a], t.min[a], 1e-5 * std::max(1.0, std::abs(t.min[a])))
                << "axis " << a;
            EXPECT_NEAR(o.max[a], t.max[a], 1e-5 * std::max(1.0, std::abs(t.max[a])))
                << "axis " << a;
        }
    }
    fs::remove_all(dir);
}

/// The outline edges of the scene's prisms, in the plane.
std::vector<std::pair<Vec3, Vec3>> prismEdges(const ir::Scene &scene) {
    std::vector<std::pair<Vec3, Vec3>> out;
    for (const auto &p : primitives(*scene.root)) {
        const auto *prism = std::get_if<ir::PrismPrim>(&p.node->shape);
        if (!prism) continue;
        for (size_t i = 0; i < prism->outline.size(); ++i) {
            const ir::Point2 &a = prism->outline[i],
                             &b = prism->outline[(i + 1) % prism->outline.size()];
            Vec3 wa = p.worldFromObject.transformPoint(Vec3(a.x, a.y, 0));
            Vec3 wb = p.worldFromObject.transformPoint(Vec3(b.x, b.y, 0));
            out.push_back({Vec3(wa.x, wa.y, 0), Vec3(wb.x, wb.y, 0)});
        }
    }
    return out;
}

double distanceToSegment(const Vec3 &p, const Vec3 &a, const Vec3 &b) {
    Vec3 d = b - a;
    double t = dot(d, d) > 0 ? std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0) : 0;
    return length(p - (a + d * t));
}

/// 2D results (under a linear_extrude): each of our outline points is one of OpenSCAD's, and
/// each of OpenSCAD's lies on our outline (OpenSCAD's section keeps the points where the plane
/// crosses its triangles' diagonals, in line with their neighbours; Clipper's cleaning drops
/// them from ours).
class FlatCrossCheck : public ::testing::TestWithParam<const char *> {};

TEST_P(FlatCrossCheck, OutlinesMatchOpenScad) {
    if (!haveOpenScad()) GTEST_SKIP() << "openscad is not on PATH; cross-check skipped";
    const char *src = GetParam();
    SCOPED_TRACE(src);
    fs::path dir = scratchDir("flat");
    ir::Mesh theirs = openscadOff(src, dir);
    fs::remove_all(dir);
    ASSERT_FALSE(theirs.positions.empty());
    Imported ours = importText(src);
    EXPECT_TRUE(ours.warnings().empty()) << ours.warnings().front();
    auto edges = prismEdges(ours.scene);
    ASSERT_FALSE(edges.empty());
    std::vector<Vec3> ref = theirs.positions;
    for (Vec3 &v : ref) v.z = 0;
    for (const auto &e : edges) {
        double best = kInfinity;
        for (const Vec3 &w : ref) best = std::min(best, length(e.first - w));
        EXPECT_LT(best, kGrid * std::max(1.0, length(e.first)))
            << "our point missing from OpenSCAD's: " << e.first.toString();
    }
    for (const Vec3 &v : ref) {
        double best = kInfinity;
        for (const auto &e : edges) best = std::min(best, distanceToSegment(v, e.first, e.second));
        EXPECT_LT(best, kGrid * std::max(1.0, length(v)))
            << "OpenSCAD's point off our outline: " << v.toString();
    }
}

INSTANTIATE_TEST_SUITE_P(
    MinkowskiAndProjection, FlatCrossCheck,
    ::testing::Values(
        // 2D Minkowski sums through Clipper: convex, a frame whose hole survives, one it fills
        "linear_extrude(1) minkowski() { square([10, 4]); circle(1, $fn=12); }",
        "linear_extrude(1) minkowski() { difference() { square(10, center=true); "
        "square(6, center=true); } circle(1, $fn=12); }",
        "linear_extrude(1) minkowski() { difference() { square(10, center=true); "
        "square(6, center=true); } circle(3, $fn=12); }",
        // Sections at z = 0, a face lying in the plane included
        "linear_extrude(1) projection(cut=true) cube(1);",
        "linear_extrude(1) projection(cut=true) translate([0, 0, -1]) cube(1);",
        "linear_extrude(1) projection(cut=true) rotate([60, 20, 0]) difference() { "
        "sphere(5, $fn=16); cylinder(r=2, h=20, center=true, $fn=12); }",
        // Shadows: a primitive, a difference and an intersection seen at an angle
        "linear_extrude(1) projection() rotate([30, 40, 0]) cube([4, 2, 6]);",
        "linear_extrude(1) projection() rotate([60, 20, 0]) difference() { sphere(5, $fn=16); "
        "cylinder(r=2, h=20, center=true, $fn=12); }",
        "linear_extrude(1) projection() rotate([60, 20, 10]) intersection() { "
        "cube(6, center=true); sphere(4, $fn=16); }"));

}  // namespace
}  // namespace rt::scad::test
