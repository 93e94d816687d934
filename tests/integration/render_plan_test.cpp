// SPDX-License-Identifier: MIT
// The render plan: scenes cast only the rays they need, the plan's savings (unions split into
// disjoint parts, objects behind the camera dropped, CSG subtrees pruned) never change a
// picture, and the default sample count follows from whether any effect is Monte Carlo.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>

#include "core/ir/scene_defaults.h"
#include "core/render/render_plan.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "importers/loader/scene_loader.h"
#include "importers/scad/scad_importer.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

struct Compiled {
    ir::Scene scene;
    std::unique_ptr<RenderScene> rs;
};

Compiled compileScene(ir::Scene source, bool plan, bool vista = true, bool lanes = true) {
    Compiled c{std::move(source), nullptr};
    DiagnosticSink diag;
    ir::completeScene(c.scene, diag);
    CompileOptions co;
    co.plan = plan;
    co.vistaFromObjects = vista ? 1 : SIZE_MAX;
    co.laneSlabs = lanes;
    c.rs = RenderScene::compile(c.scene, diag, co);
    return c;
}

scad::ImportOptions libraryOptions() {
    scad::ImportOptions io;
    io.libraryPaths = {std::string(SCADRAY_SOURCE_DIR) + "/scenes"};
    return io;
}

/// A scene file loaded as the command line loads it.
ir::Scene load(const std::string &path) {
    DiagnosticSink diag;
    LoadOptions lo;
    lo.libraryPaths = libraryOptions().libraryPaths;
    return loadScene(path, diag, lo);
}

ir::Scene loadText(const std::string &text) {
    DiagnosticSink diag;
    return scad::importScadSource("use <scadray.scad>\n" + text,
                                  std::string(SCADRAY_SOURCE_DIR) + "/scenes/test.scad", diag,
                                  libraryOptions());
}

std::string scene(const std::string &name) {
    return std::string(SCADRAY_SOURCE_DIR) + "/scenes/" + name;
}

RenderResult render(const RenderScene &rs, int spp = 1, int width = 96, int height = 72) {
    RenderOptions o;
    o.width = width;
    o.height = height;
    o.samplesPerPixel = spp;
    o.threads = 2;
    return renderImage(rs, o);
}

/// Largest channel difference between two pictures of the same size.
double maxDifference(const Image &a, const Image &b) {
    double d = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            Rgb p = a.at(x, y), q = b.at(x, y);
            d = std::max({d, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)});
        }
    return d;
}

/// The same picture, ties and ray counts, bit for bit.
void expectSameRender(const RenderResult &a, const RenderResult &b) {
    EXPECT_EQ(maxDifference(a.image, b.image), 0);
    EXPECT_EQ(maxDifference(a.ties, b.ties), 0);
    EXPECT_EQ(a.stats.camera, b.stats.camera);
    EXPECT_EQ(a.stats.shadow, b.stats.shadow);
    EXPECT_EQ(a.stats.reflection, b.stats.reflection);
    EXPECT_EQ(a.stats.refraction, b.stats.refraction);
    EXPECT_EQ(a.stats.spanOps, b.stats.spanOps);
}

TEST(RenderPlan, OnlyTheRaysTheMaterialsNeed) {
    // No transparent material: no refraction, transmission or internal reflection rays; no
    // reflective one: no reflection rays; nothing glossy, frosted or jittered: no distributed
    for (const char *name :
         {"csg_part.scad", "lecture_csg.scad", "openscad_model.scad", "print_plate.scad"}) {
        SCOPED_TRACE(name);
        Compiled c = compileScene(load(scene(name)), true);
        RenderResult r = render(*c.rs, 4);
        EXPECT_GT(r.stats.camera, 0);
        EXPECT_GT(r.stats.shadow, 0);
        EXPECT_EQ(r.stats.refraction, 0);
        EXPECT_EQ(r.stats.transmission, 0);
        EXPECT_EQ(r.stats.internalReflection, 0);
        EXPECT_EQ(r.stats.reflection, 0);
        EXPECT_EQ(r.stats.distributed, 0);
        EXPECT_FALSE(makePlan(*c.rs).monteCarlo);
    }
    // The glass scene needs them, and says so
    Compiled glass = compileScene(load(scene("glass.scad")), true);
    RenderResult g = render(*glass.rs);
    EXPECT_GT(g.stats.refraction, 0);
    EXPECT_GT(g.stats.reflection, 0);
    EXPECT_EQ(g.stats.distributed, 0);
}

