// SPDX-License-Identifier: MIT
// Camera frame construction and primary rays.
#include "core/camera/camera.h"

#include <cmath>

#include "core/ir/diagnostics.h"
#include "core/math/float_util.h"

namespace rt {

Camera::Camera(const ir::Camera &c, int width, int height)
    : origin_(c.location), invWidth_(1.0 / width), invHeight_(1.0 / height) {
    double aspect = static_cast<double>(width) / height;
    Vec3 view = c.lookAt - c.location;
    if (!(lengthSquared(view) > 0) || !view.isFinite())
        throw SceneError(c.loc, "camera location and look_at coincide (or are not finite)");
    Vec3 d = normalize(view);
    Vec3 r = cross(d, c.sky);
    if (!(length(r) > 1e-12 * length(c.sky)))
        throw SceneError(c.loc, "camera sky vector is parallel to the view direction");
    Vec3 rightUnit = normalize(r);
    if (c.projection == ir::Projection::Orthographic) {
        // The film is orthoHeight tall and orthoHeight * aspect wide
        if (!(c.orthoHeight > 0))
            throw SceneError(c.loc, "orthographic view height must be positive");
        orthographic_ = true;
        up_ = cross(rightUnit, d) * c.orthoHeight;
        right_ = rightUnit * (c.orthoHeight * aspect);
        direction_ = d;
        return;
    }
    // POV-Ray: |right| = aspect, |up| = 1, |direction| = |right| / (2 tan(angle/2))
    double hfov = c.horizontalFov(aspect);
    if (!(hfov > 0 && hfov < 180))
        throw SceneError(c.loc, "camera field of view must be between 0 and 180 degrees");
    right_ = rightUnit * aspect;
    up_ = cross(rightUnit, d);
    direction_ = d * (aspect / (2 * std::tan(radians(hfov) / 2)));
}

Ray Camera::generateRay(double x, double y) const {
    double x0 = x * invWidth_ - 0.5;
    double y0 = 0.5 - y * invHeight_;
    if (orthographic_) return Ray(origin_ + right_ * x0 + up_ * y0, direction_);
    return Ray(origin_, normalize(direction_ + right_ * x0 + up_ * y0));
}

}  // namespace rt
