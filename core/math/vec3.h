// SPDX-License-Identifier: MIT
// Three-component double vector used for points, directions and normals in world and object space.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

namespace rt {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
    constexpr explicit Vec3(double s) : x(s), y(s), z(s) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    double &operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3 operator+(const Vec3 &o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Vec3 operator-(const Vec3 &o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }
    Vec3 &operator+=(const Vec3 &o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    Vec3 &operator-=(const Vec3 &o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    Vec3 &operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Vec3 &o) const { return x == o.x && y == o.y && z == o.z; }
    constexpr bool operator!=(const Vec3 &o) const { return !(*this == o); }

    bool isFinite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
    std::string toString() const;
};

constexpr Vec3 operator*(double s, const Vec3 &v) { return v * s; }
constexpr double dot(const Vec3 &a, const Vec3 &b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double absDot(const Vec3 &a, const Vec3 &b) { return std::abs(dot(a, b)); }
constexpr Vec3 cross(const Vec3 &a, const Vec3 &b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr Vec3 mul(const Vec3 &a, const Vec3 &b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
constexpr double lengthSquared(const Vec3 &v) { return dot(v, v); }
inline double length(const Vec3 &v) { return std::sqrt(lengthSquared(v)); }
inline Vec3 normalize(const Vec3 &v) { return v / length(v); }
inline Vec3 abs(const Vec3 &v) { return {std::abs(v.x), std::abs(v.y), std::abs(v.z)}; }
inline Vec3 min(const Vec3 &a, const Vec3 &b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 max(const Vec3 &a, const Vec3 &b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline double maxComponent(const Vec3 &v) { return std::max({v.x, v.y, v.z}); }
inline int maxDimension(const Vec3 &v) {
    return (v.x > v.y) ? (v.x > v.z ? 0 : 2) : (v.y > v.z ? 1 : 2);
}
/// Flips n so that it lies in the hemisphere of v.
inline Vec3 faceForward(const Vec3 &n, const Vec3 &v) { return dot(n, v) < 0 ? -n : n; }

}  // namespace rt
