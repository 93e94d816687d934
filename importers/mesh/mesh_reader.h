// SPDX-License-Identifier: MIT
// Readers of the mesh files OpenSCAD's import() reads: STL (ASCII and binary) and OFF.
#pragma once

#include <string>

#include "core/ir/diagnostics.h"
#include "core/ir/mesh.h"

namespace rt::meshio {

/// Reads an STL file (binary or ASCII, told apart by size and content, not by the "solid"
/// prefix). Identical vertex positions are merged, so closedness can be judged. Problems are
/// ParseErrors at file:line:col (ASCII) or at the file with a byte offset (binary).
ir::Mesh readStl(const std::string &path, DiagnosticSink &diag);

/// Reads an OFF file (polygons are triangulated). Problems are ParseErrors at file:line:col.
ir::Mesh readOff(const std::string &path, DiagnosticSink &diag);

/// Dispatches on the extension (.stl, .off, case-insensitive).
ir::Mesh readMeshFile(const std::string &path, DiagnosticSink &diag);

/// Triangulates a planar (or nearly planar) simple polygon given by vertex indices into
/// `positions`, keeping its orientation; ear clipping in the plane of its Newell normal.
/// Returns false (and leaves `out` unchanged) for degenerate polygons.
bool triangulatePolygon(const std::vector<Vec3> &positions, const std::vector<uint32_t> &polygon,
                        std::vector<std::array<uint32_t, 3>> &out);

}  // namespace rt::meshio
