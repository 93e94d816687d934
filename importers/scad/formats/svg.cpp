// SPDX-License-Identifier: MIT
// SVG reading with OpenSCAD 2021.01's libsvg semantics (see svg.h), written from its
// behaviour and checked against the openscad binary. XML through libxml2, as libsvg does;
// stroke widening through Clipper's ClipperOffset at libsvg's fixed scale of 10000.
#include "importers/scad/formats/svg.h"

#include "importers/scad/geometry2d/clipper2d.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace rt::scad::svg {

namespace {

/// Segments of every Bezier curve, and points of every circle and ellipse (libsvg's fn).
constexpr int kCurveSegments = 20;
constexpr int kEllipsePoints = 40;
/// libsvg's integer scale for Clipper's stroke offset.
constexpr double kStrokeScale = 10000;
/// A path whose ends are farther apart than this is open, and is drawn as its stroke.
constexpr double kOpenPathDistance = 0.1;
constexpr double kInchToMm = 25.4;

struct TooManyPoints {};
/// A stroked line whose coordinates or width, scaled for Clipper, leave its integer range.
struct StrokeOutOfRange {};

/// Clipper's range for exact arithmetic (hiRange, 2^62 - 1).
constexpr double kClipperRange = 4611686018427387903.0;

using Path = std::vector<Vec2>;
using PathList = std::vector<Path>;

/// A 2D affine map as SVG writes it: matrix(a b c d e f).
struct Matrix {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    Vec2 apply(Vec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
    Matrix operator*(const Matrix &o) const {
        return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
};

/// boost::spirit's real parser over the whole text (0 when it is not a number).
double parseDouble(const std::string &s) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0])) ||
        s.find_first_of("xXpP") != std::string::npos)
        return 0;
    char *end = nullptr;
    double v = std::strtod(s.c_str(), &end);
    return *end == '\0' ? v : 0;
}

/// boost::char_separator: `dropped` characters split, `kept` ones split and are tokens.
std::vector<std::string> tokenize(const std::string &s, const std::string &dropped,
                                  const std::string &kept) {
    std::vector<std::string> out;
    std::string cur;
    for (char ch : s) {
        if (dropped.find(ch) != std::string::npos) {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
        } else if (kept.find(ch) != std::string::npos) {
            if (!cur.empty()) out.push_back(cur);
            cur.clear();
            out.push_back(std::string(1, ch));
        } else {
            cur += ch;
        }
    }
    if (!cur.empty()) out.push_back(cur);
    return out;
}

std::string skipSpace(const std::string &s, size_t &i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return {};
}

/// A number at s[i] as qi::double_ reads it; false when there is none.
bool readNumber(const std::string &s, size_t &i, double &out) {
    if (i >= s.size()) return false;
    const char *start = s.c_str() + i;
    if (*start == 'x' || *start == 'X' || std::isspace(static_cast<unsigned char>(*start)))
        return false;
    char *end = nullptr;
    out = std::strtod(start, &end);
    if (end == start) return false;
    // strtod also reads hexadecimal; qi::double_ stops at the 'x' of "0x"
    const char *stop = end;
    for (const char *c = start; c < stop; ++c)
        if (*c == 'x' || *c == 'X') {
            std::string head(start, c);
            out = std::strtod(head.c_str(), nullptr);
            end = const_cast<char *>(c);
            break;
        }
    i += static_cast<size_t>(end - start);
    return true;
}

enum class Unit { Undefined, None, Em, Ex, Px, In, Cm, Mm, Pt, Pc, Percent };
struct Length {
    double number = 0;
    Unit unit = Unit::Undefined;
};

