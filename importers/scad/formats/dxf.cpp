// SPDX-License-Identifier: MIT
// DXF reading with OpenSCAD 2021.01's DxfData semantics (see dxf.h). Written from the
// behaviour of dxfdata.cc and grid.h, checked against the openscad binary.
#include "importers/scad/formats/dxf.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "core/math/degree_trig.h"
#include "core/meshing/facets.h"
#include "importers/scad/lang/value.h"

namespace rt::scad::dxf {

namespace {

/// At most this many segments come from one CIRCLE, ARC or ELLIPSE (OpenSCAD would try to
/// make any number); more is a warning and the entity is left out.
constexpr double kMaxEntitySegments = 1e6;
/// At most this many segments in a file (entities and blocks), for the same reason.
constexpr size_t kMaxSegments = 500'000;

/// OpenSCAD's Grid2d with a list of segment indices per grid point: a point snaps to the
/// grid, or to an existing grid point next to it (the nearest, scanned as OpenSCAD does).
class Grid {
  public:
    std::vector<int> &align(double &x, double &y) {
        int64_t ix = index(x), iy = index(y);
        if (db_.find(Key{ix, iy}) == db_.end()) {
            int dist = 10;
            // ix/iy move as closer points are found, and the scan's bounds and later
            // distances follow the moved point, as in OpenSCAD
            for (int64_t jx = ix - 1; jx <= ix + 1; ++jx)
                for (int64_t jy = iy - 1; jy <= iy + 1; ++jy) {
                    if (db_.find(Key{jx, jy}) == db_.end()) continue;
                    int d = static_cast<int>(std::llabs(ix - jx) + std::llabs(iy - jy));
                    if (d < dist) {
                        dist = d;
                        ix = jx;
                        iy = jy;
                    }
                }
        }
        x = static_cast<double>(ix) * kGridCoarse;
        y = static_cast<double>(iy) * kGridCoarse;
        return db_[Key{ix, iy}];
    }
    std::vector<int> &data(double x, double y) { return align(x, y); }
    bool eq(double x1, double y1, double x2, double y2) {
        align(x1, y1);
        align(x2, y2);
        return std::fabs(x1 - x2) < kGridCoarse && std::fabs(y1 - y2) < kGridCoarse;
    }

  private:
    /// The grid index of a coordinate. One beyond 2^62 grid steps (or NaN) is clamped: its
    /// conversion would be undefined, and such a point cannot meet another anyway.
    static int64_t index(double v) {
        constexpr double kMaxIndex = 4611686018427387904.0;  // 2^62
        double g = std::round(v / kGridCoarse);
        if (std::isnan(g)) return 0;
        return static_cast<int64_t>(std::clamp(g, -kMaxIndex, kMaxIndex));
    }
    struct Key {
        int64_t x, y;
        bool operator==(const Key &o) const { return x == o.x && y == o.y; }
    };
    struct KeyHash {
        size_t operator()(const Key &k) const {
            return std::hash<int64_t>()(k.x) * 1000003u ^ std::hash<int64_t>()(k.y);
        }
    };
    std::unordered_map<Key, std::vector<int>, KeyHash> db_;
};

struct Line {
    int idx[2] = {-1, -1};
    bool disabled = false;
};

std::string trim(const std::string &s) {
    size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b]))) ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1]))) --e;
    return s.substr(b, e - b);
}

/// A value that is not a number in full (boost::lexical_cast fails on it).
struct BadValue {};
/// An entity without the coordinates it needs (std::vector::at in OpenSCAD).
struct MissingValue {};

bool parseInt(const std::string &s, int &out) {
    if (s.empty()) return false;
    errno = 0;
    char *end = nullptr;
    long v = std::strtol(s.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || v < INT32_MIN || v > INT32_MAX) return false;
    out = static_cast<int>(v);
    return true;
}

double toDouble(const std::string &s) {
    double v;
    if (!parseNumber(s, v)) throw BadValue{};
    return v;
}

