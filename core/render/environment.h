// SPDX-License-Identifier: MIT
// The radiance a ray sees when it leaves the scene: the background colour, or the scene's
// environment (ir::Environment) looked up by the ray's direction exactly as POV-Ray's
// sky_sphere does for the exporter's SDL (gradient z colour_map; map_type 1 image_map turned
// so its pole is +Z).
#pragma once

#include <string>

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"
#include "core/math/rgb.h"
#include "core/math/vec3.h"

namespace rt {

/// Environment radiance along direction `d` (any non-zero length). A None environment is
/// black (the caller uses the background colour instead: missRadiance).
Rgb environmentRadiance(const ir::Environment &env, const Vec3 &d);

/// What a ray that hits nothing returns: the background colour without an environment.
inline Rgb missRadiance(const ir::Settings &s, const Vec3 &d) {
    return s.environment.kind == ir::EnvironmentKind::None ? s.background
                                                           : environmentRadiance(s.environment, d);
}

/// Equirectangular texture coordinates of direction `d` with the environment's rotation:
/// u = 0 along +X, 0.25 along -Y, 0.5 along -X, 0.75 along +Y; v = 0 straight up (+Z), 0.5 on
/// the horizon, 1 straight down (glTF's convention: v counts down from the top row).
void environmentUv(double rotateDegrees, const Vec3 &d, double *u, double *v);

/// Mean radiance over the sphere of directions (gradient: exact; image: solid-angle weighted).
Rgb environmentMean(const ir::Environment &env);

}  // namespace rt
