// SPDX-License-Identifier: MIT
// surface() height maps (see surface.h), written from the behaviour of OpenSCAD 2021.01's
// surface.cc and checked against the openscad binary.
#include "importers/scad/formats/surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "core/image/png_io.h"
#include "core/system/input_file.h"
#include "importers/scad/formats/dxf.h"

namespace rt::scad::surface {

namespace {

std::string trim(const std::string &s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

/// Heights as OpenSCAD keeps them: by (line, column), the extent from the largest keys.
class Cells {
  public:
    bool add(int line, int column, double v) {
        cells_.insert_or_assign({line, column}, v);
        lines_ = std::max(lines_, line + 1);
        columns_ = std::max(columns_, column + 1);
        return static_cast<size_t>(lines_) * static_cast<size_t>(columns_) <= kMaxCells;
    }
    void into(HeightMap &out) const {
        out.lines = lines_;
        out.columns = columns_;
        out.values.assign(static_cast<size_t>(lines_) * columns_, 0.0);
        out.bottom = 0;
        for (const auto &[key, v] : cells_) {
            out.values[static_cast<size_t>(key.first) * columns_ + key.second] = v;
            out.bottom = std::min(out.bottom, v - 1);
        }
    }

  private:
    std::map<std::pair<int, int>, double> cells_;
    int lines_ = 0, columns_ = 0;
};

ReadResult readDat(const std::string &path, const std::string &bytes, Cells &cells,
                   const WarnFn &warn) {
    std::istringstream stream(bytes);
    int lines = 0;
    while (!stream.eof()) {
        std::string line;
        while (!stream.eof() && (line.empty() || line[0] == '#')) {
            std::getline(stream, line);
            line = trim(line);
        }
        if (line.empty() && stream.eof()) break;
        int column = 0;
        size_t pos = 0;
        while (pos < line.size()) {
            size_t start = line.find_first_not_of(" \t", pos);
            if (start == std::string::npos) break;
            size_t end = line.find_first_of(" \t", start);
            if (end == std::string::npos) end = line.size();
            std::string token = line.substr(start, end - start);
            pos = end;
            double v;
            if (!dxf::parseNumber(token, v)) {
                // OpenSCAD stops at the first bad value (silently on the last line)
                if (!stream.eof())
                    warn("Illegal value in '" + path +
                         "': bad lexical cast: source type value could not be interpreted as "
                         "target");
                return ReadResult::Ok;
            }
            if (!cells.add(lines, column++, v)) return ReadResult::TooLarge;
        }
        ++lines;
    }
    return ReadResult::Ok;
}

ReadResult readPng(const std::string &path, bool invert, Cells &cells, const WarnFn &warn) {
    std::vector<float> pixels;
    uint64_t width = 0, height = 0;
    int channels = 0, bits = 8;
    try {
        PngReader png(path);
        width = png.width();
        height = png.height();
        if (width * height > kMaxCells) return ReadResult::TooLarge;
        channels = png.channels();
        bits = png.fileBitDepth() == 16 ? 16 : 8;
        pixels = png.readPixels();
    } catch (const std::runtime_error &) {
        warn("Can't read PNG image '" + path + "'");
        return ReadResult::Ok;
    }
    // 8-bit RGB as lodepng decodes it (16-bit samples keep their high byte)
    auto sample = [&](size_t i) {
        double v = pixels[i];
        return bits == 16 ? std::floor(std::round(v * 65535) / 256) : std::round(v * 255);
    };
    for (uint64_t y = 0; y < height; ++y)
        for (uint64_t x = 0; x < width; ++x) {
            size_t i = static_cast<size_t>((y * width + x) * channels);
            double r = sample(i), g, b;
            if (channels >= 3) {
                g = sample(i + 1);
                b = sample(i + 2);
            } else {
                g = b = r;
            }
            double pixel = 0.2126 * r + 0.7152 * g + 0.0722 * b;
            // 2021.01 inverts as 1 - pixel, not 255 - pixel
            double z = 100.0 / 255 * (invert ? 1 - pixel : pixel);
            cells.add(static_cast<int>(height - 1 - y), static_cast<int>(x), z);
        }
    return ReadResult::Ok;
}

}  // namespace

ReadResult readHeightMap(const std::string &path, bool invert, HeightMap &out, const WarnFn &warn) {
    out = HeightMap();
    // Through the input reader: a FIFO, device or /proc file is refused before it is opened
    // for reading (it would block, or never end), as is a file past the cap
    std::string bytes;
    try {
        bytes = readInputFile(path, kMaxFileBytes);
    } catch (const InputFileError &e) {
        if (e.reason() != InputFileError::Reason::Missing &&
            e.reason() != InputFileError::Reason::Unreadable)
            throw;
        warn("The file '" + path + "' couldn't be opened.");
        return ReadResult::Ok;
    }
    Cells cells;
    static const char kPngSignature[] = "\x89PNG\r\n\x1a\n";
    ReadResult r = bytes.compare(0, 8, kPngSignature, 8) == 0 ? readPng(path, invert, cells, warn)
                                                              : readDat(path, bytes, cells, warn);
    if (r == ReadResult::Ok) cells.into(out);
    return r;
}

ir::Mesh surfaceMesh(const HeightMap &map, bool center) {
    ir::Mesh mesh;
    const int lines = map.lines, columns = map.columns;
    if (lines < 2 || columns < 2) return mesh;
    const double ox = center ? -(columns - 1) / 2.0 : 0;
    const double oy = center ? -(lines - 1) / 2.0 : 0;
    const double low = map.bottom;
    auto vertex = [&](double x, double y, double z) {
        mesh.positions.push_back({ox + x, oy + y, z});
        return static_cast<uint32_t>(mesh.positions.size() - 1);
    };
    // Polygons in OpenSCAD's corner order (counter-clockwise seen from outside)
    auto polygon = [&](std::initializer_list<Vec3> corners) {
        std::vector<uint32_t> ix;
        for (const Vec3 &c : corners) ix.push_back(vertex(c.x, c.y, c.z));
        for (size_t k = 1; k + 1 < ix.size(); ++k)
            mesh.triangles.push_back({ix[0], ix[k], ix[k + 1]});
    };
    for (int i = 1; i < lines; ++i)
        for (int j = 1; j < columns; ++j) {
            double v1 = map.at(i - 1, j - 1), v2 = map.at(i - 1, j);
            double v3 = map.at(i, j - 1), v4 = map.at(i, j);
            double vx = (v1 + v2 + v3 + v4) / 4;
            Vec3 mid{j - 0.5, i - 0.5, vx};
            polygon({{double(j - 1), double(i - 1), v1}, {double(j), double(i - 1), v2}, mid});
            polygon({{double(j), double(i - 1), v2}, {double(j), double(i), v4}, mid});
            polygon({{double(j), double(i), v4}, {double(j - 1), double(i), v3}, mid});
            polygon({{double(j - 1), double(i), v3}, {double(j - 1), double(i - 1), v1}, mid});
        }
    const double right = columns - 1, top = lines - 1;
    for (int i = 1; i < lines; ++i) {
        polygon({{0, double(i - 1), low},
                 {0, double(i - 1), map.at(i - 1, 0)},
                 {0, double(i), map.at(i, 0)},
                 {0, double(i), low}});
        polygon({{right, double(i), low},
                 {right, double(i), map.at(i, columns - 1)},
                 {right, double(i - 1), map.at(i - 1, columns - 1)},
                 {right, double(i - 1), low}});
    }
    for (int i = 1; i < columns; ++i) {
        polygon({{double(i), 0, low},
                 {double(i), 0, map.at(0, i)},
                 {double(i - 1), 0, map.at(0, i - 1)},
                 {double(i - 1), 0, low}});
        polygon({{double(i - 1), top, low},
                 {double(i - 1), top, map.at(lines - 1, i - 1)},
                 {double(i), top, map.at(lines - 1, i)},
                 {double(i), top, low}});
    }
    // The bottom: OpenSCAD's one polygon round the border, here fanned from its centre
    // (the same flat rectangle), clockwise seen from above
    std::vector<uint32_t> ring;
    for (int i = 0; i < lines - 1; ++i) ring.push_back(vertex(0, i, low));
    for (int i = 0; i < columns - 1; ++i) ring.push_back(vertex(i, top, low));
    for (int i = lines - 1; i > 0; --i) ring.push_back(vertex(right, i, low));
    for (int i = columns - 1; i > 0; --i) ring.push_back(vertex(i, 0, low));
    uint32_t c = vertex(right / 2, top / 2, low);
    for (size_t k = 0; k < ring.size(); ++k)
        mesh.triangles.push_back({c, ring[k], ring[(k + 1) % ring.size()]});
    return mesh;
}

}  // namespace rt::scad::surface
