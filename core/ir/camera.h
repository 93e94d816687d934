// SPDX-License-Identifier: MIT
// IR perspective camera in the right-handed Z-up world.
#pragma once

#include "core/ir/source_loc.h"
#include "core/math/vec3.h"

namespace rt::ir {

enum class FovAxis { Horizontal, Vertical };

/// Where the camera came from, for the render plan and the exporter's comments.
enum class CameraSource { Explicit, ViewportVariables, Automatic };

enum class Projection { Perspective, Orthographic };

struct Camera {
    Projection projection = Projection::Perspective;
    /// Orthographic only: width and height of the view in world units (the image's aspect
    /// decides which of them is used: the vertical one is kept, as in glTF viewers).
    double orthoHeight = 2;
    Vec3 location{0, -10, 5};
    Vec3 lookAt{0, 0, 0};
    Vec3 sky{0, 0, 1};
    /// Full field of view in degrees along fovAxis.
    double fov = 40;
    FovAxis fovAxis = FovAxis::Horizontal;
    CameraSource source = CameraSource::Explicit;
    SourceLoc loc;

    /// Horizontal full field of view in degrees for an image of the given width/height.
    double horizontalFov(double aspect) const;
};

}  // namespace rt::ir
