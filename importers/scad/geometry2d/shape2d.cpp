// SPDX-License-Identifier: MIT
// Outline geometry of the importer's 2D shapes (OpenSCAD 2021.01 primitives.cc createGeometry).
#include "importers/scad/geometry2d/shape2d.h"

#include <algorithm>
#include <cmath>

#include "core/math/degree_trig.h"
#include "core/meshing/facets.h"

namespace rt::scad {

namespace {

/// Corners whose turn is below this fraction of the product of their edge lengths count as
/// straight: what is left of them after rounding is noise, and keeping them would make a
/// convex polygon look reflex.
constexpr double kCollinearTolerance = 1e-12;

double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
double norm(Vec2 a) { return std::hypot(a.x, a.y); }

/// The turn at b of a -> b -> c, zero when the corner is straight within tolerance.
double turn(Vec2 a, Vec2 b, Vec2 c) {
    Vec2 u = b - a, v = c - b;
    double t = cross(u, v);
    return std::abs(t) <= kCollinearTolerance * norm(u) * norm(v) ? 0 : t;
}

/// Whether p, on the line through a and b, lies on the segment between them.
bool onSegment(Vec2 p, Vec2 a, Vec2 b) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

/// Orientation sign of c against the line a -> b.
int side(Vec2 a, Vec2 b, Vec2 c) {
    double t = cross(b - a, c - a);
    return (t > 0) - (t < 0);
}

}  // namespace

Affine2 Affine2::fromMat4(const Mat4 &m) {
    Affine2 a;
    a.m00 = m.m[0][0];
    a.m01 = m.m[0][1];
    a.tx = m.m[0][3];
    a.m10 = m.m[1][0];
    a.m11 = m.m[1][1];
    a.ty = m.m[1][3];
    return a;
}

Affine2 Affine2::operator*(const Affine2 &o) const {
    Affine2 r;
    r.m00 = m00 * o.m00 + m01 * o.m10;
    r.m01 = m00 * o.m01 + m01 * o.m11;
    r.m10 = m10 * o.m00 + m11 * o.m10;
    r.m11 = m10 * o.m01 + m11 * o.m11;
    r.tx = m00 * o.tx + m01 * o.ty + tx;
    r.ty = m10 * o.tx + m11 * o.ty + ty;
    return r;
}

bool Affine2::isIdentity() const {
    return m00 == 1 && m01 == 0 && m10 == 0 && m11 == 1 && tx == 0 && ty == 0;
}

std::vector<Outline> shapeOutlines(const Shape2d &s) {
    switch (s.kind) {
        case Shape2dKind::Square:
            return {{s.min, {s.max.x, s.min.y}, s.max, {s.min.x, s.max.y}}};
        case Shape2dKind::Circle: {
            // Vertices on the circle, the first on +X, counter-clockwise
            int n = meshing::openscadFragments(s.radius, s.fragments);
            Outline o(n);
            for (int i = 0; i < n; ++i) {
                double phi = 360.0 * i / n;
                o[i] = {s.radius * cosDegrees(phi), s.radius * sinDegrees(phi)};
            }
            return {o};
        }
        case Shape2dKind::Polygon:
            return s.outlines;
    }
    return {};
}

size_t shapePointCount(const Shape2d &s) {
    switch (s.kind) {
        case Shape2dKind::Square:
            return 4;
        case Shape2dKind::Circle:
            return static_cast<size_t>(meshing::openscadFragments(s.radius, s.fragments));
        case Shape2dKind::Polygon: {
            size_t n = 0;
            for (const Outline &o : s.outlines) n += o.size();
            return n;
        }
    }
    return 0;
}

double twiceSignedArea(const Outline &o) {
    // Relative to the first point, so far from the origin the products do not cancel digits
    double a = 0;
    for (size_t i = 1; i + 1 < o.size(); ++i) a += cross(o[i] - o[0], o[i + 1] - o[0]);
    return a;
}

Outline cleanOutline(const Outline &o) {
    Outline out;
    out.reserve(o.size());
    for (Vec2 p : o) {
        if (!out.empty() && out.back() == p) continue;
        // A straight corner at the previous point is dropped (repeatedly: dropping one can
        // straighten the one before)
        while (out.size() >= 2 && turn(out[out.size() - 2], out.back(), p) == 0) out.pop_back();
        out.push_back(p);
    }
    // The same at the seam, where the outline closes
    bool changed = true;
    while (changed && out.size() >= 3) {
        changed = false;
        if (out.front() == out.back()) {
            out.pop_back();
            changed = true;
        } else if (turn(out[out.size() - 2], out.back(), out.front()) == 0) {
            out.pop_back();
            changed = true;
        } else if (turn(out.back(), out.front(), out[1]) == 0) {
            out.erase(out.begin());
            changed = true;
        }
    }
    if (out.size() < 3) out.clear();
    return out;
}

bool isConvex(const Outline &ccw) {
    size_t n = ccw.size();
    if (n < 3) return false;
    double angle = 0;
    for (size_t i = 0; i < n; ++i) {
        Vec2 a = ccw[i], b = ccw[(i + 1) % n], c = ccw[(i + 2) % n];
        if (!(turn(a, b, c) > 0)) return false;
        Vec2 u = b - a, v = c - b;
        angle += std::atan2(cross(u, v), u.x * v.x + u.y * v.y);
    }
    // Left turns only, and once around: a star polygon turns left too, but twice or more
    return angle < 3 * M_PI;
}

Hull2d convexHull2d(std::vector<Vec2> points) {
    // Andrew's monotone chain: the lower then the upper chain of the points sorted by x, y.
    // A corner that does not turn left (within tolerance) is dropped, so collinear points
    // never become vertices, as in OpenSCAD's CGAL hull.
    Hull2d h;
    std::sort(points.begin(), points.end(),
              [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.empty()) return h;
    h.kind = points.size() == 1 ? meshing::HullKind::Point : meshing::HullKind::Line;
    if (points.size() < 3) return h;
    Outline chain;
    chain.reserve(points.size() + 1);
    auto add = [&chain](Vec2 p, size_t floor) {
        while (chain.size() >= floor + 2 && !(turn(chain[chain.size() - 2], chain.back(), p) > 0))
            chain.pop_back();
        chain.push_back(p);
    };
    for (Vec2 p : points) add(p, 0);
    size_t lower = chain.size() - 1;  // the upper chain starts at the rightmost point
    for (size_t i = points.size() - 1; i-- > 0;) add(points[i], lower);
    chain.pop_back();  // the leftmost point again
    if (chain.size() < 3) return h;
    h.kind = meshing::HullKind::Solid;
    h.ccw = std::move(chain);
    return h;
}

Outline clipConvex(const Outline &subject, const Outline &clip) {
    Outline out = subject;
    for (size_t i = 0; i < clip.size() && !out.empty(); ++i) {
        Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
        // Signed distance (times |b - a|) of a point to the left of the edge: inside is >= 0
        auto dist = [&](Vec2 p) { return cross(b - a, p - a); };
        Outline in = std::move(out);
        out.clear();
        for (size_t k = 0; k < in.size(); ++k) {
            Vec2 p = in[k], q = in[(k + 1) % in.size()];
            double dp = dist(p), dq = dist(q);
            if (dp >= 0) out.push_back(p);
            if ((dp < 0) != (dq < 0)) {
                double t = dp / (dp - dq);
                out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
            }
        }
    }
    return cleanOutline(out);
}

bool insideOutline(Vec2 p, const Outline &o) {
    bool in = false;
    for (size_t i = 0, j = o.size() - 1; i < o.size(); j = i++) {
        const Vec2 &a = o[i], &b = o[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            in = !in;
    }
    return in;
}

bool outlinesIntersect(const std::vector<Outline> &outlines) {
    struct Edge {
        Vec2 a, b;
        size_t outline, index;
        double minX, maxX;
    };
    std::vector<Edge> edges;
    for (size_t k = 0; k < outlines.size(); ++k) {
        const Outline &o = outlines[k];
        for (size_t i = 0; i < o.size(); ++i) {
            Vec2 a = o[i], b = o[(i + 1) % o.size()];
            edges.push_back({a, b, k, i, std::min(a.x, b.x), std::max(a.x, b.x)});
        }
    }
    // Sweep along x: only edges whose x ranges overlap can cross
    std::sort(edges.begin(), edges.end(),
              [](const Edge &e, const Edge &f) { return e.minX < f.minX; });
    for (size_t i = 0; i < edges.size(); ++i) {
        const Edge &e = edges[i];
        for (size_t j = i + 1; j < edges.size() && edges[j].minX <= e.maxX; ++j) {
            const Edge &f = edges[j];
            if (e.outline == f.outline) {
                size_t n = outlines[e.outline].size();
                if ((e.index + 1) % n == f.index || (f.index + 1) % n == e.index) continue;
            }
            // A proper crossing: each edge's ends lie strictly on both sides of the other
            int d1 = side(e.a, e.b, f.a), d2 = side(e.a, e.b, f.b);
            int d3 = side(f.a, f.b, e.a), d4 = side(f.a, f.b, e.b);
            if (d1 * d2 < 0 && d3 * d4 < 0) return true;
            // Touching: an end of one edge on the other (a repeated corner, a corner on an
            // edge, overlapping collinear edges)
            if ((d1 == 0 && onSegment(f.a, e.a, e.b)) || (d2 == 0 && onSegment(f.b, e.a, e.b)) ||
                (d3 == 0 && onSegment(e.a, f.a, f.b)) || (d4 == 0 && onSegment(e.b, f.a, f.b)))
                return true;
        }
    }
    return false;
}

std::vector<Region> evenOddRegions(const std::vector<Outline> &outlines) {
    // Nesting: the outlines containing each one (tested at a corner; outlines do not cross)
    size_t n = outlines.size();
    std::vector<int> depth(n, 0), parent(n, -1);
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = 0; j < n; ++j) {
            if (i == j || !insideOutline(outlines[i][0], outlines[j])) continue;
            ++depth[i];
            // The innermost container is the one nested deepest
            if (parent[i] < 0 || std::abs(twiceSignedArea(outlines[j])) <
                                     std::abs(twiceSignedArea(outlines[parent[i]])))
                parent[i] = static_cast<int>(j);
        }
    }
    auto ccw = [](Outline o) {
        if (twiceSignedArea(o) < 0) std::reverse(o.begin(), o.end());
        return o;
    };
    std::vector<Region> regions;
    std::vector<int> regionOf(n, -1);
    for (size_t i = 0; i < n; ++i) {
        if (depth[i] % 2) continue;
        regionOf[i] = static_cast<int>(regions.size());
        regions.push_back({ccw(outlines[i]), {}});
    }
    for (size_t i = 0; i < n; ++i)
        if (depth[i] % 2 && parent[i] >= 0 && regionOf[parent[i]] >= 0)
            regions[regionOf[parent[i]]].holes.push_back(ccw(outlines[i]));
    return regions;
}

}  // namespace rt::scad
