// SPDX-License-Identifier: MIT
// POV-Ray 3.7 SDL writer: the IR as a readable .pov that keeps CSG as CSG, with every material
// value explicit, and an .ini for a headless, quiet, deterministic render.
#pragma once

#include <string>

#include "core/image/image.h"
#include "core/ir/scene_ir.h"

namespace rt::pov {

struct IniOptions {
    std::string povFile;     ///< scene file name, relative to the .ini's folder
    std::string outputFile;  ///< image file name, relative to the .ini's folder
    int width = 640, height = 480;
    /// Render with k x k samples per pixel by rendering k times larger (box-downsample after).
    int supersample = 1;
    int threads = 0;  ///< 0 = POV-Ray's default (all cores)
};

/// SDL text of a complete scene (ir::completeScene applied: explicit camera and lights).
/// `sourceName` names the input in the header comment.
///
/// The IR is right-handed and Z-up; POV-Ray is left-handed. Geometry is written in its own
/// coordinates and the camera gets `right <-image_width/image_height, 0, 0>`, which makes
/// POV-Ray's look_at construction right-handed (docs/design/povray-semantics.md section 7.3).
/// Solids are grouped exactly as the ray tracer groups them: each top-level solid is one
/// POV-Ray object with one interior (that of its first primitive); the unions of a solid with a
/// transparent part are `merge`, so no internal surface shows that scadray does not have, and
/// those of an opaque solid stay `union` (same note, section 10.3).
///
/// Textured materials refer to images named `<assetPrefix>_Material_<n>.png` (the texture with
/// the material's colour baked in, linear 16-bit); they are appended to `textures` when given.
struct TextureFile {
    std::string fileName;
    Image image;
};
std::string writeSdl(const ir::Scene &scene, const std::string &sourceName,
                     std::vector<TextureFile> *textures = nullptr,
                     const std::string &assetPrefix = "scene");

/// Writes `povPath`, the .ini beside it (ini.povFile is set from povPath) and the texture
/// images, each through a temporary file and a rename.
void exportPov(const ir::Scene &scene, const std::string &povPath, const std::string &sourceName,
               IniOptions ini);

/// The .ini text: 16-bit linear PNG output, no antialiasing (supersampling by size instead),
/// no display, no progress lines.
std::string writeIni(const IniOptions &opts);

/// Writes `text` to `path` through a temporary file and a rename.
void writeTextFile(const std::string &path, const std::string &text);

}  // namespace rt::pov
