// SPDX-License-Identifier: MIT
// glTF metallic-roughness materials mapped to the IR's classic POV-Ray material, and textures.
//
// The mapping (gltf-notes section 10; heuristics that reproduce the smooth-metal and
// rough-dielectric limits; every texture other than the base colour enters through its mean):
//
// Inputs
//   C   = baseColorFactor.rgb
//   a   = baseColorFactor.a x mean A of baseColorTexture (if any; MASK and BLEND only)
//   m   = metallicFactor  x mean B of metallicRoughnessTexture (if any), clamped to [0,1]
//   r   = roughnessFactor x mean G of metallicRoughnessTexture (if any), clamped to [0,1]
//   E   = emissiveFactor x KHR_materials_emissive_strength.emissiveStrength
//         x mean of emissiveTexture (sRGB decoded, per channel) if any
//   t   = KHR_materials_transmission.transmissionFactor x mean R of transmissionTexture
//   eta = KHR_materials_ior.ior (default 1.5; 0, the legacy mode, and values below 1 warn and
//         use 1.5)
//   volume = KHR_materials_volume.thicknessFactor > 0
// Derived
//   F0d = ((eta-1)/(eta+1))^2      F0 = mix(F0d * white, C, m)      g = (1-r)^2
//   nB  = clamp(2/r^4 - 2, 1, 4000), r = 0 gives 4000 (Blinn-Phong exponent of GGX alpha r^2)
// IR material
//   color            = C; baseColorTexture -> Material::baseColorTexture (its RGB multiplies
//                      color per hit; TEXCOORD_0 only)
//   filter           = t (1-m)          (metals never transmit; tinted by C)
//   transmit         = 1-a for alphaMode BLEND, else 0; filter is then cut so filter+transmit <= 1
//   finish.ambient   = 0.1 (1 - m g)
//   finish.diffuse   = (1-m)(1-t) + 0.5 m (1-g)   (keeps rough metals from going black)
//   finish.specular  = clamp(lum(F0) (nB+8)/8, 0, 1), lum = (0.2126, 0.7152, 0.0722)
//   finish.roughness = 1/nB             finish.metallic = m
//   reflection       t > 0: fresnel on, reflectionMin 0, reflectionMax g (white),
//                           conserveEnergy on
//                    else:  reflectionMin g F0 (RGB), reflectionMax g (white), falloff 5
//                           (a Schlick-like rise to grazing angles)
//   emission         POV-Ray multiplies emission by the pigment colour, so wherever E_i > 0
//                    the colour channel becomes c_i = max(C_i, 1e-3) and emission_i = E_i / c_i
//                    (the product is E_i again; a base colour texture still modulates it)
//   interior.ior     = eta if volume and t > 0, else 1 (thin-walled transmission goes straight
//                      through, without bending)
//   alphaMode MASK   a < alphaCutoff: the primitive is not rendered (a note); otherwise opaque
//   KHR_materials_unlit: ambient 1, diffuse 0, no specular highlight, no reflection
//   No material      glTF's default material: white, metallic 1, roughness 1
//   doubleSided      ignored (both renderers intersect both sides)
// Not mapped: normalTexture, occlusionTexture, COLOR_0, KHR_materials_volume's attenuation,
// texture alpha per hit (only its mean, through a), other material extensions.
// Materials are deduplicated through Scene::addMaterial.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string_view>

#include "core/image/image_limits.h"
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

/// Below this a colour channel cannot carry emission: POV-Ray multiplies emission by the
/// pigment, so the channel is raised to it and the emission divided by it.
constexpr double kMinEmissiveColor = 1e-3;
/// Specular exponent for a perfectly smooth surface (r = 0) and the mapping's upper bound.
constexpr double kMaxSpecularExponent = 4000;

double sq(double x) { return x * x; }
double luminance(const Rgb &c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

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

}  // namespace

MaterialMapper::MaterialMapper(const ImportContext &ctx, ir::Scene &scene)
    : ctx_(ctx), scene_(scene), mapped_(ctx.model.materials.size() + 1) {}

MaterialMapper::~MaterialMapper() = default;

std::optional<int> MaterialMapper::irMaterial(int index, const ir::Mesh &mesh,
                                              const std::string &primitivePath) {
    if (index < -1 || index >= static_cast<int>(ctx_.model.materials.size()))
        ctx_.fail(primitivePath + ": material " + std::to_string(index) +
                  " does not exist (the file has " + std::to_string(ctx_.model.materials.size()) +
                  ")");
    Mapped &slot = mapped_[static_cast<size_t>(index + 1)];
    if (!slot.done) {
        slot.material = map(index, slot.hidden);
        slot.done = true;
    }
    if (slot.hidden) return std::nullopt;
    const ir::TextureRef &base = slot.material.baseColorTexture;
    if (base.valid() && (base.texCoord == 1 ? mesh.uvs1 : mesh.uvs).empty()) {
        ctx_.warning(primitivePath + ": no TEXCOORD_" +
                     std::to_string(base.texCoord) +
                     " for the base colour texture of " +
                     jsonPath("materials", static_cast<size_t>(index)) + "; texture ignored");
        ir::Material plain = slot.material;
        plain.baseColorTexture = {};
        return scene_.addMaterial(plain);
    }
    return scene_.addMaterial(slot.material);
}

