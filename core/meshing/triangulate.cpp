// SPDX-License-Identifier: MIT
// Triangulation of polygon faces as OpenSCAD 2021.01 does it, so both pick the same diagonals
// of non-planar faces: projection onto the coordinate plane across the normal's longest axis,
// a monotone-region triangulation, then edge flips towards the constrained Delaunay
// triangulation (libtess2 with TESS_CONSTRAINED_DELAUNAY_TRIANGLES, called from
// PolysetUtils::tessellate_faces / GeometryUtils::tessellatePolygonWithHoles).
#include "core/meshing/triangulate.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace rt::meshing {

namespace {

/// A polygon whose Newell area is below this fraction of its squared perimeter is treated as
/// degenerate: it is then a sliver whose normal is dominated by rounding error.
constexpr double kDegenerateAreaRatio = 1e-14;

/// libtess2 (OpenSCAD's copy, geom.c tesedgeIsLocallyDelaunay) flips an inner edge only when
/// the two angles facing it sum to at least pi + 0.01: near-cocircular corners (a square seen
/// along its normal) keep the diagonal of the monotone triangulation.
constexpr double kDelaunaySlack = 0.01;

struct Point2 {
    double s = 0, t = 0;
};

/// Twice the signed area of triangle abc (positive when counter-clockwise).
double orient(const Point2 &a, const Point2 &b, const Point2 &c) {
    return (b.s - a.s) * (c.t - a.t) - (b.t - a.t) * (c.s - a.s);
}

/// p inside or on the boundary of the counter-clockwise triangle abc.
bool inTriangle(const Point2 &p, const Point2 &a, const Point2 &b, const Point2 &c) {
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

bool samePoint(const Point2 &a, const Point2 &b) { return a.s == b.s && a.t == b.t; }

/// libtess2's sweep order: by s, then by t.
bool vertLeq(const Point2 &u, const Point2 &v) { return u.s < v.s || (u.s == v.s && u.t <= v.t); }

/// libtess2's EdgeSign for u <= v <= w: positive when v lies above the line uw.
double edgeSign(const Point2 &u, const Point2 &v, const Point2 &w) {
    double gapL = v.s - u.s, gapR = w.s - v.s;
    if (gapL + gapR > 0) return (v.t - w.t) * gapL + (v.t - u.t) * gapR;
    return 0;
}

/// Angle at b between b->a and b->c.
double cornerAngle(const Point2 &a, const Point2 &b, const Point2 &c) {
    double ux = a.s - b.s, uy = a.t - b.t, vx = c.s - b.s, vy = c.t - b.t;
    return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy);
}

using Tri = std::array<size_t, 3>;

/// Doubly linked ring of the corners not yet cut off.
struct Ring {
    std::vector<size_t> prev, next;
    explicit Ring(size_t n) : prev(n), next(n) {
        for (size_t i = 0; i < n; ++i) {
            prev[i] = (i + n - 1) % n;
            next[i] = (i + 1) % n;
        }
    }
    void remove(size_t i) {
        next[prev[i]] = next[i];
        prev[next[i]] = prev[i];
    }
};

/// Whether the ring's corners rise from the first in sweep order to the last along one side
/// and fall back along the other: one monotone region, which libtess2's sweep leaves whole.
bool isMonotone(const std::vector<Point2> &p, size_t lowest, size_t highest) {
    size_t n = p.size();
    for (size_t i = lowest; i != highest; i = (i + 1) % n)
        if (!vertLeq(p[i], p[(i + 1) % n])) return false;
    for (size_t i = highest; i != lowest; i = (i + 1) % n)
        if (!vertLeq(p[(i + 1) % n], p[i])) return false;
    return true;
}

/// libtess2's tessMeshTessellateMonoRegion (after GLU's tessmono.c) on a counter-clockwise
/// monotone ring: an edge is named by its origin corner, `up` starts at the rightmost corner
/// and `lo` just before it, and triangles are cut from whichever chain is further left.
std::vector<Tri> triangulateMonotone(const std::vector<Point2> &p, size_t highest) {
    Ring r(p.size());
    std::vector<Tri> tris;
    size_t up = highest, lo = r.prev[highest];
    auto cutAfter = [&](size_t a) {  // the triangle a, next, next-next; removes the middle one
        size_t b = r.next[a];
        tris.push_back({a, b, r.next[b]});
        r.remove(b);
    };
    while (r.next[up] != lo) {
        if (vertLeq(p[r.next[up]], p[lo])) {
            // up's far end is on the left: triangles from lo's origin
            while (r.next[lo] != up) {
                size_t b = r.next[lo], c = r.next[b];
                bool goesLeft = vertLeq(p[c], p[b]);
                if (!goesLeft && edgeSign(p[lo], p[b], p[c]) > 0) break;
                cutAfter(lo);
            }
            lo = r.prev[lo];
        } else {
            // lo's origin is on the left: triangles towards up's far end
            while (r.next[lo] != up) {
                size_t a = r.prev[up];
                bool goesRight = vertLeq(p[a], p[up]);
                if (!goesRight && edgeSign(p[r.next[up]], p[up], p[a]) < 0) break;
                tris.push_back({a, up, r.next[up]});
                r.remove(up);
                up = a;
            }
            up = r.next[up];
        }
    }
    // The rest is a fan from the leftmost corner
    while (r.next[r.next[lo]] != up) cutAfter(lo);
    tris.push_back({lo, r.next[lo], r.next[r.next[lo]]});
    return tris;
}

/// Ear clipping for rings that are not monotone (libtess2 would split them along sweep
/// diagonals first; after the Delaunay flips the two agree except at near-cocircular corners).
std::vector<Tri> triangulateByEars(const std::vector<Point2> &pts) {
    size_t n = pts.size();
    Ring r(n);
    auto convex = [&](size_t i) { return orient(pts[r.prev[i]], pts[i], pts[r.next[i]]) > 0; };
    // Only reflex corners can lie inside an ear; a corner never turns reflex by clipping, so
    // the list only needs pruning
    std::vector<size_t> reflex;
    std::vector<char> removed(n, 0);
    for (size_t i = 0; i < n; ++i)
        if (!convex(i)) reflex.push_back(i);

    auto isEar = [&](size_t i) {
        if (!convex(i)) return false;
        const Point2 &a = pts[r.prev[i]], &b = pts[i], &c = pts[r.next[i]];
        for (size_t k : reflex) {
            if (removed[k] || k == r.prev[i] || k == i || k == r.next[i]) continue;
            const Point2 &q = pts[k];
            // Repeated points (a polygon touching itself) do not block the ear
            if (samePoint(q, a) || samePoint(q, b) || samePoint(q, c)) continue;
            if (inTriangle(q, a, b, c)) return false;
        }
        return true;
    };

    std::vector<Tri> tris;
    size_t remaining = n;
    size_t cursor = 0;
    size_t sinceClip = 0;  // corners examined since the last clip
    bool relaxed = false;  // no proper ear left: clip any convex corner (self-touching input)
    while (remaining > 3) {
        bool clip = relaxed ? convex(cursor) : isEar(cursor);
        if (clip) {
            size_t a = r.prev[cursor];
            tris.push_back({a, cursor, r.next[cursor]});
            removed[cursor] = 1;
            r.remove(cursor);
            --remaining;
            cursor = a;
            sinceClip = 0;
            relaxed = false;
            continue;
        }
        cursor = r.next[cursor];
        if (++sinceClip > remaining) {
            if (relaxed) break;  // only collinear or reflex corners remain: no area left
            relaxed = true;
            sinceClip = 0;
        }
    }
    if (remaining == 3) {
        size_t a = r.prev[cursor], c = r.next[cursor];
        if (orient(pts[a], pts[cursor], pts[c]) > 0) tris.push_back({a, cursor, c});
    }
    return tris;
}

/// Flips inner edges whose facing angles sum to pi + kDelaunaySlack or more until none is left
/// (libtess2's tessMeshRefineDelaunay): a stack of edges to check, first every inner edge,
/// then after each flip the four edges around the new one; each flip lowers that sum below
/// pi, so it ends. Edges are found through a map, so the work grows with the flips, not with
/// the square of the triangle count.
void refineDelaunay(const std::vector<Point2> &p, std::vector<Tri> &tris) {
    auto key = [](size_t a, size_t b) { return (static_cast<uint64_t>(a) << 32) | b; };
    // Directed edge -> triangle holding it
    std::unordered_map<uint64_t, size_t> owner;
    owner.reserve(3 * tris.size());
    for (size_t i = 0; i < tris.size(); ++i)
        for (int e = 0; e < 3; ++e) owner[key(tris[i][e], tris[i][(e + 1) % 3])] = i;
    std::vector<std::pair<size_t, size_t>> stack;
    for (size_t i = tris.size(); i-- > 0;)
        for (int e = 3; e-- > 0;) {
            size_t a = tris[i][e], b = tris[i][(e + 1) % 3];
            if (a < b && owner.count(key(b, a))) stack.push_back({a, b});
        }
    size_t limit = tris.size() * tris.size() + 1;  // guard, as libtess2's, against rounding
    auto third = [&](const Tri &t, size_t a, size_t b) {
        for (size_t v : t)
            if (v != a && v != b) return v;
        return a;
    };
    while (!stack.empty() && limit > 0) {
        auto [u, v] = stack.back();
        stack.pop_back();
        auto fi = owner.find(key(u, v)), fj = owner.find(key(v, u));
        if (fi == owner.end() || fj == owner.end()) continue;  // flipped away meanwhile
        size_t i = fi->second, j = fj->second;
        size_t a = u, b = v, c = third(tris[i], a, b), d = third(tris[j], a, b);
        double sum = cornerAngle(p[a], p[c], p[b]) + cornerAngle(p[b], p[d], p[a]);
        // The quad a d b c must be convex for the other diagonal to lie inside
        if (!(sum >= M_PI + kDelaunaySlack && orient(p[c], p[a], p[d]) > 0 &&
              orient(p[d], p[b], p[c]) > 0))
            continue;
        for (const Tri *t : {&tris[i], &tris[j]})
            for (int e = 0; e < 3; ++e) owner.erase(key((*t)[e], (*t)[(e + 1) % 3]));
        tris[i] = {c, a, d};
        tris[j] = {d, b, c};
        for (size_t t : {i, j})
            for (int e = 0; e < 3; ++e) owner[key(tris[t][e], tris[t][(e + 1) % 3])] = t;
        --limit;
        for (auto [x, y] : {std::pair{a, d}, std::pair{d, b}, std::pair{b, c}, std::pair{c, a}})
            stack.push_back({std::min(x, y), std::max(x, y)});
    }
}

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

