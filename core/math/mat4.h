// SPDX-License-Identifier: MIT
// 4x4 double matrix acting on column vectors (p' = M p), row-major storage m[row][col].
#pragma once

#include <optional>
#include <string>

#include "core/math/vec3.h"

namespace rt {

struct Mat4 {
    double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

    static Mat4 identity() { return Mat4(); }
    static Mat4 translate(const Vec3 &t);
    static Mat4 scale(const Vec3 &s);
    /// Rotation about a unit-less axis by an angle in degrees (Rodrigues); exact at multiples
    /// of 90.
    static Mat4 rotateAxis(double degrees, const Vec3 &axis);
    static Mat4 rotateX(double degrees);
    static Mat4 rotateY(double degrees);
    static Mat4 rotateZ(double degrees);
    /// Householder reflection about the plane through the origin with normal n: I - 2 n n^T /
    /// (n.n).
    static Mat4 mirror(const Vec3 &n);

    Mat4 operator*(const Mat4 &o) const;
    bool operator==(const Mat4 &o) const;
    bool operator!=(const Mat4 &o) const { return !(*this == o); }

    // Inline: every ray is moved into the object space of each primitive it is tested against
    Vec3 transformPoint(const Vec3 &p) const {
        return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
    }
    Vec3 transformVector(const Vec3 &v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    /// The last column's upper three entries: an affine map's translation.
    Vec3 translation() const { return {m[0][3], m[1][3], m[2][3]}; }
    Mat4 transposed() const;
    /// Determinant of the upper-left 3x3 block (orientation and volume scale of an affine map).
    double det3() const;
    bool isIdentity() const { return *this == Mat4(); }
    /// True when the bottom row is (0,0,0,1).
    bool isAffine() const;
    bool isFinite() const;
    /// Inverse of an affine matrix; empty when the 3x3 block is singular (relative to its scale).
    std::optional<Mat4> affineInverse() const;
    std::string toString() const;
};

}  // namespace rt