ir::Material MaterialMapper::map(int index, bool &hidden) {
    static const tinygltf::Material kDefaultMaterial;  // every property at its glTF default
    const tinygltf::Material &gm =
        index < 0 ? kDefaultMaterial : ctx_.model.materials[static_cast<size_t>(index)];
    std::string path = index < 0 ? std::string("the default material")
                                 : jsonPath("materials", static_cast<size_t>(index));
    if (!gm.name.empty()) path += " ('" + gm.name + "')";
    const tinygltf::PbrMetallicRoughness &pbr = gm.pbrMetallicRoughness;

    // Inputs: factors, scaled by the means of their textures
    if (pbr.baseColorFactor.size() != 4)
        ctx_.warning(path + ": baseColorFactor needs 4 numbers; white used");
    bool validBase = pbr.baseColorFactor.size() == 4;
    Rgb baseColor = validBase ? rgbOf(pbr.baseColorFactor, Rgb(1)) : Rgb(1);
    double alpha = validBase ? pbr.baseColorFactor[3] : 1.0;
    double metallic = pbr.metallicFactor, roughness = pbr.roughnessFactor;
    if (pbr.metallicRoughnessTexture.index >= 0) {
        std::string what = path + ".pbrMetallicRoughness.metallicRoughnessTexture";
        if (const DecodedImage *img = decodedImage(pbr.metallicRoughnessTexture.index, what)) {
            // Linear data: B = metalness, G = roughness
            double sumB = 0, sumG = 0;
            for (size_t p = 0; p < img->pixels(); ++p) {
                sumB += img->channel(p, 2);
                sumG += img->channel(p, 1);
            }
            metallic *= sumB / static_cast<double>(img->pixels());
            roughness *= sumG / static_cast<double>(img->pixels());
        }
    }
    metallic = clamp(metallic, 0.0, 1.0);
    roughness = clamp(roughness, 0.0, 1.0);
    if (pbr.baseColorTexture.index >= 0 && gm.alphaMode != "OPAQUE") {
        std::string what = path + ".pbrMetallicRoughness.baseColorTexture";
        if (const DecodedImage *img = decodedImage(pbr.baseColorTexture.index, what)) {
            double sumA = 0;
            for (size_t p = 0; p < img->pixels(); ++p) sumA += img->channel(p, 3);
            alpha *= sumA / static_cast<double>(img->pixels());
        }
    }

    const tinygltf::Value *strengthExt =
        extension(gm.extensions, "KHR_materials_emissive_strength");
    double strength = number(strengthExt, "emissiveStrength", 1.0);
    Rgb emissive = rgbOf(gm.emissiveFactor, Rgb(0)) * std::max(strength, 0.0);
    if (gm.emissiveTexture.index >= 0 && !emissive.isBlack()) {
        if (const DecodedImage *img =
                decodedImage(gm.emissiveTexture.index, path + ".emissiveTexture")) {
            Rgb sum(0);
            for (size_t p = 0; p < img->pixels(); ++p)
                for (int c = 0; c < 3; ++c) sum[c] += img->linear(p, c);
            emissive *= sum / static_cast<double>(img->pixels());
        }
    }

    const tinygltf::Value *transmissionExt = extension(gm.extensions, "KHR_materials_transmission");
    double transmission = number(transmissionExt, "transmissionFactor", 0.0);
    int transmissionTex = textureRef(transmissionExt, "transmissionTexture");
    if (transmissionTex >= 0 && transmission > 0) {
        std::string what = path + ".extensions.KHR_materials_transmission.transmissionTexture";
        if (const DecodedImage *img = decodedImage(transmissionTex, what)) {
            double sum = 0;
            for (size_t p = 0; p < img->pixels(); ++p) sum += img->channel(p, 0);
            transmission *= sum / static_cast<double>(img->pixels());
        }
    }
    transmission = clamp(transmission, 0.0, 1.0);

    double eta = 1.5;
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
            eta = ior;
    }
    bool volume =
        number(extension(gm.extensions, "KHR_materials_volume"), "thicknessFactor", 0.0) > 0;
    bool unlit = extension(gm.extensions, "KHR_materials_unlit") != nullptr;

    // Derived quantities
    double f0d = sq((eta - 1) / (eta + 1));
    Rgb f0 = Rgb(f0d) * (1 - metallic) + baseColor * metallic;
    double gloss = sq(1 - roughness);
    double exponent = roughness <= 0
                          ? kMaxSpecularExponent
                          : clamp(2 / std::pow(roughness, 4) - 2, 1.0, kMaxSpecularExponent);

    ir::Material mat;
    mat.loc = ctx_.loc;
    mat.color = baseColor;
    if (pbr.baseColorTexture.index >= 0)
        mat.baseColorTexture = textureInfo(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord,
                                           pbr.baseColorTexture.extensions,
                                           path + ".pbrMetallicRoughness.baseColorTexture");

    // Transparency: transmission (tinted) and alpha coverage (untinted)
    mat.filter = transmission * (1 - metallic);
    if (gm.alphaMode == "BLEND") {
        mat.transmit = clamp(1 - alpha, 0.0, 1.0);
    } else if (gm.alphaMode == "MASK") {
        if (alpha < gm.alphaCutoff) {
            hidden = true;
            ctx_.note(path + ": alphaMode MASK with alpha " + std::to_string(alpha) +
                      " below the cutoff " + std::to_string(gm.alphaCutoff) +
                      "; its primitives are not rendered");
        }
    } else if (gm.alphaMode != "OPAQUE") {
        ctx_.warning(path + ": unknown alphaMode '" + gm.alphaMode + "'; OPAQUE used");
    }
    mat.filter = std::min(mat.filter, 1 - mat.transmit);

    // Local illumination
    ir::Finish &f = mat.finish;
    f.ambient = 0.1 * (1 - metallic * gloss);
    f.diffuse = (1 - metallic) * (1 - transmission) + 0.5 * metallic * (1 - gloss);
    f.brilliance = 1;
    f.phong = 0;
    f.specular = clamp(luminance(f0) * (exponent + 8) / 8, 0.0, 1.0);
    f.roughness = 1 / exponent;
    f.metallic = metallic;

    // Reflection
    if (transmission > 0) {
        f.fresnel = true;
        f.reflectionMin = Rgb(0);
        f.reflectionMax = Rgb(gloss);
        f.conserveEnergy = true;
    } else {
        f.reflectionMin = f0 * gloss;
        f.reflectionMax = Rgb(gloss);
        f.reflectionFalloff = 5;
    }

    // Emission, divided by the colour POV-Ray will multiply it with
    for (int c = 0; c < 3; ++c) {
        if (emissive[c] > 0) {
            mat.color[c] = std::max(mat.color[c], kMinEmissiveColor);
            f.emission[c] = emissive[c] / mat.color[c];
        }
    }

    mat.interior.ior = volume && transmission > 0 ? eta : 1.0;

    if (unlit) {
        f.ambient = 1;
        f.diffuse = 0;
        f.specular = 0;
        f.reflectionMin = Rgb(0);
        f.reflectionMax = Rgb(0);
        f.fresnel = false;
        f.conserveEnergy = false;
    }
    return mat;
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

