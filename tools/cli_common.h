// SPDX-License-Identifier: MIT
// Shared pieces of the scadray command line: loading a scene by file type, printing
// diagnostics, and the exit codes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/image/image.h"
#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "exporters/povray/pov_runner.h"
#include "importers/scad/scad_importer.h"

namespace CLI {
class App;
}

namespace rt::cli {

/// Exit codes: 0 success, 1 a problem with the input or the render, 2 bad command-line usage.
constexpr int kExitOk = 0;
constexpr int kExitInputError = 1;
constexpr int kExitUsage = 2;

struct LoadOptions {
    std::vector<std::string> libraryPaths;
    std::vector<std::pair<std::string, std::string>> defines;
    bool quiet = false;  ///< no progress line while a long .scad evaluates
    /// How spheres, cylinders, tori and lathes are drawn (`--facets`).
    ir::FacetMode facets = ir::FacetMode::Auto;
    int64_t maxSteps = scad::kDefaultMaxSteps;  ///< .scad evaluation step cap; 0 = none
};

/// The scene argument and the options every scene-reading subcommand takes (-D, -L,
/// --max-steps, --facets).
struct SceneArgs {
    std::string input;
    std::vector<std::string> defines, libraries;
    std::string facets;  ///< as given; empty when not given (auto)
    int64_t maxSteps = scad::kDefaultMaxSteps;

    /// Registers the positional scene and -D/-L on a subcommand.
    void addTo(CLI::App &cmd);
    /// Throws std::invalid_argument for a malformed -D.
    LoadOptions loadOptions(bool quiet) const;
};

/// Prints warnings (and notes unless quiet) to stderr as they are reported, first clearing
/// the progress line of a long evaluation if one is shown.
void attachPrinter(DiagnosticSink &diag, bool quiet);

/// Reads a scene by extension (.scad) and completes it (automatic camera, default lights).
/// Throws LocatedError for problems in the file, std::runtime_error for others. A .scad
/// evaluation that takes over a second shows an `evaluating: N M steps` line on a terminal
/// stderr (unless opts.quiet), cleared when it ends.
ir::Scene loadScene(const std::string &path, DiagnosticSink &diag, const LoadOptions &opts);

/// POV-Ray's picture of a scene, as `check` and `converge` take it: exported to
/// `dir/stem.pov` (+ .ini), rendered supersample times larger without antialiasing and
/// box-filtered down to width x height. `sceneName` goes into the file's header comment.
struct PovReference {
    ImageEstimate image;
    pov::PovRunResult run;
};
PovReference renderPovReference(const ir::Scene &scene, const std::string &dir,
                                const std::string &stem, const std::string &sceneName, int width,
                                int height, int supersample, int threads, int timeout);

/// Parses "name=expr" for -D.
std::pair<std::string, std::string> parseDefine(const std::string &text);

}  // namespace rt::cli