    // libtess2's projection: drop the normal's longest axis (the first of equals), s along the
    // next axis, t along the one after, t's sign making the polygon counter-clockwise
    int axis = 0;
    if (std::abs(normal.y) > std::abs(normal.x)) axis = 1;
    if (std::abs(normal.z) > std::abs(normal[axis])) axis = 2;
    int sAxis = (axis + 1) % 3, tAxis = (axis + 2) % 3;
    double tSign = normal[axis] > 0 ? 1 : -1;
    std::vector<Point2> pts(n);
    size_t lowest = 0, highest = 0;
    for (size_t i = 0; i < n; ++i) {
        Vec3 d = positions[ring[i]] - origin;
        pts[i] = {d[sAxis], tSign * d[tAxis]};
        if (!vertLeq(pts[lowest], pts[i])) lowest = i;
        if (!vertLeq(pts[i], pts[highest])) highest = i;
    }

    std::vector<Tri> tris;
    if (n == 3)
        tris.push_back({0, 1, 2});
    else if (isMonotone(pts, lowest, highest))
        tris = triangulateMonotone(pts, highest);
    else
        tris = triangulateByEars(pts);
    if (tris.empty()) return false;
    refineDelaunay(pts, tris);
    for (const Tri &t : tris) out.push_back({ring[t[0]], ring[t[1]], ring[t[2]]});
    return true;
}

}  // namespace rt::meshing
