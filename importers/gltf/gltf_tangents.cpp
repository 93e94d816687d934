// SPDX-License-Identifier: MIT
// MikkTSpace-style tangent generation (see gltf_tangents.h), written from the algorithm's
// description (Mikkelsen 2008, "Simulation of wrinkled surfaces revisited").
#include "importers/gltf/gltf_tangents.h"

#include <cmath>

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
    std::vector<Vec3> normal(n, Vec3(0, 0, 0)), tSum(n, Vec3(0, 0, 0)), bSum(n, Vec3(0, 0, 0));
    if (smooth) normal = mesh.normals;
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

    for (const auto &tri : mesh.triangles) {
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
        Vec3 t = (e1 * dv2 - e2 * dv1) / det;  // dP/du
        Vec3 b = (e2 * du1 - e1 * du2) / det;  // dP/dv'
        const Vec3 *corner[3] = {&p0, &p1, &p2};
        for (int c = 0; c < 3; ++c) {
            uint32_t v = tri[static_cast<size_t>(c)];
            double angle = cornerAngle(*corner[c], *corner[(c + 1) % 3], *corner[(c + 2) % 3]);
            const Vec3 &nv = normal[v];
            // Projected onto the vertex's tangent plane, then normalised, as MikkTSpace does
            Vec3 tp = t - nv * dot(nv, t), bp = b - nv * dot(nv, b);
            double lt = length(tp), lb = length(bp);
            if (lt > 0) tSum[v] += tp * (angle / lt);
            if (lb > 0) bSum[v] += bp * (angle / lb);
        }
    }

    mesh.tangents.assign(n, {1, 0, 0, 1});
    for (size_t v = 0; v < n; ++v) {
        const Vec3 &nv = normal[v];
        Vec3 t = tSum[v] - nv * dot(nv, tSum[v]);
        double l = length(t);
        t = l > 0 && std::isfinite(l) ? t / l : anyPerpendicular(nv);
        double w = dot(cross(nv, t), bSum[v]) < 0 ? -1 : 1;
        mesh.tangents[v] = {float(t.x), float(t.y), float(t.z), float(w)};
    }
    return true;
}

}  // namespace rt::gltf::detail
