// SPDX-License-Identifier: MIT
// MikkTSpace-style tangent generation (see gltf_tangents.h), written from the algorithm's
// description (Mikkelsen 2008, "Simulation of wrinkled surfaces revisited").
#include "importers/gltf/gltf_tangents.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace rt::gltf::detail {

namespace {

/// Below this |du dv' - dv du'| a triangle's uv mapping is degenerate and gives no tangent.
constexpr double kMinUvArea = 1e-20;

/// The angle at corner p between the edges to a and b.
double cornerAngle(const Vec3 &p, const Vec3 &a, const Vec3 &b) {
    Vec3 e1 = a - p, e2 = b - p;
    double l1 = length(e1), l2 = length(e2);
    if (!(l1 > 0 && l2 > 0)) return 0;
    return std::acos(clamp(dot(e1, e2) / (l1 * l2), -1.0, 1.0));
}

/// Any unit vector perpendicular to n.
Vec3 anyPerpendicular(const Vec3 &n) {
    Vec3 axis = std::abs(n.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    Vec3 t = cross(axis, n);
    double l = length(t);
    return l > 0 ? t / l : Vec3(1, 0, 0);
}

}  // namespace

bool generateTangents(ir::Mesh &mesh, int texCoord) {
    const auto &uvs = texCoord == 1 ? mesh.uvs1 : mesh.uvs;
    size_t n = mesh.positions.size();
    if (uvs.size() != n || n == 0) return false;
    bool smooth = mesh.normals.size() == n;
    std::vector<Vec3> normal(n, Vec3(0, 0, 0));
    if (smooth)
        normal = mesh.normals;
    else
        for (const auto &tri : mesh.triangles) {
            Vec3 fn = cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                            mesh.positions[tri[2]] - mesh.positions[tri[0]]);
            for (uint32_t v : tri) normal[v] += fn;  // area-weighted
        }
    for (Vec3 &v : normal) {
        double l = length(v);
        v = l > 0 ? v / l : Vec3(0, 0, 1);
    }

    // Per triangle: dP/du, dP/dv' and the orientation of its uv mapping (+1, -1; 0 when
    // degenerate in uv, which then joins any group of its corners' vertices)
    size_t nt = mesh.triangles.size();
    std::vector<Vec3> triT(nt), triB(nt);
    std::vector<int> orient(nt, 0);
    for (size_t k = 0; k < nt; ++k) {
        const auto &tri = mesh.triangles[k];
        const Vec3 &p0 = mesh.positions[tri[0]], &p1 = mesh.positions[tri[1]],
                   &p2 = mesh.positions[tri[2]];
        // glTF's v runs down the image; MikkTSpace's bitangent runs up it (v' = -v)
        double du1 = double(uvs[tri[1]][0]) - uvs[tri[0]][0];
        double dv1 = -(double(uvs[tri[1]][1]) - uvs[tri[0]][1]);
        double du2 = double(uvs[tri[2]][0]) - uvs[tri[0]][0];
        double dv2 = -(double(uvs[tri[2]][1]) - uvs[tri[0]][1]);
        double det = du1 * dv2 - du2 * dv1;
        if (!(std::abs(det) > kMinUvArea)) continue;
        Vec3 e1 = p1 - p0, e2 = p2 - p0;
        triT[k] = (e1 * dv2 - e2 * dv1) / det;  // dP/du
        triB[k] = (e2 * du1 - e1 * du2) / det;  // dP/dv'
        orient[k] = det > 0 ? 1 : -1;
    }

    // MikkTSpace's groups: the corners at a vertex whose triangles share an edge through it
    // and the same uv orientation form one tangent space. A vertex on a mirrored-uv seam
    // thus gets one per side (its angular threshold, 180 degrees by default, splits nothing
    // more). Union-find over corners (3 k + c).
    std::vector<uint32_t> parent(3 * nt);
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::unordered_map<uint64_t, std::array<uint32_t, 2>> edgeCorner;  // (v, u) -> by orientation
    constexpr uint32_t kNone = ~0u;
    for (size_t k = 0; k < nt; ++k) {
        if (orient[k] == 0) continue;
        const auto &tri = mesh.triangles[k];
        for (int c = 0; c < 3; ++c)
            for (int d = 1; d < 3; ++d) {
                uint64_t key = uint64_t(tri[size_t(c)]) << 32 | tri[size_t((c + d) % 3)];
                auto [it, isNew] =
                    edgeCorner.try_emplace(key, std::array<uint32_t, 2>{kNone, kNone});
                uint32_t &first = it->second[orient[k] > 0 ? 0 : 1];
                uint32_t corner = uint32_t(3 * k + size_t(c));
                if (first == kNone)
                    first = corner;
                else
                    parent[find(corner)] = find(first);
            }
    }

