// SPDX-License-Identifier: MIT
// `scadray check`: render a scene with scadray and with POV-Ray (exported, same camera and
// resolution, supersampled), compare statistically, and report error against run time.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/image/image_compare.h"
#include "core/image/image_io.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

struct CheckArgs {
    SceneArgs scene;
    std::string outDir, csv;
    int width = 320, height = 240;
    int supersample = 3, batches = 8, samples = 4, threads = 0, timeout = 600;
    uint64_t seed = 1;
    bool quiet = false;
    CompareOptions compare;
};

int runCheck(const CheckArgs &a) {
    using clock = std::chrono::steady_clock;
    if (a.supersample < 1 || a.supersample > 16)
        throw std::invalid_argument("--supersample must be between 1 and 16");
    RenderOptions ro;
    ro.width = a.width;
    ro.height = a.height;
    ro.samplesPerPixel = a.samples;
    ro.batches = a.batches;
    ro.threads = a.threads;
    ro.seed = a.seed;
    ro.sampleClamp = a.compare.clampMax;  // POV-Ray's PNG clips every sub-sample at 1
    validateRenderOptions(ro);
    if (!pov::povrayAvailable())
        throw std::invalid_argument("POV-Ray (povray) is not installed; tools/setup.sh installs it");

    std::string stem = fs::path(a.scene.input).stem().string();
    fs::path dir = a.outDir.empty() ? fs::path(stem + "_check") : fs::path(a.outDir);
    fs::create_directories(dir);
    auto file = [&](const std::string &suffix) { return (dir / (stem + suffix)).string(); };

    DiagnosticSink diag;
    attachPrinter(diag, true);
    ir::Scene scene = loadScene(a.scene.input, diag, a.scene.loadOptions(a.quiet));

    // POV-Ray: export, render k times larger without antialiasing, box-downsample
    PovReference pov = renderPovReference(scene, dir.string(), stem,
                                          fs::path(a.scene.input).filename().string(), a.width,
                                          a.height, a.supersample, a.threads, a.timeout);
    const pov::PovRunResult &pr = pov.run;
    const ImageEstimate &reference = pov.image;

    // scadray: independent seeded batches, so the comparison knows each pixel's noise
    auto t0 = clock::now();
    auto rs = RenderScene::compile(scene, diag);
    RenderResult rr = renderImage(*rs, ro);
    double ourWall = std::chrono::duration<double>(clock::now() - t0).count();
    ImageEstimate ours{rr.image, rr.variance, a.batches, {}, rr.ties};

    CompareResult cr = compareImages(ours, reference, a.compare);
    // A warning from POV-Ray about the exported file is an exporter bug, not a detail
    if (pr.warnings > 0) cr.pass = false;
    writeEstimate(reference, file("_reference.exr"));
    writeEstimate(ours, file("_scadray.exr"));
    writeImage(reference.mean, file("_reference.png"));
    writeImage(ours.mean, file("_scadray.png"));
    writeImage(cr.heatMap, file("_diff.png"));

    char buf[512];
    std::string report;
    report += std::string(cr.pass ? "PASS" : "DIFFERENT") + ": " + a.scene.input + " at " +
              std::to_string(a.width) + "x" + std::to_string(a.height) + "\n";
    std::snprintf(buf, sizeof buf,
                  "povray:  %.3f s wall (parse %.3f s, trace %.3f s), %dx%d supersampled at %dx%d\n",
                  pr.wallSeconds, pr.parseSeconds, pr.traceSeconds, a.supersample, a.supersample,
                  a.width * a.supersample, a.height * a.supersample);
    report += buf;
    std::snprintf(buf, sizeof buf,
                  "scadray: %.3f s (render %.3f s), %d batches x %d spp, %.2f Mrays/s\n", ourWall,
                  rr.seconds, a.batches, a.samples,
                  rr.stats.totalRays() / std::max(rr.seconds, 1e-9) / 1e6);
    report += buf;
    report += cr.summary(a.compare);
    if (pr.warnings > 0)
        report += "povray printed " + std::to_string(pr.warnings) + " warnings about the exported scene (see " +
                  stem + ".ini.log)\n";
    report += "files: " + dir.string() + "/" + stem + "{.pov,.ini,_reference.png,_scadray.png,_diff.png,...}\n";
    pov::writeTextFile(file("_report.txt"), report);
    if (!a.csv.empty()) {
        bool fresh = !fs::exists(a.csv);
        std::ofstream out(a.csv, std::ios::app);
        if (fresh)
            out << "scene,verdict,rmse,max_error,masked_percent,tiles_tested,tiles_failed,"
                   "detectable_median,povray_wall_s,povray_trace_s,scadray_wall_s,scadray_render_s\n";
        std::snprintf(buf, sizeof buf, "%s,%s,%.3g,%.3g,%.1f,%d,%d,%.3g,%.3f,%.3f,%.3f,%.3f\n",
                      a.scene.input.c_str(), cr.pass ? "pass" : "different", cr.rmse, cr.maxError,
                      100.0 * cr.maskedPixels / (a.width * a.height), cr.tilesTested,
                      cr.tilesFailed, cr.detectableMedian, pr.wallSeconds, pr.traceSeconds,
                      ourWall, rr.seconds);
        out << buf;
        if (!out) throw std::runtime_error("cannot append to '" + a.csv + "'");
    }
    if (!a.quiet || !cr.pass) std::cout << report;
    return cr.pass ? kExitOk : kExitInputError;
}

}  // namespace

void addCheckCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App *cmd = app.add_subcommand(
        "check", "Render with scadray and POV-Ray, compare statistically, report error and time");
    args->scene.addTo(*cmd);
    cmd->add_option("-o,--output-dir", args->outDir, "Folder for all files (default <scene>_check)");
    cmd->add_option("-W,--width", args->width, "Image width")->capture_default_str();
    cmd->add_option("-H,--height", args->height, "Image height")->capture_default_str();
    cmd->add_option("--supersample", args->supersample,
                    "POV-Ray reference: k x k samples per pixel (rendered k times larger)")
        ->capture_default_str();
    cmd->add_option("--batches", args->batches, "scadray: independent seeded batches")
        ->capture_default_str();
    cmd->add_option("-s,--samples", args->samples, "scadray: samples per pixel in each batch")
        ->capture_default_str();
    cmd->add_option("--seed", args->seed, "scadray: seed of the first batch")->capture_default_str();
    cmd->add_option("-t,--threads", args->threads, "Threads for both renderers (0 = all)")
        ->capture_default_str();
    cmd->add_option("--timeout", args->timeout, "Seconds POV-Ray may run")->capture_default_str();
    cmd->add_flag("-q,--quiet", args->quiet, "Print the report only when the check fails");
    cmd->add_option("--csv", args->csv, "Append a row of figures to this CSV file");
    addCompareOptions(*cmd, args->compare);
    cmd->callback([args, &action]() { action = [args]() { return runCheck(*args); }; });
}

}  // namespace rt::cli
