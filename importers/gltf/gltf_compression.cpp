// SPDX-License-Identifier: MIT
// Compressed glTF geometry: EXT_meshopt_compression bufferViews (libmeshoptimizer) and
// KHR_draco_mesh_compression primitives (libdraco), decoded into what the accessors read.
#include <draco/compression/decode.h>
#include <draco/compression/point_cloud/point_cloud_decoder.h>
#include <draco/core/varint_decoding.h>
#include <draco/metadata/metadata_decoder.h>
#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "importers/gltf/gltf_internal.h"

namespace rt::gltf::detail {

namespace {

constexpr const char *kMeshopt = "EXT_meshopt_compression";
constexpr const char *kDraco = "KHR_draco_mesh_compression";

/// A data: URI of three zero bytes, standing in for a fallback buffer tinygltf would not load.
constexpr const char *kPlaceholderUri = "data:application/octet-stream;base64,AAAA";

bool isFallback(const nlohmann::json &buffer) {
    if (!buffer.is_object() || buffer.contains("uri")) return false;
    auto ext = buffer.find("extensions");
    if (ext == buffer.end() || !ext->is_object()) return false;
    auto m = ext->find(kMeshopt);
    if (m == ext->end() || !m->is_object()) return false;
    auto f = m->find("fallback");
    return f != m->end() && f->is_boolean() && f->get<bool>();
}

/// Reads a non-negative integer member of an extension object; fails naming `what`.
size_t member(const tinygltf::Value &obj, const char *name, const std::string &what,
              const SourceLoc &loc, std::optional<size_t> fallback = std::nullopt) {
    if (!obj.Has(name)) {
        if (fallback) return *fallback;
        throw ParseError(loc, what + ": needs '" + name + "'");
    }
    const tinygltf::Value &v = obj.Get(name);
    double d = v.IsNumber() ? v.GetNumberAsDouble() : -1;
    if (!(d >= 0 && d <= 9.0e15) || d != std::floor(d))
        throw ParseError(loc, what + "." + name + ": needs a non-negative integer");
    return static_cast<size_t>(d);
}

std::string stringMember(const tinygltf::Value &obj, const char *name, const char *fallback) {
    if (!obj.Has(name) || !obj.Get(name).IsString()) return fallback;
    return obj.Get(name).Get<std::string>();
}

uint64_t ceilDiv(uint64_t a, uint64_t b) { return a / b + (a % b != 0); }

/// Fewest bytes an EXT_meshopt_compression stream of `count` elements of `stride` bytes can
/// take (the extension's Appendix A), so a count its bytes cannot hold is refused before
/// count x stride bytes are allocated and zero-filled.
/// - ATTRIBUTES: the header byte; blocks of at most min((8192 / stride) & ~15, 256) elements,
///   each with one data block per byte of the element, which holds at least its header bits
///   (2 bits per group of 16 elements: ceil(n / 64) bytes for n elements; a group of zero
///   deltas adds nothing); then the tail, the first element padded to 32 bytes. At most
///   64 : 1 for strides up to 128 (32 : 1 at 256).
/// - TRIANGLES: the header byte, one code byte per triangle and the 16-byte code table.
/// - INDICES: the header byte, at least one varint byte per index and 4 tail bytes.
uint64_t meshoptMinBytes(const std::string &mode, uint64_t count, uint64_t stride) {
    if (mode == "TRIANGLES") return 1 + count / 3 + 16;
    if (mode == "INDICES") return 1 + count + 4;
    uint64_t blockElements = std::min<uint64_t>((8192 / stride) & ~uint64_t(15), 256);
    uint64_t headerBytes =
        (count / blockElements) * ceilDiv(blockElements, 64) + ceilDiv(count % blockElements, 64);
    return 1 + stride * headerBytes + std::max<uint64_t>(stride, 32);
}

/// Most faces or vertices a KHR_draco_mesh_compression stream may declare per byte of it.
/// Draco's format has no fixed ratio (rANS-coded symbols of constant data cost next to
/// nothing), so this is a margin over what its encoder makes of the most regular input: a
/// flat 1000 x 1000 grid (2,000,000 triangles) at its best compression (speed 0, 11-bit
/// positions) takes 39 triangles and 20 vertices a byte; its standard edgebreaker spends at
/// least one bit a triangle (8 a byte), its sequential coder at least one byte a triangle.
constexpr uint64_t kMaxDracoElementsPerByte = 1024;

/// Empty when the counts a Draco stream declares for its connectivity fit its size, else
/// the reason. The decoder sizes its tables from these counts before reading the data they
/// describe (100 bytes of edgebreaker stream declaring 7 x 10^8 faces and 6 x 10^8 symbols
/// took Draco 1.5.5 64 s and 16 GB), so they are read here first, from the layout of Draco
/// bitstream 2.2 (the version KHR_draco_mesh_compression is written against): the header and
/// metadata through Draco's own readers, then the counts. Anything else (not Draco, cut
/// short) is left for the decoder to refuse.
std::string dracoDeclaredProblem(const unsigned char *data, size_t size) {
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char *>(data), size);
    draco::DracoHeader header;
    if (!draco::PointCloudDecoder::DecodeHeader(&buffer, &header).ok()) return "";
    if (header.version_major != 2 || header.version_minor != 2)
        return "is Draco bitstream " + std::to_string(header.version_major) + "." +
               std::to_string(header.version_minor) +
               "; KHR_draco_mesh_compression requires version 2.2";
    if (header.encoder_type != draco::TRIANGULAR_MESH) return "is not a Draco triangle mesh";
    buffer.set_bitstream_version(DRACO_BITSTREAM_VERSION(2, 2));
    if (header.flags & METADATA_FLAG_MASK) {
        draco::GeometryMetadata metadata;
        if (!draco::MetadataDecoder().DecodeGeometryMetadata(&buffer, &metadata)) return "";
    }
    // Sequential: faces, points. Edgebreaker: traversal type, vertices, faces, attribute
    // data, symbols, split symbols (each vertex count is a table the decoder fills)
    uint32_t faces = 0, vertices = 0, extraVertices = 0;
    uint8_t byte = 0;
    if (header.encoder_method == draco::MESH_SEQUENTIAL_ENCODING) {
        if (!draco::DecodeVarint(&faces, &buffer) || !draco::DecodeVarint(&vertices, &buffer))
            return "";
    } else if (header.encoder_method == draco::MESH_EDGEBREAKER_ENCODING) {
        uint32_t symbols = 0;
        if (!buffer.Decode(&byte) || !draco::DecodeVarint(&vertices, &buffer) ||
            !draco::DecodeVarint(&faces, &buffer) || !buffer.Decode(&byte) ||
            !draco::DecodeVarint(&symbols, &buffer) ||
            !draco::DecodeVarint(&extraVertices, &buffer))
            return "";
    } else {
        return "";
    }
    uint64_t limit = kMaxDracoElementsPerByte * uint64_t(size);
    uint64_t allVertices = uint64_t(vertices) + extraVertices;
    if (faces <= limit && allVertices <= limit) return "";
    return "declares " + std::to_string(faces) + " triangles and " + std::to_string(allVertices) +
           " vertices in " + std::to_string(size) + " bytes, more than " +
           std::to_string(kMaxDracoElementsPerByte) +
           " of either a byte can hold (corrupt or truncated)";
}

}  // namespace

