// SPDX-License-Identifier: MIT
// Shared pieces of the scadray command line: the scene options, printing diagnostics, and the
// exit codes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/image/image.h"
#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "core/system/input_file.h"
#include "exporters/povray/pov_runner.h"
#include "importers/loader/scene_loader.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace rt::cli {

/// Exit codes: 0 success, 1 a problem with the input or the render, 2 bad command-line usage.
constexpr int kExitOk = 0;
constexpr int kExitInputError = 1;
constexpr int kExitUsage = 2;

/// The scene argument and the options every scene-reading subcommand takes (-D, -L,
/// --max-steps, --facets).
struct SceneArgs {
    std::string input;
    std::vector<std::string> defines, libraries;
    std::string facets;  ///< as given; empty when not given (auto)
    int64_t maxSteps = scad::kDefaultMaxSteps;
    int64_t maxElements = scad::kDefaultMaxElements;
    int64_t maxGeometry = scad::kDefaultMaxGeometry;
    std::string environment;  ///< -e as given
    double environmentRotate = 0;

    /// Whether a subcommand takes the one positional scene: always, only with some of its
    /// options (render --encode-only does without; the command checks), or never (report
    /// takes many scenes of its own).
    enum class Positional { Required, Optional, None };
    /// Registers the positional scene (as `positional` says) and -D/-L on a subcommand.
    void addTo(CLI::App &cmd, Positional positional = Positional::Required);
    /// Throws std::invalid_argument for a malformed -D.
    LoadOptions loadOptions(bool quiet) const;
    /// The options addTo registers, as command-line arguments that give back these values
    /// (without the positional scene): for a subcommand run as its own process.
    std::vector<std::string> optionArguments() const;
};

/// Prints warnings (and notes unless quiet) to stderr as they are reported, first clearing
/// the progress line of a long evaluation if one is shown; when it goes out of scope (also
/// when an error ends the command) it prints one "N more warnings like: ..." line for each
/// kind of warning whose repeats the sink only counted.
class DiagnosticPrinter {
  public:
    DiagnosticPrinter(DiagnosticSink &diag, bool quiet);
    ~DiagnosticPrinter();
    DiagnosticPrinter(const DiagnosticPrinter &) = delete;
    DiagnosticPrinter &operator=(const DiagnosticPrinter &) = delete;

  private:
    DiagnosticSink &diag_;
};

/// Limits of the numeric options (README, "Security and limits").
constexpr int kMaxThreads = 1 << 16;
constexpr int kMaxSupersample = 16;
/// Seconds an external renderer (POV-Ray, OpenSCAD) may run: a week.
constexpr int kMaxTimeoutSeconds = 7 * 24 * 3600;

/// Registers a numeric option whose value must lie in [lo, hi]: anything else (a number out
/// of range, text, NaN or an infinity) is a usage error naming the option and the range,
/// raised before the value is converted, so nothing downstream sees an overflowed number.
/// The range shows in --help. `loOpen` excludes lo itself.
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, int &value, const std::string &help,
                       int lo, int hi);
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, long &value,
                       const std::string &help, long lo, long hi);
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, long long &value,
                       const std::string &help, long long lo, long long hi);
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, unsigned long &value,
                       const std::string &help, unsigned long lo, unsigned long hi);
CLI::Option *addNumber(CLI::App &cmd, const std::string &names, double &value,
                       const std::string &help, double lo, double hi, bool loOpen = false);

/// Throws std::invalid_argument, naming `option`, when `path` cannot be an output file: an
/// existing folder, or a name in a folder that does not exist. Checked before any work.
void requireOutputFile(const std::string &path, const std::string &option);

/// POV-Ray's picture of a scene, as `check` and `converge` take it: exported to
/// `dir/stem.pov` (+ .ini), rendered supersample times larger without antialiasing and
/// box-filtered down to width x height. `sceneName` goes into the file's header comment.
/// POV-Ray runs in a fresh private folder inside `dir` whose files then move to `dir`;
/// `stem` must be a safeFileStem (check.h).
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