Length parseLength(const std::string &s) {
    size_t i = 0;
    skipSpace(s, i);
    double v;
    if (!readNumber(s, i, v)) return {};
    skipSpace(s, i);
    static const std::array<std::pair<const char *, Unit>, 9> kUnits{{{"em", Unit::Em},
                                                                      {"ex", Unit::Ex},
                                                                      {"px", Unit::Px},
                                                                      {"in", Unit::In},
                                                                      {"cm", Unit::Cm},
                                                                      {"mm", Unit::Mm},
                                                                      {"pt", Unit::Pt},
                                                                      {"pc", Unit::Pc},
                                                                      {"%", Unit::Percent}}};
    Unit unit = Unit::None;
    for (const auto &[name, u] : kUnits)
        if (s.compare(i, std::string(name).size(), name) == 0) {
            unit = u;
            i += std::string(name).size();
            break;
        }
    skipSpace(s, i);
    if (i != s.size()) return {};
    return {v, unit};
}

struct ViewBox {
    double x = 0, y = 0, width = 0, height = 0;
    bool valid = false;
};

ViewBox parseViewBox(const std::string &s) {
    size_t i = 0;
    double v[4];
    for (int k = 0; k < 4; ++k) {
        skipSpace(s, i);
        if (k > 0 && i < s.size() && s[i] == ',') {
            ++i;
            skipSpace(s, i);
        }
        if (!readNumber(s, i, v[k])) return {};
    }
    skipSpace(s, i);
    if (i != s.size() || !(v[2] >= 0) || !(v[3] >= 0)) return {};
    return {v[0], v[1], v[2], v[3], true};
}

enum class Align { None, Min, Mid, Max };
struct Alignment {
    Align x = Align::Mid, y = Align::Mid;
    bool meet = true;
};

Alignment parseAlignment(const std::string &s) {
    std::vector<std::string> words = tokenize(s, " \t\r\n", "");
    Alignment r;
    size_t idx = 0;
    if (!words.empty() && words[0] == "defer") ++idx;
    if (idx >= words.size()) return r;
    const std::string &w = words[idx];
    if (w == "none") {
        r.x = r.y = Align::None;
    } else if (w.size() == 8 && w[0] == 'x' && w[4] == 'Y') {
        auto part = [](const std::string &t) {
            return t == "Min"   ? Align::Min
                   : t == "Mid" ? Align::Mid
                   : t == "Max" ? Align::Max
                                : Align::None;
        };
        Align ax = part(w.substr(1, 3)), ay = part(w.substr(5, 3));
        if (ax == Align::None || ay == Align::None) return Alignment();
        r.x = ax;
        r.y = ay;
    } else {
        return Alignment();
    }
    ++idx;
    if (idx < words.size()) {
        if (words[idx] != "meet" && words[idx] != "slice") return Alignment();
        r.meet = words[idx] == "meet";
        ++idx;
    }
    if (idx != words.size()) return Alignment();
    return r;
}

/// One transform attribute as a matrix (its operations applied right to left).
Matrix parseTransform(const std::string &text) {
    std::string t = text;
    auto replaceAll = [&](const std::string &from, const std::string &to) {
        for (size_t p = t.find(from); p != std::string::npos; p = t.find(from, p + to.size()))
            t.replace(p, from.size(), to);
    };
    replaceAll("matrix", "m");
    replaceAll("translate", "t");
    replaceAll("scale", "s");
    replaceAll("rotate", "r");
    replaceAll("skewX", "x");
    replaceAll("skewY", "y");
    const std::string commands = "mtsrxy";
    Matrix result;
    char op = 0;
    std::vector<double> args;
    auto finish = [&] {
        if (!op) return;
        Matrix m;
        auto arg = [&](size_t i, double dflt) { return i < args.size() ? args[i] : dflt; };
        switch (op) {
            case 'm':
                if (args.size() == 6) m = {args[0], args[1], args[2], args[3], args[4], args[5]};
                break;
            case 't':
                m.e = arg(0, 0);
                m.f = arg(1, 0);
                break;
            case 's':
                m.a = arg(0, 1);
                m.d = arg(1, m.a);
                break;
            case 'r': {
                double a = arg(0, 0) * M_PI / 180;
                Matrix rot{std::cos(a), std::sin(a), -std::sin(a), std::cos(a), 0, 0};
                if (args.size() == 3) {
                    Matrix to{1, 0, 0, 1, args[1], args[2]}, back{1, 0, 0, 1, -args[1], -args[2]};
                    m = to * rot * back;
                } else {
                    m = rot;
                }
                break;
            }
            case 'x':
                m.c = std::tan(arg(0, 0) * M_PI / 180);
                break;
            case 'y':
                m.b = std::tan(arg(0, 0) * M_PI / 180);
                break;
        }
        result = result * m;
        args.clear();
    };
    for (const std::string &v : tokenize(t, " ,()", commands)) {
        if (v.size() == 1 && commands.find(v) != std::string::npos) {
            finish();
            op = v[0];
        } else if (op) {
            args.push_back(parseDouble(v));
        }
    }
    finish();
    return result;
}

