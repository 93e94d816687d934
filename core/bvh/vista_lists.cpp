// SPDX-License-Identifier: MIT
// Cube-map cells of leaf lists around a camera (see vista_lists.h).
#include "core/bvh/vista_lists.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rt {

namespace {

/// Widening of a cell's cone beyond its face coordinates (tangents). find() picks a ray's cell
/// from its direction's face coordinates, which rounding moves by some 1e-14 of a cell; a
/// widening of 1e-9 of a face keeps the exact direction inside the cell's cone.
constexpr double kAngularMargin = 1e-9;

std::atomic<uint64_t> nextId{1};

/// The cell this thread found last, and whose lists it is (VistaLists::id_)
struct Recent {
    uint64_t owner = 0;
    const VistaLists::Cell *cell = nullptr;
};
thread_local Recent recent;

}  // namespace

VistaLists::VistaLists(const Bvh &bvh, const Vec3 &apex, int resolution)
    : bvh_(bvh), id_(nextId.fetch_add(1, std::memory_order_relaxed)), apex_(apex), n_(resolution) {
    if (bvh.empty() || n_ < 2 || n_ % 2 != 0 || !apex.isFinite()) return;
    // Every box must be finite and not empty: an empty or unbounded one gives NaN slab
    // distances, where the slab test is not monotonic and a leaf's box could pass where its
    // parent's did not (Bvh::traverseLeaves)
    double scale = std::max({std::abs(apex.x), std::abs(apex.y), std::abs(apex.z)});
    for (const Bvh::Node &node : bvh.nodes()) {
        if (!node.bounds.isFinite() || node.bounds.isEmpty()) return;
        for (int i = 0; i < 3; ++i)
            scale = std::max({scale, std::abs(node.bounds.min[i]), std::abs(node.bounds.max[i])});
    }
    // The slab test's rounding lets a ray meet a box it misses by some 1e-15 of the scene's
    // coordinates (and the box corners relative to the apex round by as much): a cell lists
    // every box within 1e-9 of them of its cone
    tolerance_ = 1e-9 * scale;
    if (!(scale > 0 && tolerance_ < kInfinity)) return;
    cells_ = std::make_unique<std::atomic<const Cell *>[]>(cellCount());  // all null (C++20)
    enabled_ = true;
}

VistaLists::~VistaLists() {
    if (!cells_) return;
    for (size_t c = 0; c < cellCount(); ++c) delete cells_[c].load(std::memory_order_relaxed);
}

const VistaLists::Cell *VistaLists::build(int face, int i, int j) const {
    // The cell's directions u: a0 <= u[a] / |u[k]| <= a1 and b0 <= u[b] / |u[k]| <= b1, where k
    // is the face's axis and s u[k] > 0 on it. As a cone of vectors v from the apex, four
    // half-spaces dot(normal, v) >= 0; each normal has length 1 to 1.42, so a box whose value
    // is below -tolerance at every corner for one of them lies outside the widened cone.
    int k = face >> 1, a = (k + 1) % 3, b = (k + 2) % 3;
    double s = (face & 1) ? -1 : 1;
    double step = 2.0 / n_;
    double a0 = -1 + step * i - kAngularMargin, a1 = -1 + step * (i + 1) + kAngularMargin;
    double b0 = -1 + step * j - kAngularMargin, b1 = -1 + step * (j + 1) + kAngularMargin;
    auto plane = [&](int axis, double sense, double bound) {
        Vec3 n;
        n[axis] = sense;
        n[k] = -sense * bound * s;
        return n;
    };
    const Vec3 normals[4] = {plane(a, 1, a0), plane(a, -1, a1), plane(b, 1, b0), plane(b, -1, b1)};
    // Conservative: a box beside the cone's edge may stay, which costs a box test, never a hit
    auto meets = [&](const Bounds3 &box) {
        Vec3 lo = box.min - apex_, hi = box.max - apex_;
        for (const Vec3 &n : normals) {
            double most = 0;
            for (int axis = 0; axis < 3; ++axis)
                most += std::max(n[axis] * lo[axis], n[axis] * hi[axis]);
            if (most < -tolerance_) return false;
        }
        return true;
    };
    // The octant of the cell's directions (no cell spans two: n_ is even)
    int octant = 0;
    if (s < 0) octant |= 1 << k;
    if (2 * i < n_) octant |= 1 << a;
    if (2 * j < n_) octant |= 1 << b;
    std::vector<uint32_t> leaves;
    bvh_.collectLeaves(octant, meets, leaves);

    auto cell = std::make_unique<Cell>();
    cell->octant = static_cast<uint8_t>(octant);
    cell->k = static_cast<uint8_t>(k);
    cell->a = static_cast<uint8_t>(a);
    cell->b = static_cast<uint8_t>(b);
    cell->s = s;
    cell->a0 = -1 + step * i;
    cell->a1 = -1 + step * (i + 1);
    cell->b0 = -1 + step * j;
    cell->b1 = -1 + step * (j + 1);
    if (leaves.size() > static_cast<size_t>(kMaxLeaves)) {
        cell->whole = true;
    } else {
        cell->count = static_cast<uint32_t>(leaves.size());
        std::copy(leaves.begin(), leaves.end(), cell->leaves);
    }
    // First one in wins; a thread that built the same cell meanwhile drops its copy
    std::atomic<const Cell *> &slot = cells_[(static_cast<size_t>(face) * n_ + i) * n_ + j];
    const Cell *expected = nullptr;
    if (slot.compare_exchange_strong(expected, cell.get(), std::memory_order_acq_rel))
        return cell.release();
    return expected;
}

