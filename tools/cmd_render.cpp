// SPDX-License-Identifier: MIT
// `scadray render`: scene file -> ray-traced image.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <tuple>

#include "core/image/image_io.h"
#include "core/render/render_plan.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "tools/animation.h"
#include "tools/cli_common.h"
#include "tools/commands.h"
#include "tools/tiles.h"

namespace rt::cli {

namespace {

struct RenderArgs {
    SceneArgs scene;
    std::string output;
    std::string tile;  ///< --tile K/N
    int width = 640, height = 480, samples = 1, threads = 0, bits = 8;
    uint64_t seed = 0;
    bool linear = false, quiet = false, plan = false, noPlan = false, noAa = false;
    bool samplesGiven = false;  ///< -s on the command line; else the plan chooses
    bool aaGiven = false;       ///< an --aa-* option: adaptive even where the plan would not be
    bool aaToleranceGiven = false;
    int aaMax = 64;
    double aaThreshold = RenderOptions().adaptiveThreshold,
           aaTolerance = RenderOptions().adaptiveTolerance;
    AnimationArgs animation;  ///< --frames and its options
    bool sceneGiven = false;  ///< optional with --encode-only only
};

std::string formatCount(int64_t n) {
    char buf[32];
    if (n >= 10'000'000)
        std::snprintf(buf, sizeof buf, "%.1fM", n / 1e6);
    else if (n >= 10'000)
        std::snprintf(buf, sizeof buf, "%.1fk", n / 1e3);
    else
        std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(n));
    return buf;
}

/// "4" for a uniform render, "adaptive 1.31" for an adaptive one.
std::string sppText(const RenderResult &r) {
    if (r.pixelsBySamples.empty())
        return std::to_string(r.samples / (int64_t(r.image.width()) * r.image.height()));
    char buf[48];
    std::snprintf(buf, sizeof buf, "adaptive %.2f", meanSamplesPerPixel(r));
    return buf;
}

/// One picture: the still image, or one frame of an animation at `$t = time`.
int renderOne(const RenderArgs &a, double time, const std::string &outputName) {
    LoadOptions lo = a.scene.loadOptions(a.quiet);
    lo.aspect = double(a.width) / a.height;
    lo.time = time;
    RenderOptions ro;
    ro.width = a.width;
    ro.height = a.height;
    ro.samplesPerPixel = a.samples;
    ro.threads = a.threads;
    ro.seed = a.seed;
    ro.adaptiveMax = a.aaMax;
    ro.adaptiveThreshold = a.aaThreshold;
    ro.adaptiveTolerance = a.aaTolerance;
    ro.adaptive = !a.samplesGiven && !a.noAa;
    TileSpec tile = a.tile.empty() ? TileSpec{} : parseTile(a.tile);
    if (tile) std::tie(ro.rowBegin, ro.rowEnd) = tileRows(tile.index - 1, tile.count, a.height);
    validateRenderOptions(ro);  // fail on bad options before reading the scene
    std::string output = outputName;
    std::string stem = std::filesystem::path(a.scene.input).stem().string();
    if (output.empty())
        output = tile ? stem + "_tile" + std::to_string(tile.index) + "of" +
                            std::to_string(tile.count) + ".exr"
                      : stem + ".png";
    if (tile && std::filesystem::path(output).extension() != ".exr")
        throw std::invalid_argument("--tile writes an OpenEXR tile (-o name.exr), not '" + output +
                                    "'; `scadray merge` makes the picture");
    requireOutputFile(output, "-o");

    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, a.quiet);
    ir::Scene scene = loadScene(a.scene.input, diag, lo);
    CompileOptions co;
    co.plan = !a.noPlan;
    co.threads = a.threads;
    auto rs = RenderScene::compile(scene, diag, co);
    RenderPlan plan = makePlan(*rs);
    SamplingRequest sampling;
    sampling.samplesGiven = a.samplesGiven;
    sampling.adaptiveGiven = a.aaGiven;
    sampling.toleranceGiven = a.aaToleranceGiven;
    sampling.noAdaptive = a.noAa;
    chooseSampling(plan, sampling, ro);
    if (a.plan)
        std::fputs(describePlan(*rs, scene.stats, plan, ro, sampling.planChooses()).c_str(),
                   stderr);

