// SPDX-License-Identifier: MIT
// A ray o + t d; world rays have unit d, object-space rays keep the world parameter t.
#pragma once

#include "core/math/vec3.h"

namespace rt {

struct Ray {
    Vec3 o, d;
    Ray() = default;
    Ray(const Vec3 &o_, const Vec3 &d_) : o(o_), d(d_) {}
    Vec3 at(double t) const { return o + d * t; }
};

}  // namespace rt
