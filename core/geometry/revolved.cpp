// SPDX-License-Identifier: MIT
// Torus and lathe: candidate crossings of the curved surface and the end half-planes,
// classified into spans by inside tests; robust quartic roots for the torus.
#include "core/geometry/revolved.h"

#include <algorithm>
#include <cmath>

#include "core/math/degree_trig.h"
#include "core/math/float_util.h"
#include "core/math/quadratic.h"

namespace rt {

namespace {

/// Distance from the z axis. Coordinates stay within ±1e100 (ir_validate), so the squares
/// cannot overflow, and hypot's extra care would cost 40% of a torus ray.
inline double radial(double x, double y) { return std::sqrt(x * x + y * y); }

/// Candidates within this fraction of the solid's size outside a piece (an edge's z range,
/// an annulus' radii, an end half-plane beyond the axis) are kept: a crossing at a vertex
/// circle or on the axis must not be lost to rounding, and one kept in vain merges away.
constexpr double kCandidateSlack = 1e-9;

/// The bounding cylinder and slab are widened by this fraction of the solid's size, so that
/// the early rejection never drops a line that touches the solid.
constexpr double kBoundsSlack = 1e-9;

/// Safeguarded Newton on a torus root stops when a step moves it by no more than this many
/// ulps of the major radius (1 in the units it works in): the next quadratically converging
/// step could not change its double.
constexpr double kRootStepUlps = 2;

/// Newton-bisection steps for one torus root: bisection alone halves a bracket of at most
/// 4 major radii to one ulp in under 60 steps; Newton usually ends it in fewer than 10.
constexpr int kMaxRootSteps = 100;

}  // namespace

// ---------------------------------------------------------------------------------------------
// Shared: wedge, candidates, classification

RevolvedSolid::RevolvedSolid(double angle, double rMin, double rMax, double zMin, double zMax)
    : angle_(angle), full_(angle >= 360), rMax_(rMax), zMin_(zMin), zMax_(zMax) {
    double c = cosDegrees(angle), s = sinDegrees(angle);
    endDir_ = Vec3(c, s, 0);
    endNormal_ = Vec3(-s, c, 0);
    candidateSlack_ = kCandidateSlack * std::max(rMax, zMax - zMin);
    if (full_) {
        bounds_ = Bounds3(Vec3(-rMax, -rMax, zMin), Vec3(rMax, rMax, zMax));
        return;
    }
    // A wedge's bounds: the radii rMin and rMax at the azimuths where x or y is extreme, which
    // are the two end planes and the axis directions between them
    for (double a : {0.0, angle, 90.0, 180.0, 270.0}) {
        if (a > angle) continue;
        Vec3 dir(cosDegrees(a), sinDegrees(a), 0);
        for (double r : {rMin, rMax})
            for (double z : {zMin, zMax}) bounds_ = unionBounds(bounds_, dir * r + Vec3(0, 0, z));
    }
}

bool RevolvedSolid::insideWedge(const Vec3 &p) const {
    if (full_) return true;
    // Azimuth in [0, angle]: above the start plane and clockwise of the end direction; past
    // a half turn the wedge is the union of the two half-spaces
    bool aboveStart = p.y >= 0;
    bool beforeEnd = p.x * endDir_.y - p.y * endDir_.x >= 0;
    return angle_ <= 180 ? aboveStart && beforeEnd : aboveStart || beforeEnd;
}

void RevolvedSolid::wedgeCandidates(const Ray &r, std::vector<Candidate> &out) const {
    // Start half-plane y = 0, x >= 0; end half-plane through the axis along endDir_
    if (r.d.y != 0) {
        double t = -r.o.y / r.d.y;
        if (r.o.x + t * r.d.x >= -candidateSlack_) out.push_back({t, kStartFace});
    }
    double rate = dot(endNormal_, r.d);
    if (rate != 0) {
        double t = -dot(endNormal_, r.o) / rate;
        if (dot(endDir_, r.at(t)) >= -candidateSlack_) out.push_back({t, kEndFace});
    }
}

bool RevolvedSolid::intersect(const Ray &r, PrimitiveSpan *span) const {
    thread_local std::vector<PrimitiveSpan> spans;
    spans.clear();
    intersectAll(r, spans);
    if (spans.empty()) return false;
    *span = {spans.front().t0, spans.back().t1, spans.front().face0, spans.back().face1};
    return true;
}

void RevolvedSolid::intersectAll(const Ray &ray, std::vector<PrimitiveSpan> &spans) const {
    double dd = lengthSquared(ray.d);
    if (!(dd > 0)) return;
    // Move the origin to the line's point closest to the centre: far origins then cost no
    // digits in the polynomials below (t = tShift + t' on the shifted ray)
    Vec3 centre(0, 0, zCentre());
    double tShift = dot(centre - ray.o, ray.d) / dd;
    Ray r(ray.o + ray.d * tShift, ray.d);

    // Reject by the bounding slab and cylinder, and keep the part of the line inside them
    double pad = kBoundsSlack * std::max(rMax_, zMax_ - zMin_);
    double tLo = -kInfinity, tHi = kInfinity;
    if (r.d.z == 0) {
        if (r.o.z < zMin_ - pad || r.o.z > zMax_ + pad) return;
    } else {
        double ta = (zMin_ - pad - r.o.z) / r.d.z, tb = (zMax_ + pad - r.o.z) / r.d.z;
        tLo = std::min(ta, tb);
        tHi = std::max(ta, tb);
    }
    double a = r.d.x * r.d.x + r.d.y * r.d.y, rBound = rMax_ + pad;
    if (a == 0) {
        if (r.o.x * r.o.x + r.o.y * r.o.y > rBound * rBound) return;
    } else {
        // Closest approach to the axis, then the half chord of the cylinder
        double tc = -(r.o.x * r.d.x + r.o.y * r.d.y) / a;
        double cx = r.o.x + tc * r.d.x, cy = r.o.y + tc * r.d.y;
        double rc = radial(cx, cy);
        double h = (rBound - rc) * (rBound + rc);
        if (h < 0) return;
        double half = std::sqrt(h / a);
        tLo = std::max(tLo, tc - half);
        tHi = std::min(tHi, tc + half);
    }
    if (!(tLo <= tHi)) return;

    // Gather the candidates in the ray's own parameter and sort them along the line. The end
    // planes are crossed by the unshifted ray: a ray spawned off an end plane starts exactly
    // on it (its offset across an exact plane is zero, as for a box) and must find it at t = 0
    thread_local std::vector<Candidate> cand;
    cand.clear();
    profileCandidates(r, tLo, tHi, cand);
    for (Candidate &c : cand) c.t += tShift;
    if (!full_) wedgeCandidates(ray, cand);
    if (cand.size() < 2) return;
    std::sort(cand.begin(), cand.end(),
              [](const Candidate &x, const Candidate &y) { return x.t < y.t; });

    // Classify each interval between neighbours at its midpoint; outside the candidates the
    // line is outside. Equal candidates bound no interval, so they never split a span, and
    // spans come out sorted, of positive length and apart by an interval outside.
    bool in = false;
    double t0 = 0;
    int face0 = 0;
    for (size_t i = 0; i + 1 < cand.size(); ++i) {
        if (!(cand[i + 1].t > cand[i].t)) continue;
        bool midInside = inside(ray.at(0.5 * (cand[i].t + cand[i + 1].t)));
        if (midInside == in) continue;
        const Candidate &c = cand[i];
        int face =
            c.face < kFirstProfileFace ? c.face : orientFace(c.face, ray.at(c.t), ray.d, midInside);
        if (midInside) {
            t0 = c.t;
            face0 = face;
        } else {
            spans.push_back({t0, c.t, face0, face});
        }
        in = midInside;
    }
    if (in) {
        const Candidate &c = cand.back();
        int face =
            c.face < kFirstProfileFace ? c.face : orientFace(c.face, ray.at(c.t), ray.d, false);
        spans.push_back({t0, c.t, face0, face});
    }
}

ObjectSurface RevolvedSolid::surface(const Vec3 &p, int face) const {
    if (face == kStartFace) {
        // The plane y = 0 is exact; the other coordinates carry the error of o + t d
        Vec3 refined(p.x, 0, p.z);
        Vec3 err = abs(refined) * gamma(3);
        return {refined, err, Vec3(0, -1, 0)};
    }
    if (face == kEndFace) {
        Vec3 refined = p - endNormal_ * dot(endNormal_, p);
        return {refined, abs(refined) * gamma(6) + Vec3(length(p) * gamma(4)), endNormal_};
    }
    return profileSurface(p, face);
}

// ---------------------------------------------------------------------------------------------
// Torus

Torus::Torus(const ir::TorusPrim &prim)
    : RevolvedSolid(prim.angle, prim.major - prim.minor, prim.major + prim.minor, -prim.minor,
                    prim.minor),
      major_(prim.major),
      minor_(prim.minor) {}

namespace {

/// Real roots of s^3 + p s + q (the derivative of a depressed quartic, scaled), each polished
/// by Newton steps; returns how many (1 or 3), ascending. Cardano in the cancellation-free
/// form for one root (Numerical Recipes 5.6), the trigonometric form for three.
int solveDepressedCubic(double p, double q, double roots[3]) {
    int n;
    double d = (q * 0.5) * (q * 0.5) + (p / 3) * (p / 3) * (p / 3);
    if (d > 0 || p >= 0) {
        double a = -std::copysign(std::cbrt(std::abs(q) * 0.5 + std::sqrt(std::max(d, 0.0))), q);
        roots[0] = a != 0 ? a - p / (3 * a) : 0;
        n = 1;
    } else {
        double m = std::sqrt(-p / 3);
        double theta = std::acos(clamp(-q / (2 * m * m * m), -1.0, 1.0)) / 3;
        for (int k = 0; k < 3; ++k) roots[k] = 2 * m * std::cos(theta - 2 * kPi * k / 3);
        n = 3;
    }
    for (int k = 0; k < n; ++k)
        for (int step = 0; step < 2; ++step) {
            double s = roots[k], slope = 3 * s * s + p;
            if (slope == 0) break;
            roots[k] = s - ((s * s + p) * s + q) / slope;
        }
    std::sort(roots, roots + n);
    return n;
}

}  // namespace

void Torus::profileCandidates(const Ray &r, double, double, std::vector<Candidate> &out) const {
    // Work in units of the major radius along the unit direction u from the line's point q
    // closest to the centre (r.o already is that point): x = q + s u with q . u = 0
    double len = length(r.d);
    double inv = 1 / major_;
    Vec3 q = r.o * inv, u = r.d / len;
    double a = minor_ * inv;
    double b2 = lengthSquared(q);
    // Bounding sphere of radius 1 + a
    double outer = (1 + a) * (1 + kBoundsSlack);
    if (b2 >= outer * outer) return;
    double reach = std::sqrt((outer - std::sqrt(b2)) * (outer + std::sqrt(b2)));

    // Tube function h(s) = D - a, D the distance from the tube's centre circle, negative
    // inside: the quartic of the line, f = ((rho - 1)^2 + z^2 - a^2) ((rho + 1)^2 + z^2 - a^2),
    // has the sign of h, and h keeps the precision that the expanded quartic loses near a thin
    // tube. As a distance it is nearly linear along the line away from the tube, so Newton
    // converges in a few steps from anywhere in a bracket (on D^2 - a^2 it would only halve the
    // distance per step from afar)
    auto tube = [&](double s, double *slope) {
        Vec3 x = q + u * s;
        double rho = radial(x.x, x.y);
        double dr = rho - 1;
        double dist = std::sqrt(dr * dr + x.z * x.z);
        if (slope) {
            double dRho = rho > 0 ? (x.x * u.x + x.y * u.y) / rho : 0;
            *slope = dist > 0 ? (dr * dRho + x.z * u.z) / dist : 0;
        }
        return dist - a;
    };

    // The quartic s^4 + P s^2 + Q s + R (no cubic term about the closest point); its
    // critical points split [-reach, reach] into pieces where it is monotonic, so each piece
    // holds at most one root, bracketed by a sign change of h
    double g = b2 + 1 - a * a;
    double k = u.x * u.x + u.y * u.y, m = q.x * u.x + q.y * u.y;
    double P = 2 * g - 4 * k, Q = -8 * m;
    double crit[3];
    int nCrit = solveDepressedCubic(P / 2, Q / 4, crit);
    double bracket[5];
    int nb = 0;
    bracket[nb++] = -reach;
    for (int i = 0; i < nCrit; ++i)
        if (crit[i] > -reach && crit[i] < reach) bracket[nb++] = crit[i];
    bracket[nb++] = reach;
    double value[5];
    for (int i = 0; i < nb; ++i) value[i] = tube(bracket[i], nullptr);

    double scale = major_ / len;  // t' = s * major / |d|
    for (int i = 0; i < nb; ++i) {
        if (value[i] == 0) out.push_back({bracket[i] * scale, kFirstProfileFace});
        if (i + 1 == nb || !((value[i] < 0) != (value[i + 1] < 0)) || value[i + 1] == 0 ||
            value[i] == 0)
            continue;
        // Safeguarded Newton from the secant point: a step that leaves the bracket becomes a
        // bisection
        double lo = bracket[i], hi = bracket[i + 1];
        bool rising = value[i] < 0;
        double s = lo + value[i] / (value[i] - value[i + 1]) * (hi - lo);
        if (!(s > lo && s < hi)) s = 0.5 * (lo + hi);
        for (int step = 0; step < kMaxRootSteps; ++step) {
            double slope, h = tube(s, &slope);
            if (h == 0) break;
            if ((h < 0) == rising)
                lo = s;
            else
                hi = s;
            double next = slope != 0 ? s - h / slope : lo;
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            if (!(lo < next && next < hi)) break;  // the bracket is down to adjacent doubles
            bool converged =
                std::abs(next - s) <= kRootStepUlps * kMachineEpsilon * (1 + std::abs(s));
            s = next;
            if (converged) break;
        }
        out.push_back({s * scale, kFirstProfileFace});
    }
}

ObjectSurface Torus::profileSurface(const Vec3 &p, int) const {
    // Move the point along the tube's radius onto the tube: c is the nearest point of the
    // tube's centre circle
    double rho = radial(p.x, p.y);
    Vec3 c = rho > 0 ? Vec3(p.x, p.y, 0) * (major_ / rho) : Vec3(major_, 0, 0);
    Vec3 v = p - c;
    double len = length(v);
    if (!(len > 0)) v = Vec3(0, 0, 1), len = 1;
    Vec3 refined = c + v * (minor_ / len);
    Vec3 err = abs(refined) * gamma(8) + Vec3(major_ * gamma(8));
    return {refined, err, v};
}

// ---------------------------------------------------------------------------------------------
// Lathe

namespace {

struct ProfileExtent {
    double rMin = kInfinity, rMax = 0, zMin = kInfinity, zMax = -kInfinity;
};

ProfileExtent extent(const ir::LathePrim &prim) {
    ProfileExtent e;
    for (const auto &o : prim.outlines)
        for (const auto &p : o) {
            e.rMin = std::min(e.rMin, p.r);
            e.rMax = std::max(e.rMax, p.r);
            e.zMin = std::min(e.zMin, p.z);
            e.zMax = std::max(e.zMax, p.z);
        }
    if (e.zMin > e.zMax) e = {0, 0, 0, 0};
    return e;
}

}  // namespace

Lathe::Lathe(const ir::LathePrim &prim)
    : RevolvedSolid(prim.angle, extent(prim).rMin, extent(prim).rMax, extent(prim).zMin,
                    extent(prim).zMax) {
    for (const auto &o : prim.outlines)
        for (size_t i = 0; i < o.size(); ++i) {
            const ir::ProfilePoint &a = o[i], &b = o[(i + 1) % o.size()];
            if (a.r == b.r && a.z == b.z) continue;
            double slope = a.z != b.z ? (b.r - a.r) / (b.z - a.z) : 0;
            edges_.push_back({a.r, a.z, b.r, b.z, slope});
        }
    // Slabs between the vertex heights: every edge spans whole slabs
    for (const Edge &e : edges_) {
        slabZ_.push_back(e.z1);
        slabZ_.push_back(e.z2);
    }
    std::sort(slabZ_.begin(), slabZ_.end());
    slabZ_.erase(std::unique(slabZ_.begin(), slabZ_.end()), slabZ_.end());
    auto slabOf = [&](double z) {
        return static_cast<size_t>(std::lower_bound(slabZ_.begin(), slabZ_.end(), z) -
                                   slabZ_.begin());
    };
    size_t slabs = slabZ_.empty() ? 0 : slabZ_.size() - 1, entries = 0;
    std::vector<uint32_t> count(slabs + 1, 0);
    for (const Edge &e : edges_) {
        if (e.z1 == e.z2) continue;
        size_t lo = slabOf(std::min(e.z1, e.z2)), hi = slabOf(std::max(e.z1, e.z2));
        for (size_t k = lo; k < hi; ++k) ++count[k];
        entries += hi - lo;
    }
    if (entries > kMaxSlabEntries) {
        slabZ_.clear();
        return;
    }
    slabStart_.assign(slabs + 1, 0);
    for (size_t k = 0; k < slabs; ++k) slabStart_[k + 1] = slabStart_[k] + count[k];
    slabEdges_.resize(entries);
    std::vector<uint32_t> fill(slabStart_.begin(), slabStart_.end() - 1);
    for (size_t i = 0; i < edges_.size(); ++i) {
        const Edge &e = edges_[i];
        if (e.z1 == e.z2) continue;
        size_t lo = slabOf(std::min(e.z1, e.z2)), hi = slabOf(std::max(e.z1, e.z2));
        for (size_t k = lo; k < hi; ++k) slabEdges_[fill[k]++] = static_cast<uint32_t>(i);
    }
}

bool Lathe::insideProfile(double r, double z) const {
    // Even-odd crossing count of the horizontal half-line from (r, z) towards +r; an edge
    // counts when it spans z half-open, so a vertex at height z counts once
    bool in = false;
    if (!slabZ_.empty()) {
        // Only the edges of the slab [z_k, z_k+1) holding z span it, and all of them do
        auto above = std::upper_bound(slabZ_.begin(), slabZ_.end(), z);
        if (above == slabZ_.begin() || above == slabZ_.end()) return false;
        size_t k = static_cast<size_t>(above - slabZ_.begin()) - 1;
        for (uint32_t i = slabStart_[k]; i < slabStart_[k + 1]; ++i) {
            const Edge &e = edges_[slabEdges_[i]];
            if (r < e.r1 + (z - e.z1) * e.slope) in = !in;
        }
        return in;
    }
    for (const Edge &e : edges_) {
        if ((e.z1 > z) == (e.z2 > z)) continue;
        double rc = e.r1 + (z - e.z1) * e.slope;
        if (r < rc) in = !in;
    }
    return in;
}

void Lathe::profileCandidates(const Ray &r, double tLo, double tHi,
                              std::vector<Candidate> &out) const {
    double slack = candidateSlack();
    double axy = differenceOfProducts(r.d.x, r.d.x, -r.d.y, r.d.y);
    double bxy = r.o.x * r.d.x + r.o.y * r.d.y;
    double cxy = differenceOfProducts(r.o.x, r.o.x, -r.o.y, r.o.y);
    // The heights the line reaches inside the bounding cylinder: edges wholly above or below
    // cannot be crossed
    double zLine0 = r.o.z, zLine1 = r.o.z;
    if (r.d.z != 0) {
        zLine0 = r.o.z + tLo * r.d.z;
        zLine1 = r.o.z + tHi * r.d.z;
        if (zLine0 > zLine1) std::swap(zLine0, zLine1);
    }
    zLine0 -= slack;
    zLine1 += slack;
    // Nor can edges nearer the axis than the line ever comes
    double rhoLine = axy > 0 ? radial(r.o.x - bxy / axy * r.d.x, r.o.y - bxy / axy * r.d.y)
                             : radial(r.o.x, r.o.y);
    rhoLine -= slack;
    for (size_t i = 0; i < edges_.size(); ++i) {
        const Edge &e = edges_[i];
        if (std::max(e.z1, e.z2) < zLine0 || std::min(e.z1, e.z2) > zLine1 ||
            std::max(e.r1, e.r2) < rhoLine)
            continue;
        int face = kFirstProfileFace + 2 * static_cast<int>(i);
        if (e.z1 == e.z2) {
            // Annulus: the plane z = z1 between the two radii
            if (r.d.z == 0) continue;
            double t = (e.z1 - r.o.z) / r.d.z;
            if (t < tLo || t > tHi) continue;
            double rho = radial(r.o.x + t * r.d.x, r.o.y + t * r.d.y);
            if (rho >= std::min(e.r1, e.r2) - slack && rho <= std::max(e.r1, e.r2) + slack)
                out.push_back({t, face});
            continue;
        }
        // Cone or cylinder piece: x^2 + y^2 = w^2 with w = r1 + slope (z - z1) linear in t
        double w0 = e.r1 + e.slope * (r.o.z - e.z1), wd = e.slope * r.d.z;
        double A = axy - wd * wd, B = 2 * (bxy - w0 * wd), C = cxy - w0 * w0;
        double roots[2];
        int n = 0;
        if (A == 0) {
            if (B == 0) continue;
            roots[n++] = -C / B;
        } else if (solveQuadratic(A, B, C, &roots[0], &roots[1])) {
            n = 2;
        }
        double zLo = std::min(e.z1, e.z2) - slack, zHi = std::max(e.z1, e.z2) + slack;
        for (int k = 0; k < n; ++k) {
            double z = r.o.z + roots[k] * r.d.z;
            if (z >= zLo && z <= zHi) out.push_back({roots[k], face});
        }
    }
}

Vec3 Lathe::edgeNormal(const Edge &e, const Vec3 &p) const {
    // (dz, -dr) in the profile plane, turned to the point's azimuth
    double nr = e.z2 - e.z1, nz = -(e.r2 - e.r1);
    double rho = radial(p.x, p.y);
    if (!(rho > 0)) return Vec3(0, 0, nz != 0 ? nz : 1);
    return Vec3(nr * p.x / rho, nr * p.y / rho, nz);
}

int Lathe::orientFace(int face, const Vec3 &p, const Vec3 &d, bool entering) const {
    // Entering, the outward normal faces the ray; leaving, it runs with it
    const Edge &e = edges_[(face - kFirstProfileFace) / 2];
    bool along = dot(edgeNormal(e, p), d) > 0;
    return along == entering ? face + 1 : face;
}

ObjectSurface Lathe::profileSurface(const Vec3 &p, int face) const {
    int index = face - kFirstProfileFace;
    const Edge &e = edges_[index / 2];
    double rho = radial(p.x, p.y);
    double rr, zz;
    if (e.z1 == e.z2) {
        rr = rho;
        zz = e.z1;
    } else if (e.r1 == e.r2) {
        rr = e.r1;
        zz = p.z;
    } else {
        // Orthogonal projection onto the edge's line in the profile plane
        double dr = e.r2 - e.r1, dz = e.z2 - e.z1;
        double tau = ((rho - e.r1) * dr + (p.z - e.z1) * dz) / (dr * dr + dz * dz);
        rr = std::max(0.0, e.r1 + tau * dr);
        zz = e.z1 + tau * dz;
    }
    Vec3 refined = rho > 0 ? Vec3(p.x * (rr / rho), p.y * (rr / rho), zz) : Vec3(rr, 0, zz);
    Vec3 n = edgeNormal(e, refined.x == 0 && refined.y == 0 ? p : refined);
    if (index % 2) n = -n;
    Vec3 err = abs(refined) * gamma(8) + Vec3(rMax() * gamma(4));
    return {refined, err, n};
}

}  // namespace rt