    bool tty = !a.quiet && isatty(STDERR_FILENO);
    if (tty)
        ro.progress = [](double f) {
            std::fprintf(stderr, "\rrendering %3d%%", static_cast<int>(f * 100));
            std::fflush(stderr);
        };
    RenderResult r = renderImage(*rs, ro);
    if (tty) std::fprintf(stderr, "\r              \r");

    WriteOptions wo;
    wo.pngDepth = a.bits == 16 ? PngDepth::Bits16 : PngDepth::Bits8;
    wo.linearPng = a.linear;
    if (tile)
        writeTile(r, output,
                  {tile, a.scene.input, sceneFingerprint(a.scene.input, scene),
                   pixelOptions(ro, a.scene, a.noPlan), "", r.samples, ro.rowBegin,
                   r.image.height(), a.width, a.height});
    else
        writeImage(r.image, output, wo);

    if (!a.quiet) {
        const RayStats &s = r.stats;
        std::string triangles =
            rs->stats().triangles > 0
                ? ", " + formatCount(static_cast<int64_t>(rs->stats().triangles)) + " triangles"
                : std::string();
        std::fprintf(stderr,
                     "scadray: %s: %dx%d, %s spp, %d objects (%zu primitives%s), %d threads, "
                     "%.3f s\n",
                     output.c_str(), a.width, a.height, sppText(r).c_str(),
                     static_cast<int>(rs->stats().objects), rs->stats().primitives,
                     triangles.c_str(), r.threads, r.seconds);
        std::fprintf(
            stderr,
            "  rays: %s total (%s camera, %s shadow, %s reflection, %s refraction, "
            "%s transmission, %s internal reflection, %s distributed), %.2f Mrays/s, %.3f s CPU\n",
            formatCount(s.totalRays()).c_str(), formatCount(s.camera).c_str(),
            formatCount(s.shadow).c_str(), formatCount(s.reflection).c_str(),
            formatCount(s.refraction).c_str(), formatCount(s.transmission).c_str(),
            formatCount(s.internalReflection).c_str(), formatCount(s.distributed).c_str(),
            s.totalRays() / std::max(r.seconds, 1e-9) / 1e6, r.cpuSeconds);
        std::fprintf(stderr, "  csg: %s span merges, %s pruned subtrees; non-finite pixels: %lld\n",
                     formatCount(s.spanOps).c_str(), formatCount(s.prunedSubtrees).c_str(),
                     static_cast<long long>(s.nonFinite));
    }
    if (a.plan && ro.adaptive)
        std::fprintf(stderr, "plan: samples: %s\n", describeSampling(r).c_str());
    return kExitOk;
}

int runRender(const RenderArgs &a) {
    // Only --encode-only does without a scene
    if (!a.sceneGiven && !a.animation.encodeOnly)
        throw std::invalid_argument("render: a scene file is required");
    if (!a.animation.active()) return renderOne(a, 0, a.output);
    std::string output = a.output;
    if (output.empty() && !a.scene.input.empty())
        output = std::filesystem::path(a.scene.input).stem().string() + ".png";
    return runAnimation(a.animation, a.scene.input, output, a.quiet,
                        [&a](double t, const std::string &path) { renderOne(a, t, path); });
}

}  // namespace

void addRenderCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App *cmd = app.add_subcommand("render", "Ray-trace a scene to an image (.png or .exr)");
    args->scene.addTo(*cmd, SceneArgs::Positional::Optional);  // --encode-only: runRender checks
    cmd->add_option("-o,--output", args->output,
                    "Output image; .png (sRGB) or .exr (linear float). Default: <scene>.png. "
                    "With --frames the frames' name: <name>_0000.png ...");
    addNumber(*cmd, "-W,--width", args->width, "Image width in pixels", 1, kMaxImageSide);
    addNumber(*cmd, "-H,--height", args->height, "Image height in pixels", 1, kMaxImageSide);
    addNumber(*cmd, "-s,--samples", args->samples,
              "Samples per pixel everywhere, stratified; 1 = pixel centres. Default: adaptive "
              "(see --aa-max), or 4 everywhere where Monte Carlo effects need them (see --plan)",
              1, kMaxSamplesPerPixel);
    auto *aaMax = addNumber(*cmd, "--aa-max", args->aaMax,
                            "Adaptive antialiasing (the default of sharp scenes; any --aa-* option "
                            "asks for it in Monte Carlo scenes too, adaptive to their noise): most "
                            "samples per pixel, 4, 16, 64, 256, 1024 or 4096",
                            4, kMaxAdaptiveSamples);
    auto *aaThreshold = addNumber(*cmd, "--aa-threshold", args->aaThreshold,
                                  "Adaptive antialiasing: refine a pixel whose display value "
                                  "(0..1, about sRGB) differs from a neighbour's by more than this",
                                  0.0, 1.0);
    auto *aaTolerance =
        addNumber(*cmd, "--aa-tolerance", args->aaTolerance,
                  "Adaptive antialiasing: stop refining a pixel when the standard "
                  "error of its mean (display units) is below this (0: always --aa-max; "
                  "Monte Carlo scenes: 0.02 unless given)",
                  0.0, 1.0);
    auto *noAa = cmd->add_flag("--no-aa", args->noAa,
                               "No adaptive antialiasing: 1 sample per pixel (4 with Monte Carlo "
                               "effects), as -s");
    for (CLI::Option *o : {aaMax, aaThreshold, aaTolerance, noAa}) o->excludes("--samples");
    for (CLI::Option *o : {aaMax, aaThreshold, aaTolerance}) o->excludes(noAa);
    cmd->add_flag("--plan", args->plan,
                  "Print the render plan first: features in use and why, objects kept and "
                  "dropped, the samples per pixel chosen");
    cmd->add_flag("--no-plan", args->noPlan,
                  "Leave nothing out, prune no CSG subtree and cast shadow rays to every light (to "
                  "measure what the plan saves)");
    addNumber(*cmd, "--seed", args->seed, "Seed of the sample pattern", uint64_t{0},
              std::numeric_limits<uint64_t>::max());
    addNumber(*cmd, "-t,--threads", args->threads, "Render threads (0 = all cores)", 0,
              kMaxThreads);
    cmd->add_option("--bits", args->bits, "PNG bits per channel")
        ->check(CLI::IsMember({8, 16}))
        ->capture_default_str();
    cmd->add_flag("--linear", args->linear, "Write PNG values linear instead of sRGB");
    cmd->add_option("--tile", args->tile,
                    "Render tile K of N horizontal bands (1 <= K <= N, as SLURM_ARRAY_TASK_ID with "
                    "--array=1-N) to an .exr that `scadray merge` assembles");
    cmd->add_flag("-q,--quiet", args->quiet, "Only warnings and errors");
    args->animation.addTo(*cmd);
    cmd->get_option("--tile")->excludes("--frames");  // a frame is one picture, not tiles
    cmd->callback([args, cmd, &action]() {
        args->samplesGiven = cmd->count("--samples") > 0;
        args->sceneGiven = cmd->count("scene") > 0;
        args->aaToleranceGiven = cmd->count("--aa-tolerance") > 0;
        args->aaGiven =
            cmd->count("--aa-max") + cmd->count("--aa-threshold") + args->aaToleranceGiven > 0;
        action = [args]() { return runRender(*args); };
    });
}

}  // namespace rt::cli
