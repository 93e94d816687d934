// SPDX-License-Identifier: MIT
// Internals shared by the glTF importer's source files, the only place that sees tinygltf.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
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

/// A number in the JSON text.
struct NumberRef {
    std::string path;  ///< "buffers[2].byteLength"
    std::string text;  ///< as written
    int line = 0, column = 0;
};

/// What scanJson finds before tinygltf parses the text.
struct JsonScan {
    bool tooDeep = false;
    int deepLine = 0, deepColumn = 0;  ///< the bracket that went past kMaxJsonDepth
    std::vector<UriRef> uris;
    size_t buffersWithoutUri = 0;
    /// The first buffers[i].byteLength written as a number below 1 (the schema's minimum;
    /// tinygltf 2.7 throws std::out_of_range on a .glb's 0)
    std::optional<NumberRef> emptyBuffer;
};

/// One pass over JSON text (valid or not; nlohmann reports syntax errors afterwards): nesting
/// depth, the `uri` of every buffers[i] and images[i], and a buffer's byteLength below 1, with
/// line and column. No recursion,
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

/// Fails unless accessor `index`, used as vertex attribute (or morph target delta) `attribute`
/// ("POSITION", "TEXCOORD_1", "COLOR_0", "JOINTS_0", ...), has a component type glTF allows
/// for it, with KHR_mesh_quantization's integer types for positions, normals, tangents and
/// texture coordinates. Attributes glTF does not define (_CUSTOM) are not checked.
void checkAttributeType(const ImportContext &ctx, int index, const std::string &attribute,
                        bool morphTarget, const std::string &what);

// Compressed geometry (gltf_compression.cpp)

/// Most bytes one decoded EXT_meshopt_compression bufferView may take (count x byteStride),
/// and most vertices and triangles one KHR_draco_mesh_compression primitive may decode to.
constexpr uint64_t kMaxMeshoptViewBytes = uint64_t(1) << 31;
constexpr uint64_t kMaxDracoElements = uint64_t(1) << 27;

/// The chunk types of a .glb ("JSON" and "BIN\0", read as little-endian words).
constexpr uint32_t kGlbJsonChunk = 0x4E4F534Au, kGlbBinChunk = 0x004E4942u;

/// The little-endian 32-bit word at byte `at` of a .glb (the caller knows it lies inside).
inline uint32_t glbWord(const std::vector<unsigned char> &bytes, size_t at) {
    uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);
    return v;
}

/// The JSON text: the whole .gltf, or a .glb's first chunk. A .glb must have passed the
/// importer's layout check (prepareGlb), which keeps the chunk inside the file.
inline std::string_view jsonText(const std::vector<unsigned char> &bytes, bool binary) {
    std::string_view text(reinterpret_cast<const char *>(bytes.data()), bytes.size());
    return binary ? text.substr(20, glbWord(bytes, 12)) : text;
}

/// Rewrites the JSON text (of a .gltf, or the JSON chunk of the .glb `bytes`) where tinygltf
/// 2.7 would refuse valid compressed files: an EXT_meshopt_compression fallback buffer (no
/// `uri`, `fallback: true`; tinygltf refuses a uri-less buffer in a .gltf and copies the BIN
/// chunk into it in a .glb) names a three-byte data: URI instead, and a
/// KHR_draco_mesh_compression primitive loses its `indices` when that accessor has no
/// bufferView (tinygltf requires one: "accessor[N] invalid bufferView"; the Draco data holds
/// the indices). Returns the indices of the fallback buffers rewritten; `bytes` is unchanged
/// when there is nothing to rewrite or the JSON does not parse. A .glb must have passed the
/// importer's layout check (prepareGlb).
std::vector<size_t> patchJsonForTinygltf(std::vector<unsigned char> &bytes, bool binary);

