// SPDX-License-Identifier: MIT
// From .scad text to pixels: transforms written in different OpenSCAD forms render the same
// picture, CSG works on transformed subtrees, and $vp* variables set the camera.
#include <gtest/gtest.h>

#include <cmath>

#include "core/ir/scene_defaults.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "importers/scad/scad_importer.h"

namespace rt {
namespace {

const char *kSetup = R"(
use <scadray.scad>
camera(location=[0, -20, 8], look_at=[0, 0, 0], fov=40);
point_light(position=[-10, -15, 20]);
)";

Image render(const std::string &body, int w = 48, int h = 36) {
    DiagnosticSink diag;
    scad::ImportOptions io;
    io.libraryPaths = {std::string(SCADRAY_SOURCE_DIR) + "/scenes"};
    ir::Scene scene = scad::importScadSource(kSetup + body, "test.scad", diag, io);
    ir::completeScene(scene, diag);
    EXPECT_EQ(diag.count(Severity::Warning), 0);
    auto rs = RenderScene::compile(scene, diag);
    RenderOptions o;
    o.width = w;
    o.height = h;
    return renderImage(*rs, o).image;
}

/// Fraction of pixels that differ by more than 1e-3 (silhouette pixels may flip on rounding).
double differingFraction(const Image &a, const Image &b) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            Rgb p = a.at(x, y), q = b.at(x, y);
            n += std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)}) > 1e-3;
        }
    return double(n) / (a.width() * a.height());
}

void expectSamePicture(const std::string &a, const std::string &b) {
    Image ia = render(a), ib = render(b);
    EXPECT_LT(differingFraction(ia, ib), 0.01) << a << "\nvs\n" << b;
    // And the pictures are not empty
    double spread = 0;
    for (float v : ia.data()) spread = std::max(spread, double(v));
    EXPECT_GT(spread, 0.1);
}

TEST(ScadRender, ComparisonDetectsADifferentPlacement) {
    // Negative control: the mirrored placement is not the unmirrored one
    EXPECT_GT(differingFraction(render("translate([3,0,0]) cube([1,2,3]);"),
                                render("translate([-4,0,0]) cube([1,2,3]);")),
              0.02);
}

TEST(ScadRender, MirrorEqualsTheMirroredPlacement) {
    expectSamePicture("mirror([1,0,0]) translate([3,0,0]) cube([1,2,3]);",
                      "translate([-4,0,0]) cube([1,2,3]);");
}

TEST(ScadRender, NegativeScaleIsAMirror) {
    expectSamePicture("scale([-1,1,1]) translate([1,0,0]) cylinder(r1=2, r2=0.5, h=3);",
                      "mirror([1,0,0]) translate([1,0,0]) cylinder(r1=2, r2=0.5, h=3);");
}

TEST(ScadRender, RotateFormsAgree) {
    expectSamePicture("rotate([0,0,90]) cube([4,1,1]);", "rotate(90) cube([4,1,1]);");
    expectSamePicture("rotate([90,0,0]) cylinder(r=1,h=4);",
                      "rotate(a=90, v=[1,0,0]) cylinder(r=1,h=4);");
    expectSamePicture("rotate([30,40,50]) cube([3,2,1]);",
                      "rotate([0,0,50]) rotate([0,40,0]) rotate([30,0,0]) cube([3,2,1]);");
}

TEST(ScadRender, MultmatrixEqualsTranslateAndScale) {
    expectSamePicture("multmatrix([[2,0,0,1],[0,1,0,-1],[0,0,0.5,0.5]]) sphere(2);",
                      "translate([1,-1,0.5]) scale([2,1,0.5]) sphere(2);");
}

TEST(ScadRender, CsgUnderTransformsAndTransformsInsideCsg) {
    expectSamePicture(
        "translate([1,0,0]) rotate([0,0,30]) difference() { cube(4, center=true); sphere(2.6); }",
        "difference() { translate([1,0,0]) rotate([0,0,30]) cube(4, center=true); "
        "translate([1,0,0]) sphere(2.6); }");
    // The subtracted sphere really cuts: the picture differs from the plain cube
    Image cut = render("difference() { cube(4, center=true); sphere(2.6); }");
    Image plain = render("cube(4, center=true);");
    EXPECT_GT(differingFraction(cut, plain), 0.02);
}

TEST(ScadRender, ViewportVariablesSetTheCamera) {
    // $vpr = [90,0,0] looks along +y from vpd in front of $vpt
    DiagnosticSink diag;
    ir::Scene viaVp = scad::importScadSource(
        "$vpt = [1,2,3]; $vpr = [90,0,0]; $vpd = 30; $vpf = 25; cube(2);", "vp.scad", diag);
    ASSERT_TRUE(viaVp.camera);
    EXPECT_EQ(viaVp.camera->source, ir::CameraSource::ViewportVariables);
    EXPECT_EQ(viaVp.camera->location, Vec3(1, -28, 3));
    EXPECT_EQ(viaVp.camera->lookAt, Vec3(1, 2, 3));
    EXPECT_EQ(viaVp.camera->fovAxis, ir::FovAxis::Vertical);
    EXPECT_EQ(viaVp.camera->fov, 25);
}

TEST(ScadRender, HullIsTheSolidItBoundsAndTakesPartInCsg) {
    // The hull of two cubes is the box they span; the cubes alone leave a gap
    expectSamePicture("hull() { cube(2); translate([3, 0, 0]) cube(2); }", "cube([5, 2, 2]);");
    EXPECT_GT(differingFraction(render("cube(2); translate([3, 0, 0]) cube(2);"),
                                render("cube([5, 2, 2]);")),
              0.01);
    expectSamePicture(
        "difference() { hull() { cube(2); translate([3, 0, 0]) cube(2); } "
        "translate([1, -1, 1]) cube([3, 4, 2]); }",
        "difference() { cube([5, 2, 2]); translate([1, -1, 1]) cube([3, 4, 2]); }");
}

TEST(ScadRender, RoundHullsGiveFinitePixels) {
    Image img = render(
        "hull() { sphere(2, $fn=24); translate([4, 0, 1]) sphere(1); "
        "translate([0, 0, 3]) rotate([10, 20, 30]) cylinder(r1=1, r2=0, h=2); }",
        64, 48);
    double lit = 0;
    for (float v : img.data()) {
        ASSERT_TRUE(std::isfinite(v));
        lit = std::max(lit, double(v));
    }
    EXPECT_GT(lit, 0.1);
}

}  // namespace
}  // namespace rt
