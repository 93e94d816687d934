// SPDX-License-Identifier: MIT
// Entry point of the OpenSCAD-subset importer: .scad file -> ir::Scene.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"

namespace rt::scad {

/// Default evaluation step cap: stops a runaway program within about 10 s.
constexpr int64_t kDefaultMaxSteps = 30'000'000;
/// Default cap on vector elements alive at once (about 24 bytes each, so ~200 MB), which also
/// bounds one comparison's work; --max-elements raises it.
constexpr int64_t kDefaultMaxElements = 8'000'000;
/// Default geometry budget: points and faces the geometry operations make or examine (offset()
/// points, extrusion slices times points, projection() and minkowski() faces, ...), summed
/// over the evaluation and estimated from the parameters before any work is done. A realistic
/// model stays far below it; --max-geometry raises it.
constexpr int64_t kDefaultMaxGeometry = 100'000'000;

struct ImportOptions {
    /// Extra folders searched by include<>/use<> after the including file's folder.
    std::vector<std::string> libraryPaths;
    /// Top-level overrides, as `openscad -D name=expr`: each expression is parsed and assigned
    /// after the main file's own assignments.
    std::vector<std::pair<std::string, std::string>> defines;
    /// Evaluation step cap (calls, loop iterations, module instances); 0 = no cap.
    int64_t maxSteps = kDefaultMaxSteps;
    /// Vector elements alive at once (and elements one comparison may visit).
    int64_t maxElements = kDefaultMaxElements;
    /// Geometry budget (kDefaultMaxGeometry); 0 = no cap.
    int64_t maxGeometry = kDefaultMaxGeometry;
    /// Called now and then during evaluation with the steps taken so far (on the evaluating
    /// thread); for a progress display.
    std::function<void(int64_t steps)> progress;
    /// `$t`, the animation time: frame i of an N-frame animation is i * (1.0 / N), bit for bit
    /// as `openscad --animate N` computes it (not i / N, which differs in the last bit for
    /// some i, e.g. 3 of 10).
    double time = 0;
};

/// Reads, parses and evaluates a .scad file. Non-fatal problems go to `diag`; fatal ones throw
/// ParseError or EvalError with the source location.
ir::Scene importScad(const std::string &path, DiagnosticSink &diag, const ImportOptions &opts = {});

/// Same for source text held in memory; `virtualPath` names it in diagnostics and anchors
/// relative include<>/use<> lookups.
ir::Scene importScadSource(const std::string &source, const std::string &virtualPath,
                           DiagnosticSink &diag, const ImportOptions &opts = {});

}  // namespace rt::scad
