// SPDX-License-Identifier: MIT
// glTF metallic-roughness material -> POV-Ray classic material (gltf-notes section 10;
// heuristics that reproduce the smooth-metal and rough-dielectric limits).
//
// Inputs (per texel for a textured material, evaluated at every hit; the importer evaluates
// untextured ones once, and keeps the MEAN of every texture in the material's constant fields,
// which is what the POV-Ray export writes: it cannot express per-texel roughness, metalness,
// emission, transmission, alpha, normal or occlusion maps)
//   C   = baseColorFactor.rgb (x base colour texture RGB x COLOR_0 RGB at a hit)
//   a   = baseColorFactor.a x texture A x COLOR_0 A (MASK and BLEND only)
//   m   = metallicFactor  x B of metallicRoughnessTexture, clamped to [0,1]
//   r   = roughnessFactor x G of metallicRoughnessTexture, clamped to [0,1]
//   E   = emissiveFactor x KHR_materials_emissive_strength x emissiveTexture (sRGB decoded)
//   t   = KHR_materials_transmission.transmissionFactor x R of transmissionTexture
//   o   = 1 + occlusionTexture.strength x (R of occlusionTexture - 1)
//   eta = KHR_materials_ior.ior (default 1.5)
//   s, S = KHR_materials_specular specularFactor x A of specularTexture, specularColorFactor
//          x specularColorTexture (sRGB decoded) (defaults 1, white)
//   k, rk = KHR_materials_clearcoat clearcoatFactor x R of clearcoatTexture,
//          clearcoatRoughnessFactor x G of clearcoatRoughnessTexture
//   Sh  = KHR_materials_sheen sheenColorFactor x sheenColorTexture (sRGB decoded); the sheen
//          roughness (x A of sheenRoughnessTexture) is read but the mapping has no use for it
//   thickness = KHR_materials_volume thicknessFactor x G of thicknessTexture
// Derived
//   F0d = min(((eta-1)/(eta+1))^2 S, 1) s     F0 = mix(F0d, C, m)      g = (1-r)^2
//   nB(r) = clamp(2/r^4 - 2, 1, 4000), r = 0 gives 4000 (Blinn-Phong exponent of GGX alpha r^2)
// Classic material
//   color            = C
//   filter           = t (1-m)          (metals never transmit; tinted by C)
//   transmit         = 1-a for alphaMode BLEND, else 0; filter is then cut so filter+transmit <= 1
//                      MASK: a < alphaCutoff cuts the surface out at that texel (rays, shadow
//                      rays included, pass straight through); elsewhere opaque
//   finish.ambient   = 0.1 (1 - m g) o  (glTF's occlusion applies to indirect light only)
//   finish.diffuse   = (1-m)(1-t) + 0.5 m (1-g)   (keeps rough metals from going black)
//   finish.specular  = clamp(lum(F0) (nB(r)+8)/8, 0, 1), lum = (0.2126, 0.7152, 0.0722)
//   finish.roughness = 1/nB(r)          finish.metallic = m
//   reflection       t > 0: fresnel on, reflectionMin 0, reflectionMax g (white),
//                           conserveEnergy on
//                    else:  reflectionMin g F0 (RGB), reflectionMax g (white), falloff 5
//                           (a Schlick-like rise to grazing angles)
//   clearcoat        a second, dielectric (F0 0.04) layer: with gk = (1-rk)^2,
//                    reflectionMin += k 0.04 gk, reflectionMax = max(reflectionMax, k gk),
//                    and where its highlight k lum(0.04)(nB(rk)+8)/8 outweighs the base one,
//                    the highlight takes its strength and size; diffuse x (1 - 0.04 k)
//   sheen            the classic model has no retro-reflective lobe: brilliance
//                    1 - 0.5 max(Sh) (a flatter falloff, brighter towards grazing, as velvet)
//                    and diffuse + 0.25 lum(Sh) (1-m)
//   emission         POV-Ray multiplies emission by the pigment colour, so wherever E_i > 0
//                    the colour channel becomes c_i = max(C_i, 1e-3) and emission_i = E_i / c_i
//   interior.ior     = eta if KHR_materials_volume thicknessFactor > 0 and t > 0, else 1
//                      (thin-walled transmission goes straight through, without bending)
//   interior fade    KHR_materials_volume attenuation T = A^(d/D) (A = attenuationColor,
//                    D = attenuationDistance, finite): fade_power 1001 (exponential),
//                    fade_distance D, fade_color 1 + ln(max(A_i, 1e-4)), as POV-Ray's
//                    exp(-(1 - fade_color) d / fade_distance) is then exactly A^(d/D)
//   KHR_materials_unlit: ambient 1, diffuse 0, no specular highlight, no reflection
// Normal maps (per hit): n = normalize(T x + B y + N z) with (x, y, z) = (RGB*2-1) and x, y
// scaled by normalTexture.scale, T the tangent made orthogonal to N, B = cross(N, T) w; the
// result is the shading normal for lighting, reflection and refraction, tilted back to the
// viewer's side of the surface where it would face away.
#include "core/materials/pbr_material.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <tuple>

