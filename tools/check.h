// SPDX-License-Identifier: MIT
// `scadray check` as a function: one scene compared with POV-Ray (or, with --openscad, with
// OpenSCAD's mesh), its figures returned, so `check` prints one and `report` tabulates many.
#pragma once

#include <cstdint>
#include <string>

#include "core/image/image_compare.h"
#include "core/render/geometry_buffer.h"
#include "tools/cli_common.h"

namespace CLI {
class App;
}

namespace rt::cli {

struct CheckArgs {
    SceneArgs scene;
    std::string outDir, csv;
    int width = 320, height = 240;
    int supersample = 3, batches = 8, samples = 4, threads = 0, timeout = 600;
    uint64_t seed = 1;
    bool quiet = false, openscad = false;
    /// Mask texture detail as edges too (the rule before textures had their own edge picture)
    bool maskTextureDetail = false;
    CompareOptions compare;
    GeometryTolerances geometry;
};

/// Registers the options that shape a check (size, samples, threads, time limit, tolerances),
/// which `check` and `report` share; not the scene, the output folder or --openscad.
void addCheckOptions(CLI::App &cmd, CheckArgs &a);

/// What one check found. Times are wall-clock seconds; shares are fractions of 1.
struct CheckResult {
    std::string scene;               ///< the scene file as given
    std::string referee = "povray";  ///< "povray" or "openscad"
    bool pass = false;
    /// Non-empty when the check could not run (the scene did not load, a renderer failed);
    /// the figures are then unset
    std::string error;
    int width = 0, height = 0;

    // Against POV-Ray
    double rmse = 0, psnr = 0, maxError = 0;
    double maskedShare = 0;  ///< pixels masked as edges (silhouettes, shadow edges, ties)
    double testedShare = 0;  ///< tiles with enough unmasked pixels to be tested
    int tilesTested = 0, tilesSkipped = 0, tilesFailed = 0;
    double detectableMedian = 0;
    bool deterministic = false;
    int povrayWarnings = 0;
    double povraySeconds = 0, povrayTraceSeconds = 0, edgeMaskSeconds = 0;
    int supersample = 0;

    // Against OpenSCAD
    long differing = 0, coverageDiffer = 0, depthDiffer = 0, normalDiffer = 0;
    long silhouette = 0, tied = 0;
    double openscadSeconds = 0, openscadRenderSeconds = 0;
    long triangles = 0;

    // scadray
    double scadraySeconds = 0, scadrayRenderSeconds = 0;

    /// The folder the check wrote to, and its three pictures in it (file names): the
    /// referee's (POV-Ray's picture, or the normals of OpenSCAD's mesh), scadray's, and the
    /// heat map of their difference
    std::string dir, refereePicture, scadrayPicture, diffPicture;
    /// The text `check` prints
    std::string text;

    /// Wall seconds of the referee: POV-Ray (both pictures) or OpenSCAD
    double refereeSeconds() const {
        return referee == "openscad" ? openscadSeconds : povraySeconds + edgeMaskSeconds;
    }
};

/// Runs one check with everything `a` says and writes its files (pictures, EXR estimates,
/// .pov) into its folder; prints nothing but the scene's warnings. Throws as `check` does
/// when the scene or a renderer fails.
CheckResult checkScene(const CheckArgs &a);

/// The stem of a scene's name with every byte but letters, digits, '_', '-' and '.' replaced
/// by '_' and a leading '-' or '.' too ("scene" when empty): the stem of every file `check` and
/// `converge` write, so that none can be read as an option by POV-Ray or OpenSCAD, nor cut at
/// a space in a POV-Ray .ini.
std::string safeFileStem(const std::string &name);

/// True when `stem` is what safeFileStem makes: only those bytes, no leading '-' or '.'.
bool isSafeFileStem(const std::string &stem);

/// The output folder of a check of `a` (a.outDir, or <scene stem>_check).
std::string checkDir(const CheckArgs &a);

/// Throws std::invalid_argument naming `option` unless `dir` is new, empty, or holds a file
/// whose name ends in `marker` (an earlier run's output, such as "_check.json"): a command
/// that writes many files never writes them into a folder of other files (a model's own
/// folder, whose textures a heat map would replace).
void requireOutputFolder(const std::string &dir, const std::string &marker,
                         const std::string &option);

/// The machine-readable file each check leaves beside its pictures, <stem>_check.json (or
/// <stem>_openscad_check.json), from which `report --from` rebuilds its row.
std::string checkJsonPath(const std::string &dir, const std::string &scene, bool openscad);
std::string checkResultJson(const CheckResult &r);
/// Reads a file checkResultJson wrote; `dir` becomes the file's folder. Throws
/// std::runtime_error naming the file when it is not one.
CheckResult readCheckResult(const std::string &path);

/// The message of an error as `scadray` prints it (file:line:col for a located one).
std::string errorMessage(const std::exception &e);

}  // namespace rt::cli
