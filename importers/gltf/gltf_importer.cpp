// SPDX-License-Identifier: MIT
// glTF entry points: reading the file with tinygltf, extension checks and scene selection.
#include "importers/gltf/gltf_importer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <limits>
#include <optional>
#include <span>
#include <string_view>

#include "importers/gltf/gltf_internal.h"

namespace rt::gltf {

namespace {

/// Extensions whose meaning the importer implements; any other in extensionsRequired is refused.
constexpr std::array<std::string_view, 14> kSupportedExtensions = {
    "KHR_materials_emissive_strength",
    "KHR_texture_transform",
    "KHR_materials_transmission",
    "KHR_materials_ior",
    "KHR_materials_volume",
    "KHR_materials_unlit",
    "KHR_lights_punctual",
    "KHR_mesh_quantization",
    "KHR_draco_mesh_compression",
    "EXT_meshopt_compression",
    "EXT_mesh_gpu_instancing",
    "KHR_materials_clearcoat",
    "KHR_materials_sheen",
    "KHR_materials_specular"};

bool isSupported(const std::string &ext) {
    return std::find(kSupportedExtensions.begin(), kSupportedExtensions.end(), ext) !=
           kSupportedExtensions.end();
}

/// What the image callback sees while tinygltf parses: images are kept encoded and decoded
/// only when a material needs them, so an undecodable or unused image costs nothing.
struct ImageCollector {
    const tinygltf::Model *model = nullptr;  ///< the model being parsed (its buffers come first)
    bool keep = true;
    /// Images read from a file or a data: URI (tinygltf hands over a temporary copy).
    std::map<int, std::vector<unsigned char>> owned;
    /// Images in a bufferView: not copied (10^4 images may share one 100 MB view), looked up
    /// in the model's buffers once it is loaded.
    std::map<int, std::pair<size_t, size_t>> inBuffer;  ///< image -> (buffer, byte offset)
    std::map<int, size_t> inBufferSize;
    std::vector<std::string> problems;