/// Decodes every bufferView that carries EXT_meshopt_compression into a new buffer and points
/// the view at it; `fallbacks` (from patchJsonForTinygltf) are emptied. Corrupt data is
/// a ParseError at `loc` naming the extension and the bufferView.
void decodeMeshoptViews(tinygltf::Model &model, const std::vector<size_t> &fallbacks,
                        const SourceLoc &loc);

/// A primitive's KHR_draco_mesh_compression data, decoded.
class DracoPrimitive {
  public:
    /// Null when the primitive has no KHR_draco_mesh_compression extension; fails (naming the
    /// extension and `path`) when its data does not decode.
    static std::unique_ptr<DracoPrimitive> decode(const ImportContext &ctx,
                                                  const tinygltf::Primitive &prim,
                                                  const std::string &path);
    ~DracoPrimitive();
    /// Whether the compressed data holds attribute `name` ("POSITION", ...).
    bool has(const std::string &name) const;
    /// Attribute `name` as `components` floats per vertex (fails if it has fewer).
    FloatArray floats(const std::string &name, int components) const;
    /// Three vertex indices per triangle.
    std::vector<uint32_t> indices() const;
    size_t vertexCount() const;

  private:
    struct Impl;
    explicit DracoPrimitive(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

// Morph targets and skins (gltf_skin.cpp)

/// Reads a vertex attribute of the primitive being built by name (from its accessor, or from
/// its Draco data), checked to have `type`; nothing when the primitive has no such attribute.
using AttributeReader = std::function<std::optional<FloatArray>(const std::string &name, int type)>;

/// Most morph targets applied to one primitive; most JOINTS_n/WEIGHTS_n sets read per vertex.
constexpr size_t kMaxMorphTargets = 256;
constexpr int kMaxSkinSets = 8;

/// The node's local matrix: `matrix` (column-major) or T * R * S (gltf_scene.cpp).
Mat4 localMatrix(const ImportContext &ctx, const tinygltf::Node &node, const std::string &path);

/// Poses meshes as the file stores them: morph target weights and skins.
class Poser {
  public:
    explicit Poser(const ImportContext &ctx) : ctx_(ctx) {}
    /// The morph weights of node `nodeIndex`'s mesh: node.weights, else mesh.weights, else
    /// none; warns when their number differs from the mesh's targets.
    std::vector<double> weights(size_t nodeIndex) const;
    /// Adds the weighted POSITION, NORMAL and TANGENT deltas of `prim`'s targets to `mesh`
    /// (normals and tangents not yet normalised).
    void morph(const tinygltf::Primitive &prim, const std::string &path,
               const std::vector<double> &weights, ir::Mesh &mesh) const;
    /// Moves `mesh`'s vertices (and normals, tangents) by skin `skin` in the pose the file
    /// stores: sum of weight x (joint's global transform x inverse bind matrix), in the glTF
    /// scene's coordinates.
    void skin(int skin, const AttributeReader &read, const std::string &path, ir::Mesh &mesh);
    /// Global (scene) transform of node `index` in glTF coordinates.
    const Mat4 &global(size_t index);

  private:
    const ImportContext &ctx_;
    std::vector<Mat4> globals_;
    std::vector<char> globalDone_;
    std::vector<int> parents_;
    std::map<int, std::vector<Mat4>> jointMatrices_;  ///< by skin index
};

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
    std::optional<int> irMaterial(int index, const ir::Mesh &mesh,
                                  const std::string &primitivePath);
    /// The texture coordinate set (0 or 1) whose tangents a primitive with glTF material
    /// `index` needs when its file gives none (its normal map's), or -1: no normal map, or the
    /// material hides its primitives. The mesh builder generates them as it builds the mesh.
    int tangentTexCoord(int index, const std::string &primitivePath);

  private:
    struct DecodedImage;
    struct Mapped {
        ir::Material material;
        bool hidden = false;
        bool done = false;
    };

    /// The mapping of glTF material `index` (-1: the default), made on first use.
    const Mapped &mapped(int index, const std::string &primitivePath);
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
