// SPDX-License-Identifier: MIT
// glTF metallic-roughness materials mapped to the IR's classic POV-Ray material, and textures.
//
// The mapping itself (every formula, clearcoat, sheen, specular, volume included) lives in
// core/materials/pbr_material.cpp: this file reads the glTF material into an rt::PbrMaterial
// and gives the classic ir::Material for it.
//
// Untextured materials are mapped once, exactly. A material with a metallicRoughness,
// emissive, transmission, normal or occlusion texture, or whose alpha varies (MASK or BLEND
// with a base colour texture, or COLOR_0 on the primitive), also carries its PbrMaterial
// (Material::texel) and the renderer evaluates the mapping at every hit from the textures'
// values there. Its constant fields hold the mapping of the textures' MEANS (B and G of
// metallicRoughness, the sRGB-decoded emissive RGB, transmission R, occlusion R, base colour
// A for BLEND), and for MASK transmit = the fraction of base colour texels cut out: the POV-Ray
// export writes these, the best constant approximation (it cannot express per-texel roughness,
// metalness, emission, alpha, normal or occlusion maps).
//
//   alphaMode MASK   untextured: alpha < alphaCutoff hides the primitive (a note); textured:
//                    per texel, cut-out texels let rays and shadow rays straight through
//   normalTexture    tangent space (TANGENT, else generated, gltf_tangents.cpp), per hit
//   occlusionTexture 1 + strength (R - 1) scales the ambient term (glTF: indirect light only)
//   No material      glTF's default material: white, metallic 1, roughness 1
//   doubleSided      ignored (both renderers intersect both sides)
// Extensions mapped: KHR_materials_emissive_strength, _transmission, _ior, _volume (thickness,
// attenuation), _unlit, _clearcoat, _sheen, _specular, their textures per texel like the
// others (clearcoatNormalTexture is not read, a warning; sheenRoughnessTexture has no use in
// the mapping). Any other KHR_materials_* extension the file uses gets one warning.
// Materials are deduplicated through Scene::addMaterial.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>

#include "core/image/image_limits.h"
#include "core/materials/pbr_material.h"
#include "importers/gltf/gltf_internal.h"

namespace rt::gltf::detail {

namespace {

/// sRGB transfer function decoded to linear (IEC 61966-2-1).
double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

const std::array<float, 256> &srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) t[static_cast<size_t>(i)] = float(srgbToLinear(i / 255.0));
        return t;
    }();
    return table;
}

}  // namespace

/// A decoded image: `components` channels of `bits` (8 or 16) per pixel, rows top first.
struct MaterialMapper::DecodedImage {
    int width = 0, height = 0, components = 0, bits = 8;
    std::vector<unsigned char> data;
    std::string label;  ///< "images[3] ('lamp.png')", for messages

    /// Channel c (0..3 = R, G, B, A) of pixel p in [0,1], with grey and missing alpha expanded.
    float channel(size_t p, int c) const {
        int src = c;
        if (components <= 2)
            src = c == 3 ? (components == 2 ? 1 : -1) : 0;
        else if (c >= components)
            src = -1;
        if (src < 0) return 1.0f;
        size_t i = p * static_cast<size_t>(components) + static_cast<size_t>(src);
        if (bits == 16) {
            uint16_t v;
            std::memcpy(&v, data.data() + 2 * i, 2);
            return v / 65535.0f;
        }
        return data[i] / 255.0f;
    }
    /// Channel c of pixel p decoded from sRGB to linear (for colour channels).
    float linear(size_t p, int c) const {
        if (bits == 8 && components > 2 && c < components)
            return srgbTable()[data[p * static_cast<size_t>(components) + static_cast<size_t>(c)]];
        return static_cast<float>(srgbToLinear(channel(p, c)));
    }
    size_t pixels() const { return static_cast<size_t>(width) * static_cast<size_t>(height); }
};

