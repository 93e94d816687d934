// SPDX-License-Identifier: MIT
// Perspective pinhole or orthographic camera with POV-Ray 3.7's look_at construction
// (docs/design/povray-semantics.md section 7), right-handed: a film position maps to the same
// ray POV-Ray traces for it. Orthographic rays start on the film rectangle (right x up)
// through the location and all run along the view direction.
#pragma once

#include "core/ir/camera.h"
#include "core/math/ray.h"

namespace rt {

class Camera {
  public:
    /// Throws SceneError when location == look_at or sky is parallel to the view direction.
    Camera(const ir::Camera &c, int width, int height);

    /// Ray through film position (x, y) in pixel units, (0,0) the top-left corner of the image:
    /// pixel (i, j)'s centre is (i + 0.5, j + 0.5). The direction is unit length.
    Ray generateRay(double x, double y) const;
    const Vec3 &position() const { return origin_; }

  private:
    bool orthographic_ = false;
    Vec3 origin_, direction_, right_, up_;
    double invWidth_, invHeight_;
};

}  // namespace rt
