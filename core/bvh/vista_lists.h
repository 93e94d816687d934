// SPDX-License-Identifier: MIT
// Leaf lists for the rays that leave one point: a perspective camera's (POV-Ray's vista buffer,
// on a cube map of directions instead of the screen). Each cell of the cube map keeps the
// scene BVH's leaves whose boxes its cone of directions meets, in the order the BVH's
// traversal meets them, so a camera ray tests those few boxes instead of walking the tree from
// the root and gets the same answer (Bvh::traverseLeaves).
#pragma once

#include <atomic>
#include <cstdint>
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
    const Cell *find(const Ray &ray, double tMin, double tMax) const;

    bool enabled() const { return enabled_; }
    /// Cells built so far that list leaves (whole-tree cells not counted).
    size_t cellsListing() const;

  private:
    const Cell *build(int face, int i, int j) const;
    size_t cellCount() const { return 6 * static_cast<size_t>(n_) * static_cast<size_t>(n_); }

    const Bvh &bvh_;
    Vec3 apex_;
    int n_;
    bool enabled_ = false;
    double tolerance_ = 0;  ///< how far outside a cell's cone a listed box may lie
    std::unique_ptr<std::atomic<const Cell *>[]> cells_;
};

}  // namespace rt
