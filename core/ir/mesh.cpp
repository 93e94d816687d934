// SPDX-License-Identifier: MIT
// Mesh bounds, topology and validation; texture means.
#include "core/ir/mesh.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/ir/diagnostics.h"

namespace rt::ir {

Bounds3 Mesh::bounds() const {
    Bounds3 b;
    for (const Vec3 &p : positions) b = unionBounds(b, p);
    return b;
}

namespace {

/// For each vertex, the index of the first vertex at exactly the same position: meshes that
/// split vertices for normals or texture coordinates (glTF, STL) still share their edges.
std::vector<uint32_t> weldedIndices(const Mesh &mesh) {
    std::vector<uint32_t> order(mesh.positions.size());
    for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto key = [&](uint32_t i) {
        const Vec3 &p = mesh.positions[i];
        return std::make_tuple(p.x + 0.0, p.y + 0.0, p.z + 0.0, i);  // + 0.0 folds -0 into +0
    };
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return key(a) < key(b); });
    std::vector<uint32_t> canonical(order.size());
    for (size_t k = 0; k < order.size(); ++k) {
        bool same = k > 0 && mesh.positions[order[k]] == mesh.positions[order[k - 1]];
        canonical[order[k]] = same ? canonical[order[k - 1]] : order[k];
    }
    return canonical;
}

}  // namespace

MeshTopology analyzeMesh(const Mesh &mesh) {
    MeshTopology t;
    std::vector<uint32_t> weld = weldedIndices(mesh);
    // Every directed edge as (undirected key, direction); sorting groups the uses of an edge
    struct EdgeUse {
        uint64_t key;
        int direction;  // +1 as (lo -> hi), -1 as (hi -> lo)
        bool operator<(const EdgeUse &o) const { return key < o.key; }
    };
    std::vector<EdgeUse> edges;
    edges.reserve(mesh.triangles.size() * 3);
    for (const auto &tri : mesh.triangles) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            ++t.degenerateTriangles;
            continue;
        }
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]],
                   &c = mesh.positions[tri[2]];
        if (lengthSquared(cross(b - a, c - a)) == 0) ++t.degenerateTriangles;
        for (int e = 0; e < 3; ++e) {
            uint32_t u = weld[tri[e]], v = weld[tri[(e + 1) % 3]];
            if (u == v) continue;  // a corner repeated by position: no edge
            edges.push_back({(uint64_t(std::min(u, v)) << 32) | std::max(u, v), u < v ? 1 : -1});
        }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        int balance = 0;
        while (j < edges.size() && edges[j].key == edges[i].key) balance += edges[j++].direction;
        size_t count = j - i;
        if (count == 1)
            ++t.boundaryEdges;
        else if (count > 2)
            ++t.nonManifoldEdges;
        else if (balance != 0)
            ++t.misorientedEdges;
        i = j;
    }
    return t;
}

void validateMesh(const Mesh &mesh) {
    size_t n = mesh.positions.size();
    for (size_t i = 0; i < n; ++i)
        if (!mesh.positions[i].isFinite())
            throw SceneError(mesh.loc, "mesh '" + mesh.name + "': position " + std::to_string(i) +
                                           " is not finite");
    if (!mesh.normals.empty() && mesh.normals.size() != n)
        throw SceneError(mesh.loc, "mesh '" + mesh.name +
                                       "': " + std::to_string(mesh.normals.size()) +
                                       " normals for " + std::to_string(n) + " positions");
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        if (!mesh.normals[i].isFinite())
            throw SceneError(mesh.loc, "mesh '" + mesh.name + "': normal " + std::to_string(i) +
                                           " is not finite");
    // Per-vertex attributes: one per position, every component finite
    auto checkAttribute = [&](const auto &values, const char *what) {
        if (!values.empty() && values.size() != n)
            throw SceneError(mesh.loc, "mesh '" + mesh.name +
                                           "': " + std::to_string(values.size()) + " " + what +
                                           "s for " + std::to_string(n) + " positions");
        for (size_t i = 0; i < values.size(); ++i)
            for (float c : values[i])
                if (!std::isfinite(c))
                    throw SceneError(mesh.loc, "mesh '" + mesh.name + "': " + what + " " +
                                                   std::to_string(i) + " is not finite");
    };
    checkAttribute(mesh.uvs, "texture coordinate");
    checkAttribute(mesh.uvs1, "second texture coordinate");
    checkAttribute(mesh.tangents, "tangent");
    checkAttribute(mesh.colors, "vertex colour");
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t v : mesh.triangles[i])
            if (v >= n)
                throw SceneError(mesh.loc, "mesh '" + mesh.name + "': triangle " +
                                               std::to_string(i) + " uses vertex " +
                                               std::to_string(v) + " of " + std::to_string(n));
}

std::array<double, 4> textureMean(const Texture &t) {
    std::array<double, 4> sum{0, 0, 0, 0};
    size_t texels = t.rgba.size() / 4;
    if (texels == 0) return {1, 1, 1, 1};
    for (size_t i = 0; i < texels; ++i)
        for (size_t c = 0; c < 4; ++c) sum[c] += t.rgba[i * 4 + c];
    for (double &s : sum) s /= static_cast<double>(texels);
    return sum;
}

}  // namespace rt::ir
