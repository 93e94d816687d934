// SPDX-License-Identifier: MIT
// Affine transform with its cached inverse; maps points, vectors, normals, rays and bounds,
// and propagates rounding-error bounds of points (pbrt-v3 section 3.9.4).
#pragma once

#include <optional>

#include "core/math/bounds3.h"
#include "core/math/float_util.h"
#include "core/math/mat4.h"
#include "core/math/ray.h"

namespace rt {

class Transform {
  public:
    Transform() = default;
    /// Builds a transform from an invertible affine matrix; empty when it is singular or not
    /// affine.
    static std::optional<Transform> fromMatrix(const Mat4 &m);
    Transform(const Mat4 &m, const Mat4 &mInv) : m_(m), mInv_(mInv) {}

    const Mat4 &matrix() const { return m_; }
    const Mat4 &inverseMatrix() const { return mInv_; }
    Transform inverse() const { return Transform(mInv_, m_); }
    Transform operator*(const Transform &o) const { return Transform(m_ * o.m_, o.mInv_ * mInv_); }
    bool isIdentity() const { return m_.isIdentity(); }
    /// True when the map reverses orientation (mirror, negative scale).
    bool swapsHandedness() const { return m_.det3() < 0; }

    Vec3 point(const Vec3 &p) const { return m_.transformPoint(p); }
    Vec3 inversePoint(const Vec3 &p) const { return mInv_.transformPoint(p); }
    /// Maps a ray by the inverse transform (world to object), keeping t.
    Ray inverseRay(const Ray &r) const {
        return Ray(mInv_.transformPoint(r.o), mInv_.transformVector(r.d));
    }
    Vec3 vector(const Vec3 &v) const { return m_.transformVector(v); }
    /// Normals transform by the inverse transpose.
    Vec3 normal(const Vec3 &n) const;
    /// Maps a point and returns a conservative bound on the absolute error of the result,
    /// given the absolute error pErr of the input.
    Vec3 point(const Vec3 &p, const Vec3 &pErr, Vec3 *outErr) const;
    /// Maps origin and direction; the ray parameter t is preserved (direction is not renormalised).
    Ray ray(const Ray &r) const { return Ray(point(r.o), vector(r.d)); }
    Bounds3 bounds(const Bounds3 &b) const;

  private:
    Mat4 m_, mInv_;
};

/// How much rounding error grows in a round trip through t and back: ||M||_F ||M^-1||_F / 3,
/// which is 1 for rotations and uniform scales and grows with shear and non-uniform scale.
double transformConditioning(const Transform &t);

}  // namespace rt
