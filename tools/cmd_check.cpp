// SPDX-License-Identifier: MIT
// `scadray check`: render a scene with scadray and with POV-Ray (exported, same camera and
// resolution, supersampled), compare statistically, and report error against run time; with
// --openscad, compare scadray's geometry per pixel with the mesh OpenSCAD exports instead.
#include <CLI/CLI.hpp>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>

#include "core/image/image_compare.h"
#include "core/image/image_io.h"
#include "core/ir/facet_mode.h"
#include "core/materials/pbr_material.h"
#include "core/render/geometry_buffer.h"
#include "core/render/render_scene.h"
#include "core/render/renderer.h"
#include "core/system/input_file.h"
#include "exporters/povray/pov_runner.h"
#include "exporters/povray/pov_writer.h"
#include "tools/check.h"
#include "tools/cli_common.h"
#include "tools/commands.h"
#include "tools/openscad_runner.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;

/// Output folder (created; requireOutputFolder has accepted it) and the path of one output
/// file in it, named by the scene's safe file stem.
struct CheckFiles {
    std::string stem;
    std::filesystem::path dir;
    explicit CheckFiles(const CheckArgs &a) {
        stem = safeFileStem(a.scene.input);
        dir = checkDir(a);
        fs::create_directories(dir);
    }
    std::string operator()(const std::string &suffix) const {
        return (dir / (stem + suffix)).string();
    }
};

/// A check's row for --csv, and the header of such rows.
struct CsvRow {
    const char *header = "";
    std::string row;
};

/// Writes the report and the JSON figures beside the pictures, appends the figures to --csv
/// (the header first when the file is new), prints the report (only on failure when quiet)
/// and maps the verdict to the exit code of `compare`.
int finishCheck(const CheckArgs &a, const CheckResult &r, const CsvRow &csv) {
    CheckFiles file(a);
    pov::writeTextFile(file(r.referee == "openscad" ? "_openscad_report.txt" : "_report.txt"),
                       r.text);
    pov::writeTextFile(checkJsonPath(r.dir, a.scene.input, a.openscad), checkResultJson(r));
    if (!a.csv.empty()) {
        bool fresh = !fs::exists(a.csv);
        std::ofstream out(a.csv, std::ios::app);
        if (fresh) out << csv.header << "\n";
        out << csv.row;
        if (!out) throw std::runtime_error("cannot append to '" + a.csv + "'");
    }
    if (!a.quiet || !r.pass) std::cout << r.text;
    return r.pass ? kExitOk : kExitInputError;
}