int toInt(const std::string &s) {
    int v;
    if (!parseInt(s, v)) throw BadValue{};
    return v;
}

double at(const std::vector<double> &v, size_t i) {
    if (i >= v.size()) throw MissingValue{};
    return v[i];
}

class Reader {
  public:
    Reader(const ReadOptions &opts, Data &out, const std::string &shownName, const WarnFn &warn)
        : opts_(opts), out_(out), shown_(shownName), warn_(warn) {}

    void parse(std::istream &stream);
    void joinPaths();

  private:
    int addPoint(double x, double y) {
        out_.points.push_back({x, y});
        return static_cast<int>(out_.points.size()) - 1;
    }
    bool layerMatches() const { return opts_.layer.empty() || opts_.layer == layer_; }
    void addLine(double x1, double y1, double x2, double y2);
    void finishEntity();
    /// Segment count of a round entity over `sweep` of `turn`, or 0 (after a warning) when
    /// there would be too many.
    int segments(double r, double sweep, double turn);

    const ReadOptions &opts_;
    Data &out_;
    const std::string &shown_;
    const WarnFn &warn_;

    Grid grid_;
    std::vector<Line> lines_;
    std::unordered_map<std::string, std::vector<Line>> blocks_;
    bool inEntities_ = false, inBlocks_ = false;
    std::string currentBlock_;

    std::string mode_, layer_, name_, iddata_;
    int dimtype_ = 0;
    double coords_[7][2] = {};
    std::vector<double> xverts_, yverts_;
    double radius_ = 0, arcStart_ = 0, arcStop_ = 0, ellipseStart_ = 0, ellipseStop_ = 0;
    std::map<std::string, int> unsupported_;
    bool tooMany_ = false;
};

void Reader::addLine(double x1, double y1, double x2, double y2) {
    if (!inEntities_ && !inBlocks_) return;
    if (inEntities_ && !layerMatches()) return;
    // Entity and block segments together (a block inserted into itself doubles each time)
    if (out_.points.size() >= 2 * kMaxSegments) {
        if (!tooMany_)
            warn_("more than " + std::to_string(kMaxSegments) + " segments in DXF file '" + shown_ +
                  "'; the rest are left out");
        tooMany_ = true;
        return;
    }
    grid_.align(x1, y1);
    grid_.align(x2, y2);
    // Block segments register the index of the next entity segment, as OpenSCAD's do
    int index = static_cast<int>(lines_.size());
    grid_.data(x1, y1).push_back(index);
    grid_.data(x2, y2).push_back(index);
    Line l;
    if (inEntities_) {
        l.idx[0] = addPoint(x1, y1);
        l.idx[1] = addPoint(x2, y2);
        lines_.push_back(l);
    }
    if (inBlocks_ && !currentBlock_.empty()) {
        l.idx[0] = addPoint(x1, y1);
        l.idx[1] = addPoint(x2, y2);
        blocks_[currentBlock_].push_back(l);
    }
}

int Reader::segments(double r, double sweep, double turn) {
    double n = meshing::openscadFragments(r, opts_.fragments);
    // n * sweep / turn in OpenSCAD's order: 13 * 2 pi / (2 pi) rounds up to 14
    double total = std::ceil(n * sweep / turn);
    if (!std::isfinite(total) || total > kMaxEntitySegments) {
        warn_(mode_ + " in DXF file '" + shown_ + "' would need " +
              (std::isfinite(total) ? formatNumber(total) : std::string("infinitely many")) +
              " segments (at most " + formatNumber(kMaxEntitySegments) + "); left out");
        return 0;
    }
    return static_cast<int>(total);
}