TEST(RenderPlan, ShadowlessAndBackFacingLightsCastNoShadowRays) {
    const std::string body =
        "camera(location=[0, -8, 3], look_at=[0, 0, 0]);\n"
        "material(color=\"white\") translate([-5, -5, -1]) cube([10, 10, 1]);\n"
        "material(color=\"red\") sphere(1);\n";
    // A shadowless light, and a light below the floor (behind every surface the camera sees,
    // except the underside of the sphere, which is hidden by the floor)
    Compiled shadowless =
        compileScene(loadText(body + "point_light([3, -3, 6], shadowless=true);"), true);
    EXPECT_EQ(render(*shadowless.rs).stats.shadow, 0);
    Compiled below = compileScene(loadText(body + "point_light([0, 0, -20]);"), true);
    EXPECT_EQ(render(*below.rs).stats.shadow, 0);
    Compiled lit = compileScene(loadText(body + "point_light([3, -3, 6]);"), true);
    EXPECT_GT(render(*lit.rs).stats.shadow, 0);
}

TEST(RenderPlan, ClearGlassCastsShadowRaysOnlyWhereItsHighlightShows) {
    // A surface with no diffuse or specular term shows a light only through its phong
    // highlight, so where POV-Ray's test leaves the highlight out the plan casts no shadow ray
    // towards it. The same scene with diffuse 1e-300 (a term that rounds away in every
    // colour, but makes every shadow ray count) casts them all: the picture is the same within
    // that term, so nothing the skipped rays found was needed. The jittered area light's
    // shadow rays draw from the pixel's random numbers and must still be cast, or every later
    // sample of the pixel would move.
    auto glass = [](const std::string &diffuse, const std::string &light) {
        return compileScene(
            loadText("camera(location=[0, -9, 4], look_at=[0, 0, 1]);\n" + light +
                     "material(color=\"white\") translate([-6, -6, -1]) cube([12, 12, 1]);\n"
                     "material(color=[1, 1, 1], transmit=0.95, ior=1.5, ambient=0, diffuse=" +
                     diffuse +
                     ", phong=0.8, phong_size=200) translate([0, 0, 1.5]) sphere(1.5);\n"),
            true);
    };
    const std::string point = "point_light([-4, -6, 8]);\n";
    const std::string jittered =
        "area_light([3, -5, 7], axis1=[1, 0, 0], axis2=[0, 1, 0], samples=[3, 3], jitter=true);\n";
    for (const std::string &light : {point, jittered}) {
        SCOPED_TRACE(light);
        Compiled skipping = glass("0", light), casting = glass("1e-300", light);
        RenderResult a = render(*skipping.rs, 4, 64, 48), b = render(*casting.rs, 4, 64, 48);
        EXPECT_LT(maxDifference(a.image, b.image), 1e-200);
        EXPECT_EQ(a.stats.camera, b.stats.camera);
        EXPECT_EQ(a.stats.refraction, b.stats.refraction);
        if (light == point)
            EXPECT_LT(a.stats.shadow, b.stats.shadow);
        else
            EXPECT_EQ(a.stats.shadow, b.stats.shadow);
    }
}

