// SPDX-License-Identifier: MIT
// SVG reading as OpenSCAD 2021.01's libsvg and import_svg.cc do it: the <svg> page (width,
// height, viewBox, preserveAspectRatio) in millimetres at a dpi, groups with transforms, and
// the shapes path, rect, circle, ellipse, line, polyline and polygon, curves and arcs cut into
// OpenSCAD's fixed numbers of segments, open paths and lines widened by their stroke.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "importers/scad/geometry2d/shape2d.h"

namespace rt::scad::svg {

/// import()'s default dpi (ImportNode::SVG_DEFAULT_DPI).
constexpr double kDefaultDpi = 72;
/// OpenSCAD's smallest dpi; a smaller one is a warning and the default.
constexpr double kMinDpi = 0.001;
/// At most this many points in one file (a path's commands can ask for any number).
constexpr size_t kMaxPoints = 10'000'000;

struct Options {
    double dpi = kDefaultDpi;
    bool center = false;
};

/// Every shape's outlines, in millimetres with y up, placed as import_svg places them. Each
/// shape's outlines are filled even-odd; OpenSCAD unites the shapes.
struct Drawing {
    std::vector<std::vector<Outline>> shapes;
    /// Elements left out (text, use, image...), counted by name, for a warning.
    std::vector<std::pair<std::string, int>> skipped;
};

/// Largest SVG file read (the caller reads it through readInputFile).
constexpr uint64_t kMaxFileBytes = uint64_t{256} << 20;

/// Parses the SVG file `path`, whose content is `bytes`; false with OpenSCAD's error text in
/// `error` ("Error parsing file '...'") when it is not XML.
bool read(const std::string &bytes, const std::string &path, const Options &opts, Drawing &out,
          std::string &error);

}  // namespace rt::scad::svg
