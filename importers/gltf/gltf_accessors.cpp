// SPDX-License-Identifier: MIT
// Bounds-checked reading of glTF accessors: strides, offsets, normalized integers and sparse data.
#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <span>

#include "importers/gltf/gltf_internal.h"

namespace rt::gltf::detail {

// glTF binary data is little-endian; the reads below copy bytes as they are.
static_assert(std::endian::native == std::endian::little, "the glTF reader assumes little-endian");

std::string jsonPath(const char *array, size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

namespace {

using Bytes = std::span<const unsigned char>;

/// Most elements an accessor without bufferView (zeros plus sparse values) may have: this many,
/// or as many as the file's buffers hold bytes (such an accessor mirrors a real one, a morph
/// target of a mesh whose vertices take at least that much), so a 650-byte file cannot ask
/// for gigabytes of zeros.
constexpr size_t kMinZeroInitialisedLimit = size_t(1) << 16;

size_t componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        case TINYGLTF_TYPE_MAT2:
            return 4;
        case TINYGLTF_TYPE_MAT3:
            return 9;
        case TINYGLTF_TYPE_MAT4:
            return 16;
        default:
            return 0;
    }
}

const char *typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return "SCALAR";
        case TINYGLTF_TYPE_VEC2:
            return "VEC2";
        case TINYGLTF_TYPE_VEC3:
            return "VEC3";
        case TINYGLTF_TYPE_VEC4:
            return "VEC4";
        case TINYGLTF_TYPE_MAT2:
            return "MAT2";
        case TINYGLTF_TYPE_MAT3:
            return "MAT3";
        case TINYGLTF_TYPE_MAT4:
            return "MAT4";
        default:
            return "unknown type";
    }
}

