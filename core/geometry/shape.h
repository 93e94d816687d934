// SPDX-License-Identifier: MIT
// World-space solids the tracer sees: the Shape interface, and a primitive placed by a transform.
#pragma once

#include <cmath>
#include <memory>

#include "core/geometry/hit.h"
#include "core/geometry/primitive.h"
#include "core/geometry/span.h"
#include "core/ir/source_loc.h"
#include "core/math/float_util.h"
#include "core/math/transform.h"

namespace rt {

/// Per-thread scratch for CSG span evaluation, with the work counters the render summary prints.
class SpanScratch {
  public:
    SpanList &acquire() {
        // Inline: every CSG node a ray evaluates takes two lists
        if (used_ == pool_.size()) grow();
        SpanList &l = *pool_[used_++];
        l.clear();
        return l;
    }
    void release() { --used_; }
    /// A list of operand indices, for a CSG node with many operands (nodes nest, so a pool).
    std::vector<int> &acquireIndices();
    void releaseIndices() { --indicesUsed_; }
    long long spanOps = 0;         ///< span-list merges performed
    long long prunedSubtrees = 0;  ///< CSG subtrees skipped by bounds or by the pruning rules
    /// Smallest t of coincident crossings that cancelled during the current evaluation.
    double cancelledTie = kInfinity;

  private:
    void grow();
    std::vector<std::unique_ptr<SpanList>> pool_;
    size_t used_ = 0;
    std::vector<std::unique_ptr<std::vector<int>>> indexPool_;
    size_t indicesUsed_ = 0;
};

/// RAII hold on a list from one of SpanScratch's pools.
template <typename List, List &(SpanScratch::*Acquire)(), void (SpanScratch::*Release)()>
class ScratchHold {
  public:
    explicit ScratchHold(SpanScratch &s) : scratch_(s), list_((s.*Acquire)()) {}
    ~ScratchHold() { (scratch_.*Release)(); }
    ScratchHold(const ScratchHold &) = delete;
    ScratchHold &operator=(const ScratchHold &) = delete;
    List &operator*() { return list_; }
    List *operator->() { return &list_; }

  private:
    SpanScratch &scratch_;
    List &list_;
};

using ScratchList = ScratchHold<SpanList, &SpanScratch::acquire, &SpanScratch::release>;
using ScratchIndices =
    ScratchHold<std::vector<int>, &SpanScratch::acquireIndices, &SpanScratch::releaseIndices>;

class Shape {
  public:
    virtual ~Shape() = default;
    virtual Bounds3 worldBounds() const = 0;
    /// Spans of the world ray line inside the solid. Only the part of the line within
    /// [tMin, tMax] is guaranteed to be classified right; spans may extend beyond it.
    virtual void spans(const Ray &ray, double tMin, double tMax, SpanList &out,
                       SpanScratch &scratch) const = 0;
    /// First surface crossing with tMin < t < tMax.
    virtual bool firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                               SpanScratch &scratch) const;
    /// Point-in-solid test, boundary included.
    virtual bool inside(const Vec3 &p) const = 0;
    /// Number of primitives (for statistics and the plan).
    virtual size_t primitiveCount() const = 0;

    /// Material index that defines the interior (ior, fade) of this solid.
    int interiorMaterial = -1;
    /// No surface of this solid transmits light: shadow rays stop at it.
    bool opaque = true;
};

/// A solid (or surface) with its world placement and one material, whose crossings carry
/// surface data: what CSG combines and the tracer shades. An analytic primitive or a mesh.
class LeafShape : public Shape {
  public:
    explicit LeafShape(int material) : material_(material) {}

    /// Spans of the whole world line inside the solid; nothing for an open surface.
    virtual void lineSpans(const Ray &worldRay, SpanList &out) const = 0;
    /// Full surface data for a crossing of this leaf by the world ray.
    virtual SurfaceInteraction surfaceAt(const Ray &worldRay, const Crossing &c) const = 0;

    void spans(const Ray &ray, double, double, SpanList &out, SpanScratch &) const override {
        lineSpans(ray, out);
    }
    size_t primitiveCount() const override { return 1; }
    int material() const { return material_; }
    /// Order of this leaf's material by value, for the coincident-face tie-break.
    int tieRank = 0;
    /// Position of this leaf among the compiled scene's leaves, from 1 (0 before): a name for
    /// it that is the same in every process, where its address is not (tiles rendered by
    /// separate processes must make the same adaptive-sampling decisions).
    uint32_t sceneIndex = 0;
    /// Where the leaf came from (the primitive, polyhedron or import call), for errors.
    SourceLoc loc;

  private:
    int material_;
};

/// Where a leaf sits in the world, and what its instances need of that: rays and points into
/// object space, surfaces back out with their error bounds grown by the transform's
/// conditioning. The identity passes everything through untouched; a pure translation (the
/// 3x3 block of the matrix and of its inverse exactly the identity: most `translate()`d parts)
/// adds its offset instead of multiplying by the matrix.
///
/// The translation's results are the matrix's: its products by 1 are exact and its products
/// by 0 are zeros, which change no sum whose other terms are not all zero; the error bounds
/// are the same bit for bit. The one difference is the sign of a zero coordinate (of a
/// direction or normal, or of a point on an axis whose offset is zero): the matrix's sum of
/// signed zeros may give +0 where this path keeps -0. The two compare equal, and every test
/// picture is byte-identical either way (tests/core/geometry/placement_test.cpp, README).
class Placement {
  public:
    explicit Placement(const Transform &worldFromObject);

