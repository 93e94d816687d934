// SPDX-License-Identifier: MIT
// Mesh file dispatch by extension, vertex welding and the solidity checks of imported meshes.
#include "importers/mesh/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "importers/mesh/reader_support.h"

namespace rt::meshio {

ir::Mesh readMeshFile(const std::string &path, DiagnosticSink &diag) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".stl") return readStl(path, diag);
    if (ext == ".off") return readOff(path, diag);
    throw ParseError(SourceLoc(std::make_shared<const std::string>(path), 0, 0),
                     "unknown mesh file type '" + ext + "' (expected .stl or .off)");
}

size_t weldMesh(ir::Mesh &mesh) {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<std::array<float, 2>> uvs;
    detail::PositionWelder welder(positions);
    welder.reserve(mesh.positions.size());
    // Old index -> new index, assigned in order of first use
    std::vector<uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    size_t kept = 0, dropped = 0;
    for (auto &tri : mesh.triangles) {
        std::array<uint32_t, 3> t;
        for (int k = 0; k < 3; ++k) {
            uint32_t &r = remap[tri[k]];
            if (r == UINT32_MAX) {
                size_t before = positions.size();
                r = welder.add(mesh.positions[tri[k]]);
                if (positions.size() > before) {
                    if (!mesh.normals.empty()) normals.push_back(mesh.normals[tri[k]]);
                    if (!mesh.uvs.empty()) uvs.push_back(mesh.uvs[tri[k]]);
                }
            }
            t[k] = r;
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            ++dropped;
            continue;
        }
        mesh.triangles[kept++] = t;
    }
    mesh.triangles.resize(kept);
    mesh.positions = std::move(positions);
    mesh.normals = std::move(normals);
    mesh.uvs = std::move(uvs);
    return dropped;
}

double signedVolume(const ir::Mesh &mesh) {
    // Relative to the centre of the bounds, which keeps the products small
    Vec3 c = mesh.bounds().centroid();
    double sixTimes = 0;
    for (const auto &t : mesh.triangles) {
        Vec3 a = mesh.positions[t[0]] - c, b = mesh.positions[t[1]] - c,
             d = mesh.positions[t[2]] - c;
        sixTimes += dot(a, cross(b, d));
    }
    return sixTimes / 6;
}

std::string solidProblem(const ir::Mesh &mesh) {
    ir::MeshTopology t = ir::analyzeMesh(mesh);
    if (!t.closed())
        return "is not closed (" + std::to_string(t.boundaryEdges) +
               " edges belong to one triangle only, " + std::to_string(t.nonManifoldEdges) +
               " to more than two)";
    if (t.misorientedEdges > 0)
        return "has inconsistently oriented triangles (" + std::to_string(t.misorientedEdges) +
               " edges are traversed the same way by both of their triangles)";
    if (signedVolume(mesh) < 0) return "is inside out (its enclosed volume is negative)";
    return {};
}

}  // namespace rt::meshio
