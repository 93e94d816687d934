// SPDX-License-Identifier: MIT
// Mesh bounds, topology and validation.
#include "core/ir/mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/ir/diagnostics.h"

namespace rt::ir {

Bounds3 Mesh::bounds() const {
    Bounds3 b;
    for (const Vec3 &p : positions) b = unionBounds(b, p);
    return b;
}

MeshTopology analyzeMesh(const Mesh &mesh) {
    MeshTopology t;
    // For each undirected edge: how often it is used, and the balance of its directions
    struct EdgeUse {
        int count = 0;
        int forward = 0;  // uses as (lo -> hi)
    };
    std::unordered_map<uint64_t, EdgeUse> edges;
    edges.reserve(mesh.triangles.size() * 3 / 2 + 1);
    for (const auto &tri : mesh.triangles) {
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            ++t.degenerateTriangles;
            continue;
        }
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        if (lengthSquared(cross(b - a, c - a)) == 0) ++t.degenerateTriangles;
        for (int e = 0; e < 3; ++e) {
            uint32_t u = tri[e], v = tri[(e + 1) % 3];
            uint64_t key = (uint64_t(std::min(u, v)) << 32) | std::max(u, v);
            EdgeUse &use = edges[key];
            ++use.count;
            use.forward += u < v ? 1 : -1;
        }
    }
    for (const auto &[key, use] : edges) {
        if (use.count == 1)
            ++t.boundaryEdges;
        else if (use.count > 2)
            ++t.nonManifoldEdges;
        else if (use.forward != 0)
            ++t.misorientedEdges;
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
        throw SceneError(mesh.loc, "mesh '" + mesh.name + "': " + std::to_string(mesh.normals.size()) +
                                       " normals for " + std::to_string(n) + " positions");
    for (size_t i = 0; i < mesh.normals.size(); ++i)
        if (!mesh.normals[i].isFinite())
            throw SceneError(mesh.loc, "mesh '" + mesh.name + "': normal " + std::to_string(i) +
                                           " is not finite");
    if (!mesh.uvs.empty() && mesh.uvs.size() != n)
        throw SceneError(mesh.loc, "mesh '" + mesh.name + "': " + std::to_string(mesh.uvs.size()) +
                                       " texture coordinates for " + std::to_string(n) + " positions");
    for (size_t i = 0; i < mesh.uvs.size(); ++i)
        if (!std::isfinite(mesh.uvs[i][0]) || !std::isfinite(mesh.uvs[i][1]))
            throw SceneError(mesh.loc, "mesh '" + mesh.name + "': texture coordinate " +
                                           std::to_string(i) + " is not finite");
    for (size_t i = 0; i < mesh.triangles.size(); ++i)
        for (uint32_t v : mesh.triangles[i])
            if (v >= n)
                throw SceneError(mesh.loc, "mesh '" + mesh.name + "': triangle " + std::to_string(i) +
                                               " uses vertex " + std::to_string(v) + " of " +
                                               std::to_string(n));
}

}  // namespace rt::ir