int MaterialMapper::irTexture(int textureIndex, const std::string &what) {
    auto found = textures_.find(textureIndex);
    if (found != textures_.end()) return found->second;
    int &slot = textures_[textureIndex];
    slot = -1;
    const DecodedImage *img = decodedImage(textureIndex, what);
    if (!img) return -1;

    auto tex = std::make_shared<ir::Texture>();
    tex->width = img->width;
    tex->height = img->height;
    tex->loc = ctx_.loc;
    // Base colour is sRGB-encoded; alpha is linear
    tex->rgba.resize(img->pixels() * 4);
    for (size_t p = 0; p < img->pixels(); ++p) {
        for (int c = 0; c < 3; ++c) tex->rgba[p * 4 + static_cast<size_t>(c)] = img->linear(p, c);
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
                case kWrapRepeat: return ir::Texture::Wrap::Repeat;
                case kWrapClamp: return ir::Texture::Wrap::ClampToEdge;
                case kWrapMirror: return ir::Texture::Wrap::MirroredRepeat;
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
        if (s.minFilter != -1 && (s.minFilter < kFilterNearest ||
                                  (s.minFilter > kFilterLinear && s.minFilter < kMinFilterFirstMip) ||
                                  s.minFilter > kMinFilterLastMip))
            ctx_.warning(samplerPath + ".minFilter: " + std::to_string(s.minFilter) +
                         " is not a glTF minification filter; ignored");
    }

    // A file-name-safe name, unique in the scene (a file may be imported more than once)
    std::string name = ctx_.baseName + "_tex" + std::to_string(textureIndex);
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
                                           const std::string &what) {
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
    ref.texture = irTexture(textureIndex, what);
    return ref.texture >= 0 ? ref : ir::TextureRef{};
}

}  // namespace rt::gltf::detail