/// `check --openscad`: OpenSCAD exports the scene's mesh; scadray traces that mesh and the scene
/// itself (with OpenSCAD's facets) through the scene's one camera, and the two geometry
/// buffers are compared per pixel.
CheckResult checkGeometry(const CheckArgs &a, CsvRow &csv) {
    using clock = std::chrono::steady_clock;
    std::string ext = fs::path(a.scene.input).extension().string();
    for (auto &ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (ext != ".scad")
        throw std::invalid_argument("--openscad checks a .scad scene, not '" + a.scene.input + "'");
    if (!a.scene.facets.empty() && a.scene.facets != "openscad")
        throw std::invalid_argument("--openscad compares OpenSCAD's own facets; --facets " +
                                    a.scene.facets + " cannot be used with it");

    if (!openscadAvailable())
        throw std::invalid_argument(
            "OpenSCAD (openscad) is not installed; scripts/setup.sh installs it");
    CheckFiles file(a);
    LoadOptions lo = a.scene.loadOptions(true);
    lo.aspect = double(a.width) / a.height;
    // Spheres and cylinders as OpenSCAD tessellates them: the referee's geometry, not a sphere
    lo.facets = ir::FacetMode::OpenScad;

    // scadray: parse, evaluate, compile and trace the scene; its camera (given or automatic)
    // is the one both pictures use
    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, true);
    auto t0 = clock::now();
    ir::Scene scene = loadScene(a.scene.input, diag, lo);
    auto rs = RenderScene::compile(scene, diag);
    GeometryBuffer ours = renderGeometry(*rs, a.width, a.height, a.threads);
    double ourSeconds = std::chrono::duration<double>(clock::now() - t0).count();

    // OpenSCAD: CGAL evaluation and mesh export, then the mesh through scadray's mesh reader
    std::string meshPath = file("_openscad.stl");
    OpenScadRun run =
        exportWithOpenScad(a.scene.input, meshPath, lo.defines, lo.libraryPaths, a.timeout);
    ir::Scene meshScene = loadScene(meshPath, diag, LoadOptions{});
    meshScene.camera = scene.camera;
    auto ms = RenderScene::compile(meshScene, diag);
    GeometryBuffer theirs = renderGeometry(*ms, a.width, a.height, a.threads);

    GeometryCompareResult cr = compareGeometry(ours, theirs, a.geometry);
    writeImage(normalImage(ours), file("_scadray_normals.png"));
    writeImage(normalImage(theirs), file("_openscad_normals.png"));
    writeImage(cr.heatMap, file("_geometry_diff.png"));

    char buf[512];
    std::string report = std::string(cr.pass ? "PASS" : "DIFFERENT") + ": " + a.scene.input +
                         " geometry against OpenSCAD at " + std::to_string(a.width) + "x" +
                         std::to_string(a.height) + "\n";
    std::snprintf(buf, sizeof buf, "openscad: %.3f s wall (CGAL render %.3f s), %zu triangles\n",
                  run.wallSeconds, run.renderSeconds, ms->stats().triangles);
    report += buf;
    std::snprintf(buf, sizeof buf, "scadray:  %.3f s (parse, compile and trace %lld rays)\n",
                  ourSeconds, static_cast<long long>(a.width) * a.height);
    report += buf;
    report += cr.summary(a.geometry);
    report += "files: " + file.dir.string() + "/" + file.stem +
              "{_openscad.stl,_scadray_normals.png,_openscad_normals.png,_geometry_diff.png}\n";
    std::snprintf(buf, sizeof buf, "%s,%s,%ld,%ld,%ld,%ld,%ld,%ld,%.3f,%.3f,%.3f\n",
                  a.scene.input.c_str(), cr.pass ? "pass" : "different", cr.differing(),
                  cr.coverageDiffer, cr.depthDiffer, cr.normalDiffer, cr.silhouette, cr.tied,
                  run.wallSeconds, run.renderSeconds, ourSeconds);
    csv = {
        "scene,verdict,differing,coverage,depth,normal,silhouette,tied,"
        "openscad_wall_s,openscad_render_s,scadray_s",
        buf};

    CheckResult r;
    r.scene = a.scene.input;
    r.referee = "openscad";
    r.pass = cr.pass;
    r.width = a.width;
    r.height = a.height;
    r.differing = cr.differing();
    r.coverageDiffer = cr.coverageDiffer;
    r.depthDiffer = cr.depthDiffer;
    r.normalDiffer = cr.normalDiffer;
    r.silhouette = cr.silhouette;
    r.tied = cr.tied;
    r.maskedShare = double(cr.silhouette + cr.tied) / (double(a.width) * a.height);
    r.openscadSeconds = run.wallSeconds;
    r.openscadRenderSeconds = run.renderSeconds;
    r.triangles = long(ms->stats().triangles);
    r.scadraySeconds = ourSeconds;
    r.dir = file.dir.string();
    r.refereePicture = file.stem + "_openscad_normals.png";
    r.scadrayPicture = file.stem + "_scadray_normals.png";
    r.diffPicture = file.stem + "_geometry_diff.png";
    r.text = report;
    return r;
}