/// An element's attributes and style.
class Attrs {
  public:
    explicit Attrs(xmlNodePtr node) {
        for (xmlAttrPtr a = node->properties; a; a = a->next) {
            xmlChar *v = xmlNodeListGetString(node->doc, a->children, 1);
            map_[reinterpret_cast<const char *>(a->name)] = v ? reinterpret_cast<char *>(v) : "";
            xmlFree(v);
        }
    }
    std::string operator[](const std::string &name) const {
        auto it = map_.find(name);
        return it == map_.end() ? std::string() : it->second;
    }
    double number(const std::string &name) const { return parseDouble((*this)[name]); }
    /// A property of the style attribute ("name:value;..."), exactly as written.
    std::string style(const std::string &name) const {
        for (const std::string &item : tokenize((*this)["style"], ";", "")) {
            size_t colon = item.find(':');
            if (colon == std::string::npos || item.find(':', colon + 1) != std::string::npos)
                continue;
            if (item.substr(0, colon) == name) return item.substr(colon + 1);
        }
        return {};
    }
    double strokeWidth() const {
        std::string w = (*this)["stroke-width"];
        double v = parseDouble(w.empty() ? style("stroke-width") : w);
        return v < 0.01 ? 1 : v;
    }
    clipper2d::LineEnd lineCap() const {
        std::string cap = (*this)["stroke-linecap"];
        if (cap.empty()) cap = style("stroke-linecap");
        if (cap == "butt") return clipper2d::LineEnd::Butt;
        if (cap == "round") return clipper2d::LineEnd::Round;
        return clipper2d::LineEnd::Square;
    }

  private:
    std::map<std::string, std::string> map_;
};

/// A line widened by the element's stroke: libsvg's offset_path.
void strokePath(PathList &out, const Path &path, const Attrs &attrs) {
    // Scaled coordinates (and the widened line) must stay in Clipper's range: converting a
    // larger double to its integers is undefined
    double halfWidth = attrs.strokeWidth() * kStrokeScale / 2;
    auto inRange = [](double v) { return std::abs(v) <= kClipperRange / 4; };
    if (!inRange(halfWidth)) throw StrokeOutOfRange{};
    for (Vec2 v : path)
        if (!inRange(v.x * kStrokeScale + halfWidth) || !inRange(v.y * kStrokeScale + halfWidth) ||
            !inRange(v.x * kStrokeScale - halfWidth) || !inRange(v.y * kStrokeScale - halfWidth))
            throw StrokeOutOfRange{};
    for (Path &q : clipper2d::strokeOpenPath(path, kStrokeScale, halfWidth, attrs.lineCap())) {
        q.push_back(q.front());
        out.push_back(std::move(q));
    }
}

bool isOpen(const Path &p) {
    return std::hypot(p.front().x - p.back().x, p.front().y - p.back().y) > kOpenPathDistance;
}

double vectorAngle(double ux, double uy, double vx, double vy) {
    double a = std::atan2(vy, vx) - std::atan2(uy, ux);
    return a < 0 ? a + 2 * M_PI : a;
}