TEST(RenderPlan, SharpSceneIsTheSameAtOneAndSixteenSamplesAwayFromEdges) {
    Compiled c = compileScene(load(scene("csg_part.scad")), true);
    RenderPlan plan = makePlan(*c.rs);
    EXPECT_EQ(plan.defaultSamples, 1);
    RenderResult one = render(*c.rs, 1, 160, 120), sixteen = render(*c.rs, 16, 160, 120);
    EXPECT_EQ(one.stats.distributed, 0);
    EXPECT_EQ(sixteen.stats.distributed, 0);
    EXPECT_EQ(sixteen.stats.camera, 16 * one.stats.camera);
    // Away from edges (the 5x5 neighbourhood of the 1-sample picture varies by less than 1 %)
    // more samples only average a smooth shading over the pixel: no noise to remove
    int smooth = 0, differing = 0;
    for (int y = 2; y < 118; ++y)
        for (int x = 2; x < 158; ++x) {
            double lo = 1e9, hi = -1e9;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    Rgb p = one.image.at(x + dx, y + dy);
                    lo = std::min({lo, p.r, p.g, p.b});
                    hi = std::max({hi, p.r, p.g, p.b});
                }
            if (hi - lo > 0.01) continue;
            ++smooth;
            Rgb p = one.image.at(x, y), q = sixteen.image.at(x, y);
            differing += std::max({std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b)}) >
                         1.0 / 1024;
        }
    EXPECT_GT(smooth, 160 * 120 / 4);
    EXPECT_EQ(differing, 0) << "of " << smooth;
}

TEST(RenderPlan, MonteCarloScenesGetMoreSamples) {
    for (const char *name : {"montecarlo/glossy.scad", "montecarlo/frosted.scad",
                             "crosscheck/soft_shadows_jitter.scad"}) {
        Compiled c = compileScene(load(scene(name)), true);
        RenderPlan plan = makePlan(*c.rs);
        EXPECT_TRUE(plan.monteCarlo) << name;
        EXPECT_EQ(plan.defaultSamples, 4) << name;
    }
    // A grid area light without jitter is deterministic
    Compiled grid = compileScene(load(scene("crosscheck/soft_shadows_grid.scad")), true);
    EXPECT_FALSE(makePlan(*grid.rs).monteCarlo);
}

TEST(RenderPlan, NeverChangesThePicture) {
    // Every scene, rendered with the plan (unions split, hidden objects dropped, CSG pruned)
    // and without: the same picture, the same tie pixels
    int scenes = 0;
    int64_t wastedShadowRays = 0;
    for (const char *dir : {"", "crosscheck", "stiff", "montecarlo"}) {
        for (const auto &e : fs::directory_iterator(scene(dir))) {
            if (e.path().extension() != ".scad" || e.path().filename() == "scadray.scad") continue;
            SCOPED_TRACE(e.path().string());
            Compiled with = compileScene(load(e.path().string()), true);
            Compiled without = compileScene(load(e.path().string()), false);
            RenderResult a = render(*with.rs, 1, 64, 48), b = render(*without.rs, 1, 64, 48);
            EXPECT_EQ(maxDifference(a.image, b.image), 0);
            EXPECT_EQ(maxDifference(a.ties, b.ties), 0);
            EXPECT_EQ(b.stats.prunedSubtrees, 0);
            EXPECT_LE(a.stats.spanOps, b.stats.spanOps);
            // Without the plan shadow rays also go to lights behind the surface and to
            // shadowless ones (and are thrown away); every other kind is the same
            EXPECT_LE(a.stats.shadow, b.stats.shadow);
            EXPECT_EQ(a.stats.camera, b.stats.camera);
            EXPECT_EQ(a.stats.reflection, b.stats.reflection);
            EXPECT_EQ(a.stats.refraction, b.stats.refraction);
            EXPECT_EQ(a.stats.distributed, b.stats.distributed);
            wastedShadowRays += b.stats.shadow - a.stats.shadow;
            ++scenes;
        }
    }
    EXPECT_GE(scenes, 30);
    EXPECT_GT(wastedShadowRays, 0);
}

