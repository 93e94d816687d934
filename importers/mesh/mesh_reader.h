// SPDX-License-Identifier: MIT
// Readers of the mesh files OpenSCAD's import() reads: STL (ASCII and binary) and OFF.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "core/ir/mesh.h"

namespace rt::meshio {

/// Reads an STL file (binary or ASCII, told apart by size and content, not by the "solid"
/// prefix). Identical vertex positions are merged, so closedness can be judged. Problems are
/// ParseErrors at file:line:col (ASCII) or at the file with a byte offset (binary), and so is
/// a file whose triangles are all degenerate. A file without triangles (an empty file, a
/// solid without facets, a binary count of 0) gives an empty mesh: OpenSCAD imports it as
/// empty geometry.
ir::Mesh readStl(const std::string &path, DiagnosticSink &diag);

/// Reads an OFF file (polygons are triangulated). Problems are ParseErrors at file:line:col.
ir::Mesh readOff(const std::string &path, DiagnosticSink &diag);

/// Dispatches on the extension (.stl, .off, case-insensitive).
ir::Mesh readMeshFile(const std::string &path, DiagnosticSink &diag);

/// Merges vertices at identical positions (exact comparison, -0 equal to +0), drops positions
/// no triangle uses and triangles left with a repeated corner; normals and texture coordinates
/// of the first merged vertex are kept. Returns the number of triangles dropped.
size_t weldMesh(ir::Mesh &mesh);

/// Volume enclosed by the triangles (divergence theorem), positive when they are
/// counter-clockwise seen from outside. Only meaningful for closed meshes.
double signedVolume(const ir::Mesh &mesh);

/// Why the mesh does not bound a solid with outward-facing triangles: "is not closed (...)",
/// "has inconsistently oriented triangles (...)" or "is inside out (...)"; empty when it does.
std::string solidProblem(const ir::Mesh &mesh);

}  // namespace rt::meshio
