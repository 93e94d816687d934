// SPDX-License-Identifier: MIT
// Axis-aligned bounding box with a NaN-safe, rounding-robust slab test (pbrt-v3 section 3.9.2).
#pragma once

#include <limits>

#include "core/math/float_util.h"
#include "core/math/ray.h"
#include "core/math/vec3.h"

namespace rt {

struct Bounds3 {
    /// Empty by default: min > max on every axis.
    Vec3 min{kInfinity}, max{-kInfinity};

    Bounds3() = default;
    Bounds3(const Vec3 &a, const Vec3 &b) : min(rt::min(a, b)), max(rt::max(a, b)) {}
    static Bounds3 point(const Vec3 &p) { return Bounds3(p, p); }
    static Bounds3 infinite() { return Bounds3(Vec3(-kInfinity), Vec3(kInfinity)); }

    bool isEmpty() const { return !(min.x <= max.x && min.y <= max.y && min.z <= max.z); }
    bool isFinite() const { return min.isFinite() && max.isFinite(); }
    Vec3 diagonal() const { return max - min; }
    Vec3 centroid() const { return (min + max) * 0.5; }
    /// Corner i (0..7): bit 0 picks max.x over min.x, bit 1 max.y, bit 2 max.z.
    Vec3 corner(int i) const {
        return {i & 1 ? max.x : min.x, i & 2 ? max.y : min.y, i & 4 ? max.z : min.z};
    }
    double surfaceArea() const {
        if (isEmpty()) return 0;
        Vec3 d = diagonal();
        return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
    }
    bool contains(const Vec3 &p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
    /// Offset of p in [0,1]^3 relative to the box (for SAH binning).
    Vec3 offset(const Vec3 &p) const {
        Vec3 o = p - min, d = diagonal();
        if (d.x > 0) o.x /= d.x;
        if (d.y > 0) o.y /= d.y;
        if (d.z > 0) o.z /= d.z;
        return o;
    }

    /// Slab test of the ray line against the box, clipped to [tMin, tMax]. NaN-safe: a component
    /// 0*inf = NaN never widens the interval; far distances are enlarged by 2 gamma(3) so the
    /// rounding of the slab distances cannot cull a real hit.
    bool intersectP(const Ray &ray, double tMin, double tMax, double *hit0 = nullptr,
                    double *hit1 = nullptr) const {
        return intersectP(ray, Vec3(1 / ray.d.x, 1 / ray.d.y, 1 / ray.d.z), tMin, tMax, hit0, hit1);
    }
    /// The same with the reciprocal of the ray's direction computed once by the caller.
    bool intersectP(const Ray &ray, const Vec3 &invDir, double tMin, double tMax,
                    double *hit0 = nullptr, double *hit1 = nullptr) const {
        double t0 = tMin, t1 = tMax;
        for (int i = 0; i < 3; ++i) {
            double invD = invDir[i];
            double tNear = (min[i] - ray.o[i]) * invD;
            double tFar = (max[i] - ray.o[i]) * invD;
            if (tNear > tFar) std::swap(tNear, tFar);
            tFar *= 1 + 2 * gamma(3);
            // Comparisons written so that NaN leaves t0/t1 unchanged
            t0 = tNear > t0 ? tNear : t0;
            t1 = tFar < t1 ? tFar : t1;
            if (t0 > t1) return false;
        }
        if (hit0) *hit0 = t0;
        if (hit1) *hit1 = t1;
        return true;
    }
};

inline Bounds3 unionBounds(const Bounds3 &a, const Bounds3 &b) {
    Bounds3 r;
    r.min = min(a.min, b.min);
    r.max = max(a.max, b.max);
    return r;
}
inline Bounds3 unionBounds(const Bounds3 &a, const Vec3 &p) {
    Bounds3 r;
    r.min = min(a.min, p);
    r.max = max(a.max, p);
    return r;
}
inline Bounds3 intersectBounds(const Bounds3 &a, const Bounds3 &b) {
    Bounds3 r;
    r.min = max(a.min, b.min);
    r.max = min(a.max, b.max);
    return r;
}

}  // namespace rt