/// SVG's endpoint arc (implementation notes F.6.5) in libsvg's number of steps.
void arcTo(Path &path, double x1, double y1, double rx, double ry, double x2, double y2,
           double angle, bool large, bool sweep) {
    double cr = std::cos(M_PI * angle / 180), sr = std::sin(M_PI * angle / 180);
    double dx = (x1 - x2) / 2, dy = (y1 - y2) / 2;
    double x1_ = cr * dx + sr * dy, y1_ = -sr * dx + cr * dy;
    double d = (x1_ * x1_) / (rx * rx) + (y1_ * y1_) / (ry * ry);
    if (d > 1) {
        rx = std::fabs(std::sqrt(d) * rx);
        ry = std::fabs(std::sqrt(d) * ry);
    }
    double t1 = rx * rx * ry * ry - rx * rx * y1_ * y1_ - ry * ry * x1_ * x1_;
    double t2 = rx * rx * y1_ * y1_ + ry * ry * x1_ * x1_;
    if (t1 < 0) t1 = 0;
    double t3 = std::sqrt(t1 / t2);
    if (large == sweep) t3 = -t3;
    double cx_ = t3 * rx * y1_ / ry, cy_ = t3 * -ry * x1_ / rx;
    double cx = cr * cx_ - sr * cy_ + (x1 + x2) / 2, cy = sr * cx_ + cr * cy_ + (y1 + y2) / 2;
    double ux = (x1_ - cx_) / rx, uy = (y1_ - cy_) / ry;
    double vx = (-x1_ - cx_) / rx, vy = (-y1_ - cy_) / ry;
    double theta = vectorAngle(1, 0, ux, uy);
    double delta = vectorAngle(ux, uy, vx, vy);
    if (!sweep) delta -= 2 * M_PI;
    double stepsD = std::fabs(delta) * 10.0 / M_PI + 4;
    if (!std::isfinite(stepsD)) return;  // a zero radius: nothing but the end point
    int steps = static_cast<int>(stepsD);
    for (int a = 0; a <= steps; ++a) {
        double phi = theta + delta * a / steps;
        double xx = cr * std::cos(phi) * rx - sr * std::sin(phi) * ry;
        double yy = sr * std::cos(phi) * rx + cr * std::sin(phi) * ry;
        path.push_back({xx + cx, yy + cy});
    }
}

double t(double a, int e) { return std::pow(1 - a, e); }

void quadTo(Path &path, double x, double y, double cx1, double cy1, double x2, double y2) {
    for (int i = 1; i <= kCurveSegments; ++i) {
        double a = i * (1.0 / kCurveSegments);
        path.push_back({x * t(a, 2) + cx1 * 2 * t(a, 1) * a + x2 * a * a,
                        y * t(a, 2) + cy1 * 2 * t(a, 1) * a + y2 * a * a});
    }
}

void cubicTo(Path &path, double x, double y, double cx1, double cy1, double cx2, double cy2,
             double x2, double y2) {
    for (int i = 1; i <= kCurveSegments; ++i) {
        double a = i * (1.0 / kCurveSegments);
        path.push_back(
            {x * t(a, 3) + cx1 * 3 * t(a, 2) * a + cx2 * 3 * t(a, 1) * a * a + x2 * a * a * a,
             y * t(a, 3) + cy1 * 3 * t(a, 2) * a + cy2 * 3 * t(a, 1) * a * a + y2 * a * a * a});
    }
}

/// A command letter, or a number (SVG's grammar: sign, digits, fraction, exponent; "4.5.5" is
/// 4.5 then .5 and "1e1-1" is 10 then -1).
struct PathToken {
    char command = 0;
    double number = 0;
};

std::vector<PathToken> lexPathData(const std::string &d) {
    static const std::string kCommands = "zmlcqahvstZMLCQAHVST";
    std::vector<PathToken> out;
    size_t i = 0, n = d.size();
    auto digits = [&] {
        size_t start = i;
        while (i < n && std::isdigit(static_cast<unsigned char>(d[i]))) ++i;
        return i > start;
    };
    while (i < n) {
        char ch = d[i];
        if (kCommands.find(ch) != std::string::npos) {
            out.push_back({ch, 0});
            ++i;
            continue;
        }
        size_t start = i;
        if (ch == '+' || ch == '-') ++i;
        bool whole = digits();
        bool frac = false;
        if (i < n && d[i] == '.') {
            ++i;
            frac = digits();
        }
        if (!whole && !frac) {
            i = start + 1;  // anything else separates (spaces, commas, stray characters)
            continue;
        }
        if (i < n && (d[i] == 'e' || d[i] == 'E')) {
            size_t save = i++;
            if (i < n && (d[i] == '+' || d[i] == '-')) ++i;
            if (!digits()) i = save;
        }
        out.push_back({0, std::strtod(d.substr(start, i - start).c_str(), nullptr)});
        if (out.size() > kMaxPoints) throw TooManyPoints{};
    }
    return out;
}