namespace {

// glTF sampler wrap modes (glTF 2.0 section 5.26)
constexpr int kWrapRepeat = 10497;
constexpr int kWrapClamp = 33071;
constexpr int kWrapMirror = 33648;
// glTF sampler filters: NEAREST, LINEAR, and the four *_MIPMAP_* minification filters
constexpr int kFilterNearest = 9728;
constexpr int kFilterLinear = 9729;
constexpr int kMinFilterFirstMip = 9984;  // NEAREST_MIPMAP_NEAREST
constexpr int kMinFilterLastMip = 9987;   // LINEAR_MIPMAP_LINEAR

/// The material extensions the mapping reads (pbr_material.cpp); any other KHR_materials_*
/// extension a file uses is warned about once.
constexpr std::array<std::string_view, 8> kMappedExtensions = {"KHR_materials_emissive_strength",
                                                               "KHR_materials_transmission",
                                                               "KHR_materials_ior",
                                                               "KHR_materials_volume",
                                                               "KHR_materials_unlit",
                                                               "KHR_materials_clearcoat",
                                                               "KHR_materials_sheen",
                                                               "KHR_materials_specular"};

const tinygltf::Value *extension(const tinygltf::ExtensionMap &exts, const char *name) {
    auto it = exts.find(name);
    return it == exts.end() ? nullptr : &it->second;
}

/// A number member of an extension object, or `fallback` when it is absent or not a number.
double number(const tinygltf::Value *ext, const char *key, double fallback) {
    if (!ext || !ext->Has(key)) return fallback;
    const tinygltf::Value &v = ext->Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

/// The `index` of a textureInfo member of an extension object, or -1.
int textureRef(const tinygltf::Value *ext, const char *key) {
    if (!ext || !ext->Has(key)) return -1;
    const tinygltf::Value &info = ext->Get(key);
    double i = number(&info, "index", -1);
    // A non-integral or absurd index counts as absent (it would also fail the range check)
    if (!(i >= 0 && i < 1e9) || i != std::floor(i)) return -1;
    return static_cast<int>(i);
}

Rgb rgbOf(const std::vector<double> &v, Rgb fallback) {
    return v.size() >= 3 ? Rgb(v[0], v[1], v[2]) : fallback;
}

/// A 3-number array member of an extension object, or `fallback`.
Rgb numbers3(const tinygltf::Value *ext, const char *key, Rgb fallback) {
    if (!ext || !ext->Has(key)) return fallback;
    const tinygltf::Value &v = ext->Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) return fallback;
    Rgb out;
    for (int c = 0; c < 3; ++c) {
        const tinygltf::Value &x = v.Get(c);
        if (!x.IsNumber() || !std::isfinite(x.GetNumberAsDouble())) return fallback;
        out[c] = x.GetNumberAsDouble();
    }
    return out;
}

}  // namespace

MaterialMapper::MaterialMapper(const ImportContext &ctx, ir::Scene &scene)
    : ctx_(ctx), scene_(scene), mapped_(ctx.model.materials.size() + 1) {
    // One warning per file for each material extension the mapping cannot express
    for (const std::string &ext : ctx.model.extensionsUsed)
        if (ext.rfind("KHR_materials_", 0) == 0 &&
            std::find(kMappedExtensions.begin(), kMappedExtensions.end(), ext) ==
                kMappedExtensions.end())
            ctx.warning(ext + " (used by " + ctx.loc.fileName() +
                        ") is not mapped to the classic "
                        "material; materials render without it");
}

MaterialMapper::~MaterialMapper() = default;

const MaterialMapper::Mapped &MaterialMapper::mapped(int index, const std::string &primitivePath) {
    if (index < -1 || index >= static_cast<int>(ctx_.model.materials.size()))
        ctx_.fail(primitivePath + ": material " + std::to_string(index) +
                  " does not exist (the file has " + std::to_string(ctx_.model.materials.size()) +
                  ")");
    Mapped &slot = mapped_[static_cast<size_t>(index + 1)];
    if (!slot.done) {
        slot.material = map(index, slot.hidden);
        slot.done = true;
    }
    return slot;
}

int MaterialMapper::tangentTexCoord(int index, const std::string &primitivePath) {
    const Mapped &slot = mapped(index, primitivePath);
    if (slot.hidden || !slot.material.texel.pbr) return -1;
    const ir::TextureRef &normal = slot.material.texel.pbr->normalTexture;
    return normal.valid() ? normal.texCoord : -1;
}

