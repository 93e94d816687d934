// SPDX-License-Identifier: MIT
// Shape defaults, span scratch pool and transformed primitive instances.
#include "core/geometry/shape.h"

#include <cmath>

namespace rt {

void SpanScratch::grow() { pool_.push_back(std::make_unique<SpanList>()); }

std::vector<int> &SpanScratch::acquireIndices() {
    if (indicesUsed_ == indexPool_.size())
        indexPool_.push_back(std::make_unique<std::vector<int>>());
    std::vector<int> &l = *indexPool_[indicesUsed_++];
    l.clear();
    return l;
}

bool Shape::firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                          SpanScratch &scratch) const {
    ScratchList list(scratch);
    scratch.cancelledTie = kInfinity;
    spans(ray, tMin, tMax, *list, scratch);
    const Crossing *found = nullptr;
    for (const Span &s : *list) {
        if (s.in.t >= tMax) break;
        if (s.in.t > tMin) {
            found = &s.in;
            break;
        }
        if (s.out.t > tMin) {
            if (s.out.t < tMax) found = &s.out;
            break;
        }
    }
    if (!found) return false;
    *c = *found;
    // Coincident faces that cancelled in front of this surface (or at it) are a tie too
    double eps = tieEpsilon(ray.o, c->t);
    if (scratch.cancelledTie > tMin - eps && scratch.cancelledTie <= c->t + eps) c->tie = true;
    return true;
}

namespace {

/// Whether the upper-left 3x3 block is exactly the identity (a zero of either sign).
bool identityBlock(const Mat4 &m) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (m.m[i][j] != (i == j ? 1.0 : 0.0)) return false;
    return true;
}

Placement::Kind placementKind(const Transform &t) {
    if (t.isIdentity()) return Placement::Kind::Identity;
    if (identityBlock(t.matrix()) && identityBlock(t.inverseMatrix()))
        return Placement::Kind::Translation;
    return Placement::Kind::General;
}

}  // namespace

Placement::Placement(const Transform &worldFromObject)
    : worldFromObject_(worldFromObject),
      kind_(placementKind(worldFromObject)),
      toWorldShift_(worldFromObject.matrix().translation()),
      toObjectShift_(worldFromObject.inverseMatrix().translation()),
      conditioning_(transformConditioning(worldFromObject)) {}

void Placement::generalPointToWorld(const ObjectSurface &os, SurfaceInteraction &si) const {
    Vec3 err;
    si.p = worldFromObject_.point(os.p, os.pError, &err);
    si.pError = err * conditioning_;
}

PrimitiveInstance::PrimitiveInstance(std::unique_ptr<Primitive> prim,
                                     const Transform &worldFromObject, int material)
    : LeafShape(material),
      prim_(std::move(prim)),
      placement_(worldFromObject),
      bounds_(placement_.worldBounds(prim_->objectBounds())),
      convex_(prim_->convex()) {}

bool PrimitiveInstance::lineSpan(const Ray &worldRay, Span *span) const {
    PrimitiveSpan ps;
    if (!prim_->intersect(placement_.toObject(worldRay), &ps)) return false;
    span->in = {ps.t0, this, ps.face0};
    span->out = {ps.t1, this, ps.face1};
    return true;
}

const std::vector<PrimitiveSpan> &PrimitiveInstance::allSpans(const Ray &worldRay) const {
    // One buffer per thread serves every instance: its spans are copied out before the next
    // call, and it keeps its capacity, so the hot path does not allocate
    thread_local std::vector<PrimitiveSpan> spans;
    spans.clear();
    prim_->intersectAll(placement_.toObject(worldRay), spans);
    return spans;
}

void PrimitiveInstance::lineSpans(const Ray &worldRay, SpanList &out) const {
    if (!convex_) {
        for (const PrimitiveSpan &ps : allSpans(worldRay))
            out.push_back({{ps.t0, this, ps.face0}, {ps.t1, this, ps.face1}});
        return;
    }
    Span s;
    if (lineSpan(worldRay, &s)) out.push_back(s);
}

bool PrimitiveInstance::firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                                      SpanScratch &) const {
    if (!convex_) {
        // The first span end beyond tMin
        for (const PrimitiveSpan &ps : allSpans(ray)) {
            if (ps.t0 >= tMax) return false;
            if (ps.t0 > tMin) {
                *c = {ps.t0, this, ps.face0};
                return true;
            }
            if (ps.t1 > tMin) {
                if (ps.t1 >= tMax) return false;
                *c = {ps.t1, this, ps.face1};
                return true;
            }
        }
        return false;
    }
    PrimitiveSpan s;
    return prim_->intersect(placement_.toObject(ray), &s) &&
           firstCrossingOf(s, this, tMin, tMax, c);
}

bool PrimitiveInstance::inside(const Vec3 &p) const {
    return prim_->inside(placement_.pointToObject(p));
}

SurfaceInteraction PrimitiveInstance::surfaceAt(const Ray &worldRay, const Crossing &c) const {
    Ray r = placement_.toObject(worldRay);
    ObjectSurface os = prim_->surface(r.at(c.t), c.face);
    SurfaceInteraction si;
    si.t = c.t;
    si.leaf = this;
    placement_.surfaceToWorld(os, si);
    si.ns = si.n;
    return si;
}

}  // namespace rt