    /// Every kept image's bytes, once the model is complete.
    std::map<int, std::span<const unsigned char>> bytes() const {
        std::map<int, std::span<const unsigned char>> all;
        for (const auto &[index, data] : owned) all[index] = std::span(data);
        for (const auto &[index, where] : inBuffer)
            all[index] = std::span(model->buffers[where.first].data)
                             .subspan(where.second, inBufferSize.at(index));
        return all;
    }
};

/// tinygltf LoadImageDataFunction: keeps the bytes; never fails, so a bad image cannot stop the
/// geometry from loading (gltf-notes section 9).
bool collectImage(tinygltf::Image *image, const int imageIndex, std::string *, std::string *, int,
                  int, const unsigned char *bytes, int size, void *user) {
    auto *collector = static_cast<ImageCollector *>(user);
    if (!collector->keep || !bytes || size <= 0) return true;
    if (image->bufferView >= 0) {
        // tinygltf hands over a bufferView's bytes without checking that the view lies inside
        // its buffer; check before reading any of them
        const tinygltf::Model &model = *collector->model;
        bool inside = false;
        if (static_cast<size_t>(image->bufferView) < model.bufferViews.size()) {
            const tinygltf::BufferView &view =
                model.bufferViews[static_cast<size_t>(image->bufferView)];
            if (view.buffer >= 0 && static_cast<size_t>(view.buffer) < model.buffers.size()) {
                size_t bufferSize = model.buffers[static_cast<size_t>(view.buffer)].data.size();
                inside = view.byteOffset <= bufferSize &&
                         view.byteLength <= bufferSize - view.byteOffset &&
                         static_cast<size_t>(size) <= view.byteLength;
                if (inside) {
                    collector->inBuffer[imageIndex] = {static_cast<size_t>(view.buffer),
                                                       view.byteOffset};
                    collector->inBufferSize[imageIndex] = static_cast<size_t>(size);
                }
            }
        }
        if (!inside)
            collector->problems.push_back(
                detail::jsonPath("images", static_cast<size_t>(imageIndex)) +
                ": its bufferView lies outside its buffer; image ignored");
        return true;
    }
    collector->owned[imageIndex].assign(bytes, bytes + size);
    return true;
}

/// tinygltf's messages, one per line, without trailing newlines.
std::vector<std::string> splitLines(const std::string &text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

struct LoadedFile {
    tinygltf::Model model;
    ImageCollector images;
    std::map<int, std::span<const unsigned char>> imageBytes;  ///< filled after loading
};

/// Line and column (from 1) of the first standalone occurrence of a number token in JSON text.
std::optional<std::pair<int, int>> findNumberToken(std::string_view text,
                                                   const std::string &token) {
    auto numberChar = [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
               c == '+' || c == '-';
    };
    for (size_t at = text.find(token); at != std::string_view::npos;
         at = text.find(token, at + 1)) {
        size_t end = at + token.size();
        if ((at > 0 && numberChar(text[at - 1])) || (end < text.size() && numberChar(text[end])))
            continue;
        int line = 1 + static_cast<int>(
                           std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
        size_t lineStart = text.rfind('\n', at);
        int col = static_cast<int>(lineStart == std::string_view::npos ? at + 1 : at - lineStart);
        return std::pair(line, col);
    }
    return std::nullopt;
}

/// Reads the decimal number at text[at]; npos when there is none.
size_t readNumber(std::string_view text, size_t &at) {
    size_t start = at, value = 0;
    while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) && at - start < 9)
        value = value * 10 + static_cast<size_t>(text[at++] - '0');
    return at == start ? std::string_view::npos : value;
}

/// nlohmann's "[json.exception.parse_error.101] parse error at line L, column C: what" taken
/// apart by plain scanning (a regular expression recursed per character of the message).
struct JsonError {
    int line = 0, column = 0;
    std::string what;
};
std::optional<JsonError> parseJsonError(std::string_view message) {
    static constexpr std::string_view kTag = "[json.exception.parse_error.";
    static constexpr std::string_view kAtLine = "parse error at line ";
    static constexpr std::string_view kColumn = ", column ";
    size_t at = message.find(kTag);
    if (at == std::string_view::npos) return std::nullopt;
    at = message.find(kAtLine, at);
    if (at == std::string_view::npos) return std::nullopt;
    at += kAtLine.size();
    size_t line = readNumber(message, at);
    if (line == std::string_view::npos || message.substr(at, kColumn.size()) != kColumn)
        return std::nullopt;
    at += kColumn.size();
    size_t column = readNumber(message, at);
    if (column == std::string_view::npos || message.substr(at, 2) != ": ") return std::nullopt;
    return JsonError{static_cast<int>(line), static_cast<int>(column),
                     std::string(message.substr(at + 2))};
}

/// The token of nlohmann's "number overflow parsing '1e999'".
std::optional<std::string> overflowToken(std::string_view message) {
    static constexpr std::string_view kOverflow = "number overflow parsing '";
    size_t at = message.find(kOverflow);
    if (at == std::string_view::npos) return std::nullopt;
    at += kOverflow.size();
    size_t end = message.find('\'', at);
    if (end == std::string_view::npos || end == at) return std::nullopt;
    return std::string(message.substr(at, end - at));
}

/// Where a problem at (line, column) of the JSON text is reported: the .gltf itself, or the
/// file with the position inside the .glb's JSON chunk in the message.
[[noreturn]] void failAt(bool binary, const std::string &path, const SourceLoc &loc, int line,
                         int column, const std::string &what) {
    if (!binary)
        throw ParseError(SourceLoc(std::make_shared<const std::string>(path), line, column), what);
    throw ParseError(loc, what + " (JSON chunk of the binary glTF, its line " +
                              std::to_string(line) + ", column " + std::to_string(column) + ")");
}

/// The file's bytes, through the input reader: a FIFO, /dev/zero or a folder is refused, and so
/// is a file larger than a glTF file can be (its lengths are 32-bit).
std::vector<unsigned char> readMainFile(const std::string &path, const SourceLoc &loc) {
    std::string bytes =
        readInputFileAt(path, loc, uint64_t{std::numeric_limits<unsigned int>::max()} - 1);
    return std::vector<unsigned char>(bytes.begin(), bytes.end());
}

/// Checks a .glb's header and chunk lengths before tinygltf reads them, and cuts the file to
/// what tinygltf should read. tinygltf 2.7 bounds the BIN chunk's data by the header's length
/// without counting the chunk's own 8-byte header, so a BIN chunk declaring up to 8 bytes more
/// than follow it made a buffer copy from past the end of the file: every length is checked
/// against the file here, each failure naming what was declared and where. Then:
/// - bytes after the header's length are dropped (with a warning): the JSON rewrite that
///   follows makes the length that of the whole vector, and tinygltf would read them as a
///   chunk;
/// - a second chunk that is an empty BIN chunk or of an unknown type is dropped, with any after
///   it, and the header's length made to match. The spec allows both (an empty BIN chunk
///   SHOULD be omitted and means the same; readers skip unknown types, and the BIN chunk can
///   only be the second); tinygltf refuses either. An unknown type is named in a warning.
void prepareGlb(std::vector<unsigned char> &bytes, const SourceLoc &loc, DiagnosticSink &diag) {
    using detail::glbWord;
    auto fail = [&](const std::string &what) {
        throw ParseError(loc, "invalid binary glTF (.glb): " + what);
    };
    const uint64_t size = bytes.size();
    if (size < 20)
        fail("the file is " + std::to_string(size) +
             " bytes, shorter than the 12-byte header and a chunk header");
    if (glbWord(bytes, 4) != 2)
        fail("container version " + std::to_string(glbWord(bytes, 4)) +
             " (at byte 4); only version 2 is read");
    const uint64_t length = glbWord(bytes, 8);
    if (length > size)
        fail("the header's length (at byte 8) is " + std::to_string(length) +
             " bytes, but the file has " + std::to_string(size) + " (truncated?)");
    const uint64_t json = glbWord(bytes, 12);
    if (glbWord(bytes, 16) != detail::kGlbJsonChunk)
        fail("the first chunk (at byte 12) is not the JSON chunk");
    if (json == 0) fail("the JSON chunk (at byte 12) is empty");
    if (20 + json > length)
        fail("the JSON chunk (at byte 12) declares " + std::to_string(json) + " bytes, but " +
             std::to_string(length - 20) + " follow its header");
    const uint64_t second = 20 + json, rest = length - second;
    uint32_t secondLength = 0, secondType = 0;
    if (rest > 0) {
        if (rest < 8)
            fail(std::to_string(rest) + " bytes after the JSON chunk (at byte " +
                 std::to_string(second) + "), too few for a chunk header");
        secondLength = glbWord(bytes, second);
        secondType = glbWord(bytes, second + 4);
        if (8 + uint64_t(secondLength) > rest)
            fail("the chunk at byte " + std::to_string(second) + " declares " +
                 std::to_string(secondLength) + " bytes, but " + std::to_string(rest - 8) +
                 " follow its header");
    }
    if (length < size)
        diag.warning(loc, std::to_string(size - length) +
                              " bytes after the binary glTF's length (" + std::to_string(length) +
                              " bytes, at byte 8) are ignored");
    bytes.resize(length);
    if (rest == 0 || (secondType == detail::kGlbBinChunk && secondLength != 0)) return;
    if (secondType != detail::kGlbBinChunk) {
        std::string name;
        for (int k = 0; k < 4; ++k) {
            auto c = static_cast<unsigned char>(secondType >> (8 * k));
            name += std::isprint(c) ? std::string(1, static_cast<char>(c))
                                    : "\\x" + std::string(1, "0123456789abcdef"[c >> 4]) +
                                          "0123456789abcdef"[c & 15];
        }
        diag.warning(loc, "binary glTF: the chunk at byte " + std::to_string(second) +
                              " has the unknown type '" + name +
                              "' and is ignored, with any "
                              "after it (the BIN chunk can only be the second)");
    }
    bytes.resize(second);
    uint32_t cut = static_cast<uint32_t>(second);
    std::memcpy(bytes.data() + 8, &cut, 4);
}

/// Checks the JSON text before tinygltf parses it: nesting depth, buffer and image URIs.
void prescan(std::string_view text, bool binary, const std::string &path, const SourceLoc &loc,
             const detail::ModelFolder &folder) {
    detail::JsonScan scan = detail::scanJson(text);
    if (scan.tooDeep)
        failAt(binary, path, loc, scan.deepLine, scan.deepColumn,
               "JSON nested more than " + std::to_string(detail::kMaxJsonDepth) + " levels deep");
    for (const detail::UriRef &ref : scan.uris) {
        std::string problem = folder.checkUri(ref.uri);
        if (!problem.empty())
            failAt(binary, path, loc, ref.line, ref.column,
                   ref.path + " '" + ref.uri + "' " + problem + "; not read");
    }
    if (const auto &empty = scan.emptyBuffer)
        failAt(binary, path, loc, empty->line, empty->column,
               empty->path + " is " + empty->text + "; a buffer holds at least 1 byte");
    // Each uri-less buffer of a .glb is a copy of the BIN chunk; only buffers[0] may be one
    if (binary && scan.buffersWithoutUri > 1)
        throw ParseError(loc, std::to_string(scan.buffersWithoutUri) +
                                  " buffers have no uri; in a binary glTF only buffers[0] may "
                                  "refer to the BIN chunk");
}

/// Turns tinygltf's error into a located ParseError.
[[noreturn]] void failLoad(const std::string &err, const std::vector<unsigned char> &bytes,
                           bool binary, const std::string &path, const SourceLoc &loc) {
    std::string message;
    for (const std::string &line : splitLines(err)) message += (message.empty() ? "" : "; ") + line;
    if (message.empty()) message = "unknown error";
    // A JSON syntax error points into the text: at its line and column for a .gltf, in the
    // message for the JSON chunk of a .glb
    if (std::optional<JsonError> e = parseJsonError(message)) {
        if (!binary)
            throw ParseError(
                SourceLoc(std::make_shared<const std::string>(path), e->line, e->column),
                "invalid JSON: " + e->what);
        throw ParseError(loc, "invalid JSON chunk in binary glTF at its line " +
                                  std::to_string(e->line) + ", column " +
                                  std::to_string(e->column) + ": " + e->what);
    }
    // A number too large for a double (1e999): nlohmann names the token but not where it is
    if (std::optional<std::string> token = overflowToken(message)) {
        if (auto at = findNumberToken(detail::jsonText(bytes, binary), *token))
            failAt(binary, path, loc, at->first, at->second,
                   "number " + *token + " is too large for a double");
    }
    throw ParseError(loc, std::string("cannot load glTF") + (binary ? " binary (.glb)" : "") +
                              " file: " + message);
}

/// Parses the file, telling .glb from .gltf by its magic bytes, not its extension.
std::unique_ptr<LoadedFile> loadFile(const std::string &path, const SourceLoc &loc,
                                     DiagnosticSink &diag, bool keepImages) {
    std::vector<unsigned char> bytes = readMainFile(path, loc);
    bool binary = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    if (binary) prepareGlb(bytes, loc, diag);
    std::vector<size_t> fallbacks = detail::patchJsonForTinygltf(bytes, binary);
    std::string baseDir = std::filesystem::path(path).parent_path().string();

    detail::FileAccess files{detail::ModelFolder(path), baseDir, {}, 0, {}, 0};
    prescan(detail::jsonText(bytes, binary), binary, path, loc, files.folder);

    auto file = std::make_unique<LoadedFile>();
    file->images.model = &file->model;
    file->images.keep = keepImages;
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(collectImage, &file->images);
    loader.SetFsCallbacks(files.callbacks());
    std::string err, warn;
    bool ok = false;
    try {
        auto size = static_cast<unsigned int>(bytes.size());
        if (binary)
            ok =
                loader.LoadBinaryFromMemory(&file->model, &err, &warn, bytes.data(), size, baseDir);
        else
            ok = loader.LoadASCIIFromString(&file->model, &err, &warn,
                                            reinterpret_cast<const char *>(bytes.data()), size,
                                            baseDir);
    } catch (const std::exception &e) {
        // nlohmann::json or an allocation inside tinygltf
        err += e.what();
        ok = false;
    }
    // The scan above refuses every URI that leads outside; this catches what it could not see
    if (!files.refused.empty()) throw ParseError(loc, "refused to read " + files.refused.front());
    for (const std::string &line : splitLines(warn)) diag.warning(loc, "tinygltf: " + line);
    for (const std::string &problem : file->images.problems) diag.warning(loc, problem);
    if (!ok) failLoad(err, bytes, binary, path, loc);
    // Before the image spans are taken: decoding adds buffers
    detail::decodeMeshoptViews(file->model, fallbacks, loc);
    file->imageBytes = file->images.bytes();
    return file;
}

/// Refuses required extensions the importer does not implement (tinygltf does not check).
void checkExtensions(const detail::ImportContext &ctx) {
    const tinygltf::Model &model = ctx.model;
    for (const std::string &ext : model.extensionsRequired)
        if (!isSupported(ext))
            ctx.fail("requires extension " + ext + ", which scadray does not support");
    for (const std::string &ext : model.extensionsUsed) {
        if (isSupported(ext)) continue;
        ctx.note("uses extension " + ext + ", which scadray ignores");
    }
}

/// The scene to show: the option, else the file's `scene`, else 0.
int chooseScene(const tinygltf::Model &model, const ImportOptions &opts, const SourceLoc &loc) {
    size_t n = model.scenes.size();
    if (opts.sceneIndex < -1)
        throw SceneError(loc, "scene index " + std::to_string(opts.sceneIndex) + " is invalid");
    if (opts.sceneIndex >= 0) {
        if (static_cast<size_t>(opts.sceneIndex) >= n)
            throw SceneError(loc, "scene " + std::to_string(opts.sceneIndex) +
                                      " requested, but the file has " + std::to_string(n) +
                                      " scene(s)");
        return opts.sceneIndex;
    }
    if (n == 0)
        throw SceneError(loc, "the file has no scenes (a library of parts); nothing to show");
    int s = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<size_t>(s) >= n)
        throw ParseError(loc, "scene: " + std::to_string(s) + " does not exist (the file has " +
                                  std::to_string(n) + " scene(s))");
    return s;
}

void checkOptions(const ImportOptions &opts, const SourceLoc &loc) {
    if (!(opts.unitScale > 0) || !std::isfinite(opts.unitScale))
        throw SceneError(loc, "glTF unit scale must be a positive number, not " +
                                  std::to_string(opts.unitScale));
}

/// The file name without directory and extension, with anything but [A-Za-z0-9_-] replaced.
std::string safeBaseName(const std::string &path) {
    std::string stem = std::filesystem::path(path).stem().string();
    for (char &c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return stem.empty() ? "gltf" : stem;
}

SourceLoc fileLoc(const std::string &path) {
    return SourceLoc(std::make_shared<const std::string>(path), 0, 0);
}

}  // namespace

ir::Scene importGltf(const std::string &path, DiagnosticSink &diag, const ImportOptions &opts) {
    SourceLoc loc = fileLoc(path);
    checkOptions(opts, loc);
    std::unique_ptr<LoadedFile> file = loadFile(path, loc, diag, true);
    detail::ImportContext ctx{file->model, loc, diag, opts, safeBaseName(path), &file->imageBytes};
    checkExtensions(ctx);
    int sceneIndex = chooseScene(file->model, opts, loc);

    ir::Scene scene;
    scene.root->loc = loc;
    detail::BuildOptions build;
    build.nodeLoc = loc;
    scene.root->children.push_back(detail::buildScene(ctx, scene, sceneIndex, build));
    return scene;
}

ir::NodePtr importGltfInto(ir::Scene &scene, const std::string &path, const SourceLoc &loc,
                           DiagnosticSink &diag, std::optional<int> materialOverride,
                           const ImportOptions &opts) {
    SourceLoc floc = fileLoc(path);
    checkOptions(opts, loc);
    if (materialOverride &&
        (*materialOverride < 0 || static_cast<size_t>(*materialOverride) >= scene.materials.size()))
        throw SceneError(loc, "import of '" + path + "': material " +
                                  std::to_string(*materialOverride) + " does not exist");
    std::unique_ptr<LoadedFile> file = loadFile(path, floc, diag, !materialOverride);
    detail::ImportContext ctx{file->model, floc, diag, opts, safeBaseName(path), &file->imageBytes};
    checkExtensions(ctx);
    int sceneIndex = chooseScene(file->model, opts, floc);

    detail::BuildOptions build;
    build.nodeLoc = loc;
    build.materialOverride = materialOverride;
    build.camerasAndLights = false;
    auto group = ir::Node::makeGroup(ir::NodeKind::Group, loc);
    group->label = "import(\"" + path + "\")";
    group->children.push_back(detail::buildScene(ctx, scene, sceneIndex, build));
    return group;
}

}  // namespace rt::gltf