    Ray toObject(const Ray &r) const {
        if (kind_ == Kind::Identity) return r;
        if (kind_ == Kind::Translation) return Ray(r.o + toObjectShift_, r.d);
        return worldFromObject_.inverseRay(r);
    }
    Vec3 pointToObject(const Vec3 &p) const {
        if (kind_ == Kind::Identity) return p;
        if (kind_ == Kind::Translation) return p + toObjectShift_;
        return worldFromObject_.inversePoint(p);
    }
    Bounds3 worldBounds(const Bounds3 &objectBounds) const {
        return worldFromObject_.bounds(objectBounds);
    }
    /// Unit world normal of an object-space normal.
    Vec3 normalToWorld(const Vec3 &n) const {
        return normalize(kind_ == Kind::General ? worldFromObject_.normal(n) : n);
    }
    /// World direction of an object-space tangent vector (not normalised).
    Vec3 vectorToWorld(const Vec3 &v) const {
        return kind_ == Kind::General ? worldFromObject_.vector(v) : v;
    }
    /// Sets the world hit point, its error bound and the unit geometric normal of `si` from
    /// an object-space surface point.
    void surfaceToWorld(const ObjectSurface &os, SurfaceInteraction &si) const {
        pointToWorld(os, si);
        si.n = normalToWorld(os.normal);
    }
    /// surfaceToWorld() without the normal: the world hit point and its error bound.
    void pointToWorld(const ObjectSurface &os, SurfaceInteraction &si) const {
        switch (kind_) {
            case Kind::Identity:
                si.p = os.p;
                si.pError = os.pError;
                break;
            case Kind::Translation:
                // Transform::point's bound with its products by 0 left out (they add +0)
                si.p = os.p + toWorldShift_;
                for (int i = 0; i < 3; ++i)
                    si.pError[i] = (gamma(3) * (std::abs(os.p[i]) + std::abs(toWorldShift_[i])) +
                                    (gamma(3) + 1) * os.pError[i]) *
                                   conditioning_;
                break;
            case Kind::General:
                generalPointToWorld(os, si);
                break;
        }
    }

    enum class Kind : uint8_t { Identity, Translation, General };
    Kind kind() const { return kind_; }
    /// What toObject() adds to a point for a Translation.
    const Vec3 &toObjectShift() const { return toObjectShift_; }

  private:
    void generalPointToWorld(const ObjectSurface &os, SurfaceInteraction &si) const;

    Transform worldFromObject_;
    Kind kind_;
    /// Translation: the offset of the matrix and of its inverse (their last columns).
    Vec3 toWorldShift_, toObjectShift_;
    /// Error growth of a round trip through the transform (condition number estimate, >= 1).
    double conditioning_;
};

/// An analytic primitive with its world placement and material.
class PrimitiveInstance final : public LeafShape {
  public:
    PrimitiveInstance(std::unique_ptr<Primitive> prim, const Transform &worldFromObject,
                      int material);

    Bounds3 worldBounds() const override { return bounds_; }
    void lineSpans(const Ray &worldRay, SpanList &out) const override;
    bool firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                       SpanScratch &scratch) const override;
    bool inside(const Vec3 &p) const override;
    SurfaceInteraction surfaceAt(const Ray &worldRay, const Crossing &c) const override;

    /// The span of the whole world line inside this primitive; for one that is not convex,
    /// from its first entry to its last exit.
    bool lineSpan(const Ray &worldRay, Span *span) const;
    /// Whether the primitive is convex: its lineSpans() are lineSpan()'s one span, or none.
    bool convex() const { return convex_; }
    /// The crossing firstCrossing() takes from the one span `s` of the line inside a convex
    /// primitive (`leaf`): its entry where that lies within (tMin, tMax), else its exit where
    /// that does.
    static bool firstCrossingOf(const PrimitiveSpan &s, const LeafShape *leaf, double tMin,
                                double tMax, Crossing *c) {
        if (s.t0 > tMin) {
            if (s.t0 >= tMax) return false;
            *c = {s.t0, leaf, s.face0};
            return true;
        }
        if (s.t1 > tMin && s.t1 < tMax) {
            *c = {s.t1, leaf, s.face1};
            return true;
        }
        return false;
    }
    const Primitive &primitive() const { return *prim_; }
    const Placement &placement() const { return placement_; }

  private:
    /// The primitive's spans of the world line, in a per-thread buffer (no allocation per ray
    /// once it has grown), for primitives that are not convex.
    const std::vector<PrimitiveSpan> &allSpans(const Ray &worldRay) const;

    std::unique_ptr<Primitive> prim_;
    Placement placement_;
    Bounds3 bounds_;
    bool convex_;
};

}  // namespace rt