std::optional<int> MaterialMapper::irMaterial(int index, const ir::Mesh &mesh,
                                              const std::string &primitivePath) {
    const Mapped &slot = mapped(index, primitivePath);
    if (slot.hidden) return std::nullopt;
    ir::Material mat = slot.material;
    std::string matPath = index < 0 ? std::string("the default material")
                                    : jsonPath("materials", static_cast<size_t>(index));
    // Textures whose coordinate set this primitive lacks are left out
    auto usable = [&](ir::TextureRef &ref, const char *what, const char *instead) {
        if (!ref.valid() || !(ref.texCoord == 1 ? mesh.uvs1 : mesh.uvs).empty()) return false;
        ctx_.warning(primitivePath + ": no TEXCOORD_" + std::to_string(ref.texCoord) + " for the " +
                     what + " texture of " + matPath + "; " + instead);
        ref = {};
        return true;
    };
    usable(mat.baseColorTexture, "base colour", "texture ignored");
    if (mat.texel.pbr) {
        PbrMaterial p = *mat.texel.pbr;
        const char *mean = "its mean used";
        bool changed = usable(p.metallicRoughnessTexture, "metallic-roughness", mean);
        changed |= usable(p.normalTexture, "normal", "texture ignored");
        changed |= usable(p.occlusionTexture, "occlusion", mean);
        changed |= usable(p.emissiveTexture, "emissive", mean);
        changed |= usable(p.transmissionTexture, "transmission", mean);
        changed |= usable(p.clearcoatTexture, "clearcoat", mean);
        changed |= usable(p.clearcoatRoughnessTexture, "clearcoat roughness", mean);
        changed |= usable(p.sheenColorTexture, "sheen colour", mean);
        changed |= usable(p.specularTexture, "specular", mean);
        changed |= usable(p.specularColorTexture, "specular colour", mean);
        changed |= usable(p.thicknessTexture, "thickness", mean);
        // Per-texel evaluation only where something varies over the surface
        bool alphaVaries = p.alphaMode != PbrMaterial::AlphaMode::Opaque &&
                           (mat.baseColorTexture.valid() || !mesh.colors.empty());
        if (!p.textured() && !alphaVaries)
            mat.texel = {};
        else if (changed)
            mat.texel.pbr = std::make_shared<const PbrMaterial>(p);
        // Without TANGENT the mesh builder generated them (tangentTexCoord)
    }
    return scene_.addMaterial(mat);
}

