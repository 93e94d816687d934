// SPDX-License-Identifier: MIT
// Automatic camera framing and default lights for scenes that do not set them.
#include "core/ir/scene_defaults.h"

#include <cmath>
#include <sstream>

#include "core/ir/ir_simplify.h"
#include "core/ir/ir_validate.h"
#include "core/math/float_util.h"

namespace rt::ir {

namespace {

/// Key light: above, to the left of and behind the viewer, casting shadows.
constexpr double kKeyIntensity = 0.8;
/// Fill light: to the right of the viewer, shadowless, so shadowed sides keep their shape.
constexpr double kFillIntensity = 0.3;
/// Lights sit this many viewing distances from the target, so their fall-off across the
/// model is small.
constexpr double kLightDistanceFactor = 2;

}  // namespace

Camera cameraFromViewport(const Vec3 &vpt, const Vec3 &vpr, double vpd, double vpf) {
    Mat4 rinv = Mat4::rotateZ(vpr.z) * Mat4::rotateY(vpr.y) * Mat4::rotateX(vpr.x - 90);
    Camera c;
    c.location = vpt + rinv.transformVector(Vec3(0, -vpd, 0));
    c.lookAt = vpt;
    c.sky = rinv.transformVector(Vec3(0, 0, 1));
    c.fov = vpf;
    c.fovAxis = FovAxis::Vertical;
    c.source = CameraSource::ViewportVariables;
    return c;
}

/// Viewer framing (Framing::Viewer) of the bounding sphere (centre, radius).
Camera viewerCamera(const Vec3 &centre, double radius, double aspect) {
    // The sphere's outline, seen from distance D, has angular radius asin(r / D); its image
    // spans tan of that over tan(fov / 2) of the smaller side
    double halfFov = radians(kViewerFov) / 2;
    double alpha = std::atan(kViewerFill * std::tan(halfFov));
    double distance = radius / std::sin(alpha);
    double az = radians(kViewerAzimuth), el = radians(kViewerElevation);
    Vec3 dir(std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el), std::sin(el));
    Camera c;
    c.location = centre + dir * distance;
    c.lookAt = centre;
    c.sky = Vec3(0, 0, 1);
    c.fov = kViewerFov;
    c.fovAxis = aspect > 0 && aspect < 1 ? FovAxis::Horizontal : FovAxis::Vertical;
    c.source = CameraSource::Automatic;
    return c;
}

void completeScene(Scene &scene, DiagnosticSink &diag, const CompleteOptions &opts) {
    validateScene(scene, diag);
    pruneEmpty(scene, diag);
    if (!scene.camera) {
        Bounds3 b = worldBounds(*scene.root, Mat4(), &scene);
        Vec3 centre(0);
        double radius = 1;
        if (!b.isEmpty() && b.isFinite()) {
            centre = b.centroid();
            radius = std::max(length(b.diagonal()) / 2, 1e-300);
        }
        std::ostringstream msg;
        if (opts.framing == Framing::Viewer) {
            scene.camera = viewerCamera(centre, radius, opts.aspect);
            msg << "no camera in the scene: framing the model as a glTF viewer does (from the "
                   "front-right, above), eye at ";
        } else {
            // OpenSCAD's viewall + autocenter: the bounding sphere fills the vertical field of
            // view
            double distance = radius / std::sin(radians(kOpenScadDefaultFov) / 2);
            Camera c = cameraFromViewport(centre, kOpenScadDefaultViewRotation, distance,
                                          kOpenScadDefaultFov);
            c.source = CameraSource::Automatic;
            scene.camera = c;
            msg << "no camera() in the scene: framing the model from OpenSCAD's default view, "
                   "eye at ";
        }
        msg << scene.camera->location.toString();
        diag.note({}, msg.str());
    }
    if (scene.lights.empty()) {
        const Camera &c = *scene.camera;
        Vec3 view = c.lookAt - c.location;
        double distance = length(view);
        Vec3 back = -normalize(view);
        Vec3 right = normalize(cross(-back, c.sky));
        Vec3 up = cross(right, -back);
        Light key;
        key.position =
            c.lookAt + normalize(back + up * 0.8 - right * 0.6) * (distance * kLightDistanceFactor);
        key.color = Rgb(kKeyIntensity);
        Light fill;
        fill.position =
            c.lookAt + normalize(back + right * 0.8 - up * 0.2) * (distance * kLightDistanceFactor);
        fill.color = Rgb(kFillIntensity);
        fill.shadowless = true;
        scene.lights = {key, fill};
        diag.note({},
                  "no lights in the scene: using a key light with shadows and a shadowless "
                  "fill light placed relative to the camera");
    }
}

}  // namespace rt::ir
