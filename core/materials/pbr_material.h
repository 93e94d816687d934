// SPDX-License-Identifier: MIT
// The mapping of glTF metallic-roughness materials (core/ir/pbr_material.h, with the
// KHR_materials_* extensions scadray maps) to POV-Ray's classic material. The importer maps
// constant materials once; the renderer maps a textured one at every hit, from its textures' values
// there (see pbr_material.cpp for every formula).
#pragma once

#include <tuple>

#include "core/geometry/hit.h"
#include "core/ir/material.h"
#include "core/ir/mesh.h"
#include "core/ir/pbr_material.h"
#include "core/math/rgb.h"

namespace rt {

using ir::PbrMaterial;

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
