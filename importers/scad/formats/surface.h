// SPDX-License-Identifier: MIT
// surface(): height maps from DAT text files and PNG images, as OpenSCAD 2021.01's surface.cc
// reads them, and the closed mesh it builds of one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/ir/mesh.h"

namespace rt::scad::surface {

/// At most this many height values (lines x columns), enough for a 1024 x 1024 image:
/// OpenSCAD's mesh has four triangles a cell, so this bounds a surface at about 4.4 million
/// triangles (and a few hundred MB while it is built). More is a located error.
constexpr size_t kMaxCells = 1'100'000;

/// Largest height-map file read (a DAT file of kMaxCells numbers with comments, or a PNG).
constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;

/// Heights by row (y) and column (x); cells a ragged DAT file leaves out are 0.
struct HeightMap {
    int lines = 0, columns = 0;
    std::vector<double> values;  ///< lines * columns, row-major
    double bottom = 0;           ///< min(0, smallest given height - 1)
    double at(int line, int column) const {
        return values[static_cast<size_t>(line) * columns + column];
    }
};

using WarnFn = std::function<void(const std::string &)>;

enum class ReadResult {
    Ok,        ///< `out` holds the map (possibly empty, after a warning)
    TooLarge,  ///< more than kMaxCells values
};

/// Reads a PNG (by its signature) or a DAT file. Problems OpenSCAD warns about are warnings
/// and leave `out` empty or cut short as OpenSCAD's is (a missing file among them). Throws
/// InputFileError for what is not a regular file or is larger than kMaxFileBytes.
ReadResult readHeightMap(const std::string &path, bool invert, HeightMap &out, const WarnFn &warn);

/// OpenSCAD's closed surface mesh of the map (empty when it has fewer than 2 lines or
/// columns): per cell four triangles to its centre, walls down to `bottom`, a bottom face.
ir::Mesh surfaceMesh(const HeightMap &map, bool center);

}  // namespace rt::scad::surface
