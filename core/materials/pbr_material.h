// SPDX-License-Identifier: MIT
// glTF metallic-roughness materials (with the KHR_materials_* extensions scadray maps) and their
// mapping to POV-Ray's classic material. The importer maps constant materials once; the renderer
// maps a textured one at every hit, from its textures' values there (see pbr_material.cpp for
// every formula).
#pragma once

#include <tuple>

#include "core/geometry/hit.h"
#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "core/math/rgb.h"

namespace rt {

/// What a glTF material says, factors and texture slots. The base colour texture stays in
/// ir::Material::baseColorTexture (its RGB multiplies the colour per hit, as for any material).
struct PbrMaterial {
    enum class AlphaMode { Opaque, Mask, Blend };

    Rgb baseColor{1};      ///< baseColorFactor.rgb
    double alpha = 1;      ///< baseColorFactor.a
    double metallic = 1;   ///< metallicFactor
    double roughness = 1;  ///< roughnessFactor
    Rgb emissive{0};       ///< emissiveFactor x KHR_materials_emissive_strength
    double transmission = 0;  ///< KHR_materials_transmission.transmissionFactor
    double ior = 1.5;         ///< KHR_materials_ior
    /// KHR_materials_volume: thicknessFactor (> 0: the mesh bounds a refracting volume),
    /// attenuationColor and attenuationDistance (0 = infinite: no attenuation)
    double thickness = 0;
    Rgb attenuationColor{1};
    double attenuationDistance = 0;
    bool unlit = false;  ///< KHR_materials_unlit
    AlphaMode alphaMode = AlphaMode::Opaque;
    double alphaCutoff = 0.5;
    /// KHR_materials_clearcoat
    double clearcoat = 0, clearcoatRoughness = 0;
    /// KHR_materials_sheen
    Rgb sheenColor{0};
    double sheenRoughness = 0;
    /// KHR_materials_specular (specularFactor, specularColorFactor)
    double specular = 1;
    Rgb specularColor{1};

    // Textures read per texel (invalid: none)
    ir::TextureRef metallicRoughnessTexture;  ///< B = metalness, G = roughness (linear)
    ir::TextureRef normalTexture;             ///< tangent space, RGB*2-1
    double normalScale = 1;
    ir::TextureRef occlusionTexture;          ///< R
    double occlusionStrength = 1;
    ir::TextureRef emissiveTexture;           ///< sRGB, multiplies emissive
    ir::TextureRef transmissionTexture;       ///< R, multiplies transmission
    ir::TextureRef clearcoatTexture;          ///< R, multiplies clearcoat
    ir::TextureRef clearcoatRoughnessTexture; ///< G, multiplies clearcoatRoughness
    ir::TextureRef sheenColorTexture;         ///< sRGB, multiplies sheenColor
    ir::TextureRef sheenRoughnessTexture;     ///< A, multiplies sheenRoughness
    ir::TextureRef specularTexture;           ///< A, multiplies specular
    ir::TextureRef specularColorTexture;      ///< sRGB, multiplies specularColor
    ir::TextureRef thicknessTexture;          ///< G, multiplies thickness

    auto key() const {
        const Rgb &c = baseColor, &e = emissive, &ac = attenuationColor, &sh = sheenColor,
                  &sc = specularColor;
        return std::tuple_cat(
            std::make_tuple(c.r, c.g, c.b, alpha, metallic, roughness, e.r, e.g, e.b, transmission,
                            ior, thickness, ac.r, ac.g, ac.b, attenuationDistance, unlit,
                            static_cast<int>(alphaMode), alphaCutoff, clearcoat, clearcoatRoughness,
                            sh.r, sh.g, sh.b, sheenRoughness, specular, sc.r, sc.g, sc.b,
                            normalScale, occlusionStrength),
            metallicRoughnessTexture.key(), normalTexture.key(), occlusionTexture.key(),
            emissiveTexture.key(), transmissionTexture.key(), clearcoatTexture.key(),
            clearcoatRoughnessTexture.key(), sheenColorTexture.key(), sheenRoughnessTexture.key(),
            specularTexture.key(), specularColorTexture.key(), thicknessTexture.key());
    }
    bool operator==(const PbrMaterial &o) const { return key() == o.key(); }

    /// Whether any texture slot is set (else the constant mapping says everything).
    bool textured() const {
        return metallicRoughnessTexture.valid() || normalTexture.valid() ||
               occlusionTexture.valid() || emissiveTexture.valid() || transmissionTexture.valid() ||
               clearcoatTexture.valid() || clearcoatRoughnessTexture.valid() ||
               sheenColorTexture.valid() || sheenRoughnessTexture.valid() ||
               specularTexture.valid() || specularColorTexture.valid() || thicknessTexture.valid();
    }
    /// Whether some texel may let light through (alpha or transmission below or above their
    /// constant values): such a material never counts as opaque.
    bool mayBeSeeThrough() const {
        return alphaMode != AlphaMode::Opaque || transmission > 0;
    }
};

/// The values the mapping reads at one point (or their means over a texture): the factors
/// times the textures' values there.
struct PbrInputs {
    Rgb baseColor{1};
    double alpha = 1;
    double metallic = 1, roughness = 1;
    Rgb emissive{0};
    double transmission = 0;
    double occlusion = 1;  ///< 1 + strength (R - 1): scales the ambient term only
    double clearcoat = 0, clearcoatRoughness = 0;
    Rgb sheenColor{0};
    double sheenRoughness = 0;
    double specular = 1;
    Rgb specularColor{1};
    double thickness = 0;
};

/// The factors alone, as the mapping reads them for an untextured material.
PbrInputs pbrFactors(const PbrMaterial &p);

/// The classic material for `in` under the constant settings of `p` (ior, attenuation,
/// unlit, alpha mode). Alpha: BLEND gives transmit 1 - alpha; MASK is
/// opaque (the caller decides what is cut out); OPAQUE ignores alpha.
ir::Material classicMaterial(const PbrMaterial &p, const PbrInputs &in);

/// A textured material evaluated at a hit.
struct TexelShading {
    ir::Material material;  ///< the classic material there (base colour texture left to the caller)
    Vec3 normal;            ///< shading normal (the normal map applied), unit, same side as si.ns
    bool cutOut = false;    ///< alpha MASK below the cutoff: the surface is not there
};

/// The images behind a material's texture slots (null: none, or not decoded).
struct TexelImages {
    const ir::Texture *baseColor = nullptr, *metallicRoughness = nullptr, *normal = nullptr,
                      *occlusion = nullptr, *emissive = nullptr, *transmission = nullptr,
                      *clearcoat = nullptr, *clearcoatRoughness = nullptr, *sheenColor = nullptr,
                      *sheenRoughness = nullptr, *specular = nullptr, *specularColor = nullptr,
                      *thickness = nullptr;
};

/// Evaluates `m` (whose `texel` is set) at hit `si`: samples its textures, alpha from the base
/// colour texture's A, baseColorFactor.a and COLOR_0's A; `viewDir` is the incoming ray's
/// direction (the perturbed normal is kept facing back against it). Without `withNormal` (shadow
/// rays) the normal map is not read.
TexelShading shadeTexel(const ir::Material &m, const TexelImages &images,
                        const SurfaceInteraction &si, const Vec3 &viewDir, bool withNormal = true);

}  // namespace rt
