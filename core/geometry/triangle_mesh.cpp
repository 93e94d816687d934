// SPDX-License-Identifier: MIT
// Triangle mesh BVH, watertight intersection, spans by winding number.
#include "core/geometry/triangle_mesh.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "core/math/float_util.h"
#include "core/math/fma_clone.h"
#include "core/system/parallel_for.h"

namespace rt {

namespace {

/// Direction of the inside-test ray: no axis or diagonal, so it rarely runs along mesh edges.
const Vec3 kInsideDirection = normalize(Vec3(0.2718281828, 0.5772156649, 0.7071067811));

Vec3 permute(const Vec3 &v, int x, int y, int z) { return {v[x], v[y], v[z]}; }

/// Fill convention for a point exactly on an edge (edge function 0): the edge from a to b, in
/// the sheared plane, owns it only if it points up, or left when horizontal. The same edge seen
/// from the neighbouring triangle runs the other way, so exactly one of the two owns the point;
/// at a shared vertex exactly one triangle of the fan does (the top-left rule of
/// rasterisation). `sign` is the orientation of the triangle in the plane.
bool ownsEdge(const Vec3 &a, const Vec3 &b, double sign) {
    double dx = (b.x - a.x) * sign, dy = (b.y - a.y) * sign;
    return dy > 0 || (dy == 0 && dx < 0);
}

#if defined(__x86_64__) && defined(__GNUC__)
#define SCADRAY_LEAF_FILTER 1
#define SCADRAY_AVX2_FMA __attribute__((target("avx2,fma")))
SCADRAY_AVX2_FMA inline __m256d differenceOfProducts4(__m256d a, __m256d b, __m256d c, __m256d d) {
    __m256d cd = _mm256_mul_pd(c, d);
    return _mm256_add_pd(_mm256_fmsub_pd(a, b, cd), _mm256_fnmadd_pd(c, d, cd));
}

/// Of up to four triangles (load(v, a) gives coordinate a of vertex v of each, one triangle a
/// lane), the lanes below n whose three edge functions in the ray's frame do not have
/// mixed signs: each value computed with the operations, in the order and the rounding, of
/// TriangleMesh::intersect (the translation, the shear as a product then a sum,
/// differenceOfProducts with its two FMAs), so a lane left out is one that intersect rejects
/// at its first test. NaN edge functions pass, as there.
template <typename Load>
SCADRAY_AVX2_FMA __attribute__((always_inline)) inline unsigned edgeCandidates(
    const Load &load, uint32_t n, const TriangleMesh::RayFrame &f) {
    const __m256d ox = _mm256_set1_pd(f.ox), oy = _mm256_set1_pd(f.oy), oz = _mm256_set1_pd(f.oz);
    const __m256d shx = _mm256_set1_pd(f.sx), shy = _mm256_set1_pd(f.sy);
    const int kx = f.kx, ky = f.ky, kz = f.kz;
    // Vertex v translated to the origin, permuted and sheared (written out: GCC keeps a loop
    // over the vertices, with its results on the stack)
    __m256d z0 = _mm256_sub_pd(load(0, kz), oz), z1 = _mm256_sub_pd(load(1, kz), oz),
            z2 = _mm256_sub_pd(load(2, kz), oz);
    __m256d x0 = _mm256_add_pd(_mm256_sub_pd(load(0, kx), ox), _mm256_mul_pd(shx, z0));
    __m256d y0 = _mm256_add_pd(_mm256_sub_pd(load(0, ky), oy), _mm256_mul_pd(shy, z0));
    __m256d x1 = _mm256_add_pd(_mm256_sub_pd(load(1, kx), ox), _mm256_mul_pd(shx, z1));
    __m256d y1 = _mm256_add_pd(_mm256_sub_pd(load(1, ky), oy), _mm256_mul_pd(shy, z1));
    __m256d x2 = _mm256_add_pd(_mm256_sub_pd(load(2, kx), ox), _mm256_mul_pd(shx, z2));
    __m256d y2 = _mm256_add_pd(_mm256_sub_pd(load(2, ky), oy), _mm256_mul_pd(shy, z2));
    __m256d e0 = differenceOfProducts4(x1, y2, y1, x2);
    __m256d e1 = differenceOfProducts4(x2, y0, y2, x0);
    __m256d e2 = differenceOfProducts4(x0, y1, y0, x1);
    const __m256d zero = _mm256_setzero_pd();
    __m256d negative = _mm256_or_pd(
        _mm256_or_pd(_mm256_cmp_pd(e0, zero, _CMP_LT_OQ), _mm256_cmp_pd(e1, zero, _CMP_LT_OQ)),
        _mm256_cmp_pd(e2, zero, _CMP_LT_OQ));
    __m256d positive = _mm256_or_pd(
        _mm256_or_pd(_mm256_cmp_pd(e0, zero, _CMP_GT_OQ), _mm256_cmp_pd(e1, zero, _CMP_GT_OQ)),
        _mm256_cmp_pd(e2, zero, _CMP_GT_OQ));
    unsigned mixed = static_cast<unsigned>(_mm256_movemask_pd(_mm256_and_pd(negative, positive)));
    return ~mixed & ((1u << n) - 1);
}

/// Coordinate a of vertex v of a float leaf's n triangles (TriangleMesh::floatLeaves' layout,
/// from the first coordinate; a lane beyond n reads the next coordinate's words, or the next
/// leaf's, or the padding, and is left out).
struct FloatLeafLoad {
    const float *c;  // _mm_loadu_ps may alias the leaf's 32-bit words
    uint32_t n;
    SCADRAY_AVX2_FMA __m256d operator()(int v, int a) const {
        return _mm256_cvtps_pd(_mm_loadu_ps(c + (3 * v + a) * n));
    }
};

/// edgeCandidates of a float leaf's n triangles (up to eight: two groups of four, independent
/// of each other, in lanes 0 to 3 and 4 to 7 of the result).
SCADRAY_AVX2_FMA unsigned floatLeafCandidates(const uint32_t *coordinates, uint32_t n,
                                              const TriangleMesh::RayFrame &f) {
    const float *c = reinterpret_cast<const float *>(coordinates);
    unsigned lanes = edgeCandidates(FloatLeafLoad{c, n}, std::min(n, 4u), f);
    if (n > 4) lanes |= edgeCandidates(FloatLeafLoad{c + 4, n}, n - 4, f) << 4;
    return lanes;
}

/// Coordinate a of vertex v of a leaf of triangle records, gathered by vertex index: at[v]
/// holds three times each lane's index of vertex v (a lane beyond the leaf repeats its first
/// triangle).
struct GatherLoad {
    const double *positions;
    __m128i at[3];
    /// The load of a group of n (1 to 4) records.
    SCADRAY_AVX2_FMA static GatherLoad of(const TriangleMesh::LeafTriangle *group, uint32_t n,
                                          const Vec3 *positions) {
        const TriangleMesh::LeafTriangle &t0 = group[0], &t1 = group[n > 1 ? 1 : 0],
                                         &t2 = group[n > 2 ? 2 : 0], &t3 = group[n > 3 ? 3 : 0];
        static_assert(sizeof(Vec3) == 3 * sizeof(double));
        GatherLoad load{&positions[0].x, {}};
        for (int v = 0; v < 3; ++v)
            load.at[v] =
                _mm_mullo_epi32(_mm_set_epi32(static_cast<int>(t3.v[v]), static_cast<int>(t2.v[v]),
                                              static_cast<int>(t1.v[v]), static_cast<int>(t0.v[v])),
                                _mm_set1_epi32(3));
        return load;
    }
    SCADRAY_AVX2_FMA __m256d operator()(int v, int a) const {
        return _mm256_mask_i32gather_pd(_mm256_setzero_pd(), positions + a, at[v],
                                        _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
    }
};

/// edgeCandidates of a leaf of n triangle records (up to eight, in two groups of four as
/// floatLeafCandidates takes them), the positions gathered by vertex index (three times an
/// index must fit in 31 bits: TriangleMesh checks the vertex count).
SCADRAY_AVX2_FMA unsigned indexedLeafCandidates(const TriangleMesh::LeafTriangle *leaf, uint32_t n,
                                                const Vec3 *positions,
                                                const TriangleMesh::RayFrame &f) {
    unsigned lanes =
        edgeCandidates(GatherLoad::of(leaf, std::min(n, 4u), positions), std::min(n, 4u), f);
    if (n > 4) lanes |= edgeCandidates(GatherLoad::of(leaf + 4, n - 4, positions), n - 4, f) << 4;
    return lanes;
}

#endif

/// True when every position of the mesh is exactly a float.
bool allFloats(const ir::Mesh &mesh) {
    for (const Vec3 &p : mesh.positions)
        for (int a = 0; a < 3; ++a)
            if (!(static_cast<double>(static_cast<float>(p[a])) == p[a])) return false;
    return true;
}

}  // namespace

bool TriangleMesh::fourWideLeaves() {
#ifdef SCADRAY_LEAF_FILTER
    // (__builtin_cpu_init first: this may run from another file's static constructor)
    static const bool has = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    }();
    return has;
#else
    return false;
#endif
}

WideBvh TriangleMesh::buildBvh(const ir::Mesh &mesh, int threads) {
    // The four-wide edge test makes a leaf of up to four triangles cost little more than one,
    // so where it runs the BVH has fuller leaves
    if (fourWideLeaves())
        return WideBvh(mesh, threads, WideBvh::kTriangleCost, WideBvh::kMaxLeafItems);
    return WideBvh(mesh, threads, WideBvh::kItemCost);
}

TriangleMesh::TriangleMesh(ir::MeshPtr mesh, int buildThreads) : mesh_(std::move(mesh)) {
    const ir::Mesh &m = *mesh_;
    smooth_.resize(m.triangles.size(), false);
    for (size_t i = 0; i < m.triangles.size(); ++i) {
        const auto &t = m.triangles[i];
        for (int k = 0; k < 3; ++k) bounds_ = unionBounds(bounds_, m.positions[t[k]]);
        if (!m.normals.empty())
            smooth_[i] =
                !(m.normals[t[0]] == m.normals[t[1]] && m.normals[t[1]] == m.normals[t[2]]);
    }
    bvh_ = buildBvh(m, buildThreads);
    floatLeaves_ = floatLeaves(m, bvh_, buildThreads);
    // Gathers take signed 32-bit offsets: three times a vertex index must fit
    fourWide_ =
        fourWideLeaves() && (!floatLeaves_.empty() || m.positions.size() <= size_t{INT32_MAX} / 3);
    if (floatLeaves_.empty())
        leafTriangles_ = leafOrder(m, bvh_);
    else
        bvh_.dropItemOrder();  // the float leaves hold it
    bvh_.setLeafData(leafData());
    topology_ = ir::analyzeMesh(m);
}

LargeVector<TriangleMesh::LeafTriangle> TriangleMesh::leafOrder(const ir::Mesh &mesh,
                                                                const WideBvh &bvh) {
    LargeVector<LeafTriangle> out;
    out.reserve(bvh.itemOrder().size());
    for (uint32_t t : bvh.itemOrder()) out.push_back({mesh.triangles[t], t});
    return out;
}

LargeVector<uint32_t> TriangleMesh::floatLeaves(const ir::Mesh &mesh, const WideBvh &bvh,
                                                int threads) {
    LargeVector<uint32_t> out;
    if (bvh.empty() || !allFloats(mesh)) return out;
    const auto &order = bvh.itemOrder();
    // Left unwritten by resize: the threads that fill it touch its pages first
    out.resize(kFloatLeafWords * order.size() + kLeafPadding);
    const auto &nodes = bvh.nodes();
    if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    const size_t parts = nodes.size() >= 4096 ? static_cast<size_t>(threads) : 1;
    parallelFor(0, nodes.size(), parts, [&](size_t, size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k)
            for (uint32_t ref : nodes[k].child) {
                if (ref == WideBvh::kEmpty || !(ref & WideBvh::kLeaf)) continue;
                const uint32_t first = WideBvh::leafFirst(ref), n = WideBvh::leafCount(ref);
                uint32_t *leaf = out.data() + kFloatLeafWords * first;
                for (uint32_t i = 0; i < n; ++i) {
                    const uint32_t triangle = order[first + i];
                    const auto &t = mesh.triangles[triangle];
                    leaf[i] = triangle;
                    uint32_t *c = leaf + n + i;
                    for (int v = 0; v < 3; ++v) {
                        const Vec3 &p = mesh.positions[t[v]];
                        c[(3 * v) * n] = std::bit_cast<uint32_t>(static_cast<float>(p.x));
                        c[(3 * v + 1) * n] = std::bit_cast<uint32_t>(static_cast<float>(p.y));
                        c[(3 * v + 2) * n] = std::bit_cast<uint32_t>(static_cast<float>(p.z));
                    }
                }
            }
    });
    std::fill(out.end() - kLeafPadding, out.end(), 0u);
    return out;
}

