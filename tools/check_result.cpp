// SPDX-License-Identifier: MIT
// A check's figures as JSON (nlohmann-json, confined to this file in tools/): what `check`
// leaves beside its pictures and `report --from` reads back.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/ir/diagnostics.h"
#include "core/system/input_file.h"
#include "tools/check.h"
#include "tools/report_html.h"

namespace rt::cli {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

/// Written into every file, so a reader can tell a check's figures from any other JSON and
/// refuse a later, incompatible layout.
constexpr const char *kFormatKey = "scadray_check";
constexpr int kFormatVersion = 1;

/// A finite number as itself, anything else as null (JSON has no NaN or infinity).
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

template <class T>
void get(const json &j, const char *key, T &out) {
    auto it = j.find(key);
    if (it == j.end() || it->is_null()) return;
    out = it->get<T>();
}

}  // namespace

namespace {

bool safeStemByte(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
}

}  // namespace

std::string safeFileStem(const std::string &name) {
    std::string stem = std::filesystem::path(name).stem().string();
    for (char &c : stem)
        if (!safeStemByte(c)) c = '_';
    // Not an option (-x), not hidden (.x), and never empty
    if (stem.empty()) return "scene";
    if (stem[0] == '-' || stem[0] == '.') stem[0] = '_';
    return stem;
}

bool isSafeFileStem(const std::string &stem) {
    return !stem.empty() && stem[0] != '-' && stem[0] != '.' &&
           std::all_of(stem.begin(), stem.end(), safeStemByte);
}

std::string checkJsonPath(const std::string &dir, const std::string &scene, bool openscad) {
    std::string stem = safeFileStem(scene);
    return (fs::path(dir) / (stem + (openscad ? "_openscad_check.json" : "_check.json"))).string();
}

std::string checkResultJson(const CheckResult &r) {
    json j;
    j[kFormatKey] = kFormatVersion;
    j["scene"] = r.scene;
    j["referee"] = r.referee;
    j["verdict"] = !r.error.empty() ? "error" : r.pass ? "pass" : "different";
    if (!r.error.empty()) j["error"] = r.error;
    j["width"] = r.width;
    j["height"] = r.height;
    if (r.error.empty()) {
        if (r.referee == "openscad") {
            j["differing"] = r.differing;
            j["coverage"] = r.coverageDiffer;
            j["depth"] = r.depthDiffer;
            j["normal"] = r.normalDiffer;
            j["silhouette"] = r.silhouette;
            j["tied"] = r.tied;
            j["openscad_wall_s"] = number(r.openscadSeconds);
            j["openscad_render_s"] = number(r.openscadRenderSeconds);
            j["triangles"] = r.triangles;
        } else {
            j["rmse"] = number(r.rmse);
            j["psnr"] = number(r.psnr);
            j["max_error"] = number(r.maxError);
            j["tiles_tested"] = r.tilesTested;
            j["tiles_skipped"] = r.tilesSkipped;
            j["tiles_failed"] = r.tilesFailed;
            j["tested_share"] = number(r.testedShare);
            j["detectable_median"] = number(r.detectableMedian);
            j["deterministic"] = r.deterministic;
            j["povray_warnings"] = r.povrayWarnings;
            j["povray_wall_s"] = number(r.povraySeconds);
            j["povray_trace_s"] = number(r.povrayTraceSeconds);
            j["edge_mask_s"] = number(r.edgeMaskSeconds);
            j["supersample"] = r.supersample;
            j["scadray_render_s"] = number(r.scadrayRenderSeconds);
        }
        j["masked_share"] = number(r.maskedShare);
        j["scadray_wall_s"] = number(r.scadraySeconds);
        // Names in the file's own folder, so the folder can move
        j["pictures"] = {{"referee", r.refereePicture},
                         {"scadray", r.scadrayPicture},
                         {"difference", r.diffPicture}};
    }
    j["report"] = r.text;
    return j.dump(2) + "\n";
}

CheckResult readCheckResult(const std::string &path) {
    json j = json::parse(readInputFile(path, kMaxReportFileBytes), nullptr, false);
    if (j.is_discarded() || !j.is_object())
        throw std::runtime_error(path + ": not JSON (expected the figures `scadray check` writes)");
    if (!j.contains(kFormatKey) || !j[kFormatKey].is_number_integer() ||
        j[kFormatKey].get<int>() != kFormatVersion)
        throw std::runtime_error(path + ": not a scadray check file of format " +
                                 std::to_string(kFormatVersion));
    CheckResult r;
    try {
        get(j, "scene", r.scene);
        get(j, "referee", r.referee);
        std::string verdict;
        get(j, "verdict", verdict);
        r.pass = verdict == "pass";
        get(j, "error", r.error);
        if (verdict == "error" && r.error.empty()) r.error = "the check failed";
        get(j, "width", r.width);
        get(j, "height", r.height);
        get(j, "differing", r.differing);
        get(j, "coverage", r.coverageDiffer);
        get(j, "depth", r.depthDiffer);
        get(j, "normal", r.normalDiffer);
        get(j, "silhouette", r.silhouette);
        get(j, "tied", r.tied);
        get(j, "openscad_wall_s", r.openscadSeconds);
        get(j, "openscad_render_s", r.openscadRenderSeconds);
        get(j, "triangles", r.triangles);
        get(j, "rmse", r.rmse);
        get(j, "psnr", r.psnr);
        get(j, "max_error", r.maxError);
        get(j, "tiles_tested", r.tilesTested);
        get(j, "tiles_skipped", r.tilesSkipped);
        get(j, "tiles_failed", r.tilesFailed);
        get(j, "tested_share", r.testedShare);
        get(j, "detectable_median", r.detectableMedian);
        get(j, "deterministic", r.deterministic);
        get(j, "povray_warnings", r.povrayWarnings);
        get(j, "povray_wall_s", r.povraySeconds);
        get(j, "povray_trace_s", r.povrayTraceSeconds);
        get(j, "edge_mask_s", r.edgeMaskSeconds);
        get(j, "supersample", r.supersample);
        get(j, "scadray_render_s", r.scadrayRenderSeconds);
        get(j, "masked_share", r.maskedShare);
        get(j, "scadray_wall_s", r.scadraySeconds);
        if (auto it = j.find("pictures"); it != j.end() && it->is_object()) {
            get(*it, "referee", r.refereePicture);
            get(*it, "scadray", r.scadrayPicture);
            get(*it, "difference", r.diffPicture);
        }
        get(j, "report", r.text);
    } catch (const json::exception &e) {
        throw std::runtime_error(path + ": a field has the wrong type (" + e.what() + ")");
    }
    if (r.referee != "povray" && r.referee != "openscad")
        throw std::runtime_error(path + ": unknown referee '" + r.referee + "'");
    // A picture name is a file in the JSON's own folder, never a path out of it
    for (std::string *name : {&r.refereePicture, &r.scadrayPicture, &r.diffPicture})
        if (name->find('/') != std::string::npos || *name == "..") name->clear();
    r.dir = fs::path(path).parent_path().string();
    if (r.dir.empty()) r.dir = ".";
    return r;
}

std::string errorMessage(const std::exception &e) {
    if (auto *located = dynamic_cast<const LocatedError *>(&e))
        return formatDiagnostic(located->diagnostic());
    return e.what();
}

}  // namespace rt::cli
