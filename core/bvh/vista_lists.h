// SPDX-License-Identifier: MIT
// Leaf lists for the rays that leave one point: a perspective camera's (POV-Ray's vista buffer,
// on a cube map of directions instead of the screen). Each cell of the cube map keeps the
// scene BVH's leaves whose boxes its cone of directions meets, in the order the BVH's
// traversal meets them, so a camera ray tests those few boxes instead of walking the tree from
// the root and gets the same answer (Bvh::traverseLeaves).
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <memory>

#include "core/bvh/bvh.h"
#include "core/math/ray.h"

namespace rt {

class VistaLists {
  public:
    /// Most leaves a cell lists; a cell whose cone meets more sends its rays through the tree.
    static constexpr int kMaxLeaves = 14;

    struct Cell {
        uint32_t count = 0;
        uint8_t octant = 0;  ///< the rays' octant the order is for (Bvh::collectLeaves)
        bool whole = false;  ///< more than kMaxLeaves: rays take the whole tree
        uint32_t leaves[kMaxLeaves];
        /// The cell's directions u on its face: a0 <= u[a] / (s u[k]) <= a1, b0 <= u[b] /
        /// (s u[k]) <= b1 and s u[k] > 0 (its cone before the widening build() gives it).
        uint8_t k = 0, a = 0, b = 0;
        double s = 1, a0 = 0, a1 = 0, b0 = 0, b1 = 0;
        /// Whether direction d lies in the cell's cone (to some 1e-16 of a face coordinate,
        /// far inside the widening): by products, without the division that places a
        /// direction on the cube map.
        bool holds(const Vec3 &d) const {
            static_assert(sizeof(Vec3) == 3 * sizeof(double),
                          "holds() indexes a direction's components");
            // The components read as the vector's bytes (memcpy of a double: one load)
            auto component = [&d](int axis) {
                double v;
                std::memcpy(&v, reinterpret_cast<const char *>(&d) + axis * sizeof(double),
                            sizeof v);
                return v;
            };
            double dk = component(k) * s, da = component(a), db = component(b);
            return dk > 0 && da >= a0 * dk && da <= a1 * dk && db >= b0 * dk && db <= b1 * dk;
        }
    };

    /// Lists over `bvh` (which must outlive this) for rays leaving `apex`, on a cube map of
    /// `resolution` x `resolution` cells a face (even, so no cell spans two octants). Cells are
    /// built on first use, by whichever thread needs one. Disabled (find() gives null) where a
    /// box of the tree is empty or not finite.
    VistaLists(const Bvh &bvh, const Vec3 &apex, int resolution = 64);
    ~VistaLists();
    VistaLists(const VistaLists &) = delete;
    VistaLists &operator=(const VistaLists &) = delete;

    /// The cell listing every leaf the ray can meet, in the order Bvh::traverse() meets them,
    /// for a ray that starts at the apex (tMin 0) and is unbounded (tMax infinite); null for
    /// any other ray, for a direction with a zero component, and where the cell is full.
    /// Each thread keeps the last cell it found and tries it first: a pixel's camera rays,
    /// and its neighbours', mostly share one.
    const Cell *find(const Ray &ray, double tMin, double tMax) const;

    bool enabled() const { return enabled_; }
    /// Cells built so far that list leaves (whole-tree cells not counted).
    size_t cellsListing() const;

  private:
    const Cell *build(int face, int i, int j) const;
    /// The cell whose face coordinates hold direction d (finite, no zero component).
    const Cell *place(const Vec3 &d) const;
    size_t cellCount() const { return 6 * static_cast<size_t>(n_) * static_cast<size_t>(n_); }

    const Bvh &bvh_;
    /// Distinct for every VistaLists made: a thread's last cell (find()) is kept with it
    uint64_t id_;
    Vec3 apex_;
    int n_;
    bool enabled_ = false;
    double tolerance_ = 0;  ///< how far outside a cell's cone a listed box may lie
    std::unique_ptr<std::atomic<const Cell *>[]> cells_;
};

}  // namespace rt
