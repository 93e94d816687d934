// SPDX-License-Identifier: MIT
// Distributions of directions about a principal direction, used for glossy reflection and
// frosted refraction: each sampler maps two uniform numbers to a direction and knows its own
// density, so the tests can check the one against the other (chi-square) and the integrator
// can weight by it where it must.
#pragma once

#include "core/math/vec3.h"

namespace rt {

/// Orthonormal basis with `n` as its third axis (Duff et al. 2017, "Building an Orthonormal
/// Basis, Revisited": branchless, no loss of precision near the poles).
struct Frame {
    Vec3 s, t, n;

    static Frame fromZ(const Vec3 &n);
    Vec3 toWorld(const Vec3 &local) const { return s * local.x + t * local.y + n * local.z; }
    Vec3 toLocal(const Vec3 &w) const { return {dot(w, s), dot(w, t), dot(w, n)}; }
};

/// Shape of the lobe of distributed rays about the principal (mirror or refracted) direction.
enum class LobeShape {
    /// The classic distributed-ray-tracing choice: the angle from the centre is Rayleigh
    /// distributed with scale sigma (a two-dimensional normal distribution of the tangent-plane
    /// offset for small angles), azimuth uniform, truncated at 90 degrees.
    Normal,
    /// Phong's cosine-power lobe (n + 1) / (2 pi) cos^n(theta) over the hemisphere about the
    /// centre, with n = 1 / sigma^2 so that small angles spread as in Normal. Sampled exactly
    /// (inversion of its cumulative distribution), so its Monte Carlo weight is one.
    Phong,
};

/// The widest accepted spread of either lobe (radians): beyond it both are nearly uniform
/// over the hemisphere and the spread stops meaning anything.
constexpr double kMaxLobeSigma = 1.5707963267948966;

/// A lobe about the local +z axis with angular spread sigma (radians, 0 < sigma <= pi/2).
class Lobe {
  public:
    Lobe(LobeShape shape, double sigma);

    /// Unit direction in the local frame (z along the centre) for u1, u2 in [0, 1).
    Vec3 sampleLocal(double u1, double u2) const;
    /// Density with respect to solid angle of a local direction (zero outside the hemisphere).
    double pdfLocal(const Vec3 &w) const;
    /// Density of the polar angle theta alone (radians), integrated over the azimuth.
    double pdfTheta(double theta) const;

    LobeShape shape() const { return shape_; }
    double sigma() const { return sigma_; }
    /// Phong exponent (Phong lobe only).
    double exponent() const { return exponent_; }

  private:
    LobeShape shape_;
    double sigma_;
    double exponent_ = 0;
    /// Normal lobe: 1 - exp(-(pi/2)^2 / (2 sigma^2)), the mass the truncation keeps.
    double truncatedMass_ = 1;
};

/// A direction of the lobe about `centre` (unit), folded back into the half-space where
/// dot(direction, side) > 0 by mirroring in the plane orthogonal to `side`: a glossy reflection
/// never goes into its surface and a frosted refraction never comes back out, and no sample is
/// lost (the mirrored density is the lobe's folded one).
Vec3 sampleLobeAbout(const Lobe &lobe, const Vec3 &centre, const Vec3 &side, double u1, double u2);

/// Generator g of the rank-1 lattice {(i / n, i g / n mod 1)} of n points: the integer nearest
/// n / golden ratio (for Fibonacci n the previous Fibonacci number, the best 2-D lattice),
/// moved up to the next integer coprime to n, so that both coordinates of the n points fall
/// in n distinct strata (10 for 16 points would leave only 8 in the second).
int latticeGenerator(int n);

}  // namespace rt