void Reader::finishEntity() {
    if (mode_ == "SECTION") {
        inEntities_ = iddata_ == "ENTITIES";
        inBlocks_ = iddata_ == "BLOCKS";
    } else if (mode_ == "LINE") {
        addLine(at(xverts_, 0), at(yverts_, 0), at(xverts_, 1), at(yverts_, 1));
    } else if (mode_ == "LWPOLYLINE") {
        size_t n = std::max(xverts_.size(), yverts_.size());
        for (size_t i = 1; i < n; ++i)
            addLine(at(xverts_, i - 1), at(yverts_, i - 1), at(xverts_, i % n), at(yverts_, i % n));
        if (dimtype_ & 1)  // closed
            addLine(at(xverts_, n - 1), at(yverts_, n - 1), at(xverts_, 0), at(yverts_, 0));
    } else if (mode_ == "CIRCLE") {
        int n = segments(radius_, 1, 1);
        double cx = at(xverts_, 0), cy = at(yverts_, 0);
        for (int i = 0; i < n; ++i) {
            double a1 = (360.0 * i) / n, a2 = (360.0 * (i + 1)) / n;
            addLine(cosDegrees(a1) * radius_ + cx, sinDegrees(a1) * radius_ + cy,
                    cosDegrees(a2) * radius_ + cx, sinDegrees(a2) * radius_ + cy);
        }
    } else if (mode_ == "ARC") {
        double cx = at(xverts_, 0), cy = at(yverts_, 0);
        if (!std::isfinite(arcStart_) || !std::isfinite(arcStop_)) {
            warn_("ARC with a non-finite angle in DXF file '" + shown_ + "'; left out");
        } else {
            // OpenSCAD adds whole turns one by one; far apart angles in one step
            if (arcStart_ - arcStop_ > 360.0 * 1000)
                arcStop_ += 360.0 * std::ceil((arcStart_ - arcStop_) / 360.0);
            while (arcStart_ > arcStop_) arcStop_ += 360.0;
            double sweep = arcStop_ - arcStart_;
            int n = segments(radius_, sweep, 360);
            for (int i = 0; i < n; ++i) {
                double a1 = arcStart_ + sweep * i / n, a2 = arcStart_ + sweep * (i + 1) / n;
                addLine(cosDegrees(a1) * radius_ + cx, sinDegrees(a1) * radius_ + cy,
                        cosDegrees(a2) * radius_ + cx, sinDegrees(a2) * radius_ + cy);
            }
        }
    } else if (mode_ == "ELLIPSE") {
        double cx = at(xverts_, 0), cy = at(yverts_, 0);
        // The major axis end (codes 11/21) is read like a point: origin and scale applied
        double ex = at(xverts_, 1), ey = at(yverts_, 1);
        if (!std::isfinite(ellipseStart_) || !std::isfinite(ellipseStop_)) {
            warn_("ELLIPSE with a non-finite angle in DXF file '" + shown_ + "'; left out");
        } else {
            if (ellipseStart_ - ellipseStop_ > 2 * M_PI * 1000)
                ellipseStop_ += 2 * M_PI * std::ceil((ellipseStart_ - ellipseStop_) / (2 * M_PI));
            while (ellipseStart_ > ellipseStop_) ellipseStop_ += 2 * M_PI;
            double major = std::sqrt(ex * ex + ey * ey);
            double c = std::clamp(ex / major, -1.0, 1.0);
            double rot = std::acos(c);
            if (ey < 0.0) rot = 2 * M_PI - rot;
            double minor = major * radius_;  // code 40: the axis ratio
            double sweep = ellipseStop_ - ellipseStart_;
            int n = segments(major, sweep, 2 * M_PI);
            double px = 0, py = 0;
            for (int i = 0; i <= n; ++i) {
                double a = ellipseStart_ + sweep * i / n;
                double x = std::cos(a) * major, y = std::sin(a) * minor;
                double rx = std::cos(rot) * x - std::sin(rot) * y + cx;
                double ry = std::sin(rot) * x + std::cos(rot) * y + cy;
                if (i > 0) addLine(px, py, rx, ry);
                px = rx;
                py = ry;
            }
        }
    } else if (mode_ == "INSERT") {
        // Scale in codes 41/42, rotation in 50
        std::vector<Line> block = blocks_[iddata_];
        for (const Line &l : block) {
            double a = arcStart_;
            Vec2 p1 = out_.points[l.idx[0]], p2 = out_.points[l.idx[1]];
            double lx1 = p1.x * ellipseStart_, ly1 = p1.y * ellipseStop_;
            double lx2 = p2.x * ellipseStart_, ly2 = p2.y * ellipseStop_;
            double s = opts_.scale;
            addLine((cosDegrees(a) * lx1 - sinDegrees(a) * ly1) * s + at(xverts_, 0),
                    (sinDegrees(a) * lx1 + cosDegrees(a) * ly1) * s + at(yverts_, 0),
                    (cosDegrees(a) * lx2 - sinDegrees(a) * ly2) * s + at(xverts_, 0),
                    (sinDegrees(a) * lx2 + cosDegrees(a) * ly2) * s + at(yverts_, 0));
        }
    } else if (mode_ == "DIMENSION" && layerMatches()) {
        Dim d;
        d.type = dimtype_;
        std::copy(&coords_[0][0], &coords_[0][0] + 14, &d.coords[0][0]);
        d.angle = arcStart_;
        d.length = radius_;
        d.name = name_;
        out_.dims.push_back(std::move(d));
    } else if (mode_ == "BLOCK") {
        currentBlock_ = iddata_;
    } else if (mode_ == "ENDBLK") {
        currentBlock_.clear();
    } else if (mode_ == "ENDSEC") {
    } else if (inBlocks_ || (inEntities_ && layerMatches())) {
        unsupported_[mode_]++;
    }
}