std::vector<size_t> patchJsonForTinygltf(std::vector<unsigned char> &bytes, bool binary) {
    std::string_view all(reinterpret_cast<const char *>(bytes.data()), bytes.size());
    if (all.find(kMeshopt) == std::string_view::npos && all.find(kDraco) == std::string_view::npos)
        return {};
    std::string_view json = jsonText(bytes, binary);
    // Too deep JSON is refused by the prescan that follows, invalid JSON by tinygltf, which
    // reports where it is
    if (scanJson(json).tooDeep) return {};
    nlohmann::json doc = nlohmann::json::parse(json, nullptr, false);
    if (doc.is_discarded() || !doc.is_object()) return {};
    std::vector<size_t> patched;
    bool changed = false;
    auto buffers = doc.find("buffers");
    if (buffers != doc.end() && buffers->is_array())
        for (size_t i = 0; i < buffers->size(); ++i) {
            nlohmann::json &b = (*buffers)[i];
            if (!isFallback(b)) continue;
            b["uri"] = kPlaceholderUri;
            b["byteLength"] = 3;
            patched.push_back(i);
            changed = true;
        }
    // Draco primitives: tinygltf wants a bufferView on every index accessor, which Draco's
    // have not; the indices come from the Draco data, so `indices` is dropped
    auto meshes = doc.find("meshes");
    auto accessors = doc.find("accessors");
    if (meshes != doc.end() && meshes->is_array() && accessors != doc.end() &&
        accessors->is_array())
        for (nlohmann::json &mesh : *meshes) {
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
                continue;
            for (nlohmann::json &prim : mesh["primitives"]) {
                if (!prim.is_object() || !prim.contains("extensions") ||
                    !prim["extensions"].is_object() || !prim["extensions"].contains(kDraco) ||
                    !prim.contains("indices") || !prim["indices"].is_number_unsigned())
                    continue;
                size_t index = prim["indices"].get<size_t>();
                if (index < accessors->size() && (*accessors)[index].is_object() &&
                    !(*accessors)[index].contains("bufferView")) {
                    prim.erase("indices");
                    changed = true;
                }
            }
        }
    if (!changed) return {};
    std::string text = doc.dump();
    if (!binary) {
        bytes.assign(text.begin(), text.end());
        return patched;
    }
    // A .glb: the JSON chunk (padded with spaces to 4 bytes) replaced, the rest kept
    while (text.size() % 4 != 0) text.push_back(' ');
    std::vector<unsigned char> out(bytes.begin(), bytes.begin() + 12);
    uint32_t length = static_cast<uint32_t>(text.size());
    out.insert(out.end(), reinterpret_cast<unsigned char *>(&length),
               reinterpret_cast<unsigned char *>(&length) + 4);
    out.insert(out.end(), bytes.begin() + 16, bytes.begin() + 20);  // chunk type "JSON"
    out.insert(out.end(), text.begin(), text.end());
    out.insert(out.end(), bytes.begin() + static_cast<long>(20 + json.size()), bytes.end());
    uint32_t total = static_cast<uint32_t>(out.size());
    std::memcpy(out.data() + 8, &total, 4);
    bytes = std::move(out);
    return patched;
}

