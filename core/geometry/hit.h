// SPDX-License-Identifier: MIT
// Surface interaction of the winning hit and error-bounded spawning of secondary rays.
#pragma once

#include "core/math/float_util.h"
#include "core/math/ray.h"

namespace rt {

class LeafShape;
class Shape;

struct SurfaceInteraction {
    double t = 0;  ///< world ray parameter of the hit
    Vec3 p;        ///< hit point, refined onto the surface
    Vec3 pError;   ///< bound on the absolute error of p
    Vec3 n;        ///< unit geometric normal, out of the primitive
    /// Unit shading normal: n, or a mesh's interpolated vertex normal (POV-Ray shades smooth
    /// triangles with it: lighting, reflection and refraction)
    Vec3 ns;
    /// Texture coordinates (glTF convention, origin top-left) when the surface has them
    double u = 0, v = 0;
    bool hasUv = false;
    /// Second texture coordinate set (glTF TEXCOORD_1), when the mesh has one
    double u1 = 0, v1 = 0;
    bool hasUv1 = false;
    /// World-space tangent along +u (not normalised) and the bitangent's handedness: the
    /// bitangent is cross(ns, tangent) * tangentSign (glTF TANGENT), when the mesh has tangents
    Vec3 tangent;
    double tangentSign = 1;
    bool hasTangent = false;
    /// Interpolated vertex colour (linear RGBA), multiplying the base colour, when the mesh has
    /// one (glTF COLOR_0)
    float vertexColor[4] = {1, 1, 1, 1};
    bool hasVertexColor = false;
    const LeafShape *leaf = nullptr;  ///< primitive or mesh whose surface was hit
    const Shape *object = nullptr;    ///< top-level object (owner of the interior)
    /// Another surface lies within the tie tolerance of this hit (coincident faces, or a
    /// surface at the ray's origin): renderers may legitimately disagree on what is seen.
    bool tie = false;
};

/// How far spawned origins sit beyond the error bound of the hit point. The bound covers the
/// refinement and the forward transform; the factor covers the rounding of the new ray's own
/// transform into object space and of the re-intersection (pbrt-v3 section 3.9.5).
constexpr double kSpawnSafety = 4;

/// Origin for a ray leaving the surface in direction w: the hit point pushed along the normal,
/// to the side of w, past its error bound, then rounded away from the surface.
inline Vec3 offsetRayOrigin(const SurfaceInteraction &si, const Vec3 &w) {
    double d = dot(abs(si.n), si.pError) * kSpawnSafety;
    Vec3 offset = si.n * d;
    if (dot(w, si.n) < 0) offset = -offset;
    Vec3 po = si.p + offset;
    for (int i = 0; i < 3; ++i) {
        if (offset[i] > 0)
            po[i] = nextUp(po[i]);
        else if (offset[i] < 0)
            po[i] = nextDown(po[i]);
    }
    return po;
}

inline Ray spawnRay(const SurfaceInteraction &si, const Vec3 &w) {
    return Ray(offsetRayOrigin(si, w), w);
}

}  // namespace rt
