// SPDX-License-Identifier: MIT
// A box placed by the identity or a translation, whose crossings and surfaces a walk over the
// scene finds inline.
#pragma once

#include "core/geometry/shape.h"

namespace rt {

/// A Box leaf whose placement is the identity or a translation (the floor tiles and the
/// `translate()`d cubes of most scenes), seen by value: firstCrossing() and surfaceAt() give
/// PrimitiveInstance's results bit for bit, with the same operations in the same order
/// (Box::slabSpan, Box::surfaceOf, Placement::pointToWorld), without its two virtual calls per
/// query, and with the ray's reciprocal direction computed once for every box it meets
/// instead of three divisions per box.
class AxisBox {
  public:
    AxisBox() = default;
    /// The shape as such a box, or an empty AxisBox (leaf() null) when it is not one.
    static AxisBox of(const Shape &shape) {
        AxisBox b;
        const auto *pi = dynamic_cast<const PrimitiveInstance *>(&shape);
        const auto *box = pi ? dynamic_cast<const Box *>(&pi->primitive()) : nullptr;
        if (!box || pi->placement().kind() == Placement::Kind::General) return b;
        b.min_ = box->min();
        b.max_ = box->max();
        b.shift_ = pi->placement().toObjectShift();
        b.shifted_ = pi->placement().kind() == Placement::Kind::Translation;
        b.leaf_ = pi;
        return b;
    }
    const PrimitiveInstance *leaf() const { return leaf_; }

    /// PrimitiveInstance::firstCrossing; `invDir`: 1 / ray.d, component by component.
    bool firstCrossing(const Ray &ray, const Vec3 &invDir, double tMin, double tMax,
                       Crossing *c) const {
        PrimitiveSpan s;
        return Box::slabSpan(min_, max_, objectOrigin(ray), ray.d, invDir, &s) &&
               PrimitiveInstance::firstCrossingOf(s, leaf_, tMin, tMax, c);
    }
    /// PrimitiveInstance::surfaceAt. The box's normal, along an axis, is a unit vector already,
    /// which normalising would leave as it is, bit for bit.
    SurfaceInteraction surfaceAt(const Ray &ray, const Crossing &c) const {
        SurfaceInteraction si;
        ObjectSurface os = Box::surfaceOf(min_, max_, objectOrigin(ray) + ray.d * c.t, c.face);
        si.t = c.t;
        si.leaf = leaf_;
        leaf_->placement().pointToWorld(os, si);
        si.n = si.ns = os.normal;
        return si;
    }

  private:
    /// Placement::toObject's origin
    Vec3 objectOrigin(const Ray &ray) const { return shifted_ ? ray.o + shift_ : ray.o; }

    Vec3 min_, max_, shift_;
    const PrimitiveInstance *leaf_ = nullptr;
    bool shifted_ = false;  ///< a translation (else the identity)
};

}  // namespace rt