void Reader::parse(std::istream &stream) {
    std::string idText, data;
    while (!stream.eof()) {
        std::getline(stream, idText);
        idText = trim(idText);
        std::getline(stream, data);
        data = trim(data);
        int id;
        if (!parseInt(idText, id)) {
            if (!stream.eof()) warn_("Illegal ID '" + idText + "' in `" + shown_ + "'");
            break;
        }
        try {
            const double s = opts_.scale;
            if (id >= 10 && id <= 16) {
                double v = toDouble(data);
                coords_[id - 10][0] = inBlocks_ ? v
                                      : (id == 11 || id == 12 || id == 16)
                                          ? v * s
                                          : (v - opts_.originX) * s;
            }
            if (id >= 20 && id <= 26) {
                double v = toDouble(data);
                coords_[id - 20][1] = inBlocks_ ? v
                                      : (id == 21 || id == 22 || id == 26)
                                          ? v * s
                                          : (v - opts_.originY) * s;
            }
            switch (id) {
                case 0:
                    finishEntity();
                    mode_ = data;
                    layer_.clear();
                    name_.clear();
                    iddata_.clear();
                    dimtype_ = 0;
                    std::fill(&coords_[0][0], &coords_[0][0] + 14, 0.0);
                    xverts_.clear();
                    yverts_.clear();
                    radius_ = arcStart_ = arcStop_ = 0;
                    ellipseStart_ = ellipseStop_ = mode_ == "INSERT" ? 1.0 : 0.0;
                    break;
                case 1:
                    name_ = data;
                    break;
                case 2:
                    iddata_ = data;
                    break;
                case 8:
                    layer_ = data;
                    break;
                case 10:
                case 11:
                    xverts_.push_back(inBlocks_ ? toDouble(data)
                                                : (toDouble(data) - opts_.originX) * s);
                    break;
                case 20:
                case 21:
                    yverts_.push_back(inBlocks_ ? toDouble(data)
                                                : (toDouble(data) - opts_.originY) * s);
                    break;
                case 40:
                    radius_ = toDouble(data);
                    if (!inBlocks_) radius_ *= s;
                    break;
                case 41:
                    ellipseStart_ = toDouble(data);
                    break;
                case 42:
                    ellipseStop_ = toDouble(data);
                    break;
                case 50:
                    arcStart_ = toDouble(data);
                    break;
                case 51:
                    arcStop_ = toDouble(data);
                    break;
                case 70:
                    dimtype_ = toInt(data);
                    break;
                default:
                    break;
            }
        } catch (const BadValue &) {
            warn_("Illegal value '" + data + "'in `" + shown_ + "'");
        } catch (const MissingValue &) {
            // The entity stays current, as in OpenSCAD (the reset after it is skipped)
            warn_("Not enough input values for " + data + ". in '" + shown_ + "'");
        }
    }
    for (const auto &[entity, count] : unsupported_) {
        char hex[32];
        std::snprintf(hex, sizeof hex, "%x", count);
        if (opts_.layer.empty())
            warn_("Unsupported DXF Entity '" + entity + "' (" + hex + ") in \"" + shown_ + "\".");
        else
            warn_("Unsupported DXF Entity '" + entity + "' (" + hex + ") in layer '" + opts_.layer +
                  "' of " + shown_);
    }
}