size_t TriangleMesh::extraBytes() const {
    return bvh_.bytes() + leafTriangles_.capacity() * sizeof(LeafTriangle) +
           floatLeaves_.capacity() * sizeof(uint32_t) + smooth_.capacity() / 8;
}

template <typename F>
void TriangleMesh::forLeaf(const RayFrame &frame, uint32_t first, uint32_t count, F &&f) const {
    unsigned lanes = (1u << count) - 1;
    if (floatLeaves_.empty()) {
        const auto &pos = mesh_->positions;
        const LeafTriangle *leaf = leafTriangles_.data() + first;
#ifdef SCADRAY_LEAF_FILTER
        if (fourWide_) lanes = indexedLeafCandidates(leaf, count, pos.data(), frame);
#endif
        for (; lanes != 0; lanes &= lanes - 1) {
            const LeafTriangle &t = leaf[__builtin_ctz(lanes)];
            f(pos[t.v[0]], pos[t.v[1]], pos[t.v[2]], t.triangle);
        }
        return;
    }
    const uint32_t *leaf = floatLeaves_.data() + kFloatLeafWords * first,
                   *coordinates = leaf + count;
#ifdef SCADRAY_LEAF_FILTER
    if (fourWide_) lanes = floatLeafCandidates(coordinates, count, frame);
#endif
    for (; lanes != 0; lanes &= lanes - 1) {
        const uint32_t i = static_cast<uint32_t>(__builtin_ctz(lanes));
        auto at = [&](int j) {
            return static_cast<double>(std::bit_cast<float>(coordinates[j * count + i]));
        };
        f(Vec3(at(0), at(1), at(2)), Vec3(at(3), at(4), at(5)), Vec3(at(6), at(7), at(8)), leaf[i]);
    }
}

