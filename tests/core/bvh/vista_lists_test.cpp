// SPDX-License-Identifier: MIT
// The camera's leaf lists: a ray from the apex that takes its cell's list makes exactly the
// visits of the whole tree's traversal (same items, same order, same tMax at each), on random
// scenes of boxes (flat, tiny, huge, around and behind the apex) at scales 1e-6 to 1e6, with
// directions on the borders of cells; rays the lists cannot serve are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "core/bvh/vista_lists.h"
#include "core/math/rng.h"

namespace rt {
namespace {

struct Visit {
    uint32_t item;
    double tMax;
    bool operator==(const Visit &) const = default;
};

/// A closest-hit visitor over boxes: an item's box entry beyond tMin lowers tMax to it, as a
/// surface hit would (so later leaves are tested against a shrinking interval).
struct Recorder {
    const std::vector<Bounds3> &boxes;
    const Ray &ray;
    double tMin;
    std::vector<Visit> visits;
    bool operator()(uint32_t item, double *tMax) {
        visits.push_back({item, *tMax});
        double t0, t1;
        if (boxes[item].intersectP(ray, tMin, *tMax, &t0, &t1) && t0 > tMin) *tMax = t0;
        return false;
    }
};

std::vector<Bounds3> randomBoxes(Rng &rng, int count, double scale, const Vec3 &apex) {
    std::vector<Bounds3> boxes;
    for (int i = 0; i < count; ++i) {
        Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
        Vec3 h(rng.uniform(), rng.uniform(), rng.uniform());
        switch (i % 5) {
            case 0:
                h[i % 3] = 0;
                break;  // flat, as a face of a mesh
            case 1:
                h = h * 1e-4;
                break;  // tiny
            case 2:
                if (i % 15 == 2) c = Vec3(0);
                break;  // around the apex
            case 3:
                h = h * 8;
                break;  // large
            default:
                break;
        }
        boxes.push_back(Bounds3((c - h) * scale + apex, (c + h) * scale + apex));
    }
    return boxes;
}

/// A direction (not normalised) on the border of two cells of a 64-cell face: largest on
/// `axis`, with sign `sign`, and face coordinate k / 32 - 1 exactly on the next axis.
Vec3 borderDirection(Rng &rng, int axis, double sign) {
    Vec3 e;
    e[axis] = sign;
    e[(axis + 1) % 3] = std::floor(rng.uniform() * 64) / 32 - 1;
    e[(axis + 2) % 3] = rng.uniform() * 1.8 - 0.9;
    return e;
}

/// Directions from the apex: random ones, and ones on the borders of cells (exactly, and one
/// ulp beside them).
std::vector<Vec3> directions(Rng &rng, int count) {
    std::vector<Vec3> dirs;
    for (int i = 0; i < count; ++i) {
        Vec3 d(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1);
        if (i % 3 == 0) {
            int axis = (i / 3) % 3;
            d = borderDirection(rng, axis, i % 2 ? 1 : -1);
            if (i % 9 == 3) d[(axis + 1) % 3] = std::nextafter(d[(axis + 1) % 3], 2.0);
        }
        if (length(d) > 1e-3) dirs.push_back(normalize(d));
    }
    return dirs;
}

TEST(VistaLists, SameVisitsAsTheWholeTree) {
    Rng rng(7);
    size_t served = 0, rays = 0;
    for (double scale : {1e-6, 1.0, 1e6}) {
        for (int scene = 0; scene < 6; ++scene) {
            SCOPED_TRACE("scale " + std::to_string(scale) + ", scene " + std::to_string(scene));
            Vec3 apex = Vec3(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2) *
                        (scene % 2 ? scale * 1e3 : scale);
            std::vector<Bounds3> boxes = randomBoxes(rng, 40 + 60 * scene, scale, apex);
            Bvh bvh(boxes);
            VistaLists vista(bvh, apex, scene < 3 ? 64 : 8);
            ASSERT_TRUE(vista.enabled());
            for (const Vec3 &d : directions(rng, 600)) {
                Ray ray(apex, d);
                ++rays;
                Recorder whole{boxes, ray, 0, {}}, listed{boxes, ray, 0, {}};
                double tWhole = kInfinity, tListed = kInfinity;
                bvh.traverse(ray, 0, &tWhole, whole);
                const VistaLists::Cell *cell = vista.find(ray, 0, kInfinity);
                if (!cell) continue;
                ++served;
                bvh.traverseLeaves(cell->leaves, cell->count, ray, 0, &tListed, listed);
                ASSERT_EQ(whole.visits, listed.visits)
                    << "direction " << d.x << " " << d.y << " " << d.z;
                ASSERT_EQ(tWhole, tListed);
#if SCADRAY_LANE_SLABS
                // Two listed leaves tested side by side (RenderScene::closestHit with AVX2)
                if (__builtin_cpu_supports("avx2")) {
                    Recorder paired{boxes, ray, 0, {}};
                    double tPaired = kInfinity;
                    bvh.traverseLeavesPairs(cell->leaves, cell->count, Bvh::LaneSlabs(ray), 0,
                                            &tPaired, paired);
                    ASSERT_EQ(whole.visits, paired.visits)
                        << "direction " << d.x << " " << d.y << " " << d.z;
                    ASSERT_EQ(tWhole, tPaired);
                }
#endif
            }
        }
    }
    // Many rays take the lists (the others meet full cells in these crowded scenes, or their
    // directions rounded into the next octant's cell)
    EXPECT_GT(served, rays / 3);
}

TEST(VistaLists, TinyBoxesOnTheBordersOfCells) {
    // A ray along the border of two cells meets a box that lies on the border line; whichever
    // cell the ray's rounded coordinates pick must list it
    Rng rng(5);
    for (double scale : {1e-6, 1.0, 1e6}) {
        Vec3 apex = Vec3(0.75, -1.5, 0.25) * scale;
        std::vector<Vec3> border;
        for (int i = 0; i < 300; ++i)
            border.push_back(normalize(borderDirection(rng, i % 3, i % 2 ? 1 : -1)));
        std::vector<Bounds3> boxes = randomBoxes(rng, 30, scale, apex);
        for (const Vec3 &d : border) {
            Vec3 c = apex + d * (3 * scale);
            boxes.push_back(Bounds3(c - Vec3(1e-7 * scale), c + Vec3(1e-7 * scale)));
        }
        Bvh bvh(boxes);
        VistaLists vista(bvh, apex, 64);
        int served = 0;
        for (const Vec3 &d : border) {
            Ray ray(apex, d);
            Recorder whole{boxes, ray, 0, {}}, listed{boxes, ray, 0, {}};
            double tWhole = kInfinity, tListed = kInfinity;
            bvh.traverse(ray, 0, &tWhole, whole);
            ASSERT_FALSE(whole.visits.empty());
            const VistaLists::Cell *cell = vista.find(ray, 0, kInfinity);
            if (!cell) continue;
            ++served;
            bvh.traverseLeaves(cell->leaves, cell->count, ray, 0, &tListed, listed);
            ASSERT_EQ(whole.visits, listed.visits)
                << "direction " << d.x << " " << d.y << " " << d.z;
        }
        EXPECT_GT(served, 200);
    }
}

// A thread tries the cell it found last first. Rays swept in small steps across many cells'
// borders, on four faces, there and back, are mostly served by the cell of the ray before;
// asked of two lists in turn (other apexes, other trees, the same directions), each serves
// only its own cells. Every served ray makes the whole tree's visits.
TEST(VistaLists, LastCellServesOnlyRaysItHolds) {
    Rng rng(11);
    for (double scale : {1e-6, 1.0, 1e6}) {
        SCOPED_TRACE("scale " + std::to_string(scale));
        struct Lists {
            Vec3 apex;
            std::vector<Bounds3> boxes;
            std::unique_ptr<Bvh> bvh;
            std::unique_ptr<VistaLists> vista;
        };
        Lists lists[2];
        for (int l = 0; l < 2; ++l) {
            Lists &L = lists[l];
            L.apex = Vec3(l ? 1.5 : -0.5, l ? -2 : 0.25, l ? 0.75 : 1) * scale;
            L.boxes = randomBoxes(rng, 20, scale, L.apex);
            // Tiny boxes on the sweep's path, which a neighbouring cell would not list
            for (int i = 0; i < 300; ++i) {
                double t = rng.uniform() * 2 * kPi;
                Vec3 d(std::cos(t), 0.8 * std::sin(t), 0.3 + 0.9 * std::sin(3 * t));
                Vec3 c = L.apex + normalize(d) * (rng.uniform() * 8 + 2) * scale;
                double h = (l ? 1e-4 : 3e-3) * scale;
                L.boxes.push_back(Bounds3(c - Vec3(h), c + Vec3(h)));
            }
            L.bvh = std::make_unique<Bvh>(L.boxes);
            L.vista = std::make_unique<VistaLists>(*L.bvh, L.apex, 64);
            ASSERT_TRUE(L.vista->enabled());
        }
        size_t served = 0, rays = 0, sameCell = 0;
        const VistaLists::Cell *before[2] = {nullptr, nullptr};
        // Once round and back, so the sweep leaves cells across each of their four sides; the
        // lists take turns every 100 steps
        for (int run = 0; run < 400; ++run) {
            for (int l = 0; l < 2; ++l) {
                const Lists &L = lists[l];
                for (int step = run * 100; step < run * 100 + 100; ++step) {
                    double t = (step < 20000 ? step : 40000 - step) * (2 * kPi / 20000);
                    Ray ray(L.apex, normalize(Vec3(std::cos(t), 0.8 * std::sin(t),
                                                   0.3 + 0.9 * std::sin(3 * t))));
                    ++rays;
                    Recorder whole{L.boxes, ray, 0, {}}, listed{L.boxes, ray, 0, {}};
                    double tWhole = kInfinity, tListed = kInfinity;
                    L.bvh->traverse(ray, 0, &tWhole, whole);
                    const VistaLists::Cell *cell = L.vista->find(ray, 0, kInfinity);
                    if (!cell) continue;
                    ++served;
                    sameCell += cell == before[l];
                    before[l] = cell;
                    ASSERT_TRUE(cell->holds(ray.d));
                    L.bvh->traverseLeaves(cell->leaves, cell->count, ray, 0, &tListed, listed);
                    ASSERT_EQ(whole.visits, listed.visits) << "list " << l << " step " << step;
                    ASSERT_EQ(tWhole, tListed);
                }
            }
        }
        EXPECT_GT(served, rays / 2);
        EXPECT_GT(sameCell, served * 9 / 10);  // the sweep stays in a cell for many steps
    }
}

TEST(VistaLists, RefusesRaysItCannotServe) {
    Rng rng(3);
    Vec3 apex(1, 2, 3);
    std::vector<Bounds3> boxes = randomBoxes(rng, 20, 1, apex);
    Bvh bvh(boxes);
    VistaLists vista(bvh, apex);
    Vec3 d = normalize(Vec3(0.3, -0.4, 0.8));
    EXPECT_NE(vista.find(Ray(apex, d), 0, kInfinity), nullptr);
    EXPECT_EQ(vista.find(Ray(apex + Vec3(1e-9, 0, 0), d), 0, kInfinity),
              nullptr);                                             // not from the apex
    EXPECT_EQ(vista.find(Ray(apex, d), 0, 10), nullptr);            // bounded
    EXPECT_EQ(vista.find(Ray(apex, d), 1e-3, kInfinity), nullptr);  // not from its start
    EXPECT_EQ(vista.find(Ray(apex, Vec3(0, 0.6, 0.8)), 0, kInfinity), nullptr);  // a zero component
    EXPECT_EQ(vista.find(Ray(apex, Vec3(-0.0, 0.6, 0.8)), 0, kInfinity), nullptr);
    EXPECT_GT(vista.cellsListing(), 0u);

    // An empty or unbounded box in the tree turns the lists off
    std::vector<Bounds3> open = boxes;
    open.push_back(Bounds3::infinite());
    Bvh openBvh(open);
    EXPECT_FALSE(VistaLists(openBvh, apex).enabled());
    Bvh emptyBvh(std::vector<Bounds3>{Bounds3()});  // a leaf holding only an empty item
    EXPECT_FALSE(VistaLists(emptyBvh, apex).enabled());
    EXPECT_FALSE(VistaLists(bvh, apex, 7).enabled());  // an odd resolution would mix octants
    Bvh none(std::vector<Bounds3>{});
    EXPECT_EQ(VistaLists(none, apex).find(Ray(apex, d), 0, kInfinity), nullptr);
}

TEST(VistaLists, CellsBuiltByTwoThreadsAtOnce) {
    // Both threads build cells as they need them; each sees complete cells and the same lists
    Rng rng(11);
    Vec3 apex(0.5, -0.25, 0.125);
    std::vector<Bounds3> boxes = randomBoxes(rng, 300, 1, apex);
    Bvh bvh(boxes);
    VistaLists vista(bvh, apex, 16);
    std::vector<Vec3> dirs = directions(rng, 4000);
    std::vector<std::vector<Visit>> results[2];
    auto run = [&](int t) {
        for (const Vec3 &d : dirs) {
            Ray ray(apex, d);
            Recorder r{boxes, ray, 0, {}};
            double tMax = kInfinity;
            if (const VistaLists::Cell *cell = vista.find(ray, 0, kInfinity))
                bvh.traverseLeaves(cell->leaves, cell->count, ray, 0, &tMax, r);
            else
                bvh.traverse(ray, 0, &tMax, r);
            results[t].push_back(std::move(r.visits));
        }
    };
    std::thread other(run, 1);
    run(0);
    other.join();
    EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace rt