void decodeMeshoptViews(tinygltf::Model &model, const std::vector<size_t> &fallbacks,
                        const SourceLoc &loc) {
    for (size_t b : fallbacks)
        if (b < model.buffers.size()) {
            model.buffers[b].data.clear();
            model.buffers[b].uri.clear();
        }
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        auto found = model.bufferViews[v].extensions.find(kMeshopt);
        if (found == model.bufferViews[v].extensions.end()) continue;
        const tinygltf::Value &ext = found->second;
        std::string what = jsonPath("bufferViews", v) + ".extensions." + kMeshopt;
        size_t buffer = member(ext, "buffer", what, loc);
        size_t offset = member(ext, "byteOffset", what, loc, 0);
        size_t length = member(ext, "byteLength", what, loc);
        size_t stride = member(ext, "byteStride", what, loc);
        size_t count = member(ext, "count", what, loc);
        std::string mode = stringMember(ext, "mode", "");
        std::string filter = stringMember(ext, "filter", "NONE");
        if (buffer >= model.buffers.size())
            throw ParseError(
                loc, what + ".buffer: buffer " + std::to_string(buffer) + " does not exist");
        const std::vector<unsigned char> &src = model.buffers[buffer].data;
        if (offset > src.size() || length > src.size() - offset)
            throw ParseError(loc, what + ": bytes " + std::to_string(offset) + "+" +
                                      std::to_string(length) + " lie outside buffer " +
                                      std::to_string(buffer) + " of " + std::to_string(src.size()) +
                                      " bytes");
        bool attributes = mode == "ATTRIBUTES", triangles = mode == "TRIANGLES",
             indices = mode == "INDICES";
        if (!attributes && !triangles && !indices)
            throw ParseError(
                loc, what + ".mode: '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
        if (attributes ? (stride == 0 || stride % 4 != 0 || stride > 256)
                       : (stride != 2 && stride != 4))
            throw ParseError(loc, what + ".byteStride: " + std::to_string(stride) +
                                      " is not allowed for mode " + mode);
        if (triangles && count % 3 != 0)
            throw ParseError(loc, what + ".count: " + std::to_string(count) +
                                      " is not a multiple of 3 for TRIANGLES");
        if (count > kMaxMeshoptViewBytes / stride)
            throw ParseError(loc, what + ": " + std::to_string(count) + " x " +
                                      std::to_string(stride) + " bytes decoded is more than " +
                                      std::to_string(kMaxMeshoptViewBytes));
        if (uint64_t least = meshoptMinBytes(mode, count, stride); length < least)
            throw ParseError(loc, what + ": count " + std::to_string(count) + " of " +
                                      std::to_string(stride) + "-byte elements (mode " + mode +
                                      ") needs at least " + std::to_string(least) +
                                      " compressed bytes, but byteLength is " +
                                      std::to_string(length) + " (corrupt or truncated)");
        std::vector<unsigned char> out(count * stride);
        const unsigned char *data = src.data() + offset;
        int rc = attributes  ? meshopt_decodeVertexBuffer(out.data(), count, stride, data, length)
                 : triangles ? meshopt_decodeIndexBuffer(out.data(), count, stride, data, length)
                             : meshopt_decodeIndexSequence(out.data(), count, stride, data, length);
        if (rc != 0)
            throw ParseError(loc, what +
                                      ": the compressed data does not decode (meshoptimizer "
                                      "error " +
                                      std::to_string(rc) + ")");
        if (filter != "NONE") {
            if (!attributes)
                throw ParseError(loc, what + ".filter: " + filter + " needs mode ATTRIBUTES");
            if (filter == "OCTAHEDRAL" && (stride == 4 || stride == 8))
                meshopt_decodeFilterOct(out.data(), count, stride);
            else if (filter == "QUATERNION" && stride == 8)
                meshopt_decodeFilterQuat(out.data(), count, stride);
            else if (filter == "EXPONENTIAL")
                meshopt_decodeFilterExp(out.data(), count, stride);
            else
                throw ParseError(loc, what + ".filter: '" + filter + "' with byteStride " +
                                          std::to_string(stride) + " is not supported");
        }
        tinygltf::Buffer decoded;
        decoded.name = what;
        decoded.data = std::move(out);
        model.buffers.push_back(std::move(decoded));
        tinygltf::BufferView &view = model.bufferViews[v];
        view.buffer = static_cast<int>(model.buffers.size() - 1);
        view.byteOffset = 0;
        view.byteLength = count * stride;
    }
}

