// SPDX-License-Identifier: MIT
// OpenSCAD's rotate_extrude tessellation (GeometryEvaluator.cc rotatePolygon, 2021.01) and the
// triangulation of a profile with holes for the end faces of a partial turn.
#include "core/meshing/revolved_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/math/degree_trig.h"

namespace rt::meshing {

using namespace ir;

namespace {

using Ref = std::pair<int, int>;  // (outline, vertex)

double orient(const ProfilePoint &a, const ProfilePoint &b, const ProfilePoint &c) {
    return (b.r - a.r) * (c.z - a.z) - (b.z - a.z) * (c.r - a.r);
}

bool same(const ProfilePoint &a, const ProfilePoint &b) { return a.r == b.r && a.z == b.z; }

double signedArea(const ProfileOutline &o) {
    double a = 0;
    for (size_t i = 0; i < o.size(); ++i) {
        const ProfilePoint &p = o[i], &q = o[(i + 1) % o.size()];
        a += p.r * q.z - q.r * p.z;
    }
    return 0.5 * a;
}

/// Even-odd point-in-outline test (crossings of the half-line towards +r).
bool insideOutline(const ProfilePoint &p, const ProfileOutline &o) {
    bool in = false;
    for (size_t i = 0; i < o.size(); ++i) {
        const ProfilePoint &a = o[i], &b = o[(i + 1) % o.size()];
        if ((a.z > p.z) == (b.z > p.z)) continue;
        double rc = a.r + (p.z - a.z) * (b.r - a.r) / (b.z - a.z);
        if (p.r < rc) in = !in;
    }
    return in;
}

/// How many other outlines hold outline k: even for an outer boundary, odd for a hole.
std::vector<int> nestingDepths(const std::vector<ProfileOutline> &outlines) {
    std::vector<int> depth(outlines.size(), 0);
    for (size_t k = 0; k < outlines.size(); ++k)
        for (size_t j = 0; j < outlines.size(); ++j)
            if (j != k && !outlines[k].empty() && outlines[j].size() >= 3 &&
                insideOutline(outlines[k][0], outlines[j]))
                ++depth[k];
    return depth;
}

/// Segments pq and ab cross at a point inside both (touching does not count).
bool crossProperly(const ProfilePoint &p, const ProfilePoint &q, const ProfilePoint &a,
                   const ProfilePoint &b) {
    double d1 = orient(p, q, a), d2 = orient(p, q, b), d3 = orient(a, b, p), d4 = orient(a, b, q);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/// p inside or on the counter-clockwise triangle abc.
bool inTriangle(const ProfilePoint &p, const ProfilePoint &a, const ProfilePoint &b,
                const ProfilePoint &c) {
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

std::vector<int> profileParents(const std::vector<ProfileOutline> &outlines) {
    std::vector<int> depth = nestingDepths(outlines), parent(outlines.size(), -1);
    for (size_t k = 0; k < outlines.size(); ++k)
        for (size_t j = 0; j < outlines.size(); ++j)
            if (j != k && !outlines[k].empty() && outlines[j].size() >= 3 &&
                insideOutline(outlines[k][0], outlines[j]) &&
                (parent[k] < 0 || depth[j] > depth[parent[k]]))
                parent[k] = static_cast<int>(j);
    return parent;
}

std::vector<std::array<Ref, 3>> triangulateProfile(const std::vector<ProfileOutline> &outlines) {
    auto at = [&](const Ref &r) -> const ProfilePoint & { return outlines[r.first][r.second]; };
    std::vector<int> depth = nestingDepths(outlines);
    // Outlines as vertex loops, outer boundaries counter-clockwise and holes clockwise
    std::vector<std::vector<Ref>> loops(outlines.size());
    for (size_t k = 0; k < outlines.size(); ++k) {
        if (outlines[k].size() < 3) continue;
        for (size_t i = 0; i < outlines[k].size(); ++i)
            loops[k].push_back({static_cast<int>(k), static_cast<int>(i)});
        bool ccw = signedArea(outlines[k]) > 0;
        if (ccw != (depth[k] % 2 == 0)) std::reverse(loops[k].begin(), loops[k].end());
    }
    std::vector<std::array<Ref, 3>> tris;
    for (size_t k = 0; k < outlines.size(); ++k) {
        if (loops[k].empty() || depth[k] % 2) continue;
        // The holes directly inside this boundary, the one reaching furthest out in r first
        std::vector<size_t> holes;
        for (size_t h = 0; h < outlines.size(); ++h)
            if (!loops[h].empty() && depth[h] == depth[k] + 1 &&
                insideOutline(outlines[h][0], outlines[k]))
                holes.push_back(h);
        auto maxR = [&](size_t h) {
            return std::max_element(
                       outlines[h].begin(), outlines[h].end(),
                       [](const ProfilePoint &a, const ProfilePoint &b) { return a.r < b.r; })
                ->r;
        };
        std::sort(holes.begin(), holes.end(),
                  [&](size_t a, size_t b) { return maxR(a) > maxR(b); });
        std::vector<Ref> poly = loops[k];
        for (size_t hi = 0; hi < holes.size(); ++hi) {
            const std::vector<Ref> &hole = loops[holes[hi]];
            size_t m = 0;
            for (size_t i = 1; i < hole.size(); ++i)
                if (at(hole[i]).r > at(hole[m]).r) m = i;
            const ProfilePoint &pm = at(hole[m]);
            // Bridge to the nearest vertex of the polygon that the hole's vertex sees: the
            // segment crosses no edge of the polygon or of a hole not yet joined
            std::vector<size_t> order(poly.size());
            for (size_t i = 0; i < poly.size(); ++i) order[i] = i;
            auto dist2 = [&](size_t i) {
                double dr = at(poly[i]).r - pm.r, dz = at(poly[i]).z - pm.z;
                return dr * dr + dz * dz;
            };
            std::sort(order.begin(), order.end(),
                      [&](size_t a, size_t b) { return dist2(a) < dist2(b); });
            auto blocked = [&](const std::vector<Ref> &loop, const ProfilePoint &pv) {
                for (size_t i = 0; i < loop.size(); ++i) {
                    const ProfilePoint &a = at(loop[i]), &b = at(loop[(i + 1) % loop.size()]);
                    if (same(a, pv) || same(b, pv) || same(a, pm) || same(b, pm)) continue;
                    if (crossProperly(pm, pv, a, b)) return true;
                }
                return false;
            };
            size_t bridge = order.front();
            for (size_t i : order) {
                const ProfilePoint &pv = at(poly[i]);
                bool ok = !blocked(poly, pv);
                for (size_t hj = hi; ok && hj < holes.size(); ++hj)
                    ok = !blocked(loops[holes[hj]], pv);
                if (ok) {
                    bridge = i;
                    break;
                }
            }
            // Splice: ... V, M, hole after M ..., M, V, ...
            std::vector<Ref> joined(poly.begin(), poly.begin() + bridge + 1);
            for (size_t i = 0; i <= hole.size(); ++i) joined.push_back(hole[(m + i) % hole.size()]);
            joined.insert(joined.end(), poly.begin() + bridge, poly.end());
            poly = std::move(joined);
        }
        // Ear clipping: a convex corner with no other vertex in its triangle
        while (poly.size() >= 3) {
            size_t n = poly.size();
            bool clipped = false;
            for (size_t i = 0; i < n && !clipped; ++i) {
                const Ref &a = poly[(i + n - 1) % n], &b = poly[i], &c = poly[(i + 1) % n];
                if (!(orient(at(a), at(b), at(c)) > 0)) continue;
                bool empty = true;
                for (size_t j = 0; j < n && empty; ++j) {
                    const ProfilePoint &p = at(poly[j]);
                    if (same(p, at(a)) || same(p, at(b)) || same(p, at(c))) continue;
                    if (inTriangle(p, at(a), at(b), at(c))) empty = false;
                }
                if (!empty) continue;
                tris.push_back({a, b, c});
                poly.erase(poly.begin() + i);
                clipped = true;
            }
            if (clipped) continue;
            // No proper ear (only degenerate corners left): drop a flat corner
            size_t flat = n;
            for (size_t i = 0; i < n && flat == n; ++i)
                if (orient(at(poly[(i + n - 1) % n]), at(poly[i]), at(poly[(i + 1) % n])) == 0)
                    flat = i;
            if (flat == n) break;
            poly.erase(poly.begin() + flat);
        }
    }
    return tris;
}

Mesh openscadRevolve(const std::vector<ProfileOutline> &outlines, double angle, int fragments) {
    Mesh mesh;
    bool full = angle >= 360;
    int f = std::max(fragments, 1);
    int rings = full ? f : f + 1;
    // Positions welded by value, so rings of points on the axis collapse to one vertex
    std::map<std::array<double, 3>, uint32_t> index;
    auto vertex = [&](double x, double y, double z) {
        std::array<double, 3> key{x + 0.0, y + 0.0, z + 0.0};  // -0 and +0 alike
        auto [it, added] = index.emplace(key, static_cast<uint32_t>(mesh.positions.size()));
        if (added) mesh.positions.emplace_back(key[0], key[1], key[2]);
        return it->second;
    };
    std::vector<int> depth = nestingDepths(outlines);
    // ids[k][j][i]: vertex i of outline k on ring j
    std::vector<std::vector<std::vector<uint32_t>>> ids(outlines.size());
    for (size_t k = 0; k < outlines.size(); ++k) {
        const ProfileOutline &o = outlines[k];
        if (o.size() < 3) continue;
        ids[k].resize(rings);
        for (int j = 0; j < rings; ++j) {
            double a = full ? -90 + j * 360.0 / f : 90 - j * angle / f;
            double s = sinDegrees(a), c = cosDegrees(a);
            for (const ProfilePoint &p : o) ids[k][j].push_back(vertex(p.r * s, p.r * c, p.z));
        }
    }
    auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (a != b && b != c && c != a) mesh.triangles.push_back({a, b, c});
    };
    // Sides: the azimuth of ring j grows with j for a partial turn and falls for a full one;
    // with outer outlines counter-clockwise in (r, z), quad (A, B, C, D) of edge i between
    // rings j and j + 1 faces out when wound A, C, B where the azimuth grows
    for (size_t k = 0; k < outlines.size(); ++k) {
        const ProfileOutline &o = outlines[k];
        if (o.size() < 3) continue;
        bool ccw = signedArea(o) > 0;
        bool flip = (ccw != (depth[k] % 2 == 0)) != full;
        size_t n = o.size();
        for (int j = 0; j < (full ? rings : rings - 1); ++j) {
            const auto &r0 = ids[k][j], &r1 = ids[k][(j + 1) % rings];
            for (size_t i = 0; i < n; ++i) {
                uint32_t A = r0[i], B = r0[(i + 1) % n], C = r1[(i + 1) % n], D = r1[i];
                if (!flip) {
                    add(A, C, B);
                    add(A, D, C);
                } else {
                    add(A, B, C);
                    add(A, C, D);
                }
            }
        }
    }
    // End faces of a partial turn: the profile at azimuth 0 faces -y (counter-clockwise in
    // (x, z)); the one at `angle` faces the other way
    if (!full) {
        for (const auto &t : triangulateProfile(outlines)) {
            auto id = [&](const Ref &r, int ring) { return ids[r.first][ring][r.second]; };
            add(id(t[0], 0), id(t[1], 0), id(t[2], 0));
            add(id(t[0], rings - 1), id(t[2], rings - 1), id(t[1], rings - 1));
        }
    }
    return mesh;
}

std::vector<Vec3> openscadRevolvePoints(const std::vector<ProfileOutline> &outlines, double angle,
                                        int fragments) {
    return openscadRevolve(outlines, angle, fragments).positions;
}

}  // namespace rt::meshing