#include "core/materials/texture_sampler.h"

namespace rt {

namespace {

/// Below this a colour channel cannot carry emission: POV-Ray multiplies emission by the
/// pigment, so the channel is raised to it and the emission divided by it.
constexpr double kMinEmissiveColor = 1e-3;
/// Specular exponent for a perfectly smooth surface (r = 0) and the mapping's upper bound.
constexpr double kMaxSpecularExponent = 4000;
/// Clearcoat's fixed F0 (a dielectric of ior 1.5, as KHR_materials_clearcoat specifies).
constexpr double kClearcoatF0 = 0.04;
/// The attenuation colour channel below which the volume counts as black (ln would diverge).
constexpr double kMinAttenuation = 1e-4;
/// How far a perturbed normal must face the viewer (cosine): normal maps are kept this much
/// on the viewer's side.
constexpr double kMinFacing = 0.01;

double sq(double x) { return x * x; }
double luminance(const Rgb &c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double specularExponent(double roughness) {
    return roughness <= 0 ? kMaxSpecularExponent
                          : clamp(2 / std::pow(roughness, 4) - 2, 1.0, kMaxSpecularExponent);
}

}  // namespace

PbrInputs pbrFactors(const PbrMaterial &p) {
    PbrInputs in;
    in.baseColor = p.baseColor;
    in.alpha = p.alpha;
    in.metallic = p.metallic;
    in.roughness = p.roughness;
    in.emissive = p.emissive;
    in.transmission = p.transmission;
    in.occlusion = 1;
    in.clearcoat = p.clearcoat;
    in.clearcoatRoughness = p.clearcoatRoughness;
    in.sheenColor = p.sheenColor;
    in.sheenRoughness = p.sheenRoughness;
    in.specular = p.specular;
    in.specularColor = p.specularColor;
    in.thickness = p.thickness;
    return in;
}

ir::Material classicMaterial(const PbrMaterial &p, const PbrInputs &in) {
    double metallic = clamp(in.metallic, 0.0, 1.0);
    double roughness = clamp(in.roughness, 0.0, 1.0);
    double transmission = clamp(in.transmission, 0.0, 1.0);
    const Rgb &baseColor = in.baseColor;

    double f0Ior = sq((p.ior - 1) / (p.ior + 1));
    Rgb f0d;
    for (int c = 0; c < 3; ++c) f0d[c] = std::min(f0Ior * in.specularColor[c], 1.0) * in.specular;
    Rgb f0 = f0d * (1 - metallic) + baseColor * metallic;
    double gloss = sq(1 - roughness);
    double exponent = specularExponent(roughness);

    ir::Material mat;
    mat.color = baseColor;

    // Transparency: transmission (tinted) and alpha coverage (untinted)
    mat.filter = transmission * (1 - metallic);
    if (p.alphaMode == PbrMaterial::AlphaMode::Blend) mat.transmit = clamp(1 - in.alpha, 0.0, 1.0);
    mat.filter = std::min(mat.filter, 1 - mat.transmit);

    // Local illumination
    ir::Finish &f = mat.finish;
    f.ambient = 0.1 * (1 - metallic * gloss) * clamp(in.occlusion, 0.0, 1.0);
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

    // Clearcoat: a dielectric layer over the base
    double coat = clamp(in.clearcoat, 0.0, 1.0);
    if (coat > 0) {
        double coatRough = clamp(in.clearcoatRoughness, 0.0, 1.0);
        double coatGloss = sq(1 - coatRough);
        double coatExponent = specularExponent(coatRough);
        f.reflectionMin += Rgb(coat * kClearcoatF0 * coatGloss);
        for (int c = 0; c < 3; ++c)
            f.reflectionMax[c] = std::max(f.reflectionMax[c], coat * coatGloss);
        double coatSpecular = clamp(coat * kClearcoatF0 * (coatExponent + 8) / 8, 0.0, 1.0);
        if (coatSpecular > f.specular) {
            f.specular = coatSpecular;
            f.roughness = 1 / coatExponent;
        }
        f.diffuse *= 1 - kClearcoatF0 * coat;
    }

    // Sheen: a flatter diffuse falloff and a little more diffuse light
    double sheen = std::max({in.sheenColor.r, in.sheenColor.g, in.sheenColor.b});
    if (sheen > 0) {
        f.brilliance = 1 - 0.5 * std::min(sheen, 1.0);
        f.diffuse += 0.25 * luminance(in.sheenColor) * (1 - metallic);
    }

    // Emission, divided by the colour POV-Ray will multiply it with
    for (int c = 0; c < 3; ++c) {
        if (in.emissive[c] > 0) {
            mat.color[c] = std::max(mat.color[c], kMinEmissiveColor);
            f.emission[c] = in.emissive[c] / mat.color[c];
        }
    }

    bool volume = in.thickness > 0;
    mat.interior.ior = volume && transmission > 0 ? p.ior : 1.0;
    if (volume && p.attenuationDistance > 0 && std::isfinite(p.attenuationDistance) &&
        !(p.attenuationColor == Rgb(1))) {
        mat.interior.fadeDistance = p.attenuationDistance;
        mat.interior.fadePower = 1001;
        for (int c = 0; c < 3; ++c)
            mat.interior.fadeColor[c] =
                1 + std::log(clamp(p.attenuationColor[c], kMinAttenuation, 1.0));
    }

    if (p.unlit) {
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

namespace {

/// The normal map's normal at a hit, or `fallback` (si.ns) without tangents or coordinates.
Vec3 mappedNormal(const PbrMaterial &p, const ir::Texture &tex, const SurfaceInteraction &si) {
    float t[4];
    if (!si.hasTangent || !sampleTexture(tex, p.normalTexture, si, t)) return si.ns;
    const Vec3 &n = si.ns;
    Vec3 tangent = si.tangent - n * dot(n, si.tangent);
    double len = length(tangent);
    if (!(len > 0)) return si.ns;
    tangent = tangent / len;
    Vec3 bitangent = cross(n, tangent) * (si.tangentSign < 0 ? -1.0 : 1.0);
    double x = (2.0 * t[0] - 1) * p.normalScale, y = (2.0 * t[1] - 1) * p.normalScale,
           z = 2.0 * t[2] - 1;
    Vec3 mapped = tangent * x + bitangent * y + n * z;
    double ml = length(mapped);
    return ml > 0 && std::isfinite(ml) ? mapped / ml : si.ns;
}

}  // namespace

TexelShading shadeTexel(const ir::Material &m, const TexelImages &images,
                        const SurfaceInteraction &si, const Vec3 &viewDir, bool withNormal) {
    const PbrMaterial &p = *m.texel.pbr;
    PbrInputs in = pbrFactors(p);
    float t[4];
    // Base colour and alpha: factor x texture x COLOR_0
    if (images.baseColor && sampleTexture(*images.baseColor, m.baseColorTexture, si, t)) {
        in.baseColor *= Rgb(t[0], t[1], t[2]);
        in.alpha *= t[3];
    }
    if (si.hasVertexColor) {
        in.baseColor *= Rgb(si.vertexColor[0], si.vertexColor[1], si.vertexColor[2]);
        in.alpha *= si.vertexColor[3];
    }
    TexelShading out;
    out.normal = si.ns;
    if (p.alphaMode == PbrMaterial::AlphaMode::Mask && in.alpha < p.alphaCutoff) {
        out.cutOut = true;
        return out;
    }
    if (images.metallicRoughness &&
        sampleTexture(*images.metallicRoughness, p.metallicRoughnessTexture, si, t)) {
        in.metallic *= t[2];
        in.roughness *= t[1];
    }
    if (images.emissive && !in.emissive.isBlack() &&
        sampleTexture(*images.emissive, p.emissiveTexture, si, t))
        in.emissive *= Rgb(t[0], t[1], t[2]);
    if (images.transmission && in.transmission > 0 &&
        sampleTexture(*images.transmission, p.transmissionTexture, si, t))
        in.transmission *= t[0];
    if (images.occlusion && sampleTexture(*images.occlusion, p.occlusionTexture, si, t))
        in.occlusion = 1 + p.occlusionStrength * (t[0] - 1);
    // The extensions' textures multiply their factors (KHR_materials_clearcoat, _sheen,
    // _specular, _volume)
    if (images.clearcoat && in.clearcoat > 0 &&
        sampleTexture(*images.clearcoat, p.clearcoatTexture, si, t))
        in.clearcoat *= t[0];
    if (images.clearcoatRoughness &&
        sampleTexture(*images.clearcoatRoughness, p.clearcoatRoughnessTexture, si, t))
        in.clearcoatRoughness *= t[1];
    if (images.sheenColor && sampleTexture(*images.sheenColor, p.sheenColorTexture, si, t))
        in.sheenColor *= Rgb(t[0], t[1], t[2]);
    if (images.sheenRoughness &&
        sampleTexture(*images.sheenRoughness, p.sheenRoughnessTexture, si, t))
        in.sheenRoughness *= t[3];
    if (images.specular && sampleTexture(*images.specular, p.specularTexture, si, t))
        in.specular *= t[3];
    if (images.specularColor && sampleTexture(*images.specularColor, p.specularColorTexture, si, t))
        in.specularColor *= Rgb(t[0], t[1], t[2]);
    if (images.thickness && in.thickness > 0 &&
        sampleTexture(*images.thickness, p.thicknessTexture, si, t))
        in.thickness *= t[1];
    out.material = classicMaterial(p, in);

    if (images.normal && withNormal) {
        Vec3 n = mappedNormal(p, *images.normal, si);
        // Keep it on the viewer's side of the surface (the side si.ns faces the viewer from)
        Vec3 toViewer = -viewDir;
        double side = dot(si.ns, toViewer) >= 0 ? 1.0 : -1.0;
        double facing = dot(n, toViewer) * side;
        if (facing < kMinFacing) {
            n = n + toViewer * (side * (kMinFacing - facing));
            n = normalize(n);
        }
        out.normal = n;
    }
    return out;
}

}  // namespace rt
