// SPDX-License-Identifier: MIT
// The scene options, diagnostic printing and POV-Ray reference of the CLI.
#include "tools/cli_common.h"

#include <sys/stat.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <stdexcept>

#include "core/image/image_io.h"
#include "core/system/input_file.h"
#include "core/system/temp_file.h"
#include "exporters/povray/pov_writer.h"
#include "tools/check.h"

namespace rt::cli {

namespace {

/// A .scad evaluation shows its progress line after this long.
constexpr auto kProgressDelay = std::chrono::seconds(1);
/// and updates it at most this often.
constexpr auto kProgressInterval = std::chrono::milliseconds(250);

/// Whether the `evaluating:` line is on the terminal (it is written from the evaluating
/// thread): a diagnostic, or the end of the evaluation, clears it first.
std::atomic<bool> progressLineShown{false};

void clearProgressLine() {
    if (progressLineShown.exchange(false)) std::fputs("\r\033[K", stderr);
}

/// Shows the step count of a .scad evaluation on the terminal once it has run for
/// kProgressDelay, and clears the line when it ends; one per command, reset after each
/// evaluation (an animation evaluates once per frame).
void showEvaluationProgress(LoadOptions &lo) {
    struct State {
        bool started = false;
        std::chrono::steady_clock::time_point next;
    };
    auto state = std::make_shared<State>();
    lo.progress = [state](int64_t steps) {
        auto now = std::chrono::steady_clock::now();
        if (!state->started) {
            state->started = true;
            state->next = now + kProgressDelay;
        }
        if (now < state->next) return;
        state->next = now + kProgressInterval;
        std::fprintf(stderr, "\revaluating: %.1f M steps", static_cast<double>(steps) / 1e6);
        std::fflush(stderr);
        progressLineShown = true;
    };
    lo.progressDone = [state] {
        state->started = false;
        clearProgressLine();
    };
}

}  // namespace

void SceneArgs::addTo(CLI::App &cmd, Positional positional) {
    if (positional != Positional::None)
        cmd.add_option("scene", input, "Scene file (.scad, .gltf, .glb, .stl, .off)")
            ->required(positional == Positional::Required);
    cmd.add_option("-D,--define", defines, "Override a top-level variable: name=value");
    cmd.add_option("-L,--library", libraries, "Extra folder searched by include<> and use<>");
    cmd.add_option("--facets", facets,
                   "Spheres, cylinders and rotate_extrude solids: smooth (exactly round), "
                   "openscad (OpenSCAD's $fn/$fa/$fs polygons) or auto (polygons where $fn "
                   "gives at most " +
                       std::to_string(ir::kAutoFacetMaxFragments) + " fragments)")
        ->check(CLI::IsMember({"smooth", "openscad", "auto"}));
    addNumber(cmd, "--max-steps", maxSteps,
              "Cap on .scad evaluation steps (calls, loop iterations, module instances) "
              "that stops runaway programs; 0 = no cap",
              decltype(maxSteps){0}, std::numeric_limits<decltype(maxSteps)>::max());
    addNumber(cmd, "--max-elements", maxElements,
              "Cap on .scad vector elements alive at once (about 24 bytes each), which also "
              "bounds one comparison of vectors",
              int64_t{1}, int64_t{1} << 40);
    addNumber(cmd, "--max-geometry", maxGeometry,
              "Cap on the points and faces .scad geometry operations make or examine "
              "(offset, extrusions, hull, minkowski, projection, round fragments), estimated "
              "before the work; 0 = no cap",
              decltype(maxGeometry){0}, std::numeric_limits<decltype(maxGeometry)>::max());
    cmd.add_option("-e,--environment", environment,
                   "What rays leaving the scene see: none (the background colour), studio (a "
                   "grey gradient sky) or an equirectangular image file (.exr, .hdr; top row "
                   "up). Default: studio for .gltf/.glb, none otherwise");
    addNumber(cmd, "--env-rotate", environmentRotate,
              "Turn the environment about +Z by this many degrees (counterclockwise seen "
              "from above)",
              -360.0, 360.0);
}

std::vector<std::string> SceneArgs::optionArguments() const {
    std::vector<std::string> args = {"--max-steps",    std::to_string(maxSteps),
                                     "--max-elements", std::to_string(maxElements),
                                     "--max-geometry", std::to_string(maxGeometry)};
    for (const std::string &d : defines) args.insert(args.end(), {"-D", d});
    for (const std::string &l : libraries) args.insert(args.end(), {"-L", l});
    if (!facets.empty()) args.insert(args.end(), {"--facets", facets});
    if (!environment.empty()) args.insert(args.end(), {"-e", environment});
    if (environmentRotate != 0) {
        // Seventeen significant digits read back as the same double (std::to_string keeps six
        // decimals)
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g", environmentRotate);
        args.insert(args.end(), {"--env-rotate", buf});
    }
    return args;
}

LoadOptions SceneArgs::loadOptions(bool quiet) const {
    LoadOptions lo;
    if (!quiet && isatty(STDERR_FILENO)) showEvaluationProgress(lo);
    lo.maxSteps = maxSteps;
    lo.maxElements = maxElements;
    lo.maxGeometry = maxGeometry;
    lo.libraryPaths = libraries;
    for (const auto &d : defines) lo.defines.push_back(parseDefine(d));
    auto mode = ir::parseFacetMode(facets.empty() ? "auto" : facets);
    if (!mode) throw std::invalid_argument("--facets must be smooth, openscad or auto");
    lo.facets = *mode;
    lo.environment = environment;
    lo.environmentRotate = environmentRotate;
    return lo;
}

DiagnosticPrinter::DiagnosticPrinter(DiagnosticSink &diag, bool quiet) : diag_(diag) {
    diag.setListener([quiet](const Diagnostic &d) {
        if (quiet && d.severity == Severity::Note) return;
        clearProgressLine();
        std::cerr << formatDiagnostic(d, d.severity != Severity::Note) << "\n";
    });
}

DiagnosticPrinter::~DiagnosticPrinter() {
    diag_.setListener(nullptr);
    clearProgressLine();
    for (const auto &line : diag_.summary()) std::cerr << "scadray: " << line << "\n";
}

void requireOutputFile(const std::string &path, const std::string &option) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path p(path);
    if (path.empty() || fs::is_directory(p, ec) || !p.has_filename())
        throw std::invalid_argument(option + ": '" + path + "' is a folder, not a file name");
    fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec))
        throw std::invalid_argument(option + ": the folder of '" + path + "' does not exist");
}