TEST(RenderPlan, VistaListsNeverChangeThePicture) {
    // Every scene, its camera rays taking the leaf lists of their direction's cell (in scenes
    // of any size here) and walking the whole tree: the same picture, ties and ray counts,
    // bit for bit
    int scenes = 0, listing = 0;
    for (const char *dir : {"", "crosscheck", "stiff", "montecarlo"}) {
        for (const auto &e : fs::directory_iterator(scene(dir))) {
            if (e.path().extension() != ".scad" || e.path().filename() == "scadray.scad") continue;
            SCOPED_TRACE(e.path().string());
            Compiled with = compileScene(load(e.path().string()), true, true);
            Compiled without = compileScene(load(e.path().string()), true, false);
            EXPECT_EQ(without.rs->vista(), nullptr);
            expectSameRender(render(*with.rs, 4, 64, 48), render(*without.rs, 4, 64, 48));
            listing += with.rs->vista() && with.rs->vista()->cellsListing() > 0;
            ++scenes;
        }
    }
    EXPECT_GE(scenes, 30);
    EXPECT_GE(listing, scenes / 2);  // most scenes' camera rays took the lists
}

TEST(RenderPlan, LaneSlabsNeverChangeThePicture) {
    // Every scene, the scene tree's nodes tested in AVX lanes and one plane at a time (camera
    // rays on the leaf lists in half the scenes, walking the tree in the others): the same
    // picture, ties and ray counts, bit for bit
    if (!__builtin_cpu_supports("avx2"))
        GTEST_SKIP() << "this machine has no AVX2: the lanes are not used";
    int scenes = 0;
    for (const char *dir : {"", "crosscheck", "stiff", "montecarlo"}) {
        for (const auto &e : fs::directory_iterator(scene(dir))) {
            if (e.path().extension() != ".scad" || e.path().filename() == "scadray.scad") continue;
            SCOPED_TRACE(e.path().string());
            bool vista = scenes % 2 == 0;
            Compiled lanes = compileScene(load(e.path().string()), true, vista, true);
            Compiled planes = compileScene(load(e.path().string()), true, vista, false);
            ASSERT_TRUE(lanes.rs->laneSlabs());
            ASSERT_FALSE(planes.rs->laneSlabs());
            expectSameRender(render(*lanes.rs, 4, 64, 48), render(*planes.rs, 4, 64, 48));
            ++scenes;
        }
    }
    EXPECT_GE(scenes, 30);
}

TEST(RenderPlan, PrintPlateSplitsItsUnionAndDropsTheSpool) {
    Compiled with = compileScene(load(scene("print_plate.scad")), true);
    Compiled without = compileScene(load(scene("print_plate.scad")), false);
    const CompileStats &s = with.rs->stats();
    EXPECT_EQ(s.unionsSplit, 1u);
    EXPECT_EQ(s.behindCamera, 1u);
    EXPECT_EQ(s.objects, 49u);  // 48 parts and the plate
    EXPECT_EQ(s.csgObjects, 48u);
    EXPECT_EQ(without.rs->stats().objects, 3u);
    EXPECT_EQ(without.rs->stats().behindCamera, 0u);
    RenderResult a = render(*with.rs), b = render(*without.rs);
    EXPECT_EQ(maxDifference(a.image, b.image), 0);
    // Span merging only within the part a ray meets
    EXPECT_LT(a.stats.spanOps * 2, b.stats.spanOps);
}