ir::Material MaterialMapper::map(int index, bool &hidden) {
    static const tinygltf::Material kDefaultMaterial;  // every property at its glTF default
    const tinygltf::Material &gm =
        index < 0 ? kDefaultMaterial : ctx_.model.materials[static_cast<size_t>(index)];
    std::string path = index < 0 ? std::string("the default material")
                                 : jsonPath("materials", static_cast<size_t>(index));
    if (!gm.name.empty()) path += " ('" + gm.name + "')";
    const tinygltf::PbrMetallicRoughness &pbr = gm.pbrMetallicRoughness;
    PbrMaterial p;

    // Factors
    if (pbr.baseColorFactor.size() != 4)
        ctx_.warning(path + ": baseColorFactor needs 4 numbers; white used");
    bool validBase = pbr.baseColorFactor.size() == 4;
    p.baseColor = validBase ? rgbOf(pbr.baseColorFactor, Rgb(1)) : Rgb(1);
    p.alpha = validBase ? pbr.baseColorFactor[3] : 1.0;
    p.metallic = clamp(pbr.metallicFactor, 0.0, 1.0);
    p.roughness = clamp(pbr.roughnessFactor, 0.0, 1.0);

    const tinygltf::Value *strengthExt =
        extension(gm.extensions, "KHR_materials_emissive_strength");
    double strength = number(strengthExt, "emissiveStrength", 1.0);
    p.emissive = rgbOf(gm.emissiveFactor, Rgb(0)) * std::max(strength, 0.0);

    const tinygltf::Value *transmissionExt = extension(gm.extensions, "KHR_materials_transmission");
    p.transmission = clamp(number(transmissionExt, "transmissionFactor", 0.0), 0.0, 1.0);

    if (const tinygltf::Value *iorExt = extension(gm.extensions, "KHR_materials_ior")) {
        double ior = number(iorExt, "ior", 1.5);
        if (ior == 0)
            ctx_.warning(path +
                         ": KHR_materials_ior ior 0 (legacy specular-glossiness mode) is "
                         "not supported; 1.5 used");
        else if (ior < 1)
            ctx_.warning(path + ": KHR_materials_ior ior " + std::to_string(ior) +
                         " is below 1; 1.5 used");
        else
            p.ior = ior;
    }
    const tinygltf::Value *volumeExt = extension(gm.extensions, "KHR_materials_volume");
    p.thickness = std::max(number(volumeExt, "thicknessFactor", 0.0), 0.0);
    p.attenuationColor = numbers3(volumeExt, "attenuationColor", Rgb(1));
    p.attenuationDistance = number(volumeExt, "attenuationDistance", 0.0);
    if (!(p.attenuationDistance > 0)) p.attenuationDistance = 0;
    p.unlit = extension(gm.extensions, "KHR_materials_unlit") != nullptr;

    const tinygltf::Value *coatExt = extension(gm.extensions, "KHR_materials_clearcoat");
    p.clearcoat = clamp(number(coatExt, "clearcoatFactor", 0.0), 0.0, 1.0);
    p.clearcoatRoughness = clamp(number(coatExt, "clearcoatRoughnessFactor", 0.0), 0.0, 1.0);
    const tinygltf::Value *sheenExt = extension(gm.extensions, "KHR_materials_sheen");
    p.sheenColor = numbers3(sheenExt, "sheenColorFactor", Rgb(0));
    p.sheenRoughness = clamp(number(sheenExt, "sheenRoughnessFactor", 0.0), 0.0, 1.0);
    const tinygltf::Value *specularExt = extension(gm.extensions, "KHR_materials_specular");
    p.specular = clamp(number(specularExt, "specularFactor", 1.0), 0.0, 1.0);
    p.specularColor = numbers3(specularExt, "specularColorFactor", Rgb(1));
    for (int c = 0; c < 3; ++c) p.specularColor[c] = std::max(p.specularColor[c], 0.0);
    // clearcoatNormalTexture has nothing to act on: the coat shares the base's normal
    if (textureRef(coatExt, "clearcoatNormalTexture") >= 0)
        ctx_.warning(path + ".extensions.KHR_materials_clearcoat.clearcoatNormalTexture" +
                     " is not read (the coat uses the base's normal)");

    if (gm.alphaMode == "BLEND")
        p.alphaMode = PbrMaterial::AlphaMode::Blend;
    else if (gm.alphaMode == "MASK")
        p.alphaMode = PbrMaterial::AlphaMode::Mask;
    else if (gm.alphaMode != "OPAQUE")
        ctx_.warning(path + ": unknown alphaMode '" + gm.alphaMode + "'; OPAQUE used");
    p.alphaCutoff = gm.alphaCutoff;

    // Texture slots, and the means the constant fields use
    PbrInputs mean = pbrFactors(p);
    ir::TextureRef base;
    if (pbr.baseColorTexture.index >= 0)
        base = textureInfo(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                           pbr.baseColorTexture.extensions,
                           path + ".pbrMetallicRoughness.baseColorTexture");
    double cutFraction = 0;  // MASK: the share of base colour texels cut out
    if (base.valid() && p.alphaMode != PbrMaterial::AlphaMode::Opaque) {
        const ir::Texture &img = *scene_.textures[static_cast<size_t>(base.texture)];
        double sumA = 0, cut = 0;
        size_t texels = img.rgba.size() / 4;
        for (size_t t = 0; t < texels; ++t) {
            double a = img.rgba[t * 4 + 3];
            sumA += a;
            cut += p.alpha * a < p.alphaCutoff;
        }
        if (texels > 0) {
            mean.alpha *= sumA / static_cast<double>(texels);
            cutFraction = cut / static_cast<double>(texels);
        }
    }
    const tinygltf::TextureInfo &mr = pbr.metallicRoughnessTexture;
    if (mr.index >= 0) {
        p.metallicRoughnessTexture =
            textureInfo(mr.index, mr.texCoord, mr.extensions,
                        path + ".pbrMetallicRoughness.metallicRoughnessTexture", false);
        // Linear data: B = metalness, G = roughness
        mean.metallic *= textureMean(p.metallicRoughnessTexture, 2);
        mean.roughness *= textureMean(p.metallicRoughnessTexture, 1);
    }
    if (gm.emissiveTexture.index >= 0 && !p.emissive.isBlack()) {
        p.emissiveTexture = textureInfo(gm.emissiveTexture.index, gm.emissiveTexture.texCoord,
                                        gm.emissiveTexture.extensions, path + ".emissiveTexture");
        for (int c = 0; c < 3; ++c) mean.emissive[c] *= textureMean(p.emissiveTexture, c);
    }
    int transmissionTex = textureRef(transmissionExt, "transmissionTexture");
    if (transmissionTex >= 0 && p.transmission > 0) {
        const tinygltf::Value &info = transmissionExt->Get("transmissionTexture");
        tinygltf::ExtensionMap infoExts;
        if (info.Has("extensions") && info.Get("extensions").IsObject())
            for (const std::string &key : info.Get("extensions").Keys())
                infoExts[key] = info.Get("extensions").Get(key);
        p.transmissionTexture =
            textureInfo(transmissionTex, static_cast<int>(number(&info, "texCoord", 0)), infoExts,
                        path + ".extensions.KHR_materials_transmission.transmissionTexture", false);
        mean.transmission *= textureMean(p.transmissionTexture, 0);
    }
    // The extensions' textures, read per texel like the others (their values multiply the
    // factors); a zero factor makes a texture moot
    struct ExtTexture {
        const tinygltf::Value *ext;
        const char *name, *key;
        ir::TextureRef PbrMaterial::*slot;
        bool srgb;
        bool needed;
    };
    for (const ExtTexture &e :
         {ExtTexture{coatExt, "KHR_materials_clearcoat", "clearcoatTexture",
                     &PbrMaterial::clearcoatTexture, false, p.clearcoat > 0},
          ExtTexture{coatExt, "KHR_materials_clearcoat", "clearcoatRoughnessTexture",
                     &PbrMaterial::clearcoatRoughnessTexture, false,
                     p.clearcoat > 0 && p.clearcoatRoughness > 0},
          ExtTexture{sheenExt, "KHR_materials_sheen", "sheenColorTexture",
                     &PbrMaterial::sheenColorTexture, true, !p.sheenColor.isBlack()},
          ExtTexture{sheenExt, "KHR_materials_sheen", "sheenRoughnessTexture",
                     &PbrMaterial::sheenRoughnessTexture, false, false},
          ExtTexture{specularExt, "KHR_materials_specular", "specularTexture",
                     &PbrMaterial::specularTexture, false, p.specular > 0},
          ExtTexture{specularExt, "KHR_materials_specular", "specularColorTexture",
                     &PbrMaterial::specularColorTexture, true,
                     p.specular > 0 && !p.specularColor.isBlack()},
          ExtTexture{volumeExt, "KHR_materials_volume", "thicknessTexture",
                     &PbrMaterial::thicknessTexture, false, p.thickness > 0}}) {
        int texture = textureRef(e.ext, e.key);
        if (texture < 0 || !e.needed) continue;  // sheen roughness: the mapping has no use for it
        const tinygltf::Value &info = e.ext->Get(e.key);
        tinygltf::ExtensionMap infoExts;
        if (info.Has("extensions") && info.Get("extensions").IsObject())
            for (const std::string &key : info.Get("extensions").Keys())
                infoExts[key] = info.Get("extensions").Get(key);
        p.*e.slot = textureInfo(texture, static_cast<int>(number(&info, "texCoord", 0)), infoExts,
                                path + ".extensions." + e.name + "." + e.key, e.srgb);
    }
    mean.clearcoat *= textureMean(p.clearcoatTexture, 0);
    mean.clearcoatRoughness *= textureMean(p.clearcoatRoughnessTexture, 1);
    for (int c = 0; c < 3; ++c) {
        mean.sheenColor[c] *= textureMean(p.sheenColorTexture, c);
        mean.specularColor[c] *= textureMean(p.specularColorTexture, c);
    }
    mean.specular *= textureMean(p.specularTexture, 3);
    mean.thickness *= textureMean(p.thicknessTexture, 1);

    if (gm.normalTexture.index >= 0 && gm.normalTexture.scale != 0) {
        p.normalTexture = textureInfo(gm.normalTexture.index, gm.normalTexture.texCoord,
                                      gm.normalTexture.extensions, path + ".normalTexture", false);
        p.normalScale = gm.normalTexture.scale;
    }
    if (gm.occlusionTexture.index >= 0 && gm.occlusionTexture.strength != 0) {
        p.occlusionTexture =
            textureInfo(gm.occlusionTexture.index, gm.occlusionTexture.texCoord,
                        gm.occlusionTexture.extensions, path + ".occlusionTexture", false);
        p.occlusionStrength = clamp(gm.occlusionTexture.strength, 0.0, 1.0);
        if (p.occlusionTexture.valid())
            mean.occlusion = 1 + p.occlusionStrength * (textureMean(p.occlusionTexture, 0) - 1);
    }

    ir::Material mat = classicMaterial(p, mean);
    mat.loc = ctx_.loc;
    mat.baseColorTexture = base;
    if (p.alphaMode == PbrMaterial::AlphaMode::Mask) {
        if (base.valid()) {
            mat.transmit = cutFraction;  // the constant approximation (export)
            mat.filter = std::min(mat.filter, 1 - mat.transmit);
        } else if (p.alpha < p.alphaCutoff) {
            hidden = true;
            ctx_.note(path + ": alphaMode MASK with alpha " + std::to_string(p.alpha) +
                      " below the cutoff " + std::to_string(p.alphaCutoff) +
                      "; its primitives are not rendered");
        }
    }
    // Kept for every material; irMaterial drops it where nothing varies per texel
    mat.texel.pbr = std::make_shared<const PbrMaterial>(p);
    return mat;
}

