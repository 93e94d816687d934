// SPDX-License-Identifier: MIT
// Analytic primitives in object space: each returns the spans of the whole ray line inside it
// (one for the convex ones), its inside test, and surface data for a crossing.
#pragma once

#include <memory>
#include <vector>

#include "core/ir/node.h"
#include "core/math/bounds3.h"
#include "core/math/float_util.h"
#include "core/math/ray.h"
#include "core/meshing/facets.h"

namespace rt {

class TriangleMesh;

/// Object-space interval of the ray line inside a solid, with the face crossed at each end.
struct PrimitiveSpan {
    double t0 = 0, t1 = 0;
    int face0 = 0, face1 = 0;
};

/// Surface point refined onto the primitive, with a bound on its absolute error.
struct ObjectSurface {
    Vec3 p, pError, normal;  ///< normal points out of the solid (not normalised)
};

class Primitive {
  public:
    virtual ~Primitive() = default;
    static std::unique_ptr<Primitive> create(const ir::PrimShape &shape);

    virtual Bounds3 objectBounds() const = 0;
    /// Span of the whole line o + t d inside the solid, t over all reals. False when the line
    /// misses the solid or only touches it (zero-length spans are dropped). A solid that is
    /// not convex gives the span from its first entry to its last exit (see intersectAll).
    virtual bool intersect(const Ray &objectRay, PrimitiveSpan *span) const = 0;
    /// Whether every line meets the solid in one span at most, so intersect() says it all.
    virtual bool convex() const { return true; }
    /// Appends the spans of the whole line inside the solid to `spans`: sorted, disjoint, not
    /// touching, of positive length. The default appends intersect()'s one span.
    virtual void intersectAll(const Ray &objectRay, std::vector<PrimitiveSpan> &spans) const;
    /// Point-in-solid test, boundary included.
    virtual bool inside(const Vec3 &p) const = 0;
    /// Refines a point near the surface of the given face onto it and returns the outward normal.
    virtual ObjectSurface surface(const Vec3 &p, int face) const = 0;
};

class Sphere final : public Primitive {
  public:
    explicit Sphere(double radius) : radius_(radius) {}
    Bounds3 objectBounds() const override { return Bounds3(Vec3(-radius_), Vec3(radius_)); }
    bool intersect(const Ray &r, PrimitiveSpan *span) const override;
    bool inside(const Vec3 &p) const override { return lengthSquared(p) <= radius_ * radius_; }
    ObjectSurface surface(const Vec3 &p, int face) const override;

  private:
    double radius_;
};

/// Axis-aligned box; faces are numbered 2*axis + (0 for the min side, 1 for the max side).
class Box final : public Primitive {
  public:
    Box(const Vec3 &min, const Vec3 &max) : min_(min), max_(max) {}
    Bounds3 objectBounds() const override { return Bounds3(min_, max_); }
    bool intersect(const Ray &r, PrimitiveSpan *span) const override {
        return slabSpan(min_, max_, r.o, r.d, Vec3(1 / r.d.x, 1 / r.d.y, 1 / r.d.z), span);
    }
    /// intersect() for the box [min, max] and the line o + t d, given d's reciprocals
    /// (`invDir`: a ray's, computed once for every box it meets). Faces 2a and 2a + 1: the
    /// min and max planes of axis a.
    static bool slabSpan(const Vec3 &min, const Vec3 &max, const Vec3 &o, const Vec3 &d,
                         const Vec3 &invDir, PrimitiveSpan *span) {
        double t0 = -kInfinity, t1 = kInfinity;
        int face0 = -1, face1 = -1;
        for (int i = 0; i < 3; ++i) {
            if (d[i] == 0) {
                // Parallel to this slab: inside it everywhere or nowhere
                if (o[i] < min[i] || o[i] > max[i]) return false;
                continue;
            }
            double tNear = (min[i] - o[i]) * invDir[i], tFar = (max[i] - o[i]) * invDir[i];
            int fNear = 2 * i, fFar = 2 * i + 1;
            if (tNear > tFar) {
                std::swap(tNear, tFar);
                std::swap(fNear, fFar);
            }
            if (tNear > t0) {
                t0 = tNear;
                face0 = fNear;
            }
            if (tFar < t1) {
                t1 = tFar;
                face1 = fFar;
            }
        }
        if (face0 < 0 || face1 < 0 || !(t0 < t1)) return false;
        *span = {t0, t1, face0, face1};
        return true;
    }
    const Vec3 &min() const { return min_; }
    const Vec3 &max() const { return max_; }
    bool inside(const Vec3 &p) const override;
    ObjectSurface surface(const Vec3 &p, int face) const override {
        return surfaceOf(min_, max_, p, face);
    }
    /// surface() of the box [min, max]. Its normal is a unit vector along an axis.
    static ObjectSurface surfaceOf(const Vec3 &min, const Vec3 &max, const Vec3 &p, int face) {
        int axis = face / 2;
        bool maxSide = face % 2;
        Vec3 refined = rt::max(min, rt::min(p, max));
        refined[axis] = maxSide ? max[axis] : min[axis];
        // The face coordinate is exact; the others carry the error of o + t d.
        Vec3 err = abs(refined) * gamma(3);
        err[axis] = 0;
        Vec3 n(0);
        n[axis] = maxSide ? 1 : -1;
        return {refined, err, n};
    }