    // One output vertex per (vertex, group): the first group keeps the vertex, others copy it
    std::vector<uint32_t> cornerVertex(3 * nt);
    std::unordered_map<uint32_t, uint32_t> groupVertex;  // group root -> output vertex
    std::vector<int64_t> firstGroup(n, -1);              // the root that kept the vertex
    std::vector<uint32_t> source;                        // output vertex -> the vertex it copies
    source.resize(n);
    std::iota(source.begin(), source.end(), 0u);
    for (size_t k = 0; k < nt; ++k) {
        if (orient[k] == 0) continue;
        for (int c = 0; c < 3; ++c) {
            uint32_t corner = uint32_t(3 * k + size_t(c)), v = mesh.triangles[k][size_t(c)];
            uint32_t root = find(corner);
            auto [it, isNew] = groupVertex.try_emplace(root, v);
            if (isNew && firstGroup[v] >= 0) {
                it->second = static_cast<uint32_t>(source.size());
                source.push_back(v);
            } else if (isNew) {
                firstGroup[v] = root;
            }
            cornerVertex[corner] = it->second;
        }
    }
    for (size_t k = 0; k < nt; ++k)  // uv-degenerate triangles join their vertices' first group
        if (orient[k] == 0)
            for (int c = 0; c < 3; ++c)
                cornerVertex[3 * k + size_t(c)] = mesh.triangles[k][size_t(c)];

    size_t m = source.size();
    std::vector<Vec3> tSum(m, Vec3(0, 0, 0)), bSum(m, Vec3(0, 0, 0));
    for (size_t k = 0; k < nt; ++k) {
        if (orient[k] == 0) continue;
        const auto &tri = mesh.triangles[k];
        const Vec3 *corner[3] = {&mesh.positions[tri[0]], &mesh.positions[tri[1]],
                                 &mesh.positions[tri[2]]};
        for (int c = 0; c < 3; ++c) {
            uint32_t out = cornerVertex[3 * k + size_t(c)];
            double angle = cornerAngle(*corner[c], *corner[(c + 1) % 3], *corner[(c + 2) % 3]);
            const Vec3 &nv = normal[tri[size_t(c)]];
            // Projected onto the vertex's tangent plane, then normalised, as MikkTSpace does
            Vec3 tp = triT[k] - nv * dot(nv, triT[k]), bp = triB[k] - nv * dot(nv, triB[k]);
            double lt = length(tp), lb = length(bp);
            if (lt > 0) tSum[out] += tp * (angle / lt);
            if (lb > 0) bSum[out] += bp * (angle / lb);
        }
    }

    // Split vertices copy every attribute of the vertex they come from
    auto extend = [&](auto &attribute) {
        if (attribute.size() != n) return;
        attribute.reserve(m);
        for (size_t i = n; i < m; ++i) attribute.push_back(attribute[source[i]]);
    };
    extend(mesh.positions);
    extend(mesh.normals);
    extend(mesh.uvs);
    extend(mesh.uvs1);
    extend(mesh.colors);
    for (size_t k = 0; k < nt; ++k)
        for (int c = 0; c < 3; ++c) mesh.triangles[k][size_t(c)] = cornerVertex[3 * k + size_t(c)];

    mesh.tangents.assign(m, {1, 0, 0, 1});
    for (size_t v = 0; v < m; ++v) {
        const Vec3 &nv = normal[source[v]];
        Vec3 t = tSum[v] - nv * dot(nv, tSum[v]);
        double l = length(t);
        t = l > 0 && std::isfinite(l) ? t / l : anyPerpendicular(nv);
        double w = dot(cross(nv, t), bSum[v]) < 0 ? -1 : 1;
        mesh.tangents[v] = {float(t.x), float(t.y), float(t.z), float(w)};
    }
    return true;
}

}  // namespace rt::gltf::detail