double MaterialMapper::textureMean(const ir::TextureRef &ref, int channel) const {
    if (!ref.valid()) return 1;
    return ir::textureMean(
        *scene_.textures[static_cast<size_t>(ref.texture)])[static_cast<size_t>(channel)];
}

const MaterialMapper::DecodedImage *MaterialMapper::decodedImage(int textureIndex,
                                                                 const std::string &what) {
    const tinygltf::Model &model = ctx_.model;
    if (textureIndex < 0 || static_cast<size_t>(textureIndex) >= model.textures.size())
        ctx_.fail(what + ": texture " + std::to_string(textureIndex) +
                  " does not exist (the file has " + std::to_string(model.textures.size()) + ")");
    const tinygltf::Texture &tex = model.textures[static_cast<size_t>(textureIndex)];
    if (tex.source < 0) {
        ctx_.warning(what + ": " + jsonPath("textures", static_cast<size_t>(textureIndex)) +
                     " has no image scadray can decode (only PNG and JPEG); texture ignored");
        return nullptr;
    }
    if (static_cast<size_t>(tex.source) >= model.images.size())
        ctx_.fail(jsonPath("textures", static_cast<size_t>(textureIndex)) + ": image " +
                  std::to_string(tex.source) + " does not exist");

    auto [it, isNew] = images_.try_emplace(tex.source);
    if (!isNew) return it->second.get();

    // Decode on first use with tinygltf's stb loader; a failure costs the texture, not the file
    const tinygltf::Image &image = model.images[static_cast<size_t>(tex.source)];
    std::string label = jsonPath("images", static_cast<size_t>(tex.source));
    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0) label += " ('" + image.uri + "')";
    const std::span<const unsigned char> *encoded = nullptr;
    if (ctx_.encodedImages) {
        auto enc = ctx_.encodedImages->find(tex.source);
        if (enc != ctx_.encodedImages->end()) encoded = &enc->second;
    }
    if (!encoded || encoded->empty()) {
        ctx_.warning(what + ": " + label + " has no data (missing or unreadable); texture ignored");
        return nullptr;
    }
    // The header first: stb allocates what it declares before reading one pixel
    std::optional<ImageHeader> header = readImageHeader(*encoded);
    std::string problem;
    if (!header)
        problem = "is not a PNG, JPEG or BMP image";
    else if (std::string p = imageSizeProblem(header->width, header->height,
                                              ctx_.opts.maxTexturePixels, ctx_.opts.maxTextureSide);
             !p.empty())
        problem = header->format + std::string(" ") + p + " for a texture";
    else if (std::string_view(header->format) == "PNG")
        problem = pngPlausibilityProblem(*header, encoded->size());
    if (problem.empty()) {
        uint64_t total = decodedPixels_ + header->width * header->height;
        if (total > ctx_.opts.maxTotalTexturePixels)
            problem = "its " + std::to_string(header->width) + " x " +
                      std::to_string(header->height) + " pixels would bring the model's decoded " +
                      "texture pixels to " + std::to_string(total) + ", more than the limit of " +
                      std::to_string(ctx_.opts.maxTotalTexturePixels);
        else
            decodedPixels_ = total;
    }
    std::string mime = image.mimeType.empty() ? "" : " (" + image.mimeType + ")";
    if (!problem.empty()) {
        ctx_.warning(what + ": cannot decode " + label + mime + ": " + problem +
                     "; texture ignored");
        return nullptr;
    }
    tinygltf::Image decoded;
    decoded.name = image.name;
    std::string err, warn;
    bool ok = encoded->size() <= static_cast<size_t>(std::numeric_limits<int>::max()) &&
              tinygltf::LoadImageData(&decoded, tex.source, &err, &warn, 0, 0, encoded->data(),
                                      static_cast<int>(encoded->size()), nullptr);
    size_t expected = static_cast<size_t>(std::max(decoded.width, 0)) *
                      static_cast<size_t>(std::max(decoded.height, 0)) *
                      static_cast<size_t>(std::max(decoded.component, 0)) *
                      (decoded.bits == 16 ? 2u : 1u);
    if (!ok || decoded.width <= 0 || decoded.height <= 0 || decoded.component <= 0 ||
        (decoded.bits != 8 && decoded.bits != 16) || decoded.image.size() != expected) {
        while (!err.empty() && err.back() == '\n') err.pop_back();
        ctx_.warning(what + ": cannot decode " + label + mime + (err.empty() ? "" : ": " + err) +
                     "; texture ignored");
        return nullptr;
    }
    auto img = std::make_unique<DecodedImage>();
    img->width = decoded.width;
    img->height = decoded.height;
    img->components = decoded.component;
    img->bits = decoded.bits;
    img->data = std::move(decoded.image);
    img->label = label;
    it->second = std::move(img);
    return it->second.get();
}

