// SPDX-License-Identifier: MIT
// The four-wide mesh BVH: the closest hit (t and triangle) and every crossing of the line are
// those of a brute-force loop over all triangles, on meshes with duplicate, coplanar
// overlapping and degenerate triangles, near the origin and far from it; the float boxes hold
// their triangles' double vertices; the tree is the same for 1, 2 and 5 build threads; the
// mesh's leaf-ordered triangle copy matches the item order.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "core/bvh/wide_bvh.h"
#include "core/geometry/triangle_mesh.h"
#include "core/math/rng.h"
#include "support/mesh_builder.h"

namespace rt {
namespace {

/// An icosphere plus trouble: every tenth triangle duplicated, coplanar overlapping triangles
/// (the same plane, shifted within it), slivers with a repeated index, and zero-area triangles
/// with three distinct collinear vertices; then scaled and moved.
std::shared_ptr<ir::Mesh> troubleMesh(int levels, double scale, const Vec3 &offset) {
    auto m = test::icosphere(levels, 1);
    size_t n = m->triangles.size();
    for (size_t i = 0; i < n; i += 10) m->triangles.push_back(m->triangles[i]);
    for (size_t i = 5; i < n; i += 37) {
        auto t = m->triangles[i];
        Vec3 shift = (m->positions[t[1]] - m->positions[t[0]]) * 0.25;
        uint32_t b = static_cast<uint32_t>(m->positions.size());
        for (int k = 0; k < 3; ++k) m->positions.push_back(m->positions[t[k]] + shift);
        m->triangles.push_back({b, b + 1, b + 2});
    }
    for (size_t i = 3; i < n; i += 53) {
        auto t = m->triangles[i];
        m->triangles.push_back({t[0], t[1], t[1]});
        uint32_t b = static_cast<uint32_t>(m->positions.size());
        Vec3 a = m->positions[t[0]], c = m->positions[t[2]];
        m->positions.push_back(a);
        m->positions.push_back((a + c) * 0.5);
        m->positions.push_back(c);
        m->triangles.push_back({b, b + 1, b + 2});
    }
    for (auto &p : m->positions) p = p * scale + offset;
    return m;
}

struct Expected {
    bool found = false;
    double t = kInfinity;
    uint32_t triangle = 0;
};

/// The closest hit by brute force, with TriangleMesh::closest's rules: tMin < t < tMax, t
/// beyond its own rounding error, and of equal t the lowest triangle.
Expected bruteClosest(const TriangleMesh &mesh, const Ray &r, double tMin, double tMax) {
    Expected e;
    for (uint32_t tri = 0; tri < mesh.triangleCount(); ++tri) {
        TriangleMesh::Hit h;
        if (!mesh.intersectTriangle(r, tri, &h) || !(h.t > tMin) || !(h.t < tMax) ||
            h.t <= h.tError)
            continue;
        if (h.t < e.t) {
            e = {true, h.t, tri};
        }
    }
    return e;
}

/// Rays from around the mesh at random points of it, at its vertices (ties between the
/// triangles of a fan, and between duplicates) and at random directions.
std::vector<Ray> testRays(const ir::Mesh &m, double scale, const Vec3 &offset, int count) {
    Rng rng(5);
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        Vec3 o = Vec3(rng.uniform() * 6 - 3, rng.uniform() * 6 - 3, rng.uniform() * 6 - 3) * scale +
                 offset;
        Vec3 target;
        switch (i % 3) {
            case 0:
                target = m.positions[static_cast<size_t>(rng.uniform() * m.positions.size())];
                break;
            case 1:
                target = Vec3(rng.uniform() * 2 - 1, rng.uniform() * 2 - 1, rng.uniform() * 2 - 1) *
                             scale +
                         offset;
                break;
            default:
                target = o + Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
                break;
        }
        if (target == o) continue;
        rays.emplace_back(o, normalize(target - o));
    }
    return rays;
}

void expectClosestMatchesBruteForce(double scale, const Vec3 &offset, bool floats = false) {
    auto m = troubleMesh(3, scale, offset);
    if (floats) m = test::inFloats(m);
    TriangleMesh mesh(m);
    ASSERT_EQ(mesh.floatLeaves().empty(), !floats);
    ASSERT_EQ(mesh.leafTriangles().empty(), floats);
    int hits = 0;
    for (const Ray &r : testRays(*m, scale, offset, 1500)) {
        for (double tMin : {0.0, -kInfinity}) {
            Expected e = bruteClosest(mesh, r, tMin, kInfinity);
            TriangleMesh::Hit hit;
            bool found = mesh.closest(r, tMin, kInfinity, &hit);
            ASSERT_EQ(found, e.found);
            if (found) {
                ASSERT_EQ(hit.t, e.t);
                ASSERT_EQ(hit.triangle, e.triangle);
                ++hits;
                // A bounded query ending at the hit finds nothing nearer
                TriangleMesh::Hit nearer;
                EXPECT_EQ(mesh.closest(r, tMin, e.t, &nearer), false);
            }
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(WideBvh, ClosestHitMatchesBruteForceWithDuplicateCoplanarAndDegenerateTriangles) {
    expectClosestMatchesBruteForce(1, Vec3(0));
}

TEST(WideBvh, FloatLeavesClosestHitMatchesBruteForceAtEveryScale) {
    // A float mesh's leaves hold its vertices as floats, four triangles tested together where
    // the CPU has AVX2: the same hits, ties (rays through vertices) included
    expectClosestMatchesBruteForce(1, Vec3(0), true);
    expectClosestMatchesBruteForce(1e-6, Vec3(0.5e-6, 0, 0), true);
    expectClosestMatchesBruteForce(1e-3, Vec3(100, -30, 20), true);
    expectClosestMatchesBruteForce(1e6, Vec3(3e9, 0, -1e9), true);
}

/// Whether the line the walk prefetches for child c of node n starts a cache line and holds
/// `target` (an address only, never read).
bool fetchLineHolds(const WideBvh &bvh, const WideBvh::Node &n, int c, uintptr_t target) {
    auto line = reinterpret_cast<uintptr_t>(bvh.fetchLine(n, c));
    return line % 64 == 0 && line <= target && target < line + 64;
}
bool fetchLineHolds(const WideBvh &bvh, const WideBvh::Node &n, int c, const void *target) {
    return fetchLineHolds(bvh, n, c, reinterpret_cast<uintptr_t>(target));
}

TEST(WideBvh, FloatLeavesHoldEachLeafsTrianglesAndVerticesSideBySide) {
    auto m = test::inFloats(troubleMesh(4, 1, Vec3(0.25, 0, 0)));
    TriangleMesh mesh(m);
    // The float leaves hold the item order, so the mesh's BVH drops its own; the same build
    // gives it
    EXPECT_TRUE(mesh.bvh().itemOrder().empty());
    WideBvh same = TriangleMesh::buildBvh(*m, 1);
    ASSERT_EQ(same.nodes().size(), mesh.bvh().nodes().size());
    const auto &order = same.itemOrder();
    const auto &words = mesh.floatLeaves();
    ASSERT_EQ(words.size(),
              TriangleMesh::kFloatLeafWords * order.size() + TriangleMesh::kLeafPadding);
    size_t leafTriangles = 0;
    uint32_t largest = 0;
    for (const auto &node : mesh.bvh().nodes())
        for (int c = 0; c < WideBvh::kWidth; ++c) {
            uint32_t ref = node.child[c];
            if (ref == WideBvh::kEmpty || !(ref & WideBvh::kLeaf)) continue;
            const uint32_t first = WideBvh::leafFirst(ref), n = WideBvh::leafCount(ref);
            const uint32_t *leaf = words.data() + TriangleMesh::kFloatLeafWords * first;
            // The walk prefetches the leaf's words
            ASSERT_TRUE(fetchLineHolds(mesh.bvh(), node, c, leaf));
            leafTriangles += n;
            largest = std::max(largest, n);
            for (uint32_t i = 0; i < n; ++i) {
                ASSERT_EQ(leaf[i], order[first + i]);
                for (int j = 0; j < 9; ++j)
                    ASSERT_EQ(std::bit_cast<float>(leaf[n + j * n + i]),
                              m->positions[m->triangles[leaf[i]][j / 3]][j % 3]);
            }
        }
    EXPECT_EQ(leafTriangles, order.size());
    // Where a leaf's triangles are tested four at a time, leaves hold up to eight (two groups),
    // and this mesh has some of more than four, so the tests above run the second group
    EXPECT_EQ(largest > 4, TriangleMesh::fourWideLeaves());
    EXPECT_LE(largest, 8u);
    // One position that is not a float (0.1) and the mesh keeps vertex indices and its order
    auto d = test::inFloats(troubleMesh(2, 1, Vec3(0)));
    d->positions[7].y = 0.1;
    TriangleMesh indexed(d);
    EXPECT_TRUE(indexed.floatLeaves().empty());
    EXPECT_FALSE(indexed.leafTriangles().empty());
    EXPECT_FALSE(indexed.bvh().itemOrder().empty());
    // whose walk prefetches a leaf's triangle records
    largest = 0;
    for (const auto &node : indexed.bvh().nodes())
        for (int c = 0; c < WideBvh::kWidth; ++c) {
            if (node.child[c] == WideBvh::kEmpty || !(node.child[c] & WideBvh::kLeaf)) continue;
            largest = std::max(largest, WideBvh::leafCount(node.child[c]));
            ASSERT_TRUE(
                fetchLineHolds(indexed.bvh(), node, c,
                               &indexed.leafTriangles()[WideBvh::leafFirst(node.child[c])]));
        }
    EXPECT_EQ(largest > 4, TriangleMesh::fourWideLeaves());
}

TEST(WideBvh, ClosestHitMatchesBruteForceFarFromTheOriginAtEveryScale) {
    // Float boxes round outward: no hit is lost where a float's spacing is coarse
    expectClosestMatchesBruteForce(1e-6, Vec3(1e6, -3e5, 2e6));
    expectClosestMatchesBruteForce(1e6, Vec3(3e9, 0, -1e9));
    expectClosestMatchesBruteForce(1e-6, Vec3(0.5e-6, 0, 0));
}

/// allHits gives every crossing of the line that a brute-force loop finds.
void expectAllHitsMatchBruteForce(const TriangleMesh &mesh, const Ray &r) {
    std::vector<std::pair<double, uint32_t>> brute, bvh;
    for (uint32_t tri = 0; tri < mesh.triangleCount(); ++tri) {
        TriangleMesh::Hit h;
        if (mesh.intersectTriangle(r, tri, &h)) brute.emplace_back(h.t, tri);
    }
    std::vector<TriangleMesh::Hit> hits;
    mesh.allHits(r, hits);
    for (const auto &h : hits) bvh.emplace_back(h.t, h.triangle);
    std::sort(brute.begin(), brute.end());
    std::sort(bvh.begin(), bvh.end());
    ASSERT_EQ(bvh, brute);
}

TEST(WideBvh, AllHitsAreEveryCrossingOfTheLine) {
    auto m = troubleMesh(3, 1, Vec3(0));
    TriangleMesh mesh(m);
    for (const Ray &r : testRays(*m, 1, Vec3(0), 600))
        ASSERT_NO_FATAL_FAILURE(expectAllHitsMatchBruteForce(mesh, r));
    auto f = test::inFloats(troubleMesh(3, 1, Vec3(0)));
    TriangleMesh floats(f);
    ASSERT_FALSE(floats.floatLeaves().empty());
    for (const Ray &r : testRays(*f, 1, Vec3(0), 600))
        ASSERT_NO_FATAL_FAILURE(expectAllHitsMatchBruteForce(floats, r));
}

/// Every triangle once in leaf order, leaves of 1..4 triangles, and each leaf's float box holds
/// its triangles' double vertices.
void expectWellFormed(const WideBvh &bvh, const ir::Mesh &m) {
    std::vector<int> seen(m.triangles.size(), 0);
    for (uint32_t t : bvh.itemOrder()) ++seen.at(t);
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    for (const auto &node : bvh.nodes())
        for (int c = 0; c < WideBvh::kWidth; ++c) {
            uint32_t ref = node.child[c];
            if (ref == WideBvh::kEmpty || !(ref & WideBvh::kLeaf)) continue;
            uint32_t first = WideBvh::leafFirst(ref), count = WideBvh::leafCount(ref);
            ASSERT_LE(first + count, bvh.itemOrder().size());
            for (uint32_t i = first; i < first + count; ++i)
                for (uint32_t v : m.triangles[bvh.itemOrder()[i]])
                    for (int a = 0; a < 3; ++a) {
                        ASSERT_LE(node.lo[a][c], m.positions[v][a]);
                        ASSERT_GE(node.hi[a][c], m.positions[v][a]);
                    }
        }
}

TEST(WideBvh, SameTreeForAnyNumberOfBuildThreads) {
    // Large enough for the parallel subtrees (more than 4096 triangles) and the parallel item
    // boxes and bins of the top levels (more than 65536)
    auto m = troubleMesh(6, 1e6, Vec3(1e7, 0, 0));
    ASSERT_GT(m->triangles.size(), 65536u);
    WideBvh one(*m, 1), two(*m, 2), five(*m, 5);
    expectWellFormed(one, *m);
    for (const WideBvh *other : {&two, &five}) {
        ASSERT_EQ(other->itemOrder(), one.itemOrder());
        ASSERT_EQ(other->nodes().size(), one.nodes().size());
        EXPECT_EQ(other->depth(), one.depth());
        for (size_t i = 0; i < one.nodes().size(); ++i) {
            const auto &a = one.nodes()[i], &b = other->nodes()[i];
            ASSERT_TRUE(std::equal(&a.lo[0][0], &a.lo[0][0] + 12, &b.lo[0][0]));
            ASSERT_TRUE(std::equal(&a.hi[0][0], &a.hi[0][0] + 12, &b.hi[0][0]));
            ASSERT_TRUE(std::equal(a.child, a.child + 4, b.child));
        }
    }
}

TEST(WideBvh, LeafOrderedTrianglesAreTheTrianglesOfTheItemOrder) {
    // The mesh's leaves read a copy of the triangles in leaf order: slot s must hold exactly
    // the triangle that the item order names there, with its own index
    auto m = troubleMesh(4, 1, Vec3(0));
    TriangleMesh mesh(m);
    const auto &order = mesh.bvh().itemOrder();
    const auto &leaves = mesh.leafTriangles();
    ASSERT_EQ(leaves.size(), order.size());
    for (size_t s = 0; s < order.size(); ++s) {
        ASSERT_EQ(leaves[s].triangle, order[s]);
        ASSERT_EQ(leaves[s].v, m->triangles[order[s]]);
    }
    // traverseSlots visits the same items, in the same order, as traverse
    for (const Ray &r : testRays(*m, 1, Vec3(0), 200)) {
        std::vector<uint32_t> items, slots;
        double t = kInfinity;
        mesh.bvh().traverse(r, -kInfinity, &t, [&](uint32_t i, double *) {
            items.push_back(i);
            return false;
        });
        mesh.bvh().traverseSlots(r, -kInfinity, &t, [&](uint32_t s, double *) {
            slots.push_back(order[s]);
            return false;
        });
        ASSERT_EQ(slots, items);
    }
}

TEST(WideBvh, EachChildsPrefetchLineIsItsNodeOrItsLeafsData) {
    // The walk prefetches, per child, the cache line its node keeps: an interior child's node,
    // a leaf's data where setLeafData gave it, otherwise the root (an empty slot: the leaf
    // data's first line, or the root), whether the lines count from the nodes alone or, for
    // data far from them, from each kind's start. A wrong line costs only time, so only this
    // test sees it
    auto m = troubleMesh(4, 1, Vec3(0));
    WideBvh bvh(*m, 1);
    const auto &nodes = bvh.nodes();
    const int64_t root = int64_t(reinterpret_cast<uintptr_t>(nodes.data()));
    auto check = [&](uintptr_t data, size_t stride) {
        size_t leaves = 0;
        for (const auto &n : nodes)
            for (int c = 0; c < WideBvh::kWidth; ++c) {
                uint32_t r = n.child[c];
                int64_t target = root;
                if (r == WideBvh::kEmpty) {
                    if (data) target = int64_t(data);
                } else if (!(r & WideBvh::kLeaf)) {
                    target = root + int64_t(r) * int64_t(sizeof(WideBvh::Node));
                } else if (data) {
                    ++leaves;
                    target = int64_t(data) + int64_t(WideBvh::leafFirst(r)) * int64_t(stride);
                }
                ASSERT_TRUE(fetchLineHolds(bvh, n, c, uintptr_t(target)))
                    << "child " << c << " ref " << r << ": line "
                    << int64_t(reinterpret_cast<uintptr_t>(bvh.fetchLine(n, c))) - root
                    << ", target " << target - root;
            }
        if (data) {
            EXPECT_GT(leaves, 100u);
        }
    };
    check(0, 0);  // as built: no leaf data
    std::vector<uint32_t> words(m->triangles.size() * 10 + 16);
    for (size_t offset : {0, 4, 60}) {
        const char *data = reinterpret_cast<const char *>(words.data()) + offset;
        bvh.setLeafData({data, 40});
        check(reinterpret_cast<uintptr_t>(data), 40);
    }
    // Only addresses (never read): data below the nodes, counted from them; and far from them
    // (another mapping), beyond 2^31 8-byte steps (16 GiB), where each kind counts from its own
    // first line
    EXPECT_TRUE(bvh.fetchesNear());
    const uintptr_t gib = uintptr_t{1} << 30;
    for (auto [data, near] : {std::pair{uintptr_t(root) - 64 * 1000 - 17, true},
                              {uintptr_t(root) + 15 * gib, true},
                              {uintptr_t(root) - 15 * gib + 8, true},
                              {uintptr_t(root) + 17 * gib, false},
                              {uintptr_t(root) - 17 * gib, false},
                              {uintptr_t(root) + 1024 * gib + 8, false}}) {
        bvh.setLeafData({reinterpret_cast<const void *>(data), 36});
        EXPECT_EQ(bvh.fetchesNear(), near) << int64_t(data - uintptr_t(root));
        check(data, 36);
    }
    bvh.setLeafData({nullptr, 0});
    EXPECT_TRUE(bvh.fetchesNear());
    check(0, 0);
    // A tree with empty slots: three items make a root of three children
    std::vector<Bounds3> boxes = {{Vec3(0), Vec3(1)}, {Vec3(2), Vec3(3)}, {Vec3(4), Vec3(5)}};
    WideBvh small(boxes);
    ASSERT_EQ(small.nodes().size(), 1u);
    for (int c = 0; c < WideBvh::kWidth; ++c)
        EXPECT_TRUE(fetchLineHolds(small, small.nodes()[0], c, small.nodes().data())) << c;
    EXPECT_EQ(small.nodes()[0].child[3], WideBvh::kEmpty);
}

TEST(WideBvh, LargeArraysAreAlignedForHugePages) {
    LargeVector<uint64_t> big(size_t{3} << 18);  // 6 MiB
    EXPECT_EQ(reinterpret_cast<uintptr_t>(big.data()) % (size_t{2} << 20), 0u);
    for (size_t i = 0; i < big.size(); i += 4096) big[i] = i;
    EXPECT_EQ(big[4096], 4096u);
    LargeVector<uint32_t> small(3, 7), none;
    EXPECT_EQ(small[2], 7u);
    none.reserve(0);
    EXPECT_TRUE(none.empty());
}

TEST(WideBvh, SmallEmptyAndCoincidentMeshes) {
    ir::Mesh empty;
    WideBvh none(empty, 2);
    double t = kInfinity;
    int visits = 0;
    none.traverse(Ray(Vec3(0), Vec3(1, 0, 0)), 0, &t,
                  [&](uint32_t, double *) { return ++visits, false; });
    EXPECT_EQ(visits, 0);
    // 40 copies of one triangle: all centroids coincide, split by count into leaves of <= 4
    ir::Mesh same;
    same.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    same.triangles.assign(40, {0, 1, 2});
    WideBvh coincident(same, 1);
    expectWellFormed(coincident, same);
    std::vector<uint32_t> visited;
    coincident.traverse(Ray(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)), 0, &t, [&](uint32_t tri, double *) {
        visited.push_back(tri);
        return false;
    });
    EXPECT_EQ(visited.size(), 40u);
    // The lowest index wins the tie among the copies
    TriangleMesh mesh(std::make_shared<ir::Mesh>(same));
    TriangleMesh::Hit hit;
    ASSERT_TRUE(mesh.closest(Ray(Vec3(0.2, 0.2, 1), Vec3(0, 0, -1)), 0, kInfinity, &hit));
    EXPECT_EQ(hit.triangle, 0u);
    EXPECT_EQ(hit.t, 1);
}

std::string describe(const Ray &r) {
    char s[200];
    std::snprintf(s, sizeof s, "ray [%.17g, %.17g, %.17g] + t [%.17g, %.17g, %.17g]", r.o.x, r.o.y,
                  r.o.z, r.d.x, r.d.y, r.d.z);
    return s;
}

/// The closest hit of every ray (for tMin = 0 and -inf) and every crossing of the line are
/// brute force's.
void expectSameAsBruteForce(const TriangleMesh &mesh, const std::vector<Ray> &rays, int *hits) {
    for (const Ray &r : rays) {
        for (double tMin : {0.0, -kInfinity}) {
            Expected e = bruteClosest(mesh, r, tMin, kInfinity);
            TriangleMesh::Hit hit;
            bool found = mesh.closest(r, tMin, kInfinity, &hit);
            ASSERT_EQ(found, e.found) << describe(r) << ", tMin " << tMin;
            if (!found) continue;
            ASSERT_EQ(hit.t, e.t) << describe(r) << ", tMin " << tMin;
            ASSERT_EQ(hit.triangle, e.triangle) << describe(r) << ", tMin " << tMin;
            ++*hits;
        }
        SCOPED_TRACE(describe(r));
        ASSERT_NO_FATAL_FAILURE(expectAllHitsMatchBruteForce(mesh, r));
    }
}

/// Rays the float node test must not lose: axis-parallel ones through vertices, rays starting
/// exactly on the planes of the float boxes, rays grazing along edges, and rays whose
/// direction has a component of 1e-30 or 1e-300 (a reciprocal beyond the float range).
std::vector<Ray> stiffRays(const ir::Mesh &m, const WideBvh &bvh, double scale, int count) {
    Rng rng(11);
    std::vector<Ray> rays;
    auto vertex = [&] {
        return m.positions[static_cast<size_t>(rng.uniform() * m.positions.size())];
    };
    for (int i = 0; i < count; ++i) {
        int axis = i % 3;
        double sign = i % 2 ? 1 : -1;
        Vec3 d(0), target = vertex();
        d[axis] = sign;
        // Axis-parallel, through a vertex (on the boxes' planes in the other two axes)
        rays.emplace_back(target - d * (3 * scale), d);
        // From a plane of a float box, towards a vertex
        const auto &node = bvh.nodes()[static_cast<size_t>(rng.uniform() * bvh.nodes().size())];
        int c = static_cast<int>(rng.uniform() * 4);
        if (node.child[c] != WideBvh::kEmpty) {
            Vec3 o = target + Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) *
                                  (3 * scale);
            o[axis] = i % 2 ? node.lo[axis][c] : node.hi[axis][c];
            if (o != target) rays.emplace_back(o, normalize(target - o));
            // and along the plane
            Vec3 along = normalize(target - o);
            along[axis] = 0;
            if (lengthSquared(along) > 0) rays.emplace_back(o, normalize(along));
        }
        // Grazing: along an edge of a triangle, from beyond its end
        const auto &t = m.triangles[static_cast<size_t>(rng.uniform() * m.triangles.size())];
        Vec3 e = m.positions[t[1]] - m.positions[t[0]];
        if (lengthSquared(e) > 0) rays.emplace_back(m.positions[t[0]] - e * 2.0, normalize(e));
        // Tiny direction components
        Vec3 o = target - d * (3 * scale);
        for (double tiny : {1e-30, -1e-300, 1e-300}) {
            Vec3 dt = d;
            dt[(axis + 1) % 3] = tiny;
            dt[(axis + 2) % 3] = -tiny * 0.5;
            rays.emplace_back(o, dt);
            // off the vertex by a little, so the tiny component decides
            Vec3 o2 = o;
            o2[(axis + 1) % 3] += scale * 1e-9;
            rays.emplace_back(o2, dt);
        }
    }
    return rays;
}

TEST(WideBvh, FloatNodeTestLosesNoHitOnStiffRaysAtEveryScale) {
    for (double scale : {1e-6, 1.0, 1e6})
        for (const Vec3 &offset : {Vec3(0), Vec3(1e5, -1e5, 1e5)}) {
            SCOPED_TRACE(testing::Message() << "scale " << scale << ", offset " << offset.x);
            for (bool floats : {false, true}) {
                // (floats 1e5 away are 1/128 apart: a sphere of 1e-6 there has collapsed)
                if (floats && scale < 1 && offset.x != 0) continue;
                auto m = troubleMesh(2, scale, offset);
                if (floats) m = test::inFloats(m);
                TriangleMesh mesh(m);
                ASSERT_EQ(mesh.floatLeaves().empty(), !floats);
                int hits = 0;
                expectSameAsBruteForce(mesh, testRays(*m, scale, offset, 150), &hits);
                expectSameAsBruteForce(mesh, stiffRays(*m, mesh.bvh(), scale, 60), &hits);
                EXPECT_GT(hits, 200);
            }
        }
}

TEST(WideBvh, FloatNodeTestRoundsTheOriginOutwardPerPlane) {
    // One triangle in the plane x = 1 and rays from just before that plane (1 - 1e-9, which
    // rounds to the float 1) climbing to it over t = 1e-6 while entering the box in y: with the
    // origin rounded to nearest, the x slab would be [0, 0] and the box missed
    for (double sign : {1.0, -1.0}) {
        ir::Mesh m;
        m.positions = {Vec3(sign, 0, -1), Vec3(sign, 2, -1), Vec3(sign, 0, 1)};
        m.triangles = {{0, 1, 2}};
        TriangleMesh mesh(std::make_shared<ir::Mesh>(m));
        Ray r(Vec3(sign * (1 - 1e-9), -0.5e-6, 0), normalize(Vec3(sign * 1e-3, 1, 0)));
        Expected e = bruteClosest(mesh, r, 0, kInfinity);
        ASSERT_TRUE(e.found);
        TriangleMesh::Hit hit;
        ASSERT_TRUE(mesh.closest(r, 0, kInfinity, &hit));
        EXPECT_EQ(hit.t, e.t);
    }
}

/// Whether the ray meets box b within [tMin, tMax], in double with the far distances grown by
/// their rounding error (a NaN distance, the origin on the plane of a flat direction, is no
/// constraint; an infinite one is not grown into a NaN): the boxes a traversal must visit.
bool meets(const Bounds3 &b, const Ray &r, double tMin, double tMax) {
    if (b.isEmpty()) return false;
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        double inv = 1 / r.d[a];
        double n = (b.min[a] - r.o[a]) * inv, f = (b.max[a] - r.o[a]) * inv;
        if (n > f) std::swap(n, f);
        if (std::isfinite(f)) f += 2 * gamma(3) * std::abs(f);
        if (n > t0) t0 = n;
        if (f < t1) t1 = f;
    }
    return t0 <= t1;
}

TEST(WideBvh, OverItemBoxesVisitsEveryBoxTheRayMeetsEvenEmptyInfiniteAndHugeOnes) {
    Rng rng(3);
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 3000; ++i) {
        Vec3 c(rng.uniform() * 20 - 10, rng.uniform() * 20 - 10, rng.uniform() * 20 - 10);
        Vec3 h(rng.uniform(), rng.uniform() * 0.1, rng.uniform() * 2);
        Bounds3 b(c - h, c + h);
        switch (i % 97) {
            case 0:
                b = Bounds3();
                break;  // empty
            case 1:
                b = Bounds3::infinite();
                break;  // unbounded
            case 2:
                b.max.x = kInfinity;
                break;  // a half space
            case 3:
                b.min.y = -1e300;
                break;  // beyond the float range
            case 4:
                b = Bounds3(Vec3(1e39), Vec3(2e39));
                break;
            case 5:
                b = Bounds3(c, c);
                break;  // a point
            default:
                break;
        }
        boxes.push_back(b);
    }
    WideBvh bvh(boxes, 2);
    std::vector<int> seen(boxes.size(), 0);
    for (uint32_t i : bvh.itemOrder()) ++seen.at(i);
    // CSG operands keep leaves of up to four (they are tested one at a time)
    for (const auto &node : bvh.nodes())
        for (uint32_t c : node.child)
            if (c != WideBvh::kEmpty && (c & WideBvh::kLeaf)) {
                ASSERT_LE(WideBvh::leafCount(c), uint32_t(WideBvh::kLeafItems));
            }
    EXPECT_THROW(WideBvh(boxes, 1, WideBvh::kItemCost, 0), std::invalid_argument);
    EXPECT_THROW(WideBvh(boxes, 1, WideBvh::kItemCost, 9), std::invalid_argument);
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    int met = 0;
    for (int k = 0; k < 800; ++k) {
        Vec3 o(rng.uniform() * 30 - 15, rng.uniform() * 30 - 15, rng.uniform() * 30 - 15);
        Vec3 d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
        if (k % 4 == 1) d[k % 3] = 0;                     // flat directions
        if (k % 4 == 2) o = boxes[k % boxes.size()].min;  // from a box corner
        if (k % 8 == 3) d[(k + 1) % 3] = 1e-300;
        if (k % 16 == 5) o = o * 1e31;  // beyond the float range: the double test
        if (lengthSquared(d) == 0) continue;
        Ray r(o, d);
        // From 0 and beyond it (the forward test) and from -inf (the whole line)
        for (double tMin : {0.0, 2.5, 1e-300, -kInfinity}) {
            double tMax = k % 3 ? kInfinity : 7.5;
            std::vector<char> visited(boxes.size(), 0);
            double far = tMax;
            bvh.traverse(r, tMin, &far,
                         [&](uint32_t i, double *) { return visited[i] = 1, false; });
            for (size_t i = 0; i < boxes.size(); ++i)
                if (meets(boxes[i], r, tMin, tMax)) {
                    ++met;
                    ASSERT_TRUE(visited[i])
                        << "box " << i << ", ray " << k << ", tMin " << tMin << ", " << describe(r);
                }
        }
    }
    EXPECT_GT(met, 5000);
}