TriangleMesh::RayFrame::RayFrame(const Ray &r) : ray(&r) {
    // Permute so the ray's largest component is z, and shear so the ray runs along +z
    kz = maxDimension(abs(r.d));
    kx = kz + 1 == 3 ? 0 : kz + 1;
    ky = kx + 1 == 3 ? 0 : kx + 1;
    Vec3 d = permute(r.d, kx, ky, kz);
    sx = -d.x / d.z;
    sy = -d.y / d.z;
    sz = 1 / d.z;
    ox = r.o[kx];
    oy = r.o[ky];
    oz = r.o[kz];
}

bool TriangleMesh::intersectTriangle(const Ray &r, uint32_t triangle, Hit *hit) const {
    const auto &t = mesh_->triangles[triangle];
    const auto &pos = mesh_->positions;
    return intersect(RayFrame(r), pos[t[0]], pos[t[1]], pos[t[2]], triangle, -kInfinity, kInfinity,
                     false, hit);
}

// The edge functions round once each through std::fma, which without an FMA instruction in the
// x86-64 baseline is a call into libm: a copy for CPUs with FMA has it inline, with the same
// results (core/math/fma_clone.h)
SCADRAY_FMA_CLONES
bool TriangleMesh::intersect(const RayFrame &f, const Vec3 &p0, const Vec3 &p1, const Vec3 &p2,
                             uint32_t triangle, double tMin, double tMax, bool tMaxInclusive,
                             Hit *hit) const {
    const Ray &r = *f.ray;
    // Translate the vertices to the ray origin, permute and shear into the ray's frame
    const int kx = f.kx, ky = f.ky, kz = f.kz;
    Vec3 p0t(p0[kx] - r.o[kx], p0[ky] - r.o[ky], p0[kz] - r.o[kz]);
    Vec3 p1t(p1[kx] - r.o[kx], p1[ky] - r.o[ky], p1[kz] - r.o[kz]);
    Vec3 p2t(p2[kx] - r.o[kx], p2[ky] - r.o[ky], p2[kz] - r.o[kz]);
    const double sx = f.sx, sy = f.sy, sz = f.sz;
    p0t.x += sx * p0t.z;
    p0t.y += sy * p0t.z;
    p1t.x += sx * p1t.z;
    p1t.y += sy * p1t.z;
    p2t.x += sx * p2t.z;
    p2t.y += sy * p2t.z;
    // Edge functions, each with one rounding (FMA), so a shared edge gives the same value with
    // opposite sign in its two triangles: no ray slips between them
    double e0 = differenceOfProducts(p1t.x, p2t.y, p1t.y, p2t.x);
    double e1 = differenceOfProducts(p2t.x, p0t.y, p2t.y, p0t.x);
    double e2 = differenceOfProducts(p0t.x, p1t.y, p0t.y, p1t.x);
    if ((e0 < 0 || e1 < 0 || e2 < 0) && (e0 > 0 || e1 > 0 || e2 > 0)) return false;
    double det = e0 + e1 + e2;
    if (det == 0 || !std::isfinite(det)) return false;
    // On an edge or vertex: count the point for one triangle only, so a closed mesh is entered
    // and left exactly once by a ray through its edges and vertices
    double sign = det > 0 ? 1 : -1;
    if ((e0 == 0 && !ownsEdge(p1t, p2t, sign)) || (e1 == 0 && !ownsEdge(p2t, p0t, sign)) ||
        (e2 == 0 && !ownsEdge(p0t, p1t, sign)))
        return false;
    p0t.z *= sz;
    p1t.z *= sz;
    p2t.z *= sz;
    double tScaled = e0 * p0t.z + e1 * p1t.z + e2 * p2t.z;
    double invDet = 1 / det;
    double t = tScaled * invDet;
    if (!(t > tMin && (t < tMax || (tMaxInclusive && t == tMax)))) return false;
    hit->t = t;
    hit->b0 = e0 * invDet;
    hit->b1 = e1 * invDet;
    hit->b2 = e2 * invDet;
    hit->triangle = triangle;
    hit->entering = dot(r.d, cross(p1 - p0, p2 - p0)) < 0;
    // Rounding-error bound of t (pbrt-v3 section 3.9.6, triangle.cpp): from the errors of the
    // sheared coordinates, the edge functions and the weighted sum of z
    double maxZt = maxComponent(abs(Vec3(p0t.z, p1t.z, p2t.z)));
    double maxXt = maxComponent(abs(Vec3(p0t.x, p1t.x, p2t.x)));
    double maxYt = maxComponent(abs(Vec3(p0t.y, p1t.y, p2t.y)));
    double deltaZ = gamma(3) * maxZt;
    double deltaX = gamma(5) * (maxXt + maxZt), deltaY = gamma(5) * (maxYt + maxZt);
    double deltaE = 2 * (gamma(2) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
    double maxE = maxComponent(abs(Vec3(e0, e1, e2)));
    hit->tError = 3 * (gamma(3) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * std::abs(invDet);
    return true;
}

bool TriangleMesh::closest(const Ray &r, double tMin, double tMax, Hit *hit) const {
    bool found = false;
    double far = tMax;
    RayFrame frame(r);
    bvh_.traverseLeaves(r, tMin, &far, [&](uint32_t first, uint32_t count, double *tFar) {
        forLeaf(frame, first, count,
                [&](const Vec3 &p0, const Vec3 &p1, const Vec3 &p2, uint32_t triangle) {
                    Hit h;
                    // A tie at the closest t goes to the lower triangle index
                    if (!intersect(frame, p0, p1, p2, triangle, tMin, *tFar,
                                   found && triangle < hit->triangle, &h))
                        return;
                    // A hit within its own rounding error of the origin may be the surface the ray
                    // starts on: t must be conservatively positive (pbrt-v3 Triangle::Intersect)
                    if (h.t <= h.tError) return;
                    *hit = h;
                    *tFar = h.t;
                    found = true;
                });
        return false;
    });
    return found;
}

void TriangleMesh::allHits(const Ray &r, std::vector<Hit> &out) const {
    double far = kInfinity;
    RayFrame frame(r);
    bvh_.traverseLeaves(r, -kInfinity, &far, [&](uint32_t first, uint32_t count, double *) {
        forLeaf(frame, first, count,
                [&](const Vec3 &p0, const Vec3 &p1, const Vec3 &p2, uint32_t triangle) {
                    Hit h;
                    if (intersect(frame, p0, p1, p2, triangle, -kInfinity, kInfinity, false, &h))
                        out.push_back(h);
                });
        return false;
    });
}

ObjectSurface TriangleMesh::surface(const Hit &hit, Vec3 *shadingNormal,
                                    SurfaceInteraction *si) const {
    const auto &idx = mesh_->triangles[hit.triangle];
    const Vec3 &p0 = mesh_->positions[idx[0]], &p1 = mesh_->positions[idx[1]],
               &p2 = mesh_->positions[idx[2]];
    ObjectSurface s;
    // Barycentric point and its error (pbrt-v3 eq. 3.14)
    s.p = p0 * hit.b0 + p1 * hit.b1 + p2 * hit.b2;
    s.pError = (abs(p0 * hit.b0) + abs(p1 * hit.b1) + abs(p2 * hit.b2)) * gamma(7);
    s.normal = cross(p1 - p0, p2 - p0);
    *shadingNormal = s.normal;
    if (smooth_[hit.triangle]) {
        const auto &n = mesh_->normals;
        Vec3 ns = n[idx[0]] * hit.b0 + n[idx[1]] * hit.b1 + n[idx[2]] * hit.b2;
        if (lengthSquared(ns) > 0) *shadingNormal = ns;
    }
    // Component c of a per-vertex attribute at the hit
    auto lerp = [&](const auto &values, int c) {
        return double(values[idx[0]][c]) * hit.b0 + double(values[idx[1]][c]) * hit.b1 +
               double(values[idx[2]][c]) * hit.b2;
    };
    si->hasUv = !mesh_->uvs.empty();
    if (si->hasUv) {
        si->u = lerp(mesh_->uvs, 0);
        si->v = lerp(mesh_->uvs, 1);
    }
    si->hasUv1 = !mesh_->uvs1.empty();
    if (si->hasUv1) {
        si->u1 = lerp(mesh_->uvs1, 0);
        si->v1 = lerp(mesh_->uvs1, 1);
    }
    si->hasTangent = !mesh_->tangents.empty();
    if (si->hasTangent) {
        // Object space here; MeshInstance::surfaceAt moves it to the world. The sign is the
        // first vertex's: glTF requires it constant over a triangle
        si->tangent = {lerp(mesh_->tangents, 0), lerp(mesh_->tangents, 1),
                       lerp(mesh_->tangents, 2)};
        si->tangentSign = mesh_->tangents[idx[0]][3] < 0 ? -1 : 1;
    }
    si->hasVertexColor = !mesh_->colors.empty();
    if (si->hasVertexColor)
        for (int c = 0; c < 4; ++c) si->vertexColor[c] = float(lerp(mesh_->colors, c));
    return s;
}

// ---------------------------------------------------------------------------------------------

MeshInstance::MeshInstance(std::shared_ptr<const TriangleMesh> mesh,
                           const Transform &worldFromObject, int material)
    : LeafShape(material),
      mesh_(std::move(mesh)),
      placement_(worldFromObject),
      bounds_(placement_.worldBounds(mesh_->bounds())) {}

void MeshInstance::lineSpans(const Ray &worldRay, SpanList &out) const {
    if (!mesh_->closed()) return;
    thread_local std::vector<TriangleMesh::Hit> hits;
    hits.clear();
    mesh_->allHits(placement_.toObject(worldRay), hits);
    // By t, and at one t by triangle, so the crossing named does not depend on the BVH's order
    std::sort(hits.begin(), hits.end(), [](const TriangleMesh::Hit &a, const TriangleMesh::Hit &b) {
        return a.t < b.t || (a.t == b.t && a.triangle < b.triangle);
    });
    // Winding number (or parity), applying all hits at one t together: a ray through an edge
    // or vertex meets several triangles at once, and their net count is what matters
    bool winding = mesh_->oriented();
    int state = 0;
    Span open;
    for (size_t i = 0; i < hits.size();) {
        size_t j = i;
        int next = state;
        while (j < hits.size() && hits[j].t == hits[i].t) {
            next = winding ? next + (hits[j].entering ? 1 : -1) : next ^ 1;
            ++j;
        }
        Crossing c{hits[i].t, this, static_cast<int>(hits[i].triangle), false};
        if (state == 0 && next != 0) open.in = c;
        if (state != 0 && next == 0) {
            open.out = c;
            if (open.in.t < open.out.t) out.push_back(open);
        }
        state = next;
        i = j;
    }
}

bool MeshInstance::firstCrossing(const Ray &ray, double tMin, double tMax, Crossing *c,
                                 SpanScratch &) const {
    TriangleMesh::Hit hit;
    if (!mesh_->closest(placement_.toObject(ray), tMin, tMax, &hit)) return false;
    *c = {hit.t, this, static_cast<int>(hit.triangle), false};
    return true;
}

bool MeshInstance::inside(const Vec3 &p) const {
    if (!mesh_->closed()) return false;
    Vec3 o = placement_.pointToObject(p);
    std::vector<TriangleMesh::Hit> hits;
    mesh_->allHits(Ray(o, kInsideDirection), hits);
    int count = 0;
    for (const auto &h : hits)
        if (h.t > 0) count += mesh_->oriented() ? (h.entering ? -1 : 1) : 1;
    return mesh_->oriented() ? count != 0 : (count % 2) != 0;
}

SurfaceInteraction MeshInstance::surfaceAt(const Ray &worldRay, const Crossing &c) const {
    Ray r = placement_.toObject(worldRay);
    TriangleMesh::Hit hit;
    if (!mesh_->intersectTriangle(r, static_cast<uint32_t>(c.face), &hit)) {
        // The crossing came from this very test; only a degenerate triangle gets here
        hit = {c.t, static_cast<uint32_t>(c.face), 1.0 / 3, 1.0 / 3, 1.0 / 3, false};
    }
    Vec3 ns;
    SurfaceInteraction si;
    ObjectSurface os = mesh_->surface(hit, &ns, &si);
    si.t = c.t;
    si.leaf = this;
    placement_.surfaceToWorld(os, si);
    si.ns = placement_.normalToWorld(ns);
    if (si.hasTangent) si.tangent = placement_.vectorToWorld(si.tangent);
    return si;
}

}  // namespace rt