TEST(RenderPlan, WhatMayBeDroppedBehindTheCamera) {
    // Camera at the origin looking along +y; a red box behind it, a sphere in front
    const std::string base =
        "camera(location=[0, 0, 1], look_at=[0, 10, 1]);\n"
        "material(color=\"white\") translate([-5, 5, -1]) cube([10, 10, 1]);\n"
        "translate([0, 10, 1]) sphere(1);\n";
    struct Case {
        std::string extra;
        size_t dropped;
        const char *reason;
    };
    const Case cases[] = {
        {"point_light([2, 4, 6]); material(color=\"red\") translate([-1, -6, 0]) cube(2);", 1, ""},
        // A shadowless light behind the camera casts no shadow rays
        {"point_light([2, 4, 6]); point_light([0, -20, 6], shadowless=true);"
         "material(color=\"red\") translate([-1, -6, 0]) cube(2);",
         1, ""},
        {"point_light([0, -20, 6]); material(color=\"red\") translate([-1, -6, 0]) cube(2);", 0,
         "a light is behind the camera"},
        {"point_light([2, 4, 6]); material(color=\"red\") translate([-1, -6, 0]) cube(2);"
         "material(reflection=0.5) translate([3, 8, 0]) cube(1);",
         0, "a material reflects"},
        {"point_light([2, 4, 6]); material(color=\"red\", transmit=0.5) translate([-1, -6, 0]) "
         "cube(2);",
         0, "a material is transparent"},
        // Straddling the camera plane: kept
        {"point_light([2, 4, 6]); material(color=\"red\") translate([-1, -1, 0]) cube(2);", 0, ""},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.extra);
        Compiled with = compileScene(loadText(base + c.extra), true);
        Compiled without = compileScene(loadText(base + c.extra), false);
        EXPECT_EQ(with.rs->stats().behindCamera, c.dropped);
        EXPECT_EQ(with.rs->stats().behindCameraKept, c.reason);
        EXPECT_EQ(maxDifference(render(*with.rs).image, render(*without.rs).image), 0);
    }
}

TEST(RenderPlan, UnionsSplitOnlyIntoDisjointPartsWithOneInterior) {
    struct Case {
        const char *src;
        size_t objects, csg;
    };
    const Case cases[] = {
        {"union() { sphere(1); translate([3, 0, 0]) sphere(1); translate([6, 0, 0]) cube(1); }", 3,
         0},
        // Touching boxes fuse: one solid without an inner face
        {"union() { cube(1); translate([1, 0, 0]) cube(1); }", 1, 1},
        {"union() { sphere(1); translate([1.5, 0, 0]) sphere(1); }", 1, 1},
        // Disjoint glass parts of different ior: a CSG solid has one interior, so not split
        {"union() { material(transmit=0.9, ior=1.5) sphere(1);"
         " material(transmit=0.9, ior=1.2) translate([3, 0, 0]) sphere(1); }",
         1, 1},
        {"material(transmit=0.9, ior=1.5) union() { sphere(1); translate([3, 0, 0]) sphere(1); }",
         2, 0},
        // Nested: the inner union's parts are disjoint from each other and from the difference
        {"union() { difference() { cube(2); sphere(1); } translate([5, 0, 0]) union() { sphere(1);"
         " translate([3, 0, 0]) sphere(1); } }",
         3, 1},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.src);
        std::string src = std::string("point_light([3, -8, 6]);\n") + c.src;
        Compiled with = compileScene(loadText(src), true),
                 without = compileScene(loadText(src), false);
        EXPECT_EQ(with.rs->stats().objects, c.objects);
        EXPECT_EQ(with.rs->stats().csgObjects, c.csg);
        EXPECT_EQ(maxDifference(render(*with.rs).image, render(*without.rs).image), 0);
    }
}

TEST(RenderPlan, DescribesItself) {
    Compiled c = compileScene(load(scene("print_plate.scad")), true);
    RenderPlan plan = makePlan(*c.rs);
    RenderOptions ro;
    ro.samplesPerPixel = plan.defaultSamples;
    ro.adaptive = plan.adaptive;
    std::string text = describePlan(*c.rs, c.scene.stats, plan, ro, true);
    for (const char *part :
         {"shadows: rays towards 1 of 2 lights (1 shadowless: none)",
          "no material reflects: no reflection rays", "no material is transparent: no refraction",
          "no distributed rays", "49 solids kept (48 with CSG span merging",
          "1 union of disjoint parts split", "dropped: 1 behind the camera",
          "1 unused material (of 3)", "BVH over 49 solids",
          "samples: adaptive, each pixel's centre", "(chosen: every material is sharp"})
        EXPECT_NE(text.find(part), std::string::npos) << part << " not in:\n" << text;
}

}  // namespace
}  // namespace rt