CheckResult checkPovray(const CheckArgs &a, CsvRow &csv) {
    using clock = std::chrono::steady_clock;
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
        throw std::invalid_argument(
            "POV-Ray (povray) is not installed; scripts/setup.sh installs it");

    CheckFiles file(a);
    const std::string &stem = file.stem;
    const fs::path &dir = file.dir;

    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, true);
    LoadOptions lo = a.scene.loadOptions(a.quiet);
    lo.aspect = double(a.width) / a.height;
    ir::Scene scene = loadScene(a.scene.input, diag, lo);
    // POV-Ray gets a glTF material's per-texel metallic-roughness, normal, occlusion, emissive,
    // transmission, clearcoat, sheen, specular and thickness maps as the mapping of their means
    // (the material's constant fields), so
    // both sides render that; texture alpha, which the export expresses per texel, stays
    int averaged = 0;
    for (ir::Material &m : scene.materials) {
        if (!m.texel.pbr || !m.texel.pbr->textured()) continue;
        if (m.texel.pbr->alphaMode != PbrMaterial::AlphaMode::Opaque) continue;
        m.texel = {};
        ++averaged;
    }
    if (averaged > 0 && !a.quiet)
        std::cout << "per-texel materials: " << averaged
                  << " compared by their textures' means (POV-Ray cannot express per-texel "
                     "metallic-roughness, normal, occlusion, emissive, transmission, "
                     "clearcoat, sheen, specular or thickness maps)\n";

    // POV-Ray: export, render k times larger without antialiasing, box-downsample
    PovReference pov =
        renderPovReference(scene, dir.string(), stem, fs::path(a.scene.input).filename().string(),
                           a.width, a.height, a.supersample, a.threads, a.timeout);
    const pov::PovRunResult &pr = pov.run;
    ImageEstimate reference = pov.image;
    // Texture detail spreads a supersampled pixel's sub-samples as a silhouette does, so with
    // textures the edge mask comes from a second POV-Ray picture without them: silhouettes,
    // shadow edges and highlights are masked, texture detail is tested
    bool textured = false;
    for (const ir::Material &m : scene.materials) textured |= m.baseColorTexture.valid();
    double edgeSeconds = 0;
    if (textured && !a.maskTextureDetail) {
        // The scene without its textures for this export only (it cannot be copied); each
        // textured colour becomes its texture's mean, so shading spreads as much as on average
        // with the texture
        std::vector<ir::Material> saved = scene.materials;
        for (ir::Material &m : scene.materials) {
            if (!m.baseColorTexture.valid()) continue;
            // A texture whose alpha cuts or blends the surface shapes silhouettes and shadows:
            // it stays, so their edges are masked like any geometry's
            if (m.texel.pbr && m.texel.pbr->alphaMode != PbrMaterial::AlphaMode::Opaque) continue;
            auto mean = ir::textureMean(*scene.textures[size_t(m.baseColorTexture.texture)]);
            m.color *= Rgb(mean[0], mean[1], mean[2]);
            m.baseColorTexture = {};
        }
        PovReference edges;
        try {
            edges = renderPovReference(scene, dir.string(), stem + "_edges",
                                       fs::path(a.scene.input).filename().string(), a.width,
                                       a.height, a.supersample, a.threads, a.timeout);
        } catch (...) {
            scene.materials = saved;
            throw;
        }
        scene.materials = saved;
        // Geometry's edges from that picture (the usual sub-sample range), texture detail
        // from the textured one where it is not smooth at the sub-sample scale: texel edges
        // and detail finer than a pixel, which the reference's k x k grid cannot average
        Image textureEdges =
            planeResidualSpread(readImage((dir / (stem + "_povray.png")).string()), a.supersample);
        reference.spread = edges.image.spread;
        for (int y = 0; y < reference.spread.height(); ++y)
            for (int x = 0; x < reference.spread.width(); ++x) {
                Rgb g = reference.spread.at(x, y), t = textureEdges.at(x, y);
                reference.spread.set(
                    x, y, Rgb(std::max(g.r, t.r), std::max(g.g, t.g), std::max(g.b, t.b)));
            }
        edgeSeconds = edges.run.wallSeconds;
    }

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
    std::snprintf(
        buf, sizeof buf,
        "povray:  %.3f s wall (parse %.3f s, trace %.3f s), %dx%d supersampled at %dx%d\n",
        pr.wallSeconds, pr.parseSeconds, pr.traceSeconds, a.supersample, a.supersample,
        a.width * a.supersample, a.height * a.supersample);
    report += buf;
    if (edgeSeconds > 0) {
        std::snprintf(buf, sizeof buf,
                      "povray:  %.3f s wall for the edge mask: the scene without textures "
                      "(smooth texture detail is tested, not masked)\n",
                      edgeSeconds);
        report += buf;
    }
    std::snprintf(buf, sizeof buf,
                  "scadray: %.3f s (render %.3f s), %d batches x %d spp, %.2f Mrays/s\n", ourWall,
                  rr.seconds, a.batches, a.samples,
                  rr.stats.totalRays() / std::max(rr.seconds, 1e-9) / 1e6);
    report += buf;
    report += cr.summary(a.compare);
    if (pr.warnings > 0)
        report += "povray printed " + std::to_string(pr.warnings) +
                  " warnings about the exported scene (see " + stem + ".ini.log)\n";
    report += "files: " + dir.string() + "/" + stem +
              "{.pov,.ini,_reference.png,_scadray.png,_diff.png,...}\n";
    std::snprintf(buf, sizeof buf, "%s,%s,%.3g,%.3g,%.1f,%d,%d,%.3g,%.3f,%.3f,%.3f,%.3f\n",
                  a.scene.input.c_str(), cr.pass ? "pass" : "different", cr.rmse, cr.maxError,
                  100.0 * cr.maskedPixels / (double(a.width) * a.height), cr.tilesTested,
                  cr.tilesFailed, cr.detectableMedian, pr.wallSeconds, pr.traceSeconds, ourWall,
                  rr.seconds);
    csv = {
        "scene,verdict,rmse,max_error,masked_percent,tiles_tested,tiles_failed,"
        "detectable_median,povray_wall_s,povray_trace_s,scadray_wall_s,scadray_render_s",
        buf};

    CheckResult r;
    r.scene = a.scene.input;
    r.pass = cr.pass;
    r.width = a.width;
    r.height = a.height;
    r.rmse = cr.rmse;
    r.psnr = cr.psnr;
    r.maxError = cr.maxError;
    r.maskedShare = cr.maskedPixels / (double(a.width) * a.height);
    r.tilesTested = cr.tilesTested;
    r.tilesSkipped = cr.tilesSkipped;
    r.tilesFailed = cr.tilesFailed;
    r.testedShare = cr.tilesTested / std::max(1.0, double(cr.tilesTested + cr.tilesSkipped));
    r.detectableMedian = cr.detectableMedian;
    r.deterministic = cr.deterministic;
    r.povrayWarnings = pr.warnings;
    r.povraySeconds = pr.wallSeconds;
    r.povrayTraceSeconds = pr.traceSeconds;
    r.edgeMaskSeconds = edgeSeconds;
    r.supersample = a.supersample;
    r.scadraySeconds = ourWall;
    r.scadrayRenderSeconds = rr.seconds;
    r.dir = dir.string();
    r.refereePicture = stem + "_reference.png";
    r.scadrayPicture = stem + "_scadray.png";
    r.diffPicture = stem + "_diff.png";
    r.text = report;
    return r;
}