  private:
    Vec3 min_, max_;
};

/// Truncated cone along +Z (OpenSCAD's cylinder): radius r1 at z0, r2 at z1, both >= 0.
/// Faces: 0 side, 1 bottom cap (z0), 2 top cap (z1).
class Cone final : public Primitive {
  public:
    Cone(double z0, double z1, double r1, double r2);
    Bounds3 objectBounds() const override;
    bool intersect(const Ray &r, PrimitiveSpan *span) const override;
    bool inside(const Vec3 &p) const override;
    ObjectSurface surface(const Vec3 &p, int face) const override;

  private:
    double radiusAt(double z) const { return r1_ + slope_ * (z - z0_); }
    /// intersect()'s work, in a function GCC may copy for CPUs with FMA (it does not copy a
    /// virtual one): its std::fma calls are then one instruction each, not calls into libm.
    bool lineSpan(const Ray &r, PrimitiveSpan *span) const;

    double z0_, z1_, r1_, r2_;
    double slope_;  ///< dr/dz
};

/// Convex polytope (OpenSCAD's faceted sphere, cylinder, cone; hulls): the intersection of
/// its faces' half-spaces, so the line's span is the latest entry and the earliest exit over
/// the planes (Kay and Kajiya 1986; Haines, "Fast ray-convex polyhedron intersection",
/// Graphics Gems II). Face i of a span is plane i.
class ConvexPolytope final : public Primitive {
  public:
    explicit ConvexPolytope(const ir::PolytopePrim &p);
    ~ConvexPolytope() override;
    Bounds3 objectBounds() const override { return bounds_; }
    bool intersect(const Ray &r, PrimitiveSpan *span) const override;
    bool inside(const Vec3 &p) const override;
    ObjectSurface surface(const Vec3 &p, int face) const override;
    size_t planeCount() const { return planes_.size(); }
    /// Whether rays find their two faces through a BVH over the faces (many faces) rather
    /// than by clipping against every plane.
    bool usesFaceBvh() const { return faceMesh_ != nullptr; }

  private:
    /// Signed distance of the ray's origin outside the plane and the rate the ray closes on
    /// it; false when the ray runs parallel to it.
    static bool planeCrossing(const meshing::FacePlane &pl, const Ray &r, double *dist,
                              double *rate);
    bool intersectPlanes(const Ray &r, PrimitiveSpan *span) const;
    bool intersectFaces(const Ray &r, PrimitiveSpan *span) const;

    std::vector<meshing::FacePlane> planes_;
    Bounds3 bounds_;
    /// Large polytopes (hulls of thousands of faces): the faces as a closed triangle mesh with
    /// its BVH, and the plane of each triangle.
    std::unique_ptr<TriangleMesh> faceMesh_;
    std::vector<int> planeOfTriangle_;
};

/// Above this many faces a polytope finds a ray's entry and exit through a BVH over its faces
/// (O(log n)) instead of clipping the ray by every plane (O(n)); below it the plane loop, with
/// no traversal overhead, is faster.
constexpr size_t kPolytopeFaceBvhMin = 48;

}  // namespace rt
