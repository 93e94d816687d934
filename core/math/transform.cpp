// SPDX-License-Identifier: MIT
// Affine transform operations with error propagation.
#include "core/math/transform.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::optional<Transform> Transform::fromMatrix(const Mat4 &m) {
    if (!m.isAffine()) return std::nullopt;
    auto inv = m.affineInverse();
    if (!inv) return std::nullopt;
    return Transform(m, *inv);
}

Vec3 Transform::normal(const Vec3 &n) const {
    const auto &mi = mInv_.m;
    return {mi[0][0] * n.x + mi[1][0] * n.y + mi[2][0] * n.z,
            mi[0][1] * n.x + mi[1][1] * n.y + mi[2][1] * n.z,
            mi[0][2] * n.x + mi[1][2] * n.y + mi[2][2] * n.z};
}

Vec3 Transform::point(const Vec3 &p, const Vec3 &pErr, Vec3 *outErr) const {
    const auto &m = m_.m;
    Vec3 r = m_.transformPoint(p);
    // Rounding of the product itself (gamma(3) per component) plus the input error scaled by |M|
    // and the error of that scaling (pbrt-v3 eq. 3.12).
    for (int i = 0; i < 3; ++i) {
        double absProduct = std::abs(m[i][0] * p.x) + std::abs(m[i][1] * p.y) +
                            std::abs(m[i][2] * p.z) + std::abs(m[i][3]);
        double propagated =
            std::abs(m[i][0]) * pErr.x + std::abs(m[i][1]) * pErr.y + std::abs(m[i][2]) * pErr.z;
        (*outErr)[i] = gamma(3) * absProduct + (gamma(3) + 1) * propagated;
    }
    return r;
}

Bounds3 Transform::bounds(const Bounds3 &b) const {
    if (b.isEmpty()) return b;
    // Arvo's method: each output axis gathers min/max of the products per input axis.
    const auto &m = m_.m;
    Vec3 lo = m_.translation(), hi = lo;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double a = m[i][j] * b.min[j], c = m[i][j] * b.max[j];
            lo[i] += std::min(a, c);
            hi[i] += std::max(a, c);
        }
    // Pad by the rounding error of the sums so transformed bounds stay conservative.
    Vec3 pad = max(abs(lo), abs(hi)) * gamma(4);
    return Bounds3(lo - pad, hi + pad);
}

namespace {

double frobenius3(const Mat4 &m) {
    double s = 0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) s += m.m[i][j] * m.m[i][j];
    return std::sqrt(s);
}

}  // namespace

double transformConditioning(const Transform &t) {
    return std::max(1.0, frobenius3(t.matrix()) * frobenius3(t.inverseMatrix()) / 3);
}

}  // namespace rt
