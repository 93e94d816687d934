// SPDX-License-Identifier: MIT
// `scadray converge`: error against run time. Renders a scene at 1, 2, 4, ... samples per pixel,
// times each render, measures its RMSE against a converged reference (and against POV-Ray), and
// fits the slope of log RMSE against log seconds.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>

#include "core/image/image_io.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"
#include "tools/check.h"
#include "tools/cli_common.h"
#include "tools/commands.h"
#include "tools/svg_plot.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

/// The reference is rendered in this many independent batches, so each pixel's mean comes with
/// the variance of that mean.
constexpr int kReferenceBatches = 16;
/// The reference has this many times the samples of the highest level unless told otherwise.
constexpr int kReferenceFactor = 8;
/// An RMSE below this (linear radiance; 1/255 is one 8-bit step) counts as no error at all:
/// the scene is deterministic at this resolution.
constexpr double kNegligibleRmse = 1e-6;
/// Slopes within this distance of -1/2 read as unbiased Monte Carlo convergence.
constexpr double kSlopeTolerance = 0.1;

struct ConvergeArgs {
    SceneArgs scene;
    std::string outDir;
    int width = 160, height = 120, maxSamples = 64, referenceSamples = 0, threads = 0;
    int supersample = 4, timeout = 600;
    double budget = 0, clamp = 0;
    uint64_t seed = 1;
    bool povray = false, quiet = false;
};

struct Level {
    int samples = 0;
    double seconds = 0;
    double mse = 0;           ///< against the reference mean
    double mseCorrected = 0;  ///< minus the reference's mean variance, at least 0
    std::optional<double> msePovray;
};

/// Mean over all pixels and channels of (a - b)^2; with `clampHigh` > 0 both values are first
/// clamped to [0, clampHigh].
double meanSquaredError(const Image &a, const Image &b, double clampHigh = 0) {
    const auto &da = a.data(), &db = b.data();
    double sum = 0;
    for (size_t i = 0; i < da.size(); ++i) {
        double va = da[i], vb = db[i];
        if (clampHigh > 0) {
            va = std::clamp(va, 0.0, clampHigh);
            vb = std::clamp(vb, 0.0, clampHigh);
        }
        sum += (va - vb) * (va - vb);
    }
    return da.empty() ? 0 : sum / double(da.size());
}

double meanValue(const Image &img) {
    double sum = 0;
    for (float v : img.data()) sum += v;
    return img.data().empty() ? 0 : sum / double(img.data().size());
}

