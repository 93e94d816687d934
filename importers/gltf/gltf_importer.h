// SPDX-License-Identifier: MIT
// glTF 2.0 (.gltf, .glb) importer: node hierarchy, meshes, materials, textures, cameras and
// KHR_lights_punctual into the IR, with glTF's Y-up placed Z-up ((x, y, z) -> (x, -z, y)).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"

namespace rt::gltf {

struct ImportOptions {
    /// World units per glTF unit (metres); 1000 places a metre model in a millimetre world.
    double unitScale = 1.0;
    /// Scene to show; -1 = the file's `scene`, else scene 0.
    int sceneIndex = -1;
    /// Largest texture decoded, in pixels (8192 x 8192 = 2^26, about 1 GiB once converted to
    /// float RGBA); a larger one is ignored with a warning, as an undecodable one is.
    uint64_t maxTexturePixels = uint64_t(1) << 26;
    /// Longest texture side decoded.
    uint64_t maxTextureSide = 16384;
    /// Most pixels decoded for all of a model's textures together (2^29, about 8 GiB as float
    /// RGBA): 1000 images naming one small, highly compressed 8192 x 8192 PNG would otherwise
    /// each be decoded and kept. Textures past it are ignored with a warning.
    uint64_t maxTotalTexturePixels = uint64_t(1) << 29;
};

/// Reads a whole file as a scene: geometry, materials, textures, the first camera in traversal
/// order (if any) as scene.camera, and the punctual lights. Problems in the file are
/// ParseError/SceneError located at the file (with the JSON path of the culprit in the message).
ir::Scene importGltf(const std::string &path, DiagnosticSink &diag, const ImportOptions &opts = {});

/// For `import("model.glb")` in a .scad file: adds the file's meshes (and, unless
/// `materialOverride` is set, its materials and textures) to `scene`, and returns a Group node
/// placing them, Z-up, with `loc` (the import() call) on every node. Cameras and lights in the
/// file are ignored with a note.
ir::NodePtr importGltfInto(ir::Scene &scene, const std::string &path, const SourceLoc &loc,
                           DiagnosticSink &diag, std::optional<int> materialOverride,
                           const ImportOptions &opts = {});

}  // namespace rt::gltf
