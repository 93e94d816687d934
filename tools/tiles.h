// SPDX-License-Identifier: MIT
// Pictures rendered in tiles (`render --tile K/N`, `merge`): the tile layout, the fingerprint
// that ties a tile to its scene and its pixel-affecting options, and tile files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/image/image_io.h"
#include "core/ir/scene_ir.h"
#include "core/render/renderer.h"
#include "tools/cli_common.h"

namespace rt::cli {

/// Tile `index` (1-based, as Slurm's SLURM_ARRAY_TASK_ID with `--array=1-N`) of `count`
/// horizontal bands (tileRows).
struct TileSpec {
    int index = 0, count = 0;
    explicit operator bool() const { return count > 0; }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

/// Parses "K/N" (1 <= K <= N); throws std::invalid_argument naming --tile otherwise.
TileSpec parseTile(const std::string &text);

/// Hash (16 hex digits) of what a scene renders from: the scene file's bytes and the scene as
/// read (every node, material, light and the camera as the IR dump writes them, the meshes'
/// vertex data, the textures' and the environment's texels), so that tiles of a scene whose
/// included files, -D values or facets differ do not merge.
std::string sceneFingerprint(const std::string &path, const ir::Scene &scene);

/// The options that change pixels, as text ("640x480 adaptive-edges max=64 threshold=0.02 ...");
/// those that do not (threads, output format) are left out.
std::string pixelOptions(const RenderOptions &ro, const SceneArgs &scene, bool noPlan);

/// What a tile file carries beside its pixels.
struct TileHeader {
    TileSpec tile;
    std::string scene;        ///< the scene file as given
    std::string sceneHash;    ///< sceneFingerprint
    std::string options;      ///< pixelOptions
    std::string fingerprint;  ///< hash of version, scene hash and options
    int64_t samples = 0;      ///< camera samples of the tile's pixels
    /// The tile's rows in the picture and the picture's size.
    int rowBegin = 0, rows = 0, width = 0, height = 0;
};

/// Writes one tile of a render: an OpenEXR file of the tile's rows (data window) in the whole
/// picture (display window), with channels R, G, B, ties.R/G/B (and var.R/G/B for batches),
/// and the header's scadray:tile, scadray:scene, scadray:sceneHash, scadray:options,
/// scadray:fingerprint and scadray:samples attributes.
void writeTile(const RenderResult &r, const std::string &path, TileHeader header);

/// Reads a tile file's header and pixels; throws std::runtime_error naming the file when it is
/// not a tile `render --tile` wrote.
TileHeader readTile(const std::string &path, ImageEstimate &pixels);

/// Assembles tiles into the picture: all of one render (same fingerprint, size and tiling) and
/// each tile once. Throws std::runtime_error naming the files at fault, the options that differ
/// and the missing tiles. `samples` receives the camera samples of all tiles.
Image mergeTiles(const std::vector<std::string> &paths, int64_t *samples = nullptr);

}  // namespace rt::cli