/// The bytes of bufferView `viewIndex`, after checking that the view lies inside its buffer.
Bytes viewBytes(const ImportContext &ctx, int viewIndex, const std::string &what) {
    const tinygltf::Model &model = ctx.model;
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size())
        ctx.fail(what + ": bufferView " + std::to_string(viewIndex) +
                 " does not exist (the file has " + std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView &view = model.bufferViews[static_cast<size_t>(viewIndex)];
    std::string viewPath = jsonPath("bufferViews", static_cast<size_t>(viewIndex));
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
        ctx.fail(viewPath + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char> &data = model.buffers[static_cast<size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        ctx.fail(viewPath + ": bytes " + std::to_string(view.byteOffset) + ".." +
                 std::to_string(view.byteOffset) + "+" + std::to_string(view.byteLength) +
                 " lie outside buffer " + std::to_string(view.buffer) + " of " +
                 std::to_string(data.size()) + " bytes");
    return Bytes(data.data() + view.byteOffset, view.byteLength);
}

/// Start of `count` elements of `elementSize` bytes, `stride` apart, from `offset` in `view`;
/// fails unless all of them lie inside the view.
const unsigned char *locate(const ImportContext &ctx, Bytes view, size_t offset, size_t count,
                            size_t elementSize, size_t stride, const std::string &what) {
    if (count == 0) return view.data();
    // Written so that nothing overflows: (count - 1) * stride is only formed once it is known
    // to be at most view.size()
    bool fits = offset <= view.size() && elementSize <= view.size() - offset &&
                (count - 1) <= (view.size() - offset - elementSize) / stride;
    if (!fits)
        ctx.fail(what + ": " + std::to_string(count) + " elements of " +
                 std::to_string(elementSize) + " bytes (stride " + std::to_string(stride) +
                 ") from byte " + std::to_string(offset) + " run past the end of its bufferView (" +
                 std::to_string(view.size()) + " bytes)");
    return view.data() + offset;
}

template <typename T>
T load(const unsigned char *p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

/// Integer or float component to float, as glTF's `normalized` says (spec 3.11: signed values
/// map to max(c / MAX, -1)).
struct NormalizedToFloat {
    float operator()(float v) const { return v; }
    float operator()(uint8_t v) const { return v / 255.0f; }
    float operator()(uint16_t v) const { return v / 65535.0f; }
    float operator()(uint32_t v) const { return static_cast<float>(v / 4294967295.0); }
    float operator()(int8_t v) const { return std::max(v / 127.0f, -1.0f); }
    float operator()(int16_t v) const { return std::max(v / 32767.0f, -1.0f); }
};
struct PlainToFloat {
    template <typename T>
    float operator()(T v) const {
        return static_cast<float>(v);
    }
};
struct ToIndex {
    template <typename T>
    uint32_t operator()(T v) const {
        return static_cast<uint32_t>(v);
    }
};

/// Converts `count` elements of `comps` components of type T, `stride` bytes apart.
template <typename T, typename Out, typename Convert>
void decodeRun(const unsigned char *src, size_t count, int comps, size_t stride, Out *out,
               Convert convert) {
    for (size_t i = 0; i < count; ++i) {
        const unsigned char *p = src + i * stride;
        for (int c = 0; c < comps; ++c) out[i * comps + c] = convert(load<T>(p + c * sizeof(T)));
    }
}

/// The component-type switch, taken once per run of elements rather than per value.
template <typename Out, typename Convert>
void decode(int componentType, const unsigned char *src, size_t count, int comps, size_t stride,
            Out *out, Convert convert) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            decodeRun<int8_t>(src, count, comps, stride, out, convert);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            decodeRun<uint8_t>(src, count, comps, stride, out, convert);
            break;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            decodeRun<int16_t>(src, count, comps, stride, out, convert);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            decodeRun<uint16_t>(src, count, comps, stride, out, convert);
            break;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            decodeRun<uint32_t>(src, count, comps, stride, out, convert);
            break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            decodeRun<float>(src, count, comps, stride, out, convert);
            break;
        default:
            break;  // rejected by readAccessor
    }
}

/// Reads a whole accessor into `count * comps` values: the dense part from its bufferView (zeros
/// without one), then the sparse substitutions.
template <typename Out, typename Convert>
std::vector<Out> readAccessor(const ImportContext &ctx, const tinygltf::Accessor &acc, int comps,
                              const std::string &what, Convert convert) {
    size_t compSize = componentSize(acc.componentType);
    size_t elementSize = compSize * static_cast<size_t>(comps);
    // A glTF buffer holds less than 2^32 bytes (the GLB limit), so no real accessor has more
    // elements; the check also keeps vertex numbers within uint32_t
    size_t maxCount = std::numeric_limits<uint32_t>::max();
    if (acc.count > maxCount)
        ctx.fail(what + ": count " + std::to_string(acc.count) + " is too large");

    std::vector<Out> out;
    if (acc.bufferView >= 0) {
        Bytes view = viewBytes(ctx, acc.bufferView, what);
        const tinygltf::BufferView &bv = ctx.model.bufferViews[static_cast<size_t>(acc.bufferView)];
        size_t stride = bv.byteStride != 0 ? bv.byteStride : elementSize;
        if (stride < elementSize || stride % compSize != 0)
            ctx.fail(what + ": byteStride " + std::to_string(bv.byteStride) + " of " +
                     jsonPath("bufferViews", static_cast<size_t>(acc.bufferView)) +
                     " does not fit elements of " + std::to_string(elementSize) + " bytes");
        const unsigned char *src =
            locate(ctx, view, acc.byteOffset, acc.count, elementSize, stride, what);
        out.resize(acc.count * static_cast<size_t>(comps));
        decode(acc.componentType, src, acc.count, comps, stride, out.data(), convert);
    } else {
        // glTF 3.6.2.3: an accessor without bufferView starts as zeros. No data bounds its
        // count, so a limit keeps a corrupt count from asking for gigabytes
        size_t bufferBytes = 0;
        for (const tinygltf::Buffer &b : ctx.model.buffers) bufferBytes += b.data.size();
        size_t limit = std::max(kMinZeroInitialisedLimit, bufferBytes);
        if (acc.count > limit)
            ctx.fail(what + ": count " + std::to_string(acc.count) +
                     " without a bufferView is more than " + std::to_string(limit) +
                     " elements (the larger of " + std::to_string(kMinZeroInitialisedLimit) +
                     " and the bytes in the file's buffers)");
        out.assign(acc.count * static_cast<size_t>(comps), Out(0));
    }

    if (!acc.sparse.isSparse) return out;
    const auto &sp = acc.sparse;
    std::string sparsePath = what + ".sparse";
    if (sp.count < 0 || static_cast<size_t>(sp.count) > acc.count)
        ctx.fail(sparsePath + ": count " + std::to_string(sp.count) + " is not in 0.." +
                 std::to_string(acc.count));
    if (sp.indices.byteOffset < 0 || sp.values.byteOffset < 0)
        ctx.fail(sparsePath + ": negative byteOffset");
    size_t n = static_cast<size_t>(sp.count);
    int indexType = sp.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(sparsePath + ".indices: componentType " + std::to_string(indexType) +
                 " is not an unsigned integer type");
    size_t indexSize = componentSize(indexType);
    const unsigned char *indexSrc =
        locate(ctx, viewBytes(ctx, sp.indices.bufferView, sparsePath + ".indices"),
               static_cast<size_t>(sp.indices.byteOffset), n, indexSize, indexSize,
               sparsePath + ".indices");
    const unsigned char *valueSrc =
        locate(ctx, viewBytes(ctx, sp.values.bufferView, sparsePath + ".values"),
               static_cast<size_t>(sp.values.byteOffset), n, elementSize, elementSize,
               sparsePath + ".values");
    std::vector<uint32_t> targets(n);
    decode(indexType, indexSrc, n, 1, indexSize, targets.data(), ToIndex{});
    for (size_t k = 0; k < n; ++k) {
        if (targets[k] >= acc.count)
            ctx.fail(sparsePath + ".indices[" + std::to_string(k) + "]: element " +
                     std::to_string(targets[k]) + " out of range for " + std::to_string(acc.count) +
                     " elements");
        decode(acc.componentType, valueSrc + k * elementSize, 1, comps, elementSize,
               out.data() + static_cast<size_t>(targets[k]) * static_cast<size_t>(comps), convert);
    }
    return out;
}

const tinygltf::Accessor &accessorAt(const ImportContext &ctx, int index, const std::string &what) {
    if (index < 0 || static_cast<size_t>(index) >= ctx.model.accessors.size())
        ctx.fail(what + ": accessor " + std::to_string(index) + " does not exist (the file has " +
                 std::to_string(ctx.model.accessors.size()) + ")");
    return ctx.model.accessors[static_cast<size_t>(index)];
}

}  // namespace

