// SPDX-License-Identifier: MIT
// Ear-clipping triangulation of planar polygons in the plane of their Newell normal.
#include <cmath>

#include "importers/mesh/mesh_reader.h"

namespace rt::meshio {

namespace {

/// A polygon whose Newell area is below this fraction of its squared perimeter is treated as
/// degenerate: it is then a sliver whose normal is dominated by rounding error.
constexpr double kDegenerateAreaRatio = 1e-14;

struct Point2 {
    double x = 0, y = 0;
};

/// Twice the signed area of triangle abc (positive when counter-clockwise).
double orient(const Point2 &a, const Point2 &b, const Point2 &c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// p inside or on the boundary of the counter-clockwise triangle abc.
bool inTriangle(const Point2 &p, const Point2 &a, const Point2 &b, const Point2 &c) {
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

bool samePoint(const Point2 &a, const Point2 &b) { return a.x == b.x && a.y == b.y; }

}  // namespace

bool triangulatePolygon(const std::vector<Vec3> &positions, const std::vector<uint32_t> &polygon,
                        std::vector<std::array<uint32_t, 3>> &out) {
    // Drop repeated corners (the same index, or the same point, twice in a row)
    std::vector<uint32_t> ring;
    ring.reserve(polygon.size());
    for (uint32_t v : polygon) {
        if (v >= positions.size()) return false;
        if (!ring.empty() && (ring.back() == v || positions[ring.back()] == positions[v])) continue;
        ring.push_back(v);
    }
    while (ring.size() > 1 &&
           (ring.front() == ring.back() || positions[ring.front()] == positions[ring.back()]))
        ring.pop_back();
    size_t n = ring.size();
    if (n < 3) return false;

    // Newell normal: robust for concave and slightly non-planar polygons; its length is twice
    // the area (F. Tampieri, "Newell's Method for Computing the Plane Equation of a Polygon",
    // Graphics Gems III)
    // (relative to the first corner: far from the origin, the sums would cancel digits)
    const Vec3 &origin = positions[ring[0]];
    Vec3 normal(0);
    double perimeter = 0;
    for (size_t i = 0; i < n; ++i) {
        Vec3 a = positions[ring[i]] - origin, b = positions[ring[(i + 1) % n]] - origin;
        normal.x += (a.y - b.y) * (a.z + b.z);
        normal.y += (a.z - b.z) * (a.x + b.x);
        normal.z += (a.x - b.x) * (a.y + b.y);
        perimeter += length(b - a);
    }
    double twiceArea = length(normal);
    if (!(twiceArea > kDegenerateAreaRatio * perimeter * perimeter)) return false;
    Vec3 w = normal / twiceArea;

    // Orthonormal basis (u, v, w): the polygon is counter-clockwise in (u, v) because w is its
    // own normal, so clipping convex corners keeps the orientation
    Vec3 helper = std::abs(w.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    Vec3 u = normalize(cross(helper, w));
    Vec3 v = cross(w, u);
    std::vector<Point2> pts(n);
    for (size_t i = 0; i < n; ++i) {
        Vec3 d = positions[ring[i]] - origin;
        pts[i] = {dot(d, u), dot(d, v)};
    }

    if (n == 3) {
        out.push_back({ring[0], ring[1], ring[2]});
        return true;
    }

    // Doubly linked ring of the corners not yet clipped
    std::vector<size_t> prev(n), next(n);
    for (size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    auto convex = [&](size_t i) { return orient(pts[prev[i]], pts[i], pts[next[i]]) > 0; };
    // Only reflex corners can lie inside an ear; a corner never turns reflex by clipping, so
    // the list only needs pruning
    std::vector<size_t> reflex;
    std::vector<char> removed(n, 0);
    for (size_t i = 0; i < n; ++i)
        if (!convex(i)) reflex.push_back(i);

    auto isEar = [&](size_t i) {
        if (!convex(i)) return false;
        const Point2 &a = pts[prev[i]], &b = pts[i], &c = pts[next[i]];
        for (size_t r : reflex) {
            if (removed[r] || r == prev[i] || r == i || r == next[i]) continue;
            const Point2 &p = pts[r];
            // Repeated points (a polygon touching itself) do not block the ear
            if (samePoint(p, a) || samePoint(p, b) || samePoint(p, c)) continue;
            if (inTriangle(p, a, b, c)) return false;
        }
        return true;
    };

    std::vector<std::array<uint32_t, 3>> tris;
    tris.reserve(n - 2);
    size_t remaining = n;
    size_t cursor = 0;
    size_t sinceClip = 0;  // corners examined since the last clip
    bool relaxed = false;  // no proper ear left: clip any convex corner (self-touching input)
    while (remaining > 3) {
        bool clip = relaxed ? convex(cursor) : isEar(cursor);
        if (clip) {
            size_t a = prev[cursor], c = next[cursor];
            tris.push_back({ring[a], ring[cursor], ring[c]});
            removed[cursor] = 1;
            next[a] = c;
            prev[c] = a;
            --remaining;
            cursor = a;
            sinceClip = 0;
            relaxed = false;
            continue;
        }
        cursor = next[cursor];
        if (++sinceClip > remaining) {
            if (relaxed) break;  // only collinear or reflex corners remain: no area left
            relaxed = true;
            sinceClip = 0;
        }
    }
    if (remaining == 3) {
        size_t a = prev[cursor], c = next[cursor];
        if (orient(pts[a], pts[cursor], pts[c]) > 0)
            tris.push_back({ring[a], ring[cursor], ring[c]});
    }
    if (tris.empty()) return false;
    out.insert(out.end(), tris.begin(), tris.end());
    return true;
}

}  // namespace rt::meshio
