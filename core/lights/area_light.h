// SPDX-License-Identifier: MIT
// POV-Ray 3.7's area_light shadow: a grid of shadow-ray targets about the light's centre
// (optionally jittered, circular, or oriented towards the shaded point) and the recursive,
// optionally adaptive, average of their filtered light colours (docs/design/povray-semantics.md
// section 5).
#pragma once

#include <functional>
#include <vector>

#include "core/ir/light.h"
#include "core/math/rgb.h"
#include "core/math/rng.h"

namespace rt {

/// The weight POV-Ray's recursive average gives each grid point when the recursion does not
/// depend on the samples (full subdivision: `adaptive` at least the depth the grid needs, as
/// with POV-Ray's default 100). The average is then the fixed sum of weight x sample, so one
/// grid point drawn with probability equal to its weight is an unbiased one-ray estimate of it.
class AreaLightWeights {
  public:
    explicit AreaLightWeights(const ir::Light::Area &area);

    /// False when the average adapts to the samples (low `adaptive`): no fixed weights exist.
    bool fixed() const { return !cdf_.empty(); }
    double weight(int u, int v) const;
    /// The grid point whose cumulative weight interval holds u in [0, 1).
    void pick(double u, int &gu, int &gv) const;

  private:
    void region(int u1, int v1, int u2, int v2, int level, double w);

    int n1_, n2_, adaptive_;
    bool adapts_ = false;
    std::vector<double> weights_, cdf_;
};

class AreaLightSampler {
  public:
    /// `shadedPoint` orients the grid of an `orient` light. `rng` draws the jitter (unused
    /// without it); within one average() every grid point is drawn at most once.
    AreaLightSampler(const ir::Light &light, const Vec3 &shadedPoint, Rng &rng);

    /// Target of grid point (u, v), u in [0, n1), v in [0, n2), jittered when the light is.
    Vec3 gridTarget(int u, int v);

    /// Average of `sample(target)` over the grid, POV-Ray's way: the mean of the four corners of
    /// a region, or of its four quadrants while the region is wider than one cell and either the
    /// recursion is shallower than `adaptive` or two neighbouring corners differ by more than
    /// 0.1 (sum of channel differences). `sample` returns the light colour arriving from a
    /// target (light colour times the shadow filter).
    Rgb average(const std::function<Rgb(const Vec3 &target)> &sample);

    /// Number of distinct grid points evaluated by the last average().
    int evaluated() const { return evaluated_; }

  private:
    Rgb corner(int u, int v, const std::function<Rgb(const Vec3 &)> &sample);
    Rgb region(int u1, int v1, int u2, int v2, int level,
               const std::function<Rgb(const Vec3 &)> &sample);

    const ir::Light &light_;
    Rng &rng_;
    Vec3 axis1_, axis2_;
    std::vector<Rgb> grid_;
    std::vector<char> done_;
    int evaluated_ = 0;
};

}  // namespace rt