CheckResult runOneCheck(const CheckArgs &a, CsvRow &csv) {
    return a.openscad ? checkGeometry(a, csv) : checkPovray(a, csv);
}

/// Accepts the output folder (requireOutputFolder) and replaces the JSON figures of an earlier
/// run by the record of a check that has not finished, which it returns: a check that fails or
/// is interrupted never leaves stale figures (what `report --from` shows), and the folder keeps
/// the mark of a check's output.
CheckResult startCheck(const CheckArgs &a) {
    std::string dir = checkDir(a);
    requireOutputFolder(dir, "_check.json", "-o");
    CheckResult failed;
    failed.scene = a.scene.input;
    failed.referee = a.openscad ? "openscad" : "povray";
    failed.error = "the check did not finish";
    failed.width = a.width;
    failed.height = a.height;
    failed.dir = dir;
    fs::create_directories(dir);
    pov::writeTextFile(checkJsonPath(dir, a.scene.input, a.openscad), checkResultJson(failed));
    return failed;
}

int runCheck(const CheckArgs &a) {
    CheckResult failed = startCheck(a);
    std::string json = checkJsonPath(failed.dir, a.scene.input, a.openscad);
    CsvRow csv;
    CheckResult r;
    try {
        r = runOneCheck(a, csv);
    } catch (const std::exception &e) {
        failed.error = errorMessage(e);
        // Best effort: the error itself is what the user must see
        try {
            pov::writeTextFile(json, checkResultJson(failed));
        } catch (const std::exception &) {
        }
        throw;
    }
    return finishCheck(a, r, csv);
}

}  // namespace

