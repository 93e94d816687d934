// SPDX-License-Identifier: MIT
// CSG nodes with many operands find the operands a ray reaches (and those that hold the camera)
// through a BVH over their bounds. With the plan that BVH is used; without it (no pruning)
// every operand is evaluated in turn. The pictures must be the same bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/csg/csg_shape.h"
#include "core/ir/scene_defaults.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "importers/scad/scad_importer.h"

namespace rt {
namespace {

RenderResult renderText(const std::string &text, bool plan, int width = 80, int height = 60) {
    DiagnosticSink diag;
    scad::ImportOptions io;
    io.libraryPaths = {std::string(SCADRAY_SOURCE_DIR) + "/scenes"};
    ir::Scene scene =
        scad::importScadSource("use <scadray.scad>\n" + text,
                               std::string(SCADRAY_SOURCE_DIR) + "/scenes/test.scad", diag, io);
    ir::completeScene(scene, diag);
    CompileOptions co;
    co.plan = plan;
    auto rs = RenderScene::compile(scene, diag, co);
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.threads = 2;
    return renderImage(*rs, o);
}

/// Pictures (and tie masks) equal bit for bit.
void expectSamePicture(const RenderResult &a, const RenderResult &b) {
    ASSERT_EQ(a.image.width(), b.image.width());
    int differing = 0;
    for (int y = 0; y < a.image.height(); ++y)
        for (int x = 0; x < a.image.width(); ++x) {
            Rgb p = a.image.at(x, y), q = b.image.at(x, y);
            differing +=
                p.r != q.r || p.g != q.g || p.b != q.b || a.ties.at(x, y).r != b.ties.at(x, y).r;
        }
    EXPECT_EQ(differing, 0);
}

// A 20 x 20 plate with 400 holes (a difference with a BVH over its subtrahends) and 40 bumps
// on it (a union with a BVH over its operands), lit with shadows: the issue's plate, small
const char *kPlate = R"(
camera(location=[-6, -14, 16], look_at=[10, 10, 0], fov=60);
point_light(position=[-20, -30, 60]);
union() {
    difference() {
        cube([20, 20, 2]);
        for (i = [0 : 19], j = [0 : 19]) translate([i + 0.5, j + 0.5, -1]) cylinder(r=0.3 + 0.01 * i, h=4);
    }
    for (k = [0 : 39]) translate([(k * 7) % 20 + 0.1, (k * 3) % 20, 2]) sphere(r=0.6);
}
)";

TEST(CsgManyOperands, PlateIsTheSameWithAndWithoutTheOperandBvh) {
    RenderResult with = renderText(kPlate, true), without = renderText(kPlate, false);
    expectSamePicture(with, without);
    EXPECT_EQ(without.stats.prunedSubtrees, 0);
    EXPECT_LT(with.stats.spanOps, without.stats.spanOps);
}

// The camera inside a glass plate with 64 holes, and inside one of its holes: whether it
// starts inside the solid is found through the BVH over the subtrahends
std::string glassPlate(const std::string &eye) {
    return "camera(location=" + eye + R"(, look_at=[8, 2, 1], fov=70);
point_light(position=[-20, -30, 60]);
material(color=[0.9, 1, 0.95], filter=0.3, transmit=0.6, ior=1.5, ambient=0.1, diffuse=0.3)
    difference() {
        cube([16, 4, 2]);
        for (i = [0 : 15], j = [0 : 3]) translate([i + 0.5, j + 0.5, -1]) cylinder(r=0.3, h=4);
    }
cube([40, 40, 0.1], center=true);
)";
}

TEST(CsgManyOperands, CameraInsideIsFoundThroughTheOperandBvh) {
    for (const char *eye : {"[3, 2, 1]", "[2.5, 1.5, 1]"}) {  // in the glass; in a hole
        SCOPED_TRACE(eye);
        std::string scene = glassPlate(eye);
        expectSamePicture(renderText(scene, true, 48, 36), renderText(scene, false, 48, 36));
    }
}

}  // namespace
}  // namespace rt
