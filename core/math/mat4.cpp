// SPDX-License-Identifier: MIT
// 4x4 matrix construction, products and affine inversion.
#include "core/math/mat4.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/math/degree_trig.h"

namespace rt {

Mat4 Mat4::translate(const Vec3 &t) {
    Mat4 r;
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Mat4 Mat4::scale(const Vec3 &s) {
    Mat4 r;
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Mat4 Mat4::rotateX(double deg) {
    double s = sinDegrees(deg), c = cosDegrees(deg);
    Mat4 r;
    r.m[1][1] = c;
    r.m[1][2] = -s;
    r.m[2][1] = s;
    r.m[2][2] = c;
    return r;
}

Mat4 Mat4::rotateY(double deg) {
    double s = sinDegrees(deg), c = cosDegrees(deg);
    Mat4 r;
    r.m[0][0] = c;
    r.m[0][2] = s;
    r.m[2][0] = -s;
    r.m[2][2] = c;
    return r;
}

Mat4 Mat4::rotateZ(double deg) {
    double s = sinDegrees(deg), c = cosDegrees(deg);
    Mat4 r;
    r.m[0][0] = c;
    r.m[0][1] = -s;
    r.m[1][0] = s;
    r.m[1][1] = c;
    return r;
}

Mat4 Mat4::rotateAxis(double deg, const Vec3 &axis) {
    double len = length(axis);
    if (!(len > 0) || !std::isfinite(len)) return Mat4();
    Vec3 u = axis / len;
    double s = sinDegrees(deg), c = cosDegrees(deg);
    double t = 1 - c;
    Mat4 r;
    r.m[0][0] = u.x * u.x * t + c;
    r.m[0][1] = u.x * u.y * t - u.z * s;
    r.m[0][2] = u.x * u.z * t + u.y * s;
    r.m[1][0] = u.y * u.x * t + u.z * s;
    r.m[1][1] = u.y * u.y * t + c;
    r.m[1][2] = u.y * u.z * t - u.x * s;
    r.m[2][0] = u.z * u.x * t - u.y * s;
    r.m[2][1] = u.z * u.y * t + u.x * s;
    r.m[2][2] = u.z * u.z * t + c;
    return r;
}

Mat4 Mat4::mirror(const Vec3 &n) {
    double nn = dot(n, n);
    if (!(nn > 0) || !std::isfinite(nn)) return Mat4();
    Mat4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = (i == j ? 1.0 : 0.0) - 2.0 * n[i] * n[j] / nn;
    return r;
}

Mat4 Mat4::operator*(const Mat4 &o) const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

bool Mat4::operator==(const Mat4 &o) const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (m[i][j] != o.m[i][j]) return false;
    return true;
}

Mat4 Mat4::transposed() const {
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = m[j][i];
    return r;
}

double Mat4::det3() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

bool Mat4::isAffine() const { return m[3][0] == 0 && m[3][1] == 0 && m[3][2] == 0 && m[3][3] == 1; }

bool Mat4::isFinite() const {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(m[i][j])) return false;
    return true;
}

std::optional<Mat4> Mat4::affineInverse() const {
    if (!isFinite()) return std::nullopt;
    // Write the 3x3 block as A = D U, D the diagonal of its row norms and U with unit rows, so
    // A^-1 = U^-1 D^-1. det(U) is |det A| over Hadamard's bound: a scale-free measure of
    // singularity, and no product of entries can overflow or underflow, so scales of 1e-150
    // or 1e150 invert as exactly as a scale of 1.
    double rowNorm[3];
    double u[3][3];
    for (int i = 0; i < 3; ++i) {
        double big = std::max({std::abs(m[i][0]), std::abs(m[i][1]), std::abs(m[i][2])});
        if (!(big > 0)) return std::nullopt;
        double a = m[i][0] / big, b = m[i][1] / big, c = m[i][2] / big;
        double n = std::sqrt(a * a + b * b + c * c);
        rowNorm[i] = big * n;
        if (!(rowNorm[i] > 0) || !std::isfinite(rowNorm[i])) return std::nullopt;
        u[i][0] = a / n;
        u[i][1] = b / n;
        u[i][2] = c / n;
    }
    double c00 = u[1][1] * u[2][2] - u[1][2] * u[2][1];
    double c01 = u[1][2] * u[2][0] - u[1][0] * u[2][2];
    double c02 = u[1][0] * u[2][1] - u[1][1] * u[2][0];
    double det = u[0][0] * c00 + u[0][1] * c01 + u[0][2] * c02;
    // Below this |det U| the rows are parallel to within about 1e-12 radians: the matrix
    // flattens space, and its inverse would amplify rounding by more than 1e12.
    constexpr double kSingularRatio = 1e-12;
    if (!(std::abs(det) > kSingularRatio)) return std::nullopt;
    double inv = 1.0 / det;
    double ui[3][3];  // U^-1 = adj(U) / det(U)
    ui[0][0] = c00 * inv;
    ui[0][1] = (u[0][2] * u[2][1] - u[0][1] * u[2][2]) * inv;
    ui[0][2] = (u[0][1] * u[1][2] - u[0][2] * u[1][1]) * inv;
    ui[1][0] = c01 * inv;
    ui[1][1] = (u[0][0] * u[2][2] - u[0][2] * u[2][0]) * inv;
    ui[1][2] = (u[0][2] * u[1][0] - u[0][0] * u[1][2]) * inv;
    ui[2][0] = c02 * inv;
    ui[2][1] = (u[0][1] * u[2][0] - u[0][0] * u[2][1]) * inv;
    ui[2][2] = (u[0][0] * u[1][1] - u[0][1] * u[1][0]) * inv;
    Mat4 r;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r.m[i][j] = ui[i][j] / rowNorm[j];
    // Translation: -A^-1 t
    Vec3 t = translation();
    for (int i = 0; i < 3; ++i) r.m[i][3] = -(r.m[i][0] * t.x + r.m[i][1] * t.y + r.m[i][2] * t.z);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            if (!std::isfinite(r.m[i][j])) return std::nullopt;
    return r;
}

std::string Mat4::toString() const {
    std::ostringstream os;
    os.precision(17);
    os << "[";
    for (int i = 0; i < 4; ++i) {
        os << (i ? ", [" : "[");
        for (int j = 0; j < 4; ++j) os << (j ? ", " : "") << m[i][j];
        os << "]";
    }
    os << "]";
    return os.str();
}

std::string Vec3::toString() const {
    std::ostringstream os;
    os.precision(17);
    os << "[" << x << ", " << y << ", " << z << "]";
    return os.str();
}

}  // namespace rt
