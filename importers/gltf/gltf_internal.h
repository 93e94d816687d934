// SPDX-License-Identifier: MIT
// Internals shared by the glTF importer's source files, the only place that sees tinygltf.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "importers/gltf/gltf_importer.h"

namespace rt::gltf::detail {

/// The parsed file and where its diagnostics go. Every problem is located at the file (glTF has
/// no line numbers); messages name the JSON path of the culprit instead.
struct ImportContext {
    const tinygltf::Model &model;
    SourceLoc loc;
    DiagnosticSink &diag;
    ImportOptions opts;
    /// File name without directory and extension, made safe for file names ("Duck").
    std::string baseName;
    /// Encoded image bytes kept by the loader callback (decoded on demand), by image index.
    const std::map<int, std::span<const unsigned char>> *encodedImages = nullptr;

    [[noreturn]] void fail(const std::string &message) const { throw ParseError(loc, message); }
    void warning(const std::string &message) const { diag.warning(loc, message); }
    void note(const std::string &message) const { diag.note(loc, message); }
};

/// "meshes[2].primitives[0]" and the like.
std::string jsonPath(const char *array, size_t index);

// What the file may read (gltf_files.cpp)

/// Deepest nesting of JSON arrays and objects accepted. tinygltf converts `extras` and
/// `extensions` recursively, so a file of 10^6 nested brackets would overflow the stack; real
/// files nest fewer than 20 levels.
constexpr size_t kMaxJsonDepth = 512;
/// Largest file a buffer or image URI may name: the GLB format's own limit (4 GiB - 1).
constexpr uint64_t kMaxExternalFileBytes = 0xFFFFFFFFull;
/// Most bytes read from all the files a model names, together: at most this, and at most twice
/// the size of the distinct files plus kExternalRereadSlack (one 1 MB file named by 10^4
/// buffers would otherwise be read, and kept, 10^4 times).
constexpr uint64_t kMaxExternalBytes = 0xFFFFFFFFull;
constexpr uint64_t kExternalRereadSlack = uint64_t(16) << 20;

/// A buffer or image URI in the JSON text.
struct UriRef {
    std::string path;  ///< "buffers[2].uri"
    std::string uri;   ///< as written (JSON escapes decoded, percent escapes not)
    int line = 0, column = 0;
};

/// What scanJson finds before tinygltf parses the text.
struct JsonScan {
    bool tooDeep = false;
    int deepLine = 0, deepColumn = 0;  ///< the bracket that went past kMaxJsonDepth
    std::vector<UriRef> uris;
    size_t buffersWithoutUri = 0;
};

/// One pass over JSON text (valid or not; nlohmann reports syntax errors afterwards): nesting
/// depth and the `uri` of every buffers[i] and images[i], with line and column. No recursion,
/// no regular expressions.
JsonScan scanJson(std::string_view text);

/// Percent-decodes a URI as tinygltf does before opening it ('+' is a space).
std::string urlDecode(const std::string &uri);

/// The folder a glTF file may read from: its own, symlinks resolved.
class ModelFolder {
  public:
    explicit ModelFolder(const std::string &gltfPath);
    /// Empty when `uri` is a data: URI or names a regular file (or nothing) inside the folder,
    /// else why not ("lies outside the model's folder ...").
    std::string checkUri(const std::string &uri) const;
    /// The same for a path tinygltf built (folder + decoded URI); `resolved` receives the
    /// canonical path.
    std::string check(const std::string &path, std::filesystem::path *resolved) const;
    const std::filesystem::path &path() const { return folder_; }

