// SPDX-License-Identifier: MIT
// Deep scene trees: freeing any tree never recurses; a tree deeper than
// ir::kMaxTreeDepth is a located error before any recursive walk; a tree exactly that deep
// validates, compiles and renders on the stacks the CLI and the render workers have.
#include <gtest/gtest.h>

#include "core/ir/ir_validate.h"
#include "core/ir/scene_defaults.h"
#include "core/render/renderer.h"
#include "core/system/large_stack.h"
#include "support/scene_builder.h"

namespace rt {
namespace {

using namespace rt::test;

/// difference() { difference() { ... { box; small box } ... } small box } `levels` deep.
ir::Scene differenceChain(int levels) {
    ir::Scene s;
    int m = s.addMaterial(plainMaterial(Rgb(1), 0.5, 0.5));
    ir::NodePtr n = box(Vec3(-1), Vec3(1), m);
    for (int i = 1; i < levels; ++i) {
        auto cut = box(Vec3(-1.5, -0.01, 0.9 - i * 1e-5), Vec3(1.5, 0.01, 2), m);
        n = csg(ir::NodeKind::Difference, std::move(n), std::move(cut));
        n->loc = SourceLoc(std::make_shared<const std::string>("deep.scad"), i, 1);
    }
    s.root->children.push_back(std::move(n));
    s.camera = lookAt(Vec3(0, -6, 3), Vec3(0));
    return s;
}

TEST(TreeDepth, FreeingAVeryDeepChainDoesNotRecurse) {
    ir::NodePtr n = sphere(1, 0);
    for (int i = 0; i < 300000; ++i) n = translated(Vec3(1e-6, 0, 0), std::move(n));
    n.reset();  // a recursive destructor overflows the 8 MB test thread long before this depth
    SUCCEED();
}

TEST(TreeDepth, DeeperThanTheLimitIsALocatedError) {
    ir::Scene s = differenceChain(ir::kMaxTreeDepth + 5);
    DiagnosticSink diag;
    try {
        ir::validateScene(s, diag);
        FAIL() << "expected SceneError";
    } catch (const SceneError &e) {
        EXPECT_NE(std::string(e.what()).find("nested more than 20000 levels"), std::string::npos)
            << e.what();
        // root -> chain top (line kMaxTreeDepth + 4) -> ...: the first node past the limit
        EXPECT_EQ(e.loc().line, 5);
        EXPECT_EQ(*e.loc().file, "deep.scad");
    }
}

TEST(TreeDepth, TheDeepestAllowedTreeValidatesCompilesAndRenders) {
    // root + chain: kMaxTreeDepth levels in all
    ir::Scene s = differenceChain(ir::kMaxTreeDepth - 1);
    s.lights.push_back(pointLight(Vec3(2, -8, 9)));
    DiagnosticSink diag;
    RenderResult r;
    runWithStack(kLargeStackBytes, [&] {
        ir::completeScene(s, diag);
        auto rs = RenderScene::compile(s, diag);
        RenderOptions o;
        o.width = 8;
        o.height = 6;
        o.threads = 2;
        r = renderImage(*rs, o);
    });
    // The box is lit in the middle of the picture, the background black at the corner
    EXPECT_GT(r.image.at(4, 3).r, 0.1);
    EXPECT_EQ(r.image.at(0, 0).r, 0);
}

}  // namespace
}  // namespace rt