void requireOutputFolder(const std::string &dir, const std::string &marker,
                         const std::string &option) {
    std::error_code ec;
    fs::file_status st = fs::symlink_status(dir, ec);
    if (!fs::exists(st)) return;
    if (!fs::is_directory(fs::status(dir, ec)))
        throw std::invalid_argument(option + ": '" + printable(dir) + "' is not a folder");
    bool empty = true;
    for (const auto &e : fs::directory_iterator(dir, ec)) {
        empty = false;
        std::string name = e.path().filename().string();
        if (name.size() >= marker.size() &&
            name.compare(name.size() - marker.size(), marker.size(), marker) == 0)
            return;
    }
    if (ec)
        throw std::invalid_argument(option + ": cannot read the folder '" + printable(dir) + "'");
    if (!empty)
        throw std::invalid_argument(
            option + ": '" + printable(dir) + "' holds other files (no *" + marker +
            " of an earlier run): its files could be replaced, so give an empty or new folder");
}

std::string checkDir(const CheckArgs &a) {
    return a.outDir.empty() ? fs::path(a.scene.input).stem().string() + "_check" : a.outDir;
}

CheckResult checkScene(const CheckArgs &a) {
    startCheck(a);
    CsvRow unused;
    return runOneCheck(a, unused);
}

void addCheckOptions(CLI::App &cmd, CheckArgs &a) {
    addNumber(cmd, "-W,--width", a.width, "Image width", 1, kMaxImageSide);
    addNumber(cmd, "-H,--height", a.height, "Image height", 1, kMaxImageSide);
    addNumber(cmd, "--supersample", a.supersample,
              "POV-Ray reference: k x k samples per pixel (rendered k times larger)", 1,
              kMaxSupersample);
    addNumber(cmd, "--batches", a.batches, "scadray: independent seeded batches", 1, kMaxBatches);
    addNumber(cmd, "-s,--samples", a.samples, "scadray: samples per pixel in each batch", 1,
              kMaxSamplesPerPixel);
    addNumber(cmd, "--seed", a.seed, "scadray: seed of the first batch", uint64_t{0},
              std::numeric_limits<uint64_t>::max());
    addNumber(cmd, "-t,--threads", a.threads, "Threads for both renderers (0 = all)", 0,
              kMaxThreads);
    addNumber(cmd, "--timeout", a.timeout, "Seconds POV-Ray or OpenSCAD may run", 1,
              kMaxTimeoutSeconds);
    addNumber(cmd, "--depth-tol", a.geometry.depthRel,
              "--openscad: relative depth difference allowed", 0.0,
              std::numeric_limits<double>::max());
    addNumber(cmd, "--normal-tol", a.geometry.normalDegrees,
              "--openscad: normal angle difference allowed, degrees", 0.0, 180.0);
    addNumber(cmd, "--max-differing", a.geometry.maxDiffering,
              "--openscad: differing pixels outside the masks that still pass", 0L,
              std::numeric_limits<long>::max());
    cmd.add_flag("--mask-texture-detail", a.maskTextureDetail,
                 "Mask edges from the textured POV-Ray picture itself (by default a textured "
                 "scene's edge mask comes from a second picture without textures)");
    addCompareOptions(cmd, a.compare);
}

void addCheckCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<CheckArgs>();
    CLI::App *cmd = app.add_subcommand(
        "check",
        "Render with scadray and POV-Ray, compare statistically, report error and time; with "
        "--openscad, compare geometry with OpenSCAD's mesh of the scene (exit 0 pass, 1 "
        "different or failed, 2 bad usage)");
    args->scene.addTo(*cmd);
    cmd->add_option("-o,--output-dir", args->outDir,
                    "Folder for all files (default <scene>_check)");
    cmd->add_flag("--openscad", args->openscad,
                  "Referee OpenSCAD: compare hit/miss, depth and normal per pixel with the mesh "
                  "`openscad` exports (implies --facets openscad)");
    addCheckOptions(*cmd, *args);
    cmd->add_flag("-q,--quiet", args->quiet, "Print the report only when the check fails");
    cmd->add_option("--csv", args->csv, "Append a row of figures to this CSV file");
    cmd->callback([args, &action]() { action = [args]() { return runCheck(*args); }; });
}

}  // namespace rt::cli
