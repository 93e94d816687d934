// SPDX-License-Identifier: MIT
// `scadray export`: scene file -> POV-Ray 3.7 SDL (.pov) plus an .ini to render it.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <limits>

#include "core/render/renderer.h"
#include "exporters/povray/pov_writer.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

struct ExportArgs {
    SceneArgs scene;
    std::string output;
    int width = 640, height = 480, supersample = 1;
    bool quiet = false;
};

int runExport(const ExportArgs &a) {
    // The options' ranges keep the .ini's size (width x supersample) within an int
    static_assert(int64_t{kMaxImageSide} * kMaxSupersample <= std::numeric_limits<int>::max());
    fs::path pov =
        a.output.empty() ? fs::path(a.scene.input).stem().concat(".pov") : fs::path(a.output);
    if (pov.extension() != ".pov")
        throw std::invalid_argument("the output of export must end in .pov");
    requireOutputFile(pov.string(), "-o");
    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, a.quiet);
    LoadOptions lo = a.scene.loadOptions(a.quiet);
    lo.aspect = double(a.width) / a.height;
    ir::Scene scene = loadScene(a.scene.input, diag, lo);
    pov::IniOptions ini;
    ini.outputFile = pov.stem().string() + "_povray.png";
    ini.width = a.width;
    ini.height = a.height;
    ini.supersample = a.supersample;
    fs::path iniPath = fs::path(pov).replace_extension(".ini");
    pov::exportPov(scene, pov.string(), fs::path(a.scene.input).filename().string(), ini);
    if (!a.quiet)
        std::cerr << "scadray: wrote " << pov.string() << " and " << iniPath.string()
                  << " (render with: cd "
                  << (pov.has_parent_path() ? pov.parent_path().string() : ".") << " && povray "
                  << iniPath.filename().string() << ")\n";
    return kExitOk;
}

}  // namespace

void addExportCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App *cmd =
        app.add_subcommand("export", "Write the scene as POV-Ray 3.7 SDL (.pov) and an .ini");
    args->scene.addTo(*cmd);
    cmd->add_option("-o,--output", args->output, "Output .pov file; the .ini goes beside it")
        ->capture_default_str();
    addNumber(*cmd, "-W,--width", args->width, "Image width written to the .ini", 1, kMaxImageSide);
    addNumber(*cmd, "-H,--height", args->height, "Image height written to the .ini", 1,
              kMaxImageSide);
    addNumber(*cmd, "--supersample", args->supersample,
              "Render k times larger in the .ini, for k x k box-filtered supersampling", 1,
              kMaxSupersample);
    cmd->add_flag("-q,--quiet", args->quiet, "Only warnings and errors");
    cmd->callback([args, &action]() { action = [args]() { return runExport(*args); }; });
}

}  // namespace rt::cli