std::string fmt(const char *format, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

/// 1, 2, 4, ... up to maxSamples, and maxSamples itself when it is not a power of two.
std::vector<int> sampleLevels(int maxSamples) {
    std::vector<int> levels;
    for (int n = 1; n <= maxSamples; n *= 2) {
        levels.push_back(n);
        if (n > maxSamples / 2) break;
    }
    if (levels.back() != maxSamples) levels.push_back(maxSamples);
    return levels;
}

/// What a fitted slope says, for the report.
std::string readSlope(double slope) {
    if (std::abs(slope + 0.5) <= kSlopeTolerance)
        return "as expected for unbiased Monte Carlo (-1/2)";
    if (slope < -0.5)
        return "steeper than -1/2: stratification pays (edges, smooth integrands), or the "
               "sample count only antialiases";
    return "flatter than -1/2: bias (the levels converge to something other than the reference) "
           "or a time floor that does not grow with the samples";
}

int runConverge(const ConvergeArgs &a) {
    LoadOptions lo = a.scene.loadOptions(a.quiet);
    lo.aspect = double(a.width) / a.height;
    // Check every option before reading the scene
    RenderOptions base;
    base.width = a.width;
    base.height = a.height;
    base.threads = a.threads;
    base.sampleClamp = a.clamp;
    base.jitterSingleSample = true;
    std::vector<int> levels = sampleLevels(a.maxSamples);
    for (int n : levels) {
        RenderOptions ro = base;
        ro.samplesPerPixel = n;
        validateRenderOptions(ro);
    }
    if (a.referenceSamples > 0) {
        RenderOptions ro = base;
        ro.samplesPerPixel = std::max(1, a.referenceSamples / kReferenceBatches);
        ro.batches = kReferenceBatches;
        validateRenderOptions(ro);
    }

    std::string stem = safeFileStem(a.scene.input);
    std::string sceneName = fs::path(a.scene.input).filename().string();
    fs::path dir = a.outDir.empty()
                       ? fs::path(fs::path(a.scene.input).stem().string() + "_converge")
                       : fs::path(a.outDir);
    auto file = [&](const std::string &suffix) { return (dir / (stem + suffix)).string(); };

    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, a.quiet);
    ir::Scene scene = loadScene(a.scene.input, diag, lo);
    auto rs = RenderScene::compile(scene, diag);
    auto say = [&](const std::string &line) {
        if (!a.quiet) std::cerr << line << "\n";
    };

    // Warm up (first-touch page faults, thread start-up) so the cheapest level is timed fairly
    {
        RenderOptions ro = base;
        ro.seed = a.seed + 1000003;
        renderImage(*rs, ro);
    }

    // The levels, each with its own seed (and none the reference's), so their errors are
    // independent of the reference's noise and of each other
    std::vector<Level> results;
    std::vector<Image> images;
    std::string stopNote;
    for (size_t i = 0; i < levels.size(); ++i) {
        RenderOptions ro = base;
        ro.samplesPerPixel = levels[i];
        ro.seed = a.seed + 1 + i;
        RenderResult rr = renderImage(*rs, ro);
        Level l;
        l.samples = levels[i];
        l.seconds = rr.seconds;
        results.push_back(l);
        images.push_back(std::move(rr.image));
        say("  " + std::to_string(levels[i]) + " spp: " + fmt("%.3f", rr.seconds) + " s");
        if (a.budget > 0 && rr.seconds > a.budget / 2 && i + 1 < levels.size()) {
            stopNote = "stopped after " + std::to_string(levels[i]) + " spp: it took " +
                       fmt("%.3g", rr.seconds) + " s, more than half the budget of " +
                       fmt("%.3g", a.budget) + " s";
            say("  " + stopNote);
            break;
        }
    }
    int highest = results.back().samples;

    // The reference: many more samples, in batches, so its own noise is known
    int referenceSamples = a.referenceSamples > 0 ? a.referenceSamples : kReferenceFactor * highest;
    RenderOptions ref = base;
    ref.samplesPerPixel = std::max(1, referenceSamples / kReferenceBatches);
    ref.batches = kReferenceBatches;
    ref.seed = a.seed;
    int referenceTotal = ref.samplesPerPixel * ref.batches;
    say("  reference: " + std::to_string(kReferenceBatches) + " batches x " +
        std::to_string(ref.samplesPerPixel) + " spp ...");
    RenderResult reference = renderImage(*rs, ref);
    double referenceVariance = meanValue(reference.variance);
    say("  reference: " + fmt("%.3f", reference.seconds) + " s");

    // POV-Ray, when asked for and installed: export, render k times larger, box-downsample
    std::optional<Image> povImage;
    pov::PovRunResult pr;
    std::string povNote;
    if (a.povray) {
        if (!pov::povrayAvailable()) {
            povNote = "POV-Ray not installed; skipped";
            std::cerr << "scadray: note: --povray: " << povNote << "\n";
        } else {
            fs::create_directories(dir);
            say("  POV-Ray ...");
            PovReference povRef = renderPovReference(scene, dir.string(), stem, sceneName, a.width,
                                                     a.height, a.supersample, a.threads, a.timeout);
            pr = povRef.run;
            povImage = povRef.image.mean;
            say("  POV-Ray: " + fmt("%.3f", pr.wallSeconds) + " s");
        }
    }

    // Errors of each level
    bool allNegligible = true;
    for (size_t i = 0; i < results.size(); ++i) {
        Level &l = results[i];
        l.mse = meanSquaredError(images[i], reference.image);
        l.mseCorrected = std::max(0.0, l.mse - referenceVariance);
        // POV-Ray's PNG clips at 1, so its error compares pixels clamped to [0, 1]
        if (povImage) l.msePovray = meanSquaredError(images[i], *povImage, 1.0);
        if (!(std::sqrt(l.mse) < kNegligibleRmse)) allNegligible = false;
    }
    std::vector<double> seconds, rmseCorrected, rmsePovray;
    for (const Level &l : results) {
        seconds.push_back(l.seconds);
        rmseCorrected.push_back(std::sqrt(l.mseCorrected));
        if (l.msePovray) rmsePovray.push_back(std::sqrt(*l.msePovray));
    }
    LogLogFit fit = allNegligible ? LogLogFit{} : fitLogLog(seconds, rmseCorrected);
    int belowNoise = 0;
    for (const Level &l : results) belowNoise += l.mseCorrected <= 0;

    // CSV
    std::string csv = "samples,seconds,rmse,rmse_corrected,efficiency,rmse_povray\n";
    // Unbounded where the error is nil (or negligible everywhere): left empty, printed "inf"
    auto efficiency = [&](const Level &l) {
        return !allNegligible && l.mseCorrected > 0 && l.seconds > 0
                   ? 1 / (l.mseCorrected * l.seconds)
                   : std::numeric_limits<double>::infinity();
    };
    for (const Level &l : results) {
        double e = efficiency(l);
        csv += std::to_string(l.samples) + "," + fmt("%.6g", l.seconds) + "," +
               fmt("%.6g", std::sqrt(l.mse)) + "," + fmt("%.6g", std::sqrt(l.mseCorrected)) + "," +
               (std::isfinite(e) ? fmt("%.6g", e) : "") + "," +
               (l.msePovray ? fmt("%.6g", std::sqrt(*l.msePovray)) : "") + "\n";
    }

    // Plot
    LogLogPlot plot;
    plot.title = sceneName + ": error against render time";
    plot.legendTitle = sceneName + ", " + std::to_string(a.width) + "x" + std::to_string(a.height);
    plot.xLabel = "render time (seconds)";
    plot.yLabel = "RMSE (linear radiance)";
    const std::string blue = "#1f77b4", red = "#d62728";
    plot.addSeries({"scadray vs reference (" + std::to_string(results.front().samples) + " to " +
                        std::to_string(highest) + " spp)",
                    blue, seconds, rmseCorrected, Stroke::Solid, true});
    if (povImage)
        plot.addSeries({"scadray vs POV-Ray (" + std::to_string(a.supersample) + "x" +
                            std::to_string(a.supersample) + " supersampled)",
                        red, seconds, rmsePovray, Stroke::Solid, true});
    if (fit.valid)
        plot.addLine({"least-squares fit: slope " + fmt("%.3f", fit.slope), blue, fit.slope, 1,
                      std::pow(10.0, fit.intercept), Stroke::Dashed});
    for (size_t i = 0; i < results.size(); ++i)
        if (rmseCorrected[i] > 0 && seconds[i] > 0) {
            plot.addLine({"slope -1/2 (unbiased Monte Carlo)", "#555555", -0.5, seconds[i],
                          rmseCorrected[i], Stroke::Dotted});
            break;
        }
    plot.addNote("vs reference: RMSE corrected for the reference's own noise");
    plot.addNote("reference: " + std::to_string(referenceTotal) + " spp (" +
                 std::to_string(kReferenceBatches) + " batches)");
    if (allNegligible) plot.addNote("all errors ~0: a deterministic scene");

    // Report
    char buf[256];
    std::string report =
        "scadray converge: " + a.scene.input + " at " + std::to_string(a.width) + "x" +
        std::to_string(a.height) + ", " + std::to_string(results.size()) + " levels, reference " +
        std::to_string(referenceTotal) + " spp (" + std::to_string(kReferenceBatches) +
        " batches x " + std::to_string(ref.samplesPerPixel) + ") in " +
        fmt("%.3f", reference.seconds) + " s, " + std::to_string(reference.threads) + " threads\n";
    std::snprintf(buf, sizeof buf, "%6s %10s %11s %11s %7s %11s %12s\n", "spp", "seconds", "rmse",
                  "rmse_corr", "slope", "efficiency", "rmse_povray");
    report += buf;
    for (size_t i = 0; i < results.size(); ++i) {
        const Level &l = results[i];
        std::string local = "-";
        if (i > 0 && rmseCorrected[i] > 0 && rmseCorrected[i - 1] > 0 && seconds[i] > 0 &&
            seconds[i - 1] > 0 && seconds[i] != seconds[i - 1])
            local = fmt("%.2f", std::log(rmseCorrected[i] / rmseCorrected[i - 1]) /
                                    std::log(seconds[i] / seconds[i - 1]));
        double e = efficiency(l);
        std::snprintf(buf, sizeof buf, "%6d %10.4g %11.4g %11.4g %7s %11s %12s\n", l.samples,
                      l.seconds, std::sqrt(l.mse), std::sqrt(l.mseCorrected), local.c_str(),
                      std::isfinite(e) ? fmt("%.4g", e).c_str() : "inf",
                      l.msePovray ? fmt("%.4g", std::sqrt(*l.msePovray)).c_str() : "-");
        report += buf;
    }
    report +=
        "rmse_corr = sqrt(max(0, MSE - mean reference variance)): the reference's own noise "
        "(RMSE " +
        fmt("%.3g", std::sqrt(referenceVariance)) +
        ") removed; plot and fit use it. efficiency = 1 / (corrected MSE x seconds)\n";
    if (allNegligible) {
        report += "all errors are ~0 (RMSE below " + fmt("%.0e", kNegligibleRmse) +
                  " at every level): the scene is deterministic at this resolution (no Monte "
                  "Carlo effects, nothing for more samples to antialias); nothing to fit\n";
    } else if (fit.valid) {
        report += "fit: slope " + fmt("%.3f", fit.slope) +
                  " of log RMSE against log seconds over " + std::to_string(fit.points) +
                  " levels: " + readSlope(fit.slope) + "\n";
        if (belowNoise > 0)
            report += std::to_string(belowNoise) +
                      " levels are within the reference's noise and left out of the fit; raise "
                      "--reference-samples\n";
    } else if (results.size() < 2) {
        report += "no fit: only one level was rendered\n";
    } else {
        report +=
            "no fit: fewer than two levels have an error above the reference's noise; raise "
            "--reference-samples\n";
    }
    if (referenceTotal < 4 * highest)
        report +=
            "note: the reference has fewer than 4x the samples of the highest level; its "
            "noise dominates there\n";
    if (!stopNote.empty()) report += "--budget: " + stopNote + "\n";
    if (povImage) {
        report += "POV-Ray: " + fmt("%.3f", pr.wallSeconds) + " s wall (trace " +
                  fmt("%.3f", pr.traceSeconds) + " s), " + std::to_string(a.supersample) + "x" +
                  std::to_string(a.supersample) +
                  " supersampled; against scadray's reference: RMSE " +
                  fmt("%.4g", std::sqrt(meanSquaredError(reference.image, *povImage, 1.0))) +
                  " (the floor of rmse_povray; pixels clamped to [0, 1] as in POV-Ray's PNG)\n";
        if (pr.warnings > 0)
            report += "POV-Ray printed " + std::to_string(pr.warnings) +
                      " warnings about the exported scene (see " + stem + ".ini.log)\n";
    } else if (!povNote.empty()) {
        report += "--povray: " + povNote + "\n";
    }

    // Write everything at the end, each file through a temporary and a rename
    fs::create_directories(dir);
    pov::writeTextFile(file("_converge.csv"), csv);
    plot.write(file("_converge.svg"));
    report += "files: " + file("_converge.csv") + ", " + file("_converge.svg") + "\n";
    if (!a.quiet) std::cout << report;
    return kExitOk;
}

}  // namespace

void addConvergeCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<ConvergeArgs>();
    CLI::App *cmd = app.add_subcommand(
        "converge",
        "Error against run time: render at 1, 2, 4, ... spp, compare with a reference, "
        "fit the slope, write a CSV and an SVG plot");
    args->scene.addTo(*cmd);
    cmd->add_option("-o,--output-dir", args->outDir,
                    "Folder for the CSV and the plot (default <scene>_converge)");
    constexpr double kAny = std::numeric_limits<double>::max();
    addNumber(*cmd, "-W,--width", args->width, "Image width", 1, kMaxImageSide);
    addNumber(*cmd, "-H,--height", args->height, "Image height", 1, kMaxImageSide);
    addNumber(*cmd, "--max-samples", args->maxSamples,
              "Highest samples per pixel; levels 1, 2, 4, ... up to it", 1, kMaxSamplesPerPixel);
    addNumber(*cmd, "--budget", args->budget,
              "Seconds: stop doubling once a level took more than half of this", 0.0, kAny, true);
    addNumber(*cmd, "--reference-samples", args->referenceSamples,
              "Samples per pixel of the reference, in 16 batches (default 8 x the highest "
              "level)",
              1, kMaxSamplesPerPixel * kReferenceBatches);
    addNumber(*cmd, "--clamp", args->clamp,
              "Clamp each sample's radiance to [0, this] in every render (default 0: off, "
              "compare linear radiance)",
              0.0, kAny);
    addNumber(*cmd, "--seed", args->seed, "Seed of the reference; level i uses seed + 1 + i",
              uint64_t{0}, std::numeric_limits<uint64_t>::max());
    addNumber(*cmd, "-t,--threads", args->threads, "Render threads (0 = all cores)", 0,
              kMaxThreads);
    cmd->add_flag(
        "--povray", args->povray,
        "Also measure each level against POV-Ray's supersampled picture (when installed)");
    addNumber(*cmd, "--supersample", args->supersample,
              "POV-Ray: k x k samples per pixel (rendered k times larger)", 1, kMaxSupersample);
    addNumber(*cmd, "--timeout", args->timeout, "Seconds POV-Ray may run", 1, kMaxTimeoutSeconds);
    cmd->add_flag("-q,--quiet", args->quiet, "Only warnings and errors (files are still written)");
    cmd->callback([args, &action]() { action = [args]() { return runConverge(*args); }; });
}

}  // namespace rt::cli
