// SPDX-License-Identifier: MIT
// IR material: POV-Ray 3.7's classic pigment, finish and interior, with every value explicit.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <tuple>

#include "core/ir/source_loc.h"
#include "core/math/rgb.h"

namespace rt::ir {

struct PbrMaterial;  // core/ir/pbr_material.h

/// OpenSCAD's default face colour (Cornfield scheme front colour #f9d72c), as linear values of
/// the 8-bit sRGB-less integers divided by 255, exactly as OpenSCAD treats colours.
constexpr Rgb kOpenScadDefaultColor{0xf9 / 255.0, 0xd7 / 255.0, 0x2c / 255.0};

/// Local-illumination and reflection parameters (docs/design/povray-semantics.md sections 3
/// and 6).
struct Finish {
    double ambient = 0.15;
    double diffuse = 0.75;
    double brilliance = 1;
    double phong = 0;
    double phongSize = 40;
    double specular = 0;
    double roughness = 0.05;  ///< POV-Ray's roughness; the specular exponent is 1/roughness
    double metallic = 0;
    Rgb reflectionMin{0};
    Rgb reflectionMax{0};
    double reflectionFalloff = 1;
    double reflectionExponent = 1;
    bool fresnel = false;
    bool conserveEnergy = false;
    Rgb emission{0};
    /// Monte Carlo extensions POV-Ray 3.7 lacks (its writer approximates them): the angular
    /// spread (standard deviation, degrees) of reflected rays about the mirror direction
    /// (glossy) and of refracted rays about the refracted direction (frosted); 0 = sharp.
    double glossy = 0;
    double frosted = 0;
    /// Rays a glossy or frosted surface spreads over its lobe where a path first meets one;
    /// later blurred bounces of that path take one ray each, so the cost stays linear.
    int blurSamples = 8;
    enum class Lobe { Normal, Phong };
    Lobe blurLobe = Lobe::Normal;

    bool operator==(const Finish &) const = default;
    bool hasReflection() const { return !reflectionMin.isBlack() || !reflectionMax.isBlack(); }
};

/// What is inside a solid: index of refraction and POV-Ray's interior fade.
struct Interior {
    double ior = 1;
    double fadeDistance = 0;
    double fadePower = 0;
    Rgb fadeColor{0};

    bool operator==(const Interior &) const = default;
};

/// How a material reads a texture (glTF textureInfo): the image, the texture coordinate set
/// and KHR_texture_transform, applied as uv' = translate(offset) rotate(rotation) scale(scale) uv.
struct TextureRef {
    int texture = -1;  ///< index into Scene::textures, or -1 for none
    int texCoord = 0;  ///< 0: Mesh::uvs (TEXCOORD_0), 1: Mesh::uvs1 (TEXCOORD_1)
    double offsetU = 0, offsetV = 0;
    double rotation = 0;  ///< radians, as KHR_texture_transform defines it
    double scaleU = 1, scaleV = 1;

    bool operator==(const TextureRef &) const = default;
    bool valid() const { return texture >= 0; }
    bool hasTransform() const {
        return offsetU != 0 || offsetV != 0 || rotation != 0 || scaleU != 1 || scaleV != 1;
    }
    auto key() const {
        return std::make_tuple(texture, texCoord, offsetU, offsetV, rotation, scaleU, scaleV);
    }
};

/// A glTF material's per-texel description (factors plus texture slots), shared and immutable;
/// compared, ordered and hashed by value. Empty = none.
struct TexelMaterial {
    std::shared_ptr<const PbrMaterial> pbr;

    bool operator==(const TexelMaterial &o) const;
    bool operator<(const TexelMaterial &o) const;
    size_t hash() const;
    /// Whether some texel may let light through (alpha MASK or BLEND, transmission).
    bool mayBeSeeThrough() const { return pbr && seeThrough(); }

  private:
    bool seeThrough() const;
};

struct Material {
    Rgb color = kOpenScadDefaultColor;
    double filter = 0;    ///< light passing through, tinted by color
    double transmit = 0;  ///< light passing through untinted
    Finish finish;
    Interior interior;
    /// Texture whose RGB multiplies `color` per hit (none by default).
    TextureRef baseColorTexture;
    /// glTF textures evaluated per hit (the fields above stay their mean, for export).
    TexelMaterial texel;
    SourceLoc loc;  ///< where it was first defined (not part of equality)

    /// Every field that decides how the material looks, as one tuple: equality dedupes
    /// materials, its order ranks coincident CSG faces, its hash indexes Scene::materials.
    auto appearanceKey() const {
        const Finish &f = finish;
        const Rgb &rmin = f.reflectionMin, &rmax = f.reflectionMax, &e = f.emission;
        const Rgb &fc = interior.fadeColor;
        return std::tuple_cat(
            std::make_tuple(color.r, color.g, color.b, filter, transmit, f.ambient, f.diffuse,
                            f.brilliance, f.phong, f.phongSize, f.specular, f.roughness, f.metallic,
                            rmax.r, rmax.g, rmax.b, rmin.r, rmin.g, rmin.b, f.reflectionFalloff,
                            f.reflectionExponent, f.fresnel, f.conserveEnergy, e.r, e.g, e.b,
                            f.glossy, f.frosted, f.blurSamples, f.blurLobe, interior.ior,
                            interior.fadeDistance, interior.fadePower, fc.r, fc.g, fc.b),
            baseColorTexture.key(), std::make_tuple(texel));
    }
    bool sameAppearance(const Material &o) const { return appearanceKey() == o.appearanceKey(); }
    bool isTransparent() const { return filter > 0 || transmit > 0 || texel.mayBeSeeThrough(); }
};

}  // namespace rt::ir

template <>
struct std::hash<rt::ir::TexelMaterial> {
    size_t operator()(const rt::ir::TexelMaterial &t) const { return t.hash(); }
};