int MaterialMapper::irTexture(int textureIndex, const std::string &what, bool srgb) {
    auto found = textures_.find({textureIndex, srgb});
    if (found != textures_.end()) return found->second;
    int &slot = textures_[{textureIndex, srgb}];
    slot = -1;
    const DecodedImage *img = decodedImage(textureIndex, what);
    if (!img) return -1;

    auto tex = std::make_shared<ir::Texture>();
    tex->width = img->width;
    tex->height = img->height;
    tex->loc = ctx_.loc;
    // Colour is sRGB-encoded, data (normals, roughness...) linear; alpha is linear
    tex->rgba.resize(img->pixels() * 4);
    for (size_t p = 0; p < img->pixels(); ++p) {
        for (int c = 0; c < 3; ++c)
            tex->rgba[p * 4 + static_cast<size_t>(c)] =
                srgb ? img->linear(p, c) : img->channel(p, c);
        tex->rgba[p * 4 + 3] = img->channel(p, 3);
    }

    // Sampler: wrap modes per axis and the filter
    const tinygltf::Texture &gt = ctx_.model.textures[static_cast<size_t>(textureIndex)];
    if (gt.sampler >= 0) {
        if (static_cast<size_t>(gt.sampler) >= ctx_.model.samplers.size())
            ctx_.fail(jsonPath("textures", static_cast<size_t>(textureIndex)) + ": sampler " +
                      std::to_string(gt.sampler) + " does not exist");
        const tinygltf::Sampler &s = ctx_.model.samplers[static_cast<size_t>(gt.sampler)];
        std::string samplerPath = jsonPath("samplers", static_cast<size_t>(gt.sampler));
        auto wrapMode = [&](int wrap, const char *axis) {
            switch (wrap) {
                case kWrapRepeat:
                    return ir::Texture::Wrap::Repeat;
                case kWrapClamp:
                    return ir::Texture::Wrap::ClampToEdge;
                case kWrapMirror:
                    return ir::Texture::Wrap::MirroredRepeat;
                default:
                    ctx_.warning(samplerPath + "." + axis + ": " + std::to_string(wrap) +
                                 " is not a wrap mode; REPEAT used");
                    return ir::Texture::Wrap::Repeat;
            }
        };
        tex->wrapU = wrapMode(s.wrapS, "wrapS");
        tex->wrapV = wrapMode(s.wrapT, "wrapT");
        // magFilter decides the lookup (-1: unset, the implementation's choice: linear).
        // minFilter is checked for validity only: without mipmaps a minified texture is
        // filtered as a magnified one
        if (s.magFilter == kFilterNearest)
            tex->nearest = true;
        else if (s.magFilter != -1 && s.magFilter != kFilterLinear)
            ctx_.warning(samplerPath + ".magFilter: " + std::to_string(s.magFilter) +
                         " is not NEAREST (9728) or LINEAR (9729); LINEAR used");
        if (s.minFilter != -1 &&
            (s.minFilter < kFilterNearest ||
             (s.minFilter > kFilterLinear && s.minFilter < kMinFilterFirstMip) ||
             s.minFilter > kMinFilterLastMip))
            ctx_.warning(samplerPath + ".minFilter: " + std::to_string(s.minFilter) +
                         " is not a glTF minification filter; ignored");
    }

    // A file-name-safe name, unique in the scene (a file may be imported more than once)
    std::string name =
        ctx_.baseName + "_tex" + std::to_string(textureIndex) + (srgb ? "" : "_data");
    auto taken = [&](const std::string &n) {
        return std::any_of(scene_.textures.begin(), scene_.textures.end(),
                           [&](const ir::TexturePtr &t) { return t->name == n; });
    };
    std::string unique = name;
    for (int k = 2; taken(unique); ++k) unique = name + "_" + std::to_string(k);
    tex->name = unique;

    scene_.textures.push_back(std::move(tex));
    slot = static_cast<int>(scene_.textures.size()) - 1;
    return slot;
}