FloatArray readFloats(const ImportContext &ctx, int index, int type, const std::string &what) {
    const tinygltf::Accessor &acc = accessorAt(ctx, index, what);
    std::string path = what + " (" + jsonPath("accessors", static_cast<size_t>(index)) + ")";
    if (acc.type != type)
        ctx.fail(path + ": type " + typeName(acc.type) + ", expected " + typeName(type));
    if (componentSize(acc.componentType) == 0)
        ctx.fail(path + ": invalid componentType " + std::to_string(acc.componentType));
    FloatArray result;
    result.count = acc.count;
    result.components = componentCount(type);
    if (acc.normalized && acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        result.values = readAccessor<float>(ctx, acc, result.components, path, NormalizedToFloat{});
    else
        result.values = readAccessor<float>(ctx, acc, result.components, path, PlainToFloat{});
    return result;
}

std::vector<uint32_t> readIndices(const ImportContext &ctx, int index, const std::string &what) {
    const tinygltf::Accessor &acc = accessorAt(ctx, index, what);
    std::string path = what + " (" + jsonPath("accessors", static_cast<size_t>(index)) + ")";
    if (acc.type != TINYGLTF_TYPE_SCALAR)
        ctx.fail(path + ": indices must be SCALAR, not " + typeName(acc.type));
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(path + ": indices must be unsigned integers (componentType " +
                 std::to_string(acc.componentType) + ")");
    return readAccessor<uint32_t>(ctx, acc, 1, path, ToIndex{});
}

void checkAttributeType(const ImportContext &ctx, int index, const std::string &attribute,
                        bool morphTarget, const std::string &what) {
    const tinygltf::Accessor &acc = accessorAt(ctx, index, what);
    int t = acc.componentType;
    bool n = acc.normalized;
    bool isFloat = t == TINYGLTF_COMPONENT_TYPE_FLOAT;
    bool int8or16 = t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_SHORT;
    bool uint8or16 =
        t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    auto startsWith = [&](const char *prefix) { return attribute.rfind(prefix, 0) == 0; };
    bool ok = true;
    const char *allowed = "";
    // glTF 3.7.2.1 and the KHR_mesh_quantization table: (unsigned) byte and short, normalized
    // or not, for positions and texture coordinates; signed normalized for normals and tangents
    // (and for every morph delta but the positions')
    if (attribute == "POSITION" || startsWith("TEXCOORD_")) {
        ok = isFloat || int8or16 || (uint8or16 && !morphTarget);
        allowed = morphTarget ? "float or (normalized) byte/short"
                              : "float or (normalized) byte/short, signed or unsigned";
    } else if (attribute == "NORMAL" || attribute == "TANGENT") {
        ok = isFloat || (int8or16 && n);
        allowed = "float or normalized signed byte/short";
    } else if (startsWith("COLOR_")) {
        ok = isFloat || (uint8or16 && n);
        allowed = "float or normalized unsigned byte/short";
    } else if (startsWith("JOINTS_")) {
        ok = uint8or16 && !n;
        allowed = "unsigned byte/short";
    } else if (startsWith("WEIGHTS_")) {
        ok = isFloat || (uint8or16 && n);
        allowed = "float or normalized unsigned byte/short";
    }
    if (!ok)
        ctx.fail(what + " (" + jsonPath("accessors", static_cast<size_t>(index)) +
                 "): componentType " + std::to_string(t) + (n ? " normalized" : "") +
                 " is not allowed for " + attribute + " (" + allowed + ")");
}

}  // namespace rt::gltf::detail