/// The path data of `d` as libsvg reads it; open subpaths become their strokes.
PathList parsePathData(const std::string &d, const Attrs &attrs) {
    PathList list(1);
    double x = 0, y = 0, xx = 0, yy = 0, rx = 0, ry = 0, cx1 = 0, cy1 = 0, cx2 = 0, cy2 = 0;
    double angle = 0;
    bool large = false, sweep = false, lastCubic = false, lastQuad = false;
    char cmd = ' ';
    int point = 0;
    bool closed = false;
    // The segment ends at (xx, yy); the next number starts the command's arguments again
    auto advance = [&](bool cubic, bool quad) {
        x = xx;
        y = yy;
        point = -1;
        lastCubic = cubic;
        lastQuad = quad;
    };
    for (const PathToken &tok : lexPathData(d)) {
        double p = 0;
        if (tok.command) {
            point = -1;
            cmd = tok.command;
        } else {
            p = tok.number;
        }
        bool rel = std::islower(static_cast<unsigned char>(cmd));
        switch (cmd) {
            case 'a':
            case 'A':
                switch (point) {
                    case 0:
                        rx = std::fabs(p);
                        break;
                    case 1:
                        ry = std::fabs(p);
                        break;
                    case 2:
                        angle = p;
                        break;
                    case 3:
                        large = p > 0.5;
                        break;
                    case 4:
                        sweep = p > 0.5;
                        break;
                    case 5:
                        xx = rel ? x + p : p;
                        break;
                    case 6:
                        yy = rel ? y + p : p;
                        arcTo(list.back(), x, y, rx, ry, xx, yy, angle, large, sweep);
                        advance(false, false);
                        break;
                }
                break;
            case 'l':
            case 'L':
                switch (point) {
                    case 0:
                        xx = rel ? x + p : p;
                        break;
                    case 1:
                        yy = rel ? y + p : p;
                        list.back().push_back({xx, yy});
                        advance(false, false);
                        break;
                }
                break;
            case 'c':
            case 'C':
                switch (point) {
                    case 0:
                        cx1 = p;
                        break;
                    case 1:
                        cy1 = p;
                        break;
                    case 2:
                        cx2 = p;
                        break;
                    case 3:
                        cy2 = p;
                        break;
                    case 4:
                        xx = rel ? x + p : p;
                        break;
                    case 5:
                        yy = rel ? y + p : p;
                        if (rel) {
                            cx1 += x;
                            cy1 += y;
                            cx2 += x;
                            cy2 += y;
                        }
                        cubicTo(list.back(), x, y, cx1, cy1, cx2, cy2, xx, yy);
                        advance(true, false);
                        break;
                }
                break;
            case 's':
            case 'S':
                switch (point) {
                    case 0:
                        if (lastCubic) {
                            cx1 = 2 * x - cx2;
                            cy1 = 2 * y - cy2;
                        } else {
                            cx1 = x;
                            cy1 = y;
                        }
                        cx2 = p;
                        break;
                    case 1:
                        cy2 = p;
                        break;
                    case 2:
                        xx = rel ? x + p : p;
                        break;
                    case 3:
                        yy = rel ? y + p : p;
                        if (rel) {
                            cx2 += x;
                            cy2 += y;
                        }
                        cubicTo(list.back(), x, y, cx1, cy1, cx2, cy2, xx, yy);
                        advance(true, false);
                        break;
                }
                break;
            case 'q':
            case 'Q':
                switch (point) {
                    case 0:
                        cx1 = p;
                        break;
                    case 1:
                        cy1 = p;
                        break;
                    case 2:
                        xx = rel ? x + p : p;
                        break;
                    case 3:
                        yy = rel ? y + p : p;
                        if (rel) {
                            cx1 += x;
                            cy1 += y;
                        }
                        quadTo(list.back(), x, y, cx1, cy1, xx, yy);
                        advance(false, true);
                        break;
                }
                break;
            case 't':
            case 'T':
                switch (point) {
                    case 0:
                        if (lastQuad) {
                            cx1 = 2 * x - cx1;
                            cy1 = 2 * y - cy1;
                        } else {
                            cx1 = x;
                            cy1 = y;
                        }
                        xx = rel ? x + p : p;
                        break;
                    case 1:
                        yy = rel ? y + p : p;
                        quadTo(list.back(), x, y, cx1, cy1, xx, yy);
                        advance(false, true);
                        break;
                }
                break;
            case 'm':
            case 'M':
                switch (point) {
                    case 0:
                        xx = rel ? x + p : p;
                        break;
                    case 1: {
                        yy = rel ? y + p : p;
                        cmd = rel ? 'l' : 'L';
                        if (!list.back().empty()) {
                            Path path = list.back();
                            if (isOpen(path)) {
                                list.pop_back();
                                strokePath(list, path, attrs);
                            }
                            list.emplace_back();
                        }
                        list.back().push_back({xx, yy});
                        advance(false, false);
                        break;
                    }
                }
                break;
            case 'v':
            case 'V':
                if (point == 0) {
                    y = rel ? y + p : p;
                    list.back().push_back({x, y});
                    point = -1;
                    lastCubic = lastQuad = false;
                }
                break;
            case 'h':
            case 'H':
                if (point == 0) {
                    x = rel ? x + p : p;
                    list.back().push_back({x, y});
                    point = -1;
                    lastCubic = lastQuad = false;
                }
                break;
            case 'z':
            case 'Z':
                if (!list.back().empty()) {
                    Vec2 first = list.back()[0];
                    list.back().push_back(first);
                    x = first.x;
                    y = first.y;
                }
                list.emplace_back();
                closed = true;
                lastCubic = lastQuad = false;
                break;
        }
        ++point;
        if (list.back().size() > kMaxPoints || list.size() > kMaxPoints) throw TooManyPoints{};
    }
    while (!list.empty() && list.back().empty()) list.pop_back();
    if (!closed && !list.empty() && isOpen(list.back())) {
        Path path = list.back();
        list.pop_back();
        strokePath(list, path, attrs);
    }
    return list;
}

