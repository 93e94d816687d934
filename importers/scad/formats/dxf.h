// SPDX-License-Identifier: MIT
// DXF reading as OpenSCAD 2021.01's DxfData does it (dxfdata.cc): the entities it knows (LINE,
// LWPOLYLINE, CIRCLE, ARC, ELLIPSE, INSERT of BLOCKs, DIMENSION), points snapped to a
// 1/1024 grid, segments joined into open and closed paths, and the polygon outlines
// import() makes of them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/ir/node.h"
#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad::dxf {

/// OpenSCAD's GRID_COARSE: segment ends closer than this are joined.
constexpr double kGridCoarse = 1.0 / 1024;

/// A DIMENSION entity (group codes 10..16/20..26, 50, 40, 70, 1).
struct Dim {
    int type = 0;
    double coords[7][2] = {};
    double angle = 0;
    double length = 0;
    std::string name;
};

/// A chain of joined segments; a closed one repeats its first point at the end.
struct Path {
    std::vector<int> indices;  ///< into Data::points
    bool closed = false;
};

struct Data {
    std::vector<Vec2> points;
    std::vector<Path> paths;
    std::vector<Dim> dims;
};

struct ReadOptions {
    std::string layer;  ///< empty: every layer
    double originX = 0, originY = 0, scale = 1;
    ir::Fragments fragments;  ///< for CIRCLE, ARC and ELLIPSE
};

using WarnFn = std::function<void(const std::string &)>;

/// Largest DXF file read (the caller reads it through readInputFile).
constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;

/// Parses a DXF file's `bytes` into `out`; `shownName` names it in warnings. Bad group codes or
/// values warn as OpenSCAD does and stop or skip.
void read(const std::string &bytes, const std::string &shownName, const ReadOptions &opts,
          Data &out, const WarnFn &warn);

/// DxfData::toPolygon2d: every path as an outline, open ones closed, points in reverse order.
/// The outlines are meant to be filled by the even-odd rule (OpenSCAD sanitizes them).
std::vector<Outline> outlines(const Data &d);

/// dxf_dim(): the value of the first dimension called `name` (any when empty); false with
/// `problem` set ("unsupported type" or "not found") otherwise.
bool dimension(const Data &d, const std::string &name, double &value, bool &unsupportedType);

/// A number as boost::lexical_cast<double> reads it (as OpenSCAD's DXF and DAT readers do):
/// the whole text, no hexadecimal; false otherwise.
bool parseNumber(const std::string &text, double &out);

/// dxf_cross(): the crossing of the lines through the first two two-point paths.
bool cross(const Data &d, double &x, double &y);

}  // namespace rt::scad::dxf