const VistaLists::Cell *VistaLists::find(const Ray &ray, double tMin, double tMax) const {
    // Only rays from the apex itself, over their whole length: the cell's cone holds them
    if (!enabled_ || tMin != 0 || tMax < kInfinity || !(ray.o == apex_)) return nullptr;
    const Vec3 &d = ray.d;
    // A zero (or subnormal) component makes slab distances NaN or infinite
    constexpr double kTiny = 1e-300;
    Vec3 m = abs(d);
    if (!(m.x > kTiny && m.y > kTiny && m.z > kTiny && m.x < kInfinity && m.y < kInfinity &&
          m.z < kInfinity))
        return nullptr;
    // The thread's last cell, where its cone holds the direction: any cell whose cone holds it
    // lists every leaf the ray can meet
    const Cell *cell;
    if (recent.owner == id_ && recent.cell->holds(d)) {
        cell = recent.cell;
    } else {
        cell = place(d);
        recent = {id_, cell};
    }
    // A direction rounding put into a cell of the next octant walks the tree (finite nonzero
    // components have their reciprocals' signs, which order traverse()'s children; their sign
    // bits are the comparisons d < 0)
    int octant = std::signbit(d.x) | std::signbit(d.y) << 1 | std::signbit(d.z) << 2;
    if (cell->whole || cell->octant != octant) return nullptr;
    return cell;
}

const VistaLists::Cell *VistaLists::place(const Vec3 &d) const {
    Vec3 m = abs(d);
    // The face: the axis where the direction is largest, and its sign; then the cell by the
    // face coordinates d[a] / |d[k]|
    int k;
    double dk, da, db;
    if (m.x >= m.y && m.x >= m.z) {
        k = 0, dk = d.x, da = d.y, db = d.z;
    } else if (m.y >= m.z) {
        k = 1, dk = d.y, da = d.z, db = d.x;
    } else {
        k = 2, dk = d.z, da = d.x, db = d.y;
    }
    int face = 2 * k + (dk < 0 ? 1 : 0);
    double half = 0.5 * n_, scale = half / std::abs(dk);
    int i = std::clamp(static_cast<int>(da * scale + half), 0, n_ - 1);
    int j = std::clamp(static_cast<int>(db * scale + half), 0, n_ - 1);
    const Cell *cell =
        cells_[(static_cast<size_t>(face) * n_ + i) * n_ + j].load(std::memory_order_acquire);
    return cell ? cell : build(face, i, j);
}

size_t VistaLists::cellsListing() const {
    size_t listing = 0;
    for (size_t c = 0; cells_ && c < cellCount(); ++c) {
        const Cell *cell = cells_[c].load(std::memory_order_acquire);
        listing += cell && !cell->whole;
    }
    return listing;
}

}  // namespace rt