/// libsvg's circle and ellipse: 40 points, starting one step past the top.
Path ellipsePath(double x, double y, double rx, double ry) {
    Path p;
    for (int i = 1; i <= kEllipsePoints; ++i) {
        double a = i * (2 * M_PI / kEllipsePoints);
        p.push_back({rx * std::sin(a) + x, ry * std::cos(a) + y});
    }
    return p;
}

Path pointsPath(const std::string &text) {
    Path p;
    std::vector<std::string> tokens = tokenize(text, " ,\t\r\n", "");
    for (size_t i = 0; i + 1 < tokens.size(); i += 2)
        p.push_back({parseDouble(tokens[i]), parseDouble(tokens[i + 1])});
    return p;
}

struct Page {
    Length width, height;
    ViewBox viewBox;
    Alignment alignment;
};

struct Shape {
    PathList paths;
    const Page *page = nullptr;  ///< the <svg> element's own entry
};

class Reader {
  public:
    explicit Reader(Drawing &out) : out_(out) {}

    void visit(xmlNodePtr node, const Matrix &placed, bool root) {
        for (; node; node = node->next) {
            if (node->type != XML_ELEMENT_NODE) continue;
            std::string name = reinterpret_cast<const char *>(node->name);
            if (name == "defs") continue;  // definitions are drawn only where used
            Attrs attrs(node);
            // The outermost element's own transform is not applied, as in libsvg
            Matrix m = root ? placed : placed * parseTransform(attrs["transform"]);
            Shape shape;
            bool known = true;
            if (name == "svg") {
                pages_.push_back(std::make_unique<Page>());
                Page &page = *pages_.back();
                page.width = parseLength(attrs["width"]);
                page.height = parseLength(attrs["height"]);
                page.viewBox = parseViewBox(attrs["viewBox"]);
                page.alignment = parseAlignment(attrs["preserveAspectRatio"]);
                shape.page = &page;
            } else if (name == "g") {
            } else if (name == "path") {
                shape.paths = parsePathData(attrs["d"], attrs);
            } else if (name == "rect") {
                double x = attrs.number("x"), y = attrs.number("y");
                double w = attrs.number("width"), h = attrs.number("height");
                double rx = attrs.number("rx"), ry = attrs.number("ry");
                bool hasRx = !(std::fabs(rx) < 1e-8), hasRy = !(std::fabs(ry) < 1e-8);
                if (hasRx || hasRy) {
                    if (!hasRx)
                        rx = ry;
                    else if (!hasRy)
                        ry = rx;
                    rx = std::min(rx, w / 2);
                    ry = std::min(ry, h / 2);
                    // libsvg writes the rounded rectangle as path data (numbers at the
                    // stream's 6 significant digits) and reads that
                    std::ostringstream d;
                    d << "M " << x + rx << "," << y << " H " << x + w - rx << " A " << rx << ","
                      << ry << " 0 0,1 " << x + w << "," << y + ry << " V " << y + h - ry << " A "
                      << rx << "," << ry << " 0 0,1 " << x + w - rx << "," << y + h << " H "
                      << x + rx << " A " << rx << "," << ry << " 0 0,1 " << x << "," << y + h - ry
                      << " V " << y + ry << " A " << rx << "," << ry << " 0 0,1 " << x + rx << ","
                      << y << " z";
                    shape.paths = parsePathData(d.str(), attrs);
                } else {
                    shape.paths.push_back({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}, {x, y}});
                }
            } else if (name == "circle") {
                double r = attrs.number("r");
                shape.paths.push_back(ellipsePath(attrs.number("cx"), attrs.number("cy"), r, r));
            } else if (name == "ellipse") {
                shape.paths.push_back(ellipsePath(attrs.number("cx"), attrs.number("cy"),
                                                  attrs.number("rx"), attrs.number("ry")));
            } else if (name == "line") {
                Path p{{attrs.number("x1"), attrs.number("y1")},
                       {attrs.number("x2"), attrs.number("y2")}};
                strokePath(shape.paths, p, attrs);
            } else if (name == "polyline") {
                Path p = pointsPath(attrs["points"]);
                if (!p.empty()) strokePath(shape.paths, p, attrs);
            } else if (name == "polygon") {
                Path p = pointsPath(attrs["points"]);
                if (!p.empty()) {
                    p.push_back(p.front());
                    shape.paths.push_back(std::move(p));
                }
            } else {
                known = false;
                if (name != "title" && name != "desc" && name != "metadata") skip(name);
            }
            if (known) {
                for (Path &p : shape.paths)
                    for (Vec2 &v : p) v = m.apply(v);
                out_shapes_.push_back(std::move(shape));
            }
            // Children of unknown elements are still drawn (libsvg skips only the element),
            // except those of text, which OpenSCAD 2021.01 does not draw
            if (name != "text") visit(node->children, known ? m : placed, false);
        }
    }

    std::vector<Shape> out_shapes_;
    std::vector<std::unique_ptr<Page>> pages_;

  private:
    void skip(const std::string &name) {
        for (auto &s : out_.skipped)
            if (s.first == name) {
                ++s.second;
                return;
            }
        out_.skipped.push_back({name, 1});
    }
    Drawing &out_;
};

