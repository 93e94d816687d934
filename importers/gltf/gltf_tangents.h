// SPDX-License-Identifier: MIT
// Tangents for normal-mapped meshes whose file has none (glTF 2.0: "When tangents are not
// specified, client implementations SHOULD calculate tangents using default MikkTSpace
// algorithms").
#pragma once

#include "core/ir/mesh.h"

namespace rt::gltf::detail {

/// Fills mesh.tangents (one per position, xyz unit, w = +1 or -1) from the positions, the
/// normals (face normals where the mesh has none) and texture coordinate set `texCoord`
/// (0: uvs, 1: uvs1), in MikkTSpace's manner: per-corner tangent and bitangent from the
/// triangle's uv gradients, projected onto the vertex normal's plane, weighted by the corner
/// angle, summed per vertex group; w is the bitangent's handedness with glTF's convention (v
/// down). As MikkTSpace does, the corners at a vertex are grouped by edge-connected triangles
/// of the same uv orientation, and a vertex with several groups (a mirrored-uv seam) is split:
/// the copies (every attribute the same, appended to the mesh; the triangles renumbered) get
/// each group's own tangent and handedness. Returns false (mesh untouched) when the mesh lacks
/// that coordinate set.
bool generateTangents(ir::Mesh &mesh, int texCoord);

}  // namespace rt::gltf::detail
