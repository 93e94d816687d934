// SPDX-License-Identifier: MIT
// Triangle meshes: shared geometry with its own BVH and a watertight ray-triangle test, and the
// placed instance the tracer and CSG see (closest hit; for closed meshes, whole-line spans by
// winding number and an inside test).
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "core/bvh/wide_bvh.h"
#include "core/geometry/shape.h"
#include "core/ir/mesh.h"

namespace rt {

/// Immutable mesh geometry in object space, shared by every instance that places it.
class TriangleMesh {
  public:
    /// A triangle's vertex indices and its own index, kept in the BVH's leaf order so that a
    /// leaf reads one contiguous run instead of the item order and then the triangle list.
    struct LeafTriangle {
        std::array<uint32_t, 3> v;
        uint32_t triangle;
        friend bool operator==(const LeafTriangle &, const LeafTriangle &) = default;
    };
    /// The triangles of `mesh` in the leaf order of `bvh` (built over that mesh).
    static LargeVector<LeafTriangle> leafOrder(const ir::Mesh &mesh, const WideBvh &bvh);
    /// Words after the last leaf, so a four-lane load of a shorter leaf (or of the second four
    /// of a leaf of five to seven) stays in the array.
    static constexpr size_t kLeafPadding = 4;
    /// Words of float leaves a triangle takes: its index and its nine coordinates.
    static constexpr size_t kFloatLeafWords = 10;
    /// `mesh`'s triangles leaf by leaf of `bvh` (built over that mesh), each leaf in one run of
    /// 32-bit words: for a leaf of n triangles from slot `first`, at [10 * first, 10 * (first +
    /// n)), first the n triangles' indices, then their vertices as floats, coordinate by
    /// coordinate: coordinate j (vertex j / 3, axis j % 3) of the i-th triangle in word
    /// n + j * n + i, so a leaf's triangles sit side by side, four to a SIMD register (a leaf
    /// holds up to eight: two registers a coordinate). Then
    /// kLeafPadding words. Empty unless every position is a float (as STL and glTF give them),
    /// so the floats stand for the positions exactly. threads: 0 for all cores.
    static LargeVector<uint32_t> floatLeaves(const ir::Mesh &mesh, const WideBvh &bvh,
                                             int threads = 0);
    /// Whether a leaf's triangles are tested four at a time (on a CPU with AVX2 and FMA); mesh
    /// BVHs are then built with WideBvh::kTriangleCost and leaves of up to eight triangles (two
    /// groups of four), for fuller leaves and fewer nodes.
    static bool fourWideLeaves();
    /// The BVH a TriangleMesh builds over `mesh` on this CPU (threads: 0 for all cores).
    static WideBvh buildBvh(const ir::Mesh &mesh, int threads);

    struct Hit {
        double t = 0;
        uint32_t triangle = 0;
        double b0 = 0, b1 = 0, b2 = 0;  ///< barycentric weights of the three vertices
        bool entering = false;          ///< the ray crosses against the outward normal
        double tError = 0;              ///< bound on the rounding error of t
    };

    /// buildThreads: threads of the BVH build, 0 for all cores; the BVH does not depend on it.
    explicit TriangleMesh(ir::MeshPtr mesh, int buildThreads = 0);

    const ir::Mesh &mesh() const { return *mesh_; }
    const Bounds3 &bounds() const { return bounds_; }
    bool closed() const { return topology_.closed(); }
    bool oriented() const { return topology_.oriented(); }
    const ir::MeshTopology &topology() const { return topology_; }
    size_t triangleCount() const { return mesh_->triangles.size(); }
    /// Bytes held by the BVH and the derived data (not counting the shared ir::Mesh).
    size_t extraBytes() const;
    const WideBvh &bvh() const { return bvh_; }
    /// A mesh's leaves hold either its triangles' indices and vertices as floats (floatLeaves,
    /// for a mesh whose positions are all floats; its BVH then keeps no item order, which the
    /// leaves hold) or their vertex indices (leafTriangles, for the others); the other array is
    /// empty. The hits are the same either way.
    const LargeVector<LeafTriangle> &leafTriangles() const { return leafTriangles_; }
    const LargeVector<uint32_t> &floatLeaves() const { return floatLeaves_; }