// Draco

struct DracoPrimitive::Impl {
    std::unique_ptr<draco::Mesh> mesh;
    std::map<std::string, int> ids;  ///< attribute name -> Draco unique id
    const ImportContext *ctx = nullptr;
    std::string path;
    std::map<std::string, int> accessors;  ///< attribute name -> accessor
};

DracoPrimitive::DracoPrimitive(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DracoPrimitive::~DracoPrimitive() = default;

std::unique_ptr<DracoPrimitive> DracoPrimitive::decode(const ImportContext &ctx,
                                                       const tinygltf::Primitive &prim,
                                                       const std::string &path) {
    auto found = prim.extensions.find(kDraco);
    if (found == prim.extensions.end()) return nullptr;
    const tinygltf::Value &ext = found->second;
    std::string what = path + ".extensions." + kDraco;
    if (!ext.Has("bufferView") || !ext.Get("bufferView").IsNumber())
        ctx.fail(what + ": needs a bufferView");
    double view = ext.Get("bufferView").GetNumberAsDouble();
    if (!(view >= 0 && view < static_cast<double>(ctx.model.bufferViews.size())) ||
        view != std::floor(view))
        ctx.fail(what + ".bufferView: bufferView " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView &bv = ctx.model.bufferViews[static_cast<size_t>(view)];
    if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= ctx.model.buffers.size())
        ctx.fail(what + ": the buffer of its bufferView does not exist");
    const std::vector<unsigned char> &data = ctx.model.buffers[static_cast<size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset)
        ctx.fail(what + ": its bufferView lies outside its buffer");

    auto impl = std::make_unique<Impl>();
    impl->ctx = &ctx;
    impl->path = what;
    const tinygltf::Value &attrs = ext.Get("attributes");
    if (!attrs.IsObject()) ctx.fail(what + ": needs an attributes object");
    for (const std::string &name : attrs.Keys()) {
        const tinygltf::Value &id = attrs.Get(name);
        double d = id.IsNumber() ? id.GetNumberAsDouble() : -1;
        if (!(d >= 0 && d < 1e9) || d != std::floor(d))
            ctx.fail(what + ".attributes." + name + ": needs a Draco attribute id");
        auto acc = prim.attributes.find(name);
        if (acc == prim.attributes.end())
            ctx.fail(what + ".attributes." + name + ": the primitive has no such attribute");
        impl->ids[name] = static_cast<int>(d);
        impl->accessors[name] = acc->second;
    }

    const unsigned char *compressed = data.data() + bv.byteOffset;
    if (std::string problem = dracoDeclaredProblem(compressed, bv.byteLength); !problem.empty())
        ctx.fail(what + ": its data (" + jsonPath("bufferViews", static_cast<size_t>(view)) + ") " +
                 problem);
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char *>(compressed), bv.byteLength);
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok())
        ctx.fail(what + ": the compressed data does not decode (Draco: " +
                 result.status().error_msg_string() + ")");
    impl->mesh = std::move(result).value();
    if (!impl->mesh) ctx.fail(what + ": the compressed data does not decode");
    const draco::Mesh &mesh = *impl->mesh;
    if (mesh.num_points() > kMaxDracoElements || mesh.num_faces() > kMaxDracoElements)
        ctx.fail(what + ": " + std::to_string(mesh.num_points()) + " vertices and " +
                 std::to_string(mesh.num_faces()) + " triangles, more than " +
                 std::to_string(kMaxDracoElements));
    for (const auto &[name, id] : impl->ids) {
        const draco::PointAttribute *a = mesh.GetAttributeByUniqueId(static_cast<uint32_t>(id));
        if (!a)
            ctx.fail(what + ".attributes." + name + ": the compressed data has no attribute " +
                     std::to_string(id));
        int accessor = impl->accessors[name];
        if (accessor >= 0 && static_cast<size_t>(accessor) < ctx.model.accessors.size() &&
            ctx.model.accessors[static_cast<size_t>(accessor)].count != mesh.num_points())
            ctx.fail(what + ".attributes." + name + ": decodes to " +
                     std::to_string(mesh.num_points()) + " vertices, but " +
                     jsonPath("accessors", static_cast<size_t>(accessor)) + " has count " +
                     std::to_string(ctx.model.accessors[static_cast<size_t>(accessor)].count));
    }
    return std::unique_ptr<DracoPrimitive>(new DracoPrimitive(std::move(impl)));
}