  private:
    std::filesystem::path folder_;
};

/// tinygltf's filesystem callbacks: every path is checked by `folder` before it is opened;
/// refusals are kept to be reported.
struct FileAccess {
    ModelFolder folder;
    std::string baseDir;  ///< the base directory handed to tinygltf
    std::vector<std::string> refused;
    uint64_t bytesRead = 0;
    std::map<std::string, uint64_t> sizes;  ///< distinct files read, by canonical path
    uint64_t distinctBytes = 0;
    tinygltf::FsCallbacks callbacks();
};

// Accessors (gltf_accessors.cpp)

/// Attribute data converted to float: `count` elements of `components` values each.
struct FloatArray {
    size_t count = 0;
    int components = 0;
    std::vector<float> values;
};

/// Reads accessor `index`, which must be of `type` (TINYGLTF_TYPE_VEC3, ...), as floats:
/// float components as they are, normalized integers mapped to [0,1] or [-1,1], plain integers
/// converted. byteStride, the view and accessor offsets and sparse substitution are applied;
/// every byte read is checked to lie in its buffer. `what` names the reference in messages
/// ("meshes[0].primitives[1].attributes.POSITION").
FloatArray readFloats(const ImportContext &ctx, int index, int type, const std::string &what);

/// Reads an index accessor (SCALAR of u8, u16 or u32), bounds-checked like readFloats.
std::vector<uint32_t> readIndices(const ImportContext &ctx, int index, const std::string &what);

// Materials and textures (gltf_materials.cpp)

/// Maps glTF materials to IR materials (added to the scene, deduplicated) and decodes the
/// textures they need, each once.
class MaterialMapper {
  public:
    MaterialMapper(const ImportContext &ctx, ir::Scene &scene);
    ~MaterialMapper();

    /// IR material for glTF material `index` (-1: glTF's default material), or nothing when
    /// the material hides its primitives (alphaMode MASK with alpha below the cutoff). Without
    /// the texture coordinates it reads, the base colour texture is left out.
    std::optional<int> irMaterial(int index, const ir::Mesh &mesh, const std::string &primitivePath);

  private:
    struct DecodedImage;
    struct Mapped {
        ir::Material material;
        bool hidden = false;
        bool done = false;
    };

    ir::Material map(int index, bool &hidden);
    const DecodedImage *decodedImage(int textureIndex, const std::string &what);
    /// Mean of channel `channel` (0..3) over the texture `ref` names; 1 without one.
    double textureMean(const ir::TextureRef &ref, int channel) const;
    /// `srgb`: colour data (decoded to linear), else linear data (normals, roughness...).
    int irTexture(int textureIndex, const std::string &what, bool srgb = true);
    /// The IR reference of a glTF textureInfo (`index`, `texCoord`, its `extensions`):
    /// the texture decoded once, TEXCOORD_0 or _1, and KHR_texture_transform (whose own
    /// `texCoord` overrides). Invalid (texture -1) with a warning naming `what` when the
    /// texture fails or uses a coordinate set other than 0 and 1.
    ir::TextureRef textureInfo(int textureIndex, int texCoord,
                               const tinygltf::ExtensionMap &extensions, const std::string &what,
                               bool srgb = true);

    const ImportContext &ctx_;
    ir::Scene &scene_;
    std::vector<Mapped> mapped_;  ///< by glTF material index + 1 (slot 0: default material)
    std::map<int, std::unique_ptr<DecodedImage>> images_;  ///< by image index; null = failed
    uint64_t decodedPixels_ = 0;  ///< declared pixels of the images decoded so far
    /// (glTF texture index, sRGB) -> IR texture index (-1 = failed)
    std::map<std::pair<int, bool>, int> textures_;
};

// Scene graph, cameras and lights (gltf_scene.cpp)

struct BuildOptions {
    /// Location put on every IR node (the file, or the import() call).
    SourceLoc nodeLoc;
    /// When set, every primitive gets this material and the file's materials are not read.
    std::optional<int> materialOverride;
    /// Read the first camera and the punctual lights into the scene (else note and ignore them).
    bool camerasAndLights = true;
};

/// Adds the meshes (and materials) of scene `sceneIndex` to `scene` and returns its node tree
/// under one root transform: glTF Y-up to Z-up, times the unit scale.
ir::NodePtr buildScene(const ImportContext &ctx, ir::Scene &scene, int sceneIndex,
                       const BuildOptions &options);

}  // namespace rt::gltf::detail