ir::TextureRef MaterialMapper::textureInfo(int textureIndex, int texCoord,
                                           const tinygltf::ExtensionMap &extensions,
                                           const std::string &what, bool srgb) {
    ir::TextureRef ref;
    const tinygltf::Value *transform = extension(extensions, "KHR_texture_transform");
    if (transform) {
        auto pair = [&](const char *key, double &a, double &b) {
            if (!transform->Has(key)) return;
            const tinygltf::Value &v = transform->Get(key);
            if (v.IsArray() && v.ArrayLen() == 2 && v.Get(0).IsNumber() && v.Get(1).IsNumber() &&
                std::isfinite(v.Get(0).GetNumberAsDouble()) &&
                std::isfinite(v.Get(1).GetNumberAsDouble())) {
                a = v.Get(0).GetNumberAsDouble();
                b = v.Get(1).GetNumberAsDouble();
            } else {
                ctx_.warning(what + ".extensions.KHR_texture_transform." + key +
                             ": needs two finite numbers; ignored");
            }
        };
        pair("offset", ref.offsetU, ref.offsetV);
        pair("scale", ref.scaleU, ref.scaleV);
        double rotation = number(transform, "rotation", 0.0);
        if (std::isfinite(rotation)) ref.rotation = rotation;
        double set = number(transform, "texCoord", texCoord);
        if (set == std::floor(set) && set >= 0 && set < 1e9) texCoord = static_cast<int>(set);
    }
    if (texCoord != 0 && texCoord != 1) {
        ctx_.warning(what + ": uses TEXCOORD_" + std::to_string(texCoord) +
                     " (scadray reads TEXCOORD_0 and TEXCOORD_1); texture ignored");
        return {};
    }
    ref.texCoord = texCoord;
    ref.texture = irTexture(textureIndex, what, srgb);
    return ref.texture >= 0 ? ref : ir::TextureRef{};
}

}  // namespace rt::gltf::detail
