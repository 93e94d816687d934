// SPDX-License-Identifier: MIT
// glTF metallic-roughness materials as data: the factors and texture slots of a material and of
// the KHR_materials_* extensions scadray maps. How they look is core/materials/pbr_material.h.
#pragma once

#include <tuple>

#include "core/ir/material.h"
#include "core/math/rgb.h"

namespace rt::ir {

/// What a glTF material says, factors and texture slots. The base colour texture stays in
/// ir::Material::baseColorTexture (its RGB multiplies the colour per hit, as for any material).
struct PbrMaterial {
    enum class AlphaMode { Opaque, Mask, Blend };

    Rgb baseColor{1};         ///< baseColorFactor.rgb
    double alpha = 1;         ///< baseColorFactor.a
    double metallic = 1;      ///< metallicFactor
    double roughness = 1;     ///< roughnessFactor
    Rgb emissive{0};          ///< emissiveFactor x KHR_materials_emissive_strength
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
    TextureRef metallicRoughnessTexture;  ///< B = metalness, G = roughness (linear)
    TextureRef normalTexture;             ///< tangent space, RGB*2-1
    double normalScale = 1;
    TextureRef occlusionTexture;  ///< R
    double occlusionStrength = 1;
    TextureRef emissiveTexture;            ///< sRGB, multiplies emissive
    TextureRef transmissionTexture;        ///< R, multiplies transmission
    TextureRef clearcoatTexture;           ///< R, multiplies clearcoat
    TextureRef clearcoatRoughnessTexture;  ///< G, multiplies clearcoatRoughness
    TextureRef sheenColorTexture;          ///< sRGB, multiplies sheenColor
    TextureRef sheenRoughnessTexture;      ///< A, multiplies sheenRoughness
    TextureRef specularTexture;            ///< A, multiplies specular
    TextureRef specularColorTexture;       ///< sRGB, multiplies specularColor
    TextureRef thicknessTexture;           ///< G, multiplies thickness

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
    bool mayBeSeeThrough() const { return alphaMode != AlphaMode::Opaque || transmission > 0; }
};

}  // namespace rt::ir