void Reader::joinPaths() {
    std::map<int, int> enabled;
    for (size_t i = 0; i < lines_.size(); ++i) enabled[static_cast<int>(i)] = static_cast<int>(i);
    auto pointOf = [&](int line, int end) { return out_.points[lines_[line].idx[end]]; };
    // Follows the chain from (line, point) until no enabled segment continues it
    auto follow = [&](Path &path, int line, int point) {
        path.indices.push_back(lines_[line].idx[point]);
        while (true) {
            path.indices.push_back(lines_[line].idx[!point]);
            Vec2 ref = pointOf(line, !point);
            lines_[line].disabled = true;
            enabled.erase(line);
            bool found = false;
            for (int k : grid_.data(ref.x, ref.y)) {
                if (k < 0 || static_cast<size_t>(k) >= lines_.size() || lines_[k].disabled)
                    continue;
                for (int e = 0; e < 2 && !found; ++e) {
                    Vec2 p = pointOf(k, e);
                    if (grid_.eq(ref.x, ref.y, p.x, p.y)) {
                        line = k;
                        point = e;
                        found = true;
                    }
                }
                if (found) break;
            }
            if (!found) return;
        }
    };
    // Open paths first: from a segment end that no other enabled segment shares
    while (!enabled.empty()) {
        int startLine = -1, startPoint = 0;
        for (const auto &entry : enabled) {
            int idx = entry.second;
            for (int j = 0; j < 2 && startLine < 0; ++j) {
                Vec2 p = pointOf(idx, j);
                bool shared = false;
                for (int k : grid_.data(p.x, p.y)) {
                    if (k < 0 || static_cast<size_t>(k) >= lines_.size()) continue;
                    if (k == idx || lines_[k].disabled) continue;
                    shared = true;
                    break;
                }
                if (!shared) {
                    startLine = idx;
                    startPoint = j;
                }
            }
            if (startLine >= 0) break;
        }
        if (startLine < 0) break;
        out_.paths.emplace_back();
        follow(out_.paths.back(), startLine, startPoint);
    }
    // Then closed ones
    while (!enabled.empty()) {
        int line = enabled.begin()->second;
        out_.paths.emplace_back();
        out_.paths.back().closed = true;
        follow(out_.paths.back(), line, 0);
    }
    // fixup_path_direction: closed paths up to the first open one (open paths come first,
    // so any open path stops it) turn to one orientation
    for (Path &path : out_.paths) {
        if (!path.closed) break;
        const auto &ix = path.indices;
        size_t b = 0;
        for (size_t j = 1; j < ix.size(); ++j)
            if (out_.points[ix[j]].x < out_.points[ix[b]].x) b = j;
        size_t a = b == 0 ? ix.size() - 2 : b - 1;
        size_t c = b == ix.size() - 1 ? 1 : b + 1;
        Vec2 pb = out_.points[ix[b]];
        Vec2 da = out_.points[ix[a]] - pb, dc = out_.points[ix[c]] - pb;
        if (std::atan2(da.x, da.y) < std::atan2(dc.x, dc.y))
            std::reverse(path.indices.begin(), path.indices.end());
    }
}

}  // namespace

