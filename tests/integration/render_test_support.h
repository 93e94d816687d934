// SPDX-License-Identifier: MIT
// Scenes of scenes/ compiled for the renderer, and the render options of a small two-thread
// picture, for the integration tests that render in process (tile_render_test.cpp,
// adaptive_render_test.cpp). The scenes' diagnostics are dropped: these tests check pixels.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "core/ir/scene_defaults.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "importers/loader/scene_loader.h"
#include "importers/scad/scad_importer.h"

namespace rt::test {

/// A scene and its compiled form (which points into it, so they travel together).
struct Compiled {
    ir::Scene scene;
    std::unique_ptr<RenderScene> rs;
};

/// Import options that find scenes/scadray.scad for `use <scadray.scad>`.
inline scad::ImportOptions libraryOptions() {
    scad::ImportOptions io;
    io.libraryPaths = {std::string(SCADRAY_SOURCE_DIR) + "/scenes"};
    return io;
}

/// `scene` completed (default camera and lights) and compiled.
inline Compiled compile(ir::Scene scene) {
    Compiled c{std::move(scene), nullptr};
    DiagnosticSink diag;
    ir::completeScene(c.scene, diag);
    c.rs = RenderScene::compile(c.scene, diag);
    return c;
}

/// scenes/`name` loaded as the command line loads it (its defaults: --facets auto, the
/// automatic camera and lights) and compiled.
inline Compiled loadScene(const std::string &name) {
    DiagnosticSink diag;
    LoadOptions lo;
    lo.libraryPaths = libraryOptions().libraryPaths;
    Compiled c{rt::loadScene(std::string(SCADRAY_SOURCE_DIR) + "/scenes/" + name, diag, lo),
               nullptr};
    c.rs = RenderScene::compile(c.scene, diag);
    return c;
}

/// A `w` x `h` picture on two threads, every other option at its default.
inline RenderOptions options(int w, int h) {
    RenderOptions o;
    o.width = w;
    o.height = h;
    o.threads = 2;
    return o;
}

}  // namespace rt::test
