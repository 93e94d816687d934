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
/// vpt, with up Rinv (0,0,1) (docs/design/openscad-subset.md section 14).
Camera cameraFromViewport(const Vec3 &vpt, const Vec3 &vpr, double vpd, double vpf);

/// How the automatic camera frames a scene without one.
enum class Framing {
    /// OpenSCAD's viewall + autocenter from its default view (.scad files): the bounding
    /// sphere touches the top and bottom of a 22.5 degree vertical field of view.
    OpenScad,
    /// As glTF viewers frame a model (glTF, STL and OFF files): the bounding sphere seen from
    /// the front-right and above fills kViewerFill of the picture's smaller side.
    Viewer,
};

/// Viewer framing: the eye lies kViewerAzimuth degrees to the right of the front (-Y, glTF's
/// +Z) and kViewerElevation degrees above the horizon, seen through kViewerFov degrees along
/// the picture's smaller side; the bounding sphere's outline spans kViewerFill of that side.
constexpr double kViewerAzimuth = 20;
constexpr double kViewerElevation = 15;
constexpr double kViewerFov = 40;
constexpr double kViewerFill = 0.88;

struct CompleteOptions {
    Framing framing = Framing::OpenScad;
    /// Picture width / height when known (0: unknown, taken as landscape); Viewer framing
    /// fits the smaller side.
    double aspect = 0;
};

/// The Viewer framing's camera for a bounding sphere (centre, radius) and a picture aspect
/// (width / height; 0 when unknown).
Camera viewerCamera(const Vec3 &centre, double radius, double aspect);

/// Fills what the scene leaves out: when there is no camera, one that frames the model's bounds
/// (opts.framing: OpenSCAD's default view, viewall + autocenter, or a glTF viewer's); when there
/// are no lights, a key light with shadows and a shadowless fill placed relative to the camera. An
/// empty scene gets a camera looking at the origin. Notes what it added to `diag`. Validates the
/// scene first (ir::validateScene: out-of-range or non-finite input is a located SceneError) and
/// prunes subtrees without volume (ir::pruneEmpty), so every consumer sees the same solids.
void completeScene(Scene &scene, DiagnosticSink &diag, const CompleteOptions &opts = {});

}  // namespace rt::ir
