// SPDX-License-Identifier: MIT
// Swept solids of linear_extrude, with OpenSCAD 2021.01's rings, side triangles and slices.
#include "importers/scad/geometry2d/extrude.h"
#include "core/meshing/triangulate.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "core/math/degree_trig.h"
#include "core/meshing/facets.h"
#include "importers/mesh/mesh_reader.h"

namespace rt::scad {

namespace {

/// Diagonals whose lengths differ by less than this fraction of their mean count as equal
/// (OpenSCAD's sgn_vdiff, 10 ppm); the tie is then broken by the twist direction.
constexpr double kDiagonalTieRatio = 1e-5;

double lerp(double a, double b, double t) { return a + (b - a) * t; }

int sgnDiagonal(Vec2 d1, Vec2 d2) {
    double l1 = std::hypot(d1.x, d1.y), l2 = std::hypot(d2.x, d2.y);
    return 2 * std::abs(l1 - l2) > kDiagonalTieRatio * (l1 + l2) ? (l1 < l2 ? -1 : 1) : 0;
}

/// p scaled by k after turning clockwise by rot degrees (OpenSCAD: Scaling * rotate(-rot)).
Vec2 place(Vec2 p, Vec2 k, double rot) {
    double c = cosDegrees(-rot), s = sinDegrees(-rot);
    return {k.x * (c * p.x - s * p.y), k.y * (s * p.x + c * p.y)};
}

/// ceil(x) as an int, saturated (NaN counts as 1): slice counts beyond the cap are clamped by
/// the caller, and a huge twist or $fn must not make the conversion undefined.
int ceilCount(double x) {
    if (!(x >= 1)) return 1;
    return x >= static_cast<double>(INT_MAX) ? INT_MAX : static_cast<int>(std::ceil(x));
}

int helixSlices(double rSqr, double height, double twist, const ir::Fragments &f) {
    twist = std::abs(twist);
    int minSlices = std::max(ceilCount(twist / 120.0), 1);
    if (std::sqrt(rSqr) < meshing::kGridFine) return minSlices;
    if (f.fn > 0) return std::max(ceilCount(twist / 360.0 * f.fn), minSlices);
    // Helix length T sqrt(r^2 + c^2) with pitch c = height / T
    double t = twist * M_PI / 180, c = height / t;
    int faSlices = ceilCount(twist / f.fa);
    int fsSlices = ceilCount(t * std::sqrt(rSqr + c * c) / f.fs);
    return std::max(std::min(faSlices, fsSlices), minSlices);
}

double archimedesLength(double a, double theta) {
    return 0.5 * a * (theta * std::sqrt(1 + theta * theta) + std::asinh(theta));
}

int conicalHelixSlices(double rSqr, double height, double twist, double scale,
                       const ir::Fragments &f) {
    twist = std::abs(twist);
    double r = std::sqrt(rSqr);
    int minSlices = std::max(ceilCount(twist / 120.0), 1);
    if (r < meshing::kGridFine) return minSlices;
    if (f.fn > 0) return std::max(ceilCount(twist * f.fn / 360), minSlices);
    // The path of the farthest point projects to a piece of an Archimedes spiral that would
    // reach the origin where the scale reaches 0
    double rads = twist * M_PI / 180;
    double angleEnd = scale > 1 ? rads * scale / (scale - 1) : rads / (1 - scale);
    double angleStart = angleEnd - rads;
    double a = r / angleEnd;
    double spiral = archimedesLength(a, angleEnd) - archimedesLength(a, angleStart);
    double total = std::sqrt(spiral * spiral + height * height);
    int fsSlices = ceilCount(total / f.fs);
    int faSlices = ceilCount(twist / f.fa);
    return std::max(std::min(faSlices, fsSlices), minSlices);
}

int diagonalSlices(double deltaSqr, double height, const ir::Fragments &f) {
    if (std::sqrt(deltaSqr) < meshing::kGridFine) return 1;
    if (f.fn > 0)
        return f.fn >= static_cast<double>(INT_MAX) ? INT_MAX : std::max(static_cast<int>(f.fn), 1);
    return std::max(ceilCount(std::sqrt(deltaSqr + height * height) / f.fs), 1);
}

}  // namespace

int extrudeSlices(int slices, double height, double twist, Vec2 scale, double rSqr, double deltaSqr,
                  const ir::Fragments &f) {
    if (slices > 0) return slices;
    if (twist != 0) {
        // 2021.01 uses the straight helix for non-uniform scales too
        if ((scale.x == 1 && scale.y == 1) || scale.x != scale.y)
            return helixSlices(rSqr, height, twist, f);
        return conicalHelixSlices(rSqr, height, twist, scale.x, f);
    }
    if (scale.x != scale.y) return diagonalSlices(deltaSqr, height, f);
    return 1;
}

ir::PrismPrim straightPrism(const Outline &ccw, double z0, double z1, double k0, double k1) {
    ir::PrismPrim p;
    for (Vec2 v : ccw) p.outline.push_back({v.x, v.y});
    p.z0 = z0;
    p.z1 = z1;
    p.k0 = k0;
    p.k1 = k1;
    return p;
}

bool sweepMesh(const Outline &ccw, const Sweep &s, ir::Mesh &out) {
    size_t n = ccw.size();
    int slices = std::max(s.slices, 1);
    // Rings of vertices, each a single apex where both scales are 0
    std::vector<std::vector<uint32_t>> rings(slices + 1);
    std::vector<std::vector<Vec2>> placed(slices + 1);
    std::vector<double> rot(slices + 1);
    for (int j = 0; j <= slices; ++j) {
        double t = static_cast<double>(j) / slices;
        Vec2 k{lerp(s.scale0.x, s.scale1.x, t), lerp(s.scale0.y, s.scale1.y, t)};
        rot[j] = lerp(s.rot0, s.rot1, t);
        double z = lerp(s.z0, s.z1, t);
        bool apex = k.x == 0 && k.y == 0;
        for (size_t i = 0; i < n; ++i) {
            Vec2 q = place(ccw[i], k, rot[j]);
            placed[j].push_back(q);
            if (apex && i > 0) {
                rings[j].push_back(rings[j][0]);
                continue;
            }
            rings[j].push_back(static_cast<uint32_t>(out.positions.size()));
            out.positions.push_back(Vec3(q.x, q.y, z));
        }
    }
    // Side quads split along the shorter diagonal (add_slice); on a tie by the twist
    // direction. Towards an apex the split flips, and only one triangle is left.
    for (int j = 0; j < slices; ++j) {
        const auto &r1 = rings[j], &r2 = rings[j + 1];
        bool apexAbove = r2.size() > 1 && r2[0] == r2[1];
        bool backTwist = rot[j + 1] <= rot[j];
        bool flip = backTwist;  // outlines here are all positive (counter-clockwise)
        for (size_t i = 0; i < n; ++i) {
            size_t p = i, c = (i + 1) % n;
            Vec2 prev1 = placed[j][p], curr1 = placed[j][c];
            Vec2 prev2 = placed[j + 1][p], curr2 = placed[j + 1][c];
            int d = sgnDiagonal(prev1 - curr2, curr1 - prev2);
            bool splitFirst = d == -1 || (d == 0 && !flip);
            if (splitFirst != apexAbove) {
                out.triangles.push_back({r1[c], r2[c], r1[p]});
                if (!apexAbove) out.triangles.push_back({r2[p], r1[p], r2[c]});
            } else {
                out.triangles.push_back({r1[c], r2[p], r1[p]});
                if (!apexAbove) out.triangles.push_back({r1[c], r2[c], r2[p]});
            }
        }
    }
    // Caps: the bottom faces down, the top up
    auto cap = [&](const std::vector<uint32_t> &ring, bool down) {
        if (ring.size() > 1 && ring[0] == ring[1]) return true;
        std::vector<uint32_t> poly = ring;
        if (down) std::reverse(poly.begin(), poly.end());
        return meshing::triangulatePolygon(out.positions, poly, out.triangles);
    };
    bool ok = cap(rings[0], true);
    ok = cap(rings[slices], false) && ok;
    return ok;
}

bool prismMesh(const ir::PrismPrim &p, ir::Mesh &out) {
    Outline ccw;
    for (const ir::Point2 &q : p.outline) ccw.push_back({q.x, q.y});
    Sweep s;
    s.z0 = p.z0;
    s.z1 = p.z1;
    s.scale0 = {p.k0, p.k0};
    s.scale1 = {p.k1, p.k1};
    return sweepMesh(ccw, s, out);
}

}  // namespace rt::scad