std::pair<std::string, std::string> parseDefine(const std::string &text) {
    auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
        throw std::invalid_argument("-D expects name=value, got '" + text + "'");
    return {text.substr(0, eq), text.substr(eq + 1)};
}

PovReference renderPovReference(const ir::Scene &scene, const std::string &dir,
                                const std::string &stem, const std::string &sceneName, int width,
                                int height, int supersample, int threads, int timeout) {
    namespace fs = std::filesystem;
    if (!isSafeFileStem(stem))
        throw std::logic_error("renderPovReference: '" + stem + "' is not a safe file stem");
    // POV-Ray runs in a folder made fresh for this run (mkdtemp), so nothing planted in the
    // output folder (a povray.ini, an .ini or .pov of the same name, a stale texture) is read;
    // its files are named by a safe stem, so nothing of a scene's name becomes an option: POV-Ray
    // re-splits its arguments at spaces, takes KEY=VALUE words and +/- words as options, and
    // cuts .ini values at a space
    TempDir run(dir);
    fs::path r(run.path());
    pov::IniOptions ini;
    ini.outputFile = stem + "_povray.png";
    ini.width = width;
    ini.height = height;
    ini.supersample = supersample;
    ini.threads = threads;
    // Kept beside the check's other files: the export, the picture, the log (also when POV-Ray
    // failed, whose log the error points to). The run's own povray.conf goes with the folder.
    auto keepFiles = [&] {
        for (const auto &entry : fs::directory_iterator(r)) {
            if (!entry.is_regular_file()) continue;
            fs::path target = fs::path(dir) / entry.path().filename();
            refuseOverwritingInput(target.string());
            fs::rename(entry.path(), target);
        }
    };
    PovReference ref;
    try {
        pov::exportPov(scene, (r / (stem + ".pov")).string(), sceneName, ini);
        ref.run = pov::runPovRay(run.path(), stem + ".ini", threads, timeout);
    } catch (...) {
        try {
            keepFiles();
        } catch (const std::exception &) {
        }
        throw;
    }
    ref.image = downsample(readImage((r / ini.outputFile).string()), supersample);
    keepFiles();
    return ref;
}

}  // namespace rt::cli