    /// Watertight ray-triangle test (Woop, Benthin and Wald 2013; pbrt-v3 section 3.6.2) for
    /// any t along the line, with a fill convention on edges and vertices: a ray through a
    /// shared edge or vertex hits exactly one triangle of each consistently oriented sheet, so
    /// the winding number of a closed mesh is counted right.
    bool intersectTriangle(const Ray &r, uint32_t triangle, Hit *hit) const;
    /// Closest hit with tMin < t < tMax, where t also exceeds the rounding-error bound of its own
    /// computation, so a ray spawned from the surface does not find it again. Of triangles hit
    /// at the same t, the lowest index wins, whatever order the BVH visits them in.
    bool closest(const Ray &r, double tMin, double tMax, Hit *hit) const;
    /// Every crossing of the whole line, unsorted.
    void allHits(const Ray &r, std::vector<Hit> &out) const;
    /// Surface data at a hit, in object space.
    /// The object-space surface of a hit; sets the shading normal (object space) and the
    /// interpolated per-vertex attributes of `si` (texture coordinates, the object-space
    /// tangent, vertex colour) that the mesh has.
    ObjectSurface surface(const Hit &hit, Vec3 *shadingNormal, SurfaceInteraction *si) const;

    /// The ray in the watertight test's frame: the axis of its largest component is z.
    struct RayFrame {
        const Ray *ray;
        int kx, ky, kz;
        double sx, sy, sz;
        double ox, oy, oz;  ///< the origin, permuted
        explicit RayFrame(const Ray &r);
    };

  private:
    /// intersectTriangle for a ray frame and the triangle's vertices, returning false early
    /// when t is not within (tMin, tMax), or (tMin, tMax] when tMaxInclusive.
    bool intersect(const RayFrame &f, const Vec3 &p0, const Vec3 &p1, const Vec3 &p2,
                   uint32_t triangle, double tMin, double tMax, bool tMaxInclusive, Hit *hit) const;
    /// Where the walk prefetches a leaf's data (WideBvh::setLeafData): its float leaf, or its
    /// triangles' records.
    WideBvh::LeafData leafData() const {
        if (!floatLeaves_.empty()) return {floatLeaves_.data(), kFloatLeafWords * sizeof(uint32_t)};
        return {leafTriangles_.data(), sizeof(LeafTriangle)};
    }
    /// Calls f(p0, p1, p2, triangle) for the triangles of the leaf [first, first + count) that
    /// the ray can hit: all of them, or on a CPU with AVX2 and FMA, those whose edge functions
    /// in the ray's frame do not have mixed signs (computed four at a time exactly as intersect
    /// computes them, so what it leaves out, intersect rejects).
    template <typename F>
    void forLeaf(const RayFrame &frame, uint32_t first, uint32_t count, F &&f) const;

    ir::MeshPtr mesh_;
    WideBvh bvh_;
    LargeVector<LeafTriangle>
        leafTriangles_;                  ///< in bvh_.itemOrder(), for a mesh not all in floats
    LargeVector<uint32_t> floatLeaves_;  ///< as floatLeaves() lays them out, or empty
    bool fourWide_ = false;              ///< leaves take the four-wide edge test
    Bounds3 bounds_;
    ir::MeshTopology topology_;
    /// Per triangle: true when its vertex normals differ (POV-Ray shades only such triangles
    /// smoothly; the others use the geometric normal)
    std::vector<bool> smooth_;
};

/// A mesh placed in the world with a material.
class MeshInstance final : public LeafShape {
  public:
    MeshInstance(std::shared_ptr<const TriangleMesh> mesh, const Transform &worldFromObject,
                 int material);

    Bounds3 worldBounds() const override { return bounds_; }
    void lineSpans(const Ray &worldRay, SpanList &out) const override;
    bool firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                       SpanScratch &scratch) const override;
    /// Winding number (parity for closed but inconsistently oriented meshes) of a ray from p;
    /// always false for an open mesh, which bounds nothing.
    bool inside(const Vec3 &p) const override;
    SurfaceInteraction surfaceAt(const Ray &worldRay, const Crossing &c) const override;

    const TriangleMesh &geometry() const { return *mesh_; }

  private:
    std::shared_ptr<const TriangleMesh> mesh_;
    Placement placement_;
    Bounds3 bounds_;
};

}  // namespace rt