bool parseNumber(const std::string &s, double &out) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) ||
        s.find_first_of("xXpP") != std::string::npos)
        return false;
    char *end = nullptr;
    out = std::strtod(s.c_str(), &end);
    return *end == '\0';
}

void read(const std::string &bytes, const std::string &shownName, const ReadOptions &opts,
          Data &out, const WarnFn &warn) {
    std::istringstream stream(bytes);
    Reader r(opts, out, shownName, warn);
    r.parse(stream);
    r.joinPaths();
}

std::vector<Outline> outlines(const Data &d) {
    std::vector<Outline> result;
    for (const Path &p : d.paths) {
        Outline o;
        size_t n = p.indices.size();
        size_t end = p.closed ? n : n + 1;  // an open path is closed
        for (size_t j = 1; j < end; ++j) o.push_back(d.points[p.indices[n - j]]);
        result.push_back(std::move(o));
    }
    return result;
}

bool dimension(const Data &d, const std::string &name, double &value, bool &unsupportedType) {
    unsupportedType = false;
    for (const Dim &dim : d.dims) {
        if (!name.empty() && dim.name != name) continue;
        const auto &c = dim.coords;
        switch (dim.type & 7) {
            case 0: {  // rotated, horizontal or vertical
                double x = c[4][0] - c[3][0], y = c[4][1] - c[3][1];
                value = std::fabs(x * cosDegrees(dim.angle) + y * sinDegrees(dim.angle));
                return true;
            }
            case 1: {  // aligned
                double x = c[4][0] - c[3][0], y = c[4][1] - c[3][1];
                value = std::sqrt(x * x + y * y);
                return true;
            }
            case 2: {  // angular
                constexpr double kDeg = 180.0 / M_PI;
                double a1 = std::atan2(c[0][0] - c[5][0], c[0][1] - c[5][1]) * kDeg;
                double a2 = std::atan2(c[4][0] - c[3][0], c[4][1] - c[3][1]) * kDeg;
                value = std::fabs(a1 - a2);
                return true;
            }
            case 3:
            case 4: {  // diameter, radius
                double x = c[5][0] - c[0][0], y = c[5][1] - c[0][1];
                value = std::sqrt(x * x + y * y);
                return true;
            }
            case 6:  // ordinate
                value = (dim.type & 64) ? c[3][0] : c[3][1];
                return true;
            default:
                unsupportedType = true;
                return false;
        }
    }
    return false;
}

bool cross(const Data &d, double &x, double &y) {
    double c[4][2];
    size_t j = 0;
    for (const Path &p : d.paths) {
        if (p.indices.size() != 2) continue;
        for (int e = 0; e < 2; ++e) {
            c[j][0] = d.points[p.indices[e]].x;
            c[j][1] = d.points[p.indices[e]].y;
            ++j;
        }
        if (j == 4) {
            double x1 = c[0][0], y1 = c[0][1], x2 = c[1][0], y2 = c[1][1];
            double x3 = c[2][0], y3 = c[2][1], x4 = c[3][0], y4 = c[3][1];
            double dem = (y4 - y3) * (x2 - x1) - (x4 - x3) * (y2 - y1);
            if (dem == 0) return false;
            double ua = ((x4 - x3) * (y1 - y3) - (y4 - y3) * (x1 - x3)) / dem;
            x = x1 + ua * (x2 - x1);
            y = y1 + ua * (y2 - y1);
            return true;
        }
    }
    return false;
}

}  // namespace rt::scad::dxf
