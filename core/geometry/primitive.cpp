// SPDX-License-Identifier: MIT
// Sphere, box and truncated cone: whole-line spans, inside tests and surface refinement.
#include "core/geometry/primitive.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/geometry/revolved.h"
#include "core/geometry/triangle_mesh.h"
#include "core/ir/prism.h"
#include "core/math/float_util.h"
#include "core/math/fma_clone.h"
#include "core/math/quadratic.h"

namespace rt {

std::unique_ptr<Primitive> Primitive::create(const ir::PrimShape &shape) {
    if (const auto *s = std::get_if<ir::SpherePrim>(&shape))
        return std::make_unique<Sphere>(s->radius);
    if (const auto *b = std::get_if<ir::BoxPrim>(&shape))
        return std::make_unique<Box>(b->min, b->max);
    if (const auto *c = std::get_if<ir::CylinderPrim>(&shape))
        return std::make_unique<Cone>(c->z0, c->z1, c->r1, c->r2);
    if (const auto *p = std::get_if<ir::PolytopePrim>(&shape))
        return std::make_unique<ConvexPolytope>(*p);
    // A convex prism is the polytope of its faces; a non-convex one is drawn as its mesh
    if (const auto *p = std::get_if<ir::PrismPrim>(&shape); p && p->mesh < 0)
        return std::make_unique<ConvexPolytope>(ir::prismPolytope(*p));
    if (const auto *t = std::get_if<ir::TorusPrim>(&shape)) return std::make_unique<Torus>(*t);
    if (const auto *l = std::get_if<ir::LathePrim>(&shape)) return std::make_unique<Lathe>(*l);
    throw std::logic_error("Primitive::create: meshes are MeshInstances, not primitives");
}

void Primitive::intersectAll(const Ray &objectRay, std::vector<PrimitiveSpan> &spans) const {
    PrimitiveSpan s;
    if (intersect(objectRay, &s)) spans.push_back(s);
}

// ---------------------------------------------------------------------------------------------
// Sphere

bool Sphere::intersect(const Ray &r, PrimitiveSpan *span) const {
    double a = lengthSquared(r.d);
    if (!(a > 0)) return false;
    // Discriminant from the distance of the line to the centre (Hearn and Baker; pbrt-v4
    // Sphere::BasicIntersect): 4a (R - |v|)(R + |v|) does not cancel for rays far from the sphere.
    double f = dot(r.o, r.d) / a;
    Vec3 v = r.o - r.d * f;
    double len = length(v);
    double discrim = 4 * a * (radius_ - len) * (radius_ + len);
    // A tangent line (discrim 0) only touches the sphere: no span
    if (!(discrim > 0)) return false;
    double rootDiscrim = std::sqrt(discrim);
    double b = 2 * dot(r.o, r.d);
    double q = (b < 0) ? -0.5 * (b - rootDiscrim) : -0.5 * (b + rootDiscrim);
    double lo = length(r.o);
    double c = (lo - radius_) * (lo + radius_);
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    if (!(t0 < t1)) return false;
    *span = {t0, t1, 0, 0};
    return true;
}

ObjectSurface Sphere::surface(const Vec3 &p, int) const {
    // Reproject onto the sphere: the refined point has a relative error of gamma(5)
    // (pbrt-v3 section 3.9.4).
    double len = length(p);
    Vec3 refined = len > 0 ? p * (radius_ / len) : Vec3(0, 0, radius_);
    return {refined, abs(refined) * gamma(5), refined};
}

// ---------------------------------------------------------------------------------------------
// Box

bool Box::inside(const Vec3 &p) const {
    return p.x >= min_.x && p.x <= max_.x && p.y >= min_.y && p.y <= max_.y && p.z >= min_.z &&
           p.z <= max_.z;
}

// ---------------------------------------------------------------------------------------------
// Truncated cone

Cone::Cone(double z0, double z1, double r1, double r2)
    : z0_(z0), z1_(z1), r1_(r1), r2_(r2), slope_((r2 - r1) / (z1 - z0)) {}

Bounds3 Cone::objectBounds() const {
    double r = std::max(r1_, r2_);
    return Bounds3(Vec3(-r, -r, z0_), Vec3(r, r, z1_));
}

bool Cone::intersect(const Ray &r, PrimitiveSpan *span) const { return lineSpan(r, span); }

SCADRAY_FMA_CLONES
bool Cone::lineSpan(const Ray &r, PrimitiveSpan *span) const {
    // Clip the line to the slab z0 <= z <= z1
    double ta = -kInfinity, tb = kInfinity;
    int fa = 0, fb = 0;  // side unless a cap bounds the interval
    if (r.d.z == 0) {
        if (r.o.z < z0_ || r.o.z > z1_) return false;
    } else {
        ta = (z0_ - r.o.z) / r.d.z;
        tb = (z1_ - r.o.z) / r.d.z;
        fa = 1;
        fb = 2;
        if (ta > tb) {
            std::swap(ta, tb);
            std::swap(fa, fb);
        }
    }
    // Inside the infinite cone: x^2 + y^2 - r(z)^2 <= 0 with r(z) = w0 + wd t along the ray.
    // Within the slab r(z) >= 0, so the solid's part of the line is one interval.
    double w0 = radiusAt(r.o.z), wd = slope_ * r.d.z;
    double A = differenceOfProducts(r.d.x, r.d.x, -r.d.y, r.d.y) - wd * wd;
    double B = 2 * (r.o.x * r.d.x + r.o.y * r.d.y - w0 * wd);
    double C = differenceOfProducts(r.o.x, r.o.x, -r.o.y, r.o.y) - w0 * w0;
    double s0 = -kInfinity, s1 = kInfinity;  // side interval
    if (A == 0 && B == 0) {
        if (C > 0) return false;
    } else if (A == 0) {
        // Ray parallel to a generator line: one root
        double tr = -C / B;
        if (B > 0)
            s1 = tr;
        else
            s0 = tr;
    } else {
        double q0, q1;
        if (!solveQuadratic(A, B, C, &q0, &q1)) {
            if (A > 0) return false;  // never inside
            // A < 0 and no root: inside along the whole line
        } else if (A > 0) {
            s0 = q0;
            s1 = q1;
        } else {
            // Inside outside the roots; only one piece meets the slab (the other nappe has r < 0)
            double lenLow = std::min(tb, q0) - ta, lenHigh = tb - std::max(ta, q1);
            if (lenLow >= lenHigh)
                s1 = q0;
            else
                s0 = q1;
        }
    }
    double t0 = ta, t1 = tb;
    int face0 = fa, face1 = fb;
    if (s0 > t0) {
        t0 = s0;
        face0 = 0;
    }
    if (s1 < t1) {
        t1 = s1;
        face1 = 0;
    }
    if (!(t0 < t1) || std::isinf(t0) || std::isinf(t1)) return false;
    *span = {t0, t1, face0, face1};
    return true;
}

bool Cone::inside(const Vec3 &p) const {
    if (p.z < z0_ || p.z > z1_) return false;
    double rz = radiusAt(p.z);
    return p.x * p.x + p.y * p.y <= rz * rz;
}

ObjectSurface Cone::surface(const Vec3 &p, int face) const {
    if (face == 1 || face == 2) {
        Vec3 refined = p;
        refined.z = face == 1 ? z0_ : z1_;
        Vec3 err = abs(refined) * gamma(3);
        err.z = 0;
        return {refined, err, Vec3(0, 0, face == 1 ? -1 : 1)};
    }
    // Side: move the point radially onto the cone at its height
    Vec3 refined = p;
    refined.z = clamp(p.z, std::min(z0_, z1_), std::max(z0_, z1_));
    double rz = radiusAt(refined.z);
    // sqrt of the squares, as pbrt's cylinder: coordinates stay within ±1e100 (ir_validate),
    // so they cannot overflow, and glibc's correctly rounded hypot cost 2 % of print_plate.scad
    double rho = std::sqrt(p.x * p.x + p.y * p.y);
    if (rho > 0) {
        refined.x *= rz / rho;
        refined.y *= rz / rho;
    }
    // Gradient of x^2 + y^2 - r(z)^2, halved
    Vec3 n(refined.x, refined.y, -rz * slope_);
    if (lengthSquared(n) == 0) n = Vec3(0, 0, slope_ > 0 ? 1 : -1);  // apex
    return {refined, abs(refined) * gamma(6), n};
}

// ---------------------------------------------------------------------------------------------
// Convex polytope

ConvexPolytope::ConvexPolytope(const ir::PolytopePrim &p) {
    std::vector<int> faceOfPlane;
    planes_ = meshing::polytopePlanes(p, &faceOfPlane);
    for (const Vec3 &v : p.vertices) bounds_ = unionBounds(bounds_, v);
    if (planes_.size() < kPolytopeFaceBvhMin) return;
    // Each face is convex and planar: a fan of triangles, wound as the face (outward)
    auto mesh = std::make_shared<ir::Mesh>();
    mesh->positions = p.vertices;
    for (size_t i = 0; i < planes_.size(); ++i) {
        const auto &f = p.faces[faceOfPlane[i]];
        for (size_t k = 1; k + 1 < f.size(); ++k) {
            mesh->triangles.push_back({static_cast<uint32_t>(f[0]), static_cast<uint32_t>(f[k]),
                                       static_cast<uint32_t>(f[k + 1])});
            planeOfTriangle_.push_back(static_cast<int>(i));
        }
    }
    auto faces = std::make_unique<TriangleMesh>(mesh);
    // Only a closed surface bounds the line's one span; otherwise keep the plane loop
    if (faces->closed()) faceMesh_ = std::move(faces);
}

ConvexPolytope::~ConvexPolytope() = default;

bool ConvexPolytope::intersect(const Ray &r, PrimitiveSpan *span) const {
    return faceMesh_ ? intersectFaces(r, span) : intersectPlanes(r, span);
}

bool ConvexPolytope::intersectFaces(const Ray &r, PrimitiveSpan *span) const {
    // A convex surface is crossed once going in and once going out; the watertight triangle
    // test counts a crossing through an edge or vertex once, so the first and last crossings
    // are the span (a ray grazing an edge meets it once or not at all: no span)
    thread_local std::vector<TriangleMesh::Hit> hits;
    hits.clear();
    faceMesh_->allHits(r, hits);
    if (hits.size() < 2) return false;
    const TriangleMesh::Hit *in = &hits[0], *out = &hits[0];
    for (const auto &h : hits) {
        if (h.t < in->t) in = &h;
        if (h.t > out->t) out = &h;
    }
    // The BVH names the faces; the distances come from their planes, as in the plane loop, so
    // that they agree with the surface points refined onto those planes (a triangle's own t
    // rounds differently, and a ray spawned off the face could find it again at t = 1e-17)
    int face0 = planeOfTriangle_[in->triangle], face1 = planeOfTriangle_[out->triangle];
    double dist, rate;
    double t0 = planeCrossing(planes_[face0], r, &dist, &rate) ? -dist / rate : in->t;
    double t1 = planeCrossing(planes_[face1], r, &dist, &rate) ? -dist / rate : out->t;
    if (!(t0 < t1)) return false;
    *span = {t0, t1, face0, face1};
    return true;
}

bool ConvexPolytope::planeCrossing(const meshing::FacePlane &pl, const Ray &r, double *dist,
                                   double *rate) {
    // Signed distance of the origin outside the plane, and the rate the ray closes on it; an
    // axis plane reads its coordinate directly, as Box does
    if (pl.axis >= 0) {
        *dist = pl.normal[pl.axis] * r.o[pl.axis] - pl.offset;
        *rate = pl.normal[pl.axis] * r.d[pl.axis];
    } else {
        *dist = dot(pl.normal, r.o) - pl.offset;
        *rate = dot(pl.normal, r.d);
    }
    return *rate != 0;
}

bool ConvexPolytope::intersectPlanes(const Ray &r, PrimitiveSpan *span) const {
    double t0 = -kInfinity, t1 = kInfinity;
    int face0 = -1, face1 = -1;
    for (size_t i = 0; i < planes_.size(); ++i) {
        double dist, rate;
        if (!planeCrossing(planes_[i], r, &dist, &rate)) {
            // Parallel: inside this half-space everywhere or nowhere
            if (dist > 0) return false;
            continue;
        }
        double t = -dist / rate;
        if (rate < 0) {
            if (t > t0) {
                t0 = t;
                face0 = static_cast<int>(i);
            }
        } else if (t < t1) {
            t1 = t;
            face1 = static_cast<int>(i);
        }
        // The half-spaces already leave nothing of the line
        if (!(t0 < t1)) return false;
    }
    if (face0 < 0 || face1 < 0) return false;
    *span = {t0, t1, face0, face1};
    return true;
}

bool ConvexPolytope::inside(const Vec3 &p) const {
    for (const auto &pl : planes_)
        if (dot(pl.normal, p) > pl.offset) return false;
    return true;
}

ObjectSurface ConvexPolytope::surface(const Vec3 &p, int face) const {
    const meshing::FacePlane &pl = planes_[face];
    if (pl.axis >= 0) {
        // The face coordinate is exact; the others carry the error of o + t d
        Vec3 refined = p;
        refined[pl.axis] = pl.normal[pl.axis] * pl.offset;
        Vec3 err = abs(refined) * gamma(3);
        err[pl.axis] = 0;
        return {refined, err, pl.normal};
    }
    // Project onto the plane; the projection adds a few roundings of |p| and of the offset
    Vec3 refined = p - pl.normal * (dot(pl.normal, p) - pl.offset);
    Vec3 err = abs(refined) * gamma(6) + Vec3(std::abs(pl.offset) * gamma(4));
    return {refined, err, pl.normal};
}

}  // namespace rt