TEST(WideBvh, EmptySlotsAreNeverVisited) {
    // The float tests cull an empty slot's inverted infinite box by themselves (the walk masks
    // empty slots out only for the double test): from every sign pattern, with zero (+0 and -0)
    // and tiny direction components, from box planes and corners, forward and along the whole
    // line, in float and (far from the origin) in double. A visit would read past the leaves
    Rng rng(11);
    for (int n = 1; n <= 9; ++n) {
        std::vector<Bounds3> boxes;
        for (int i = 0; i < n; ++i) {
            Vec3 c(rng.uniform() * 4 - 2, rng.uniform() * 4 - 2, rng.uniform() * 4 - 2);
            boxes.emplace_back(c - Vec3(0.5), c + Vec3(0.5));
        }
        WideBvh bvh(boxes);
        size_t empty = 0;
        for (const auto &node : bvh.nodes())
            for (uint32_t c : node.child) empty += c == WideBvh::kEmpty;
        if (n < 4) {
            EXPECT_GT(empty, 0u);
        }
        const double components[] = {1, -1, 0, -0.0, 1e-30, -1e-300, 0.25};
        int rays = 0;
        for (double dx : components)
            for (double dy : components)
                for (double dz : components) {
                    Vec3 d(dx, dy, dz);
                    if (lengthSquared(d) == 0) continue;
                    for (int k = 0; k < 4; ++k) {
                        const Bounds3 &b = boxes[k % n];
                        Vec3 o = k == 0   ? b.min
                                 : k == 1 ? Vec3(b.max.x, 0, b.min.z)
                                 : k == 2 ? Vec3(0)
                                          : Vec3(1e31);
                        Ray r(o, d);
                        for (double tMin : {0.0, 1e-300, -kInfinity})
                            for (double tMax : {kInfinity, 7.5}) {
                                double far = tMax;
                                bvh.traverseLeaves(
                                    r, tMin, &far, [&](uint32_t first, uint32_t count, double *) {
                                        EXPECT_LE(first + count, uint32_t(n)) << describe(r);
                                        return false;
                                    });
                                ++rays;
                            }
                    }
                }
        EXPECT_GT(rays, 1000);
    }
}

}  // namespace
}  // namespace rt