double toMm(const Length &l, double viewBox, bool valid, double dpi) {
    switch (l.unit) {
        case Unit::None:
            return kInchToMm * l.number / dpi;
        case Unit::Px:
            return kInchToMm * l.number / 96.0;
        case Unit::Pt:
            return kInchToMm * l.number / 72.0;
        case Unit::Pc:
            return kInchToMm * l.number / 6.0;
        case Unit::In:
            return kInchToMm * l.number;
        case Unit::Cm:
            return 10 * l.number;
        case Unit::Mm:
            return l.number;
        case Unit::Undefined:
            return valid ? kInchToMm * viewBox / dpi : 0.0;
        default:
            return valid ? viewBox : 0.0;
    }
}

}  // namespace

bool read(const std::string &bytes, const std::string &path, const Options &opts, Drawing &out,
          std::string &error) {
    out = Drawing();
    if (bytes.size() > static_cast<size_t>(std::numeric_limits<int>::max())) {
        error = "Error parsing file '" + path + "'";
        return false;
    }
    // From memory: libxml2 never opens the file itself (nor, without XML_PARSE_DTDLOAD and
    // with XML_PARSE_NONET, anything the file names)
    xmlDocPtr doc =
        xmlReadMemory(bytes.data(), static_cast<int>(bytes.size()), path.c_str(), nullptr,
                      XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!doc) {
        error = "Error parsing file '" + path + "'";
        return false;
    }
    std::unique_ptr<xmlDoc, void (*)(xmlDocPtr)> guard(doc, xmlFreeDoc);
    Reader reader(out);
    try {
        reader.visit(xmlDocGetRootElement(doc), Matrix(), true);
    } catch (const TooManyPoints &) {
        error = "more than " + std::to_string(kMaxPoints) + " points in '" + path + "'";
        return false;
    } catch (const StrokeOutOfRange &) {
        error = "a stroked line of '" + path + "' reaches beyond the range of 2D geometry";
        return false;
    }

    // import_svg: page size in mm, the viewBox scaled into it and aligned, y flipped
    double widthMm = 0, heightMm = 0;
    Vec2 scale{1, 1}, align{0, 0}, viewBox{0, 0};
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (const Shape &s : reader.out_shapes_) {
        if (s.page) {
            const Page &pg = *s.page;
            bool valid = pg.viewBox.valid;
            widthMm = toMm(pg.width, pg.viewBox.width, valid, opts.dpi);
            heightMm = toMm(pg.height, pg.viewBox.height, valid, opts.dpi);
            scale = {valid ? widthMm / pg.viewBox.width : 1.0,
                     valid ? heightMm / pg.viewBox.height : 1.0};
            align = {0, 0};
            if (valid && (pg.alignment.x != Align::None || pg.alignment.y != Align::None)) {
                scale.x =
                    pg.alignment.meet ? std::min(scale.x, scale.y) : std::max(scale.x, scale.y);
                scale.y = scale.x;
                auto place = [](Align a, double pageMm, double k, double vb) {
                    return a == Align::Mid   ? pageMm / 2 - k * vb / 2
                           : a == Align::Max ? pageMm - k * vb
                                             : 0.0;
                };
                align.x = place(pg.alignment.x, widthMm, scale.x, pg.viewBox.width);
                align.y = place(pg.alignment.y, heightMm, scale.y, pg.viewBox.height);
            }
            viewBox = valid ? Vec2{pg.viewBox.x, pg.viewBox.y} : Vec2{0, 0};
        }
        for (const Path &p : s.paths)
            for (Vec2 v : p) {
                minX = std::min(minX, scale.x * v.x);
                maxX = std::max(maxX, scale.x * v.x);
                minY = std::min(minY, scale.y * v.y);
                maxY = std::max(maxY, scale.y * v.y);
            }
    }
    double cx = opts.center ? (minX + maxX) / 2 : -align.x;
    double cy = opts.center ? (minY + maxY) / 2 : heightMm - align.y;
    for (const Shape &s : reader.out_shapes_) {
        std::vector<Outline> outlines;
        for (const Path &p : s.paths) {
            Outline o;
            for (Vec2 v : p)
                o.push_back({scale.x * (-viewBox.x + v.x) - cx, scale.y * (-viewBox.y - v.y) + cy});
            outlines.push_back(std::move(o));
        }
        if (!outlines.empty()) out.shapes.push_back(std::move(outlines));
    }
    return true;
}

}  // namespace rt::scad::svg
