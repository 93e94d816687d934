// SPDX-License-Identifier: MIT
// The automatic camera and default lights that make a plain .scad file render well, resolved
// once on the IR so the ray tracer and the POV-Ray exporter see the same camera and lights.
#pragma once

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"

namespace rt::ir {

/// OpenSCAD 2021.01 GUI defaults: gimbal rotation of the default view, and the perspective
/// field of view (vertical, degrees, gluPerspective).
constexpr Vec3 kOpenScadDefaultViewRotation{55, 0, 25};
constexpr double kOpenScadDefaultFov = 22.5;
/// Builtin values of $vpt/$vpr/$vpd in OpenSCAD 2021.01 (src/builtin.cc).
constexpr Vec3 kOpenScadBuiltinVpt{0, 0, 0};
constexpr Vec3 kOpenScadBuiltinVpr{0, 0, 0};
constexpr double kOpenScadBuiltinVpd = 500;

/// OpenSCAD's gimbal camera ($vpt, $vpr, $vpd, $vpf) as an explicit camera with vertical fov:
/// with Rinv = Rz(vpr.z) Ry(vpr.y) Rx(vpr.x - 90), the eye is vpt + Rinv (0,-vpd,0), looking at
/// vpt, with up Rinv (0,0,1) (openscad-subset.md section 5).
Camera cameraFromViewport(const Vec3 &vpt, const Vec3 &vpr, double vpd, double vpf);

/// Fills what the scene leaves out: when there is no camera, one that frames the model's bounds
/// from OpenSCAD's default view direction (viewall + autocenter); when there are no lights, a key
/// light with shadows and a shadowless fill placed relative to the camera. An empty scene gets a
/// camera looking at the origin. Notes what it added to `diag`. Validates the scene first
/// (ir::validateScene: out-of-range or non-finite input is a located SceneError) and prunes
/// subtrees without volume (ir::pruneEmpty), so every consumer sees the same solids.
void completeScene(Scene &scene, DiagnosticSink &diag);

}  // namespace rt::ir
