// SPDX-License-Identifier: MIT
// The one way a scene file becomes an ir::Scene: the importer chosen by the file's extension,
// the environment, the --facets pass and the automatic camera and lights, the same for the
// command line, `check`, `report`, `converge`, the tests and any program linking scadray.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/facet_mode.h"
#include "core/ir/scene_ir.h"
#include "importers/scad/scad_importer.h"

namespace rt {

/// The kinds of scene file, each read by one importer.
enum class SceneFormat {
    Scad,  ///< OpenSCAD program (importers/scad)
    Gltf,  ///< glTF 2.0, .gltf or .glb (importers/gltf)
    Mesh,  ///< a bare STL or OFF mesh (importers/mesh)
};

/// The format a file's extension names (case-insensitive), or none for an unknown extension.
std::optional<SceneFormat> sceneFormat(const std::string &path);

struct LoadOptions {
    std::vector<std::string> libraryPaths;
    std::vector<std::pair<std::string, std::string>> defines;
    /// How spheres, cylinders, tori and lathes are drawn (`--facets`).
    ir::FacetMode facets = ir::FacetMode::Auto;
    int64_t maxSteps = scad::kDefaultMaxSteps;        ///< .scad evaluation step cap; 0 = none
    int64_t maxElements = scad::kDefaultMaxElements;  ///< .scad vector elements alive at once
    int64_t maxGeometry = scad::kDefaultMaxGeometry;  ///< .scad geometry budget; 0 = none
    /// `-e`: empty (the file type's default: the studio sky for glTF, none otherwise), "none",
    /// "studio" or an equirectangular image file; `--env-rotate` degrees about +Z.
    std::string environment;
    double environmentRotate = 0;
    /// Picture width / height when the caller knows it (the automatic camera of glTF, STL
    /// and OFF files fits the smaller side); 0 when unknown.
    double aspect = 0;
    /// `$t` of a .scad scene (animation frames); other scene types have no time.
    double time = 0;
    /// Called with the step count while a .scad file evaluates (see
    /// scad::ImportOptions::progress), and `progressDone` once the evaluation ends, also when
    /// it fails; both may be empty.
    std::function<void(int64_t steps)> progress;
    std::function<void()> progressDone;
};

/// Reads a scene by its extension (sceneFormat) and completes it (automatic camera, default
/// lights), with the environment opts.environment names. The environment is read first, so a
/// bad image fails before a long evaluation. The path must be a regular file
/// (requireRegularFile). Throws LocatedError for problems in the file, std::runtime_error for
/// others (an unknown extension, an unreadable environment image).
ir::Scene loadScene(const std::string &path, DiagnosticSink &diag, const LoadOptions &opts);

}  // namespace rt