bool DracoPrimitive::has(const std::string &name) const { return impl_->ids.count(name) > 0; }

size_t DracoPrimitive::vertexCount() const { return impl_->mesh->num_points(); }

FloatArray DracoPrimitive::floats(const std::string &name, int components) const {
    const draco::Mesh &mesh = *impl_->mesh;
    const draco::PointAttribute *a =
        mesh.GetAttributeByUniqueId(static_cast<uint32_t>(impl_->ids.at(name)));
    // glTF's `normalized` decides when Draco kept integers without its own flag
    const tinygltf::Accessor &acc =
        impl_->ctx->model.accessors[static_cast<size_t>(impl_->accessors.at(name))];
    double scale = 1;
    if (acc.normalized && !a->normalized()) {
        switch (a->data_type()) {
            case draco::DT_UINT8:
                scale = 1 / 255.0;
                break;
            case draco::DT_UINT16:
                scale = 1 / 65535.0;
                break;
            case draco::DT_INT8:
                scale = 1 / 127.0;
                break;
            case draco::DT_INT16:
                scale = 1 / 32767.0;
                break;
            default:
                break;
        }
    }
    FloatArray out;
    out.count = mesh.num_points();
    out.components = components;
    out.values.assign(out.count * static_cast<size_t>(components), 0.0f);
    for (uint32_t i = 0; i < mesh.num_points(); ++i) {
        float *dst = out.values.data() + size_t(i) * static_cast<size_t>(components);
        if (!a->ConvertValue<float>(a->mapped_index(draco::PointIndex(i)),
                                    static_cast<int8_t>(components), dst))
            impl_->ctx->fail(impl_->path + ".attributes." + name +
                             ": the decoded values do not convert to numbers");
        if (scale != 1)
            for (int c = 0; c < components; ++c)
                dst[c] = std::max(static_cast<float>(dst[c] * scale), -1.0f);
    }
    return out;
}

std::vector<uint32_t> DracoPrimitive::indices() const {
    const draco::Mesh &mesh = *impl_->mesh;
    std::vector<uint32_t> out;
    out.reserve(size_t(mesh.num_faces()) * 3);
    for (uint32_t f = 0; f < mesh.num_faces(); ++f)
        for (const draco::PointIndex &p : mesh.face(draco::FaceIndex(f))) out.push_back(p.value());
    return out;
}

}  // namespace rt::gltf::detail
