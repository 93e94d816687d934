// SPDX-License-Identifier: MIT
// Solids of revolution about +Z (OpenSCAD's rotate_extrude): the torus and the lathe of a
// polygonal profile, whole or cut to a wedge of azimuths; a line may cross them several times.
#pragma once

#include <cmath>
#include <vector>

#include "core/geometry/primitive.h"

namespace rt {

/// What the torus and the lathe share: the wedge of azimuths [0, angle] they fill, and the
/// spans of a line found from candidate crossings. Every crossing of the curved surface and
/// of the two end half-planes is a candidate; the candidates are sorted and each interval
/// between neighbours is classified by the exact inside test at its midpoint, so a spurious
/// candidate only splits an interval of one class, and coincident candidates (a ray through
/// a vertex circle, or through the axis where the end planes meet) cannot upset the parity.
/// Faces: kStartFace and kEndFace are the end half-planes, the curved surface numbers from
/// kFirstProfileFace.
class RevolvedSolid : public Primitive {
  public:
    static constexpr int kStartFace = 0, kEndFace = 1, kFirstProfileFace = 2;

    Bounds3 objectBounds() const override { return bounds_; }
    bool convex() const override { return false; }
    /// From the first entry to the last exit.
    bool intersect(const Ray &r, PrimitiveSpan *span) const override;
    void intersectAll(const Ray &r, std::vector<PrimitiveSpan> &spans) const override;
    bool inside(const Vec3 &p) const override {
        return insideWedge(p) && insideProfile(std::sqrt(p.x * p.x + p.y * p.y), p.z);
    }
    ObjectSurface surface(const Vec3 &p, int face) const override;

    double angle() const { return angle_; }

  protected:
    struct Candidate {
        double t;
        int face;
    };

    /// `rMin..rMax` and `zMin..zMax` bound the profile.
    RevolvedSolid(double angle, double rMin, double rMax, double zMin, double zMax);

    /// Appends the crossings of the line with the curved surface. The ray's origin is the
    /// point of the line closest to (0, 0, zCentre()), and [tLo, tHi] the part of the line in
    /// the bounding cylinder.
    virtual void profileCandidates(const Ray &r, double tLo, double tHi,
                                   std::vector<Candidate> &out) const = 0;
    /// Whether the profile point (r >= 0, z) is in the solid (boundary either way).
    virtual bool insideProfile(double r, double z) const = 0;
    /// The point refined onto the curved face and its outward normal.
    virtual ObjectSurface profileSurface(const Vec3 &p, int face) const = 0;
    /// The face to record for a crossing of the curved surface, given whether the line enters
    /// the solid there (a lathe records which side of an edge is outside). Default: `face`.
    virtual int orientFace(int face, const Vec3 &, const Vec3 &, bool) const { return face; }

    double zCentre() const { return 0.5 * (zMin_ + zMax_); }
    double rMax() const { return rMax_; }
    /// Candidate tests keep crossings this far (times the solid's size) outside a piece's
    /// range: a kept crossing that is no boundary only splits an interval of one class.
    double candidateSlack() const { return candidateSlack_; }

  private:
    bool insideWedge(const Vec3 &p) const;
    void wedgeCandidates(const Ray &r, std::vector<Candidate> &out) const;

    double angle_;
    bool full_;
    Vec3 endDir_;     ///< unit direction of the end half-plane (azimuth `angle`)
    Vec3 endNormal_;  ///< outward unit normal of the end half-plane
    double rMax_, zMin_, zMax_;
    double candidateSlack_;
    Bounds3 bounds_;
};

/// Torus about +Z: (sqrt(x^2 + y^2) - major)^2 + z^2 <= minor^2, revolved by `angle` degrees.
/// The line's quartic is formed about the line's point closest to the centre, in units of the
/// major radius, where it has no cubic term; its roots are isolated between the critical
/// points (roots of the cubic derivative) and each is found by safeguarded Newton iteration
/// on the tube's own distance function, so thin, horn, huge and tiny tori and grazing rays
/// keep full precision.
class Torus final : public RevolvedSolid {
  public:
    explicit Torus(const ir::TorusPrim &prim);

  protected:
    void profileCandidates(const Ray &r, double tLo, double tHi,
                           std::vector<Candidate> &out) const override;
    bool insideProfile(double r, double z) const override {
        double dr = r - major_;
        return dr * dr + z * z <= minor_ * minor_;
    }
    ObjectSurface profileSurface(const Vec3 &p, int face) const override;

  private:
    double major_, minor_;
};

/// Lathe: the even-odd region of profile outlines revolved about +Z. Each outline edge sweeps
/// a cone piece (a quadratic in t), a cylinder piece or an annulus (a plane crossing). Curved
/// faces are kFirstProfileFace + 2 * edge + (1 where the outside is to the edge's left).
class Lathe final : public RevolvedSolid {
  public:
    explicit Lathe(const ir::LathePrim &prim);

  protected:
    void profileCandidates(const Ray &r, double tLo, double tHi,
                           std::vector<Candidate> &out) const override;
    bool insideProfile(double r, double z) const override;
    ObjectSurface profileSurface(const Vec3 &p, int face) const override;
    int orientFace(int face, const Vec3 &p, const Vec3 &d, bool entering) const override;

  private:
    struct Edge {
        double r1, z1, r2, z2;
        double slope;  ///< dr/dz (cone and cylinder pieces)
    };
    /// The normal of an edge's swept surface at p, pointing to the edge's right in (r, z).
    Vec3 edgeNormal(const Edge &e, const Vec3 &p) const;

    std::vector<Edge> edges_;
    /// The heights of the profile's vertices, sorted and unique, and for the slab between
    /// neighbours k and k + 1 the edges spanning it (slabEdges_[slabStart_[k] ..
    /// slabStart_[k + 1]]): the inside test reads only the edges at its height. Empty (every
    /// edge is read) for zig-zag profiles whose table would grow past kMaxSlabEntries.
    std::vector<double> slabZ_;
    std::vector<uint32_t> slabStart_, slabEdges_;
};

/// Largest edge-per-slab table a lathe keeps for its inside test (4 bytes each).
constexpr size_t kMaxSlabEntries = 1 << 22;

}  // namespace rt
