// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's clipper-utils.cc semantics over the system's Clipper 6.4.2.
#include "importers/scad/geometry2d/clipper2d.h"

#include <cmath>
#include <string>

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <limits>

namespace rt::scad::clipper2d {

namespace {

using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;
using ClipperLib::PolyNode;
using ClipperLib::PolyTree;

/// fromPolygon2d: scaled, truncated points; outlines of an unsanitized set are turned
/// counter-clockwise (Clipper's positive orientation) first.
Paths toPaths(const PolygonSet &p) {
    Paths out;
    out.reserve(p.outlines.size());
    for (const Outline &o : p.outlines) {
        Path path;
        path.reserve(o.size());
        for (Vec2 v : o) path.emplace_back(toFixed(v.x), toFixed(v.y));
        if (!p.sanitized && !ClipperLib::Orientation(path)) std::reverse(path.begin(), path.end());
        out.push_back(std::move(path));
    }
    return out;
}

/// toPolygon2d: every node of the tree in Clipper's order, cleaned with CleanPolygon's default
/// distance (1.415 integer units in 2021.01), dropped below 3 points.
PolygonSet fromTree(const PolyTree &tree) {
    PolygonSet out;
    for (const PolyNode *node = tree.GetFirst(); node; node = node->GetNext()) {
        Path cleaned;
        ClipperLib::CleanPolygon(node->Contour, cleaned);
        if (cleaned.size() < 3) continue;
        Outline o;
        o.reserve(cleaned.size());
        for (const IntPoint &ip : cleaned) o.push_back({fromFixed(ip.X), fromFixed(ip.Y)});
        out.outlines.push_back(std::move(o));
    }
    out.sanitized = true;
    return out;
}

PolyTree sanitizeTree(const Paths &paths) {
    PolyTree tree;
    ClipperLib::Clipper clipper;
    clipper.AddPaths(paths, ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftEvenOdd);
    return tree;
}

Outline outlineOf(const Path &path, bool reverse) {
    Outline o;
    o.reserve(path.size());
    for (const IntPoint &ip : path) o.push_back({fromFixed(ip.X), fromFixed(ip.Y)});
    if (reverse) std::reverse(o.begin(), o.end());
    return o;
}

void collectRegions(const PolyNode &outer, std::vector<Region> &out) {
    Region r;
    r.outer = outlineOf(outer.Contour, !ClipperLib::Orientation(outer.Contour));
    for (const PolyNode *hole : outer.Childs) {
        r.holes.push_back(outlineOf(hole->Contour, !ClipperLib::Orientation(hole->Contour)));
        for (const PolyNode *island : hole->Childs) collectRegions(*island, out);
    }
    out.push_back(std::move(r));
}

}  // namespace

int64_t toFixed(double v) {
    if (!(std::abs(v) <= kMaxCoordinate))
        throw RangeError("2D coordinate " + std::to_string(v) +
                         " is beyond the range of OpenSCAD's 2D geometry (|x| <= 7e13)");
    // An implicit conversion in OpenSCAD (IntPoint takes integers): truncation toward zero
    return static_cast<int64_t>(v * kScale);
}

void PolygonSet::xRange(double &minX, double &maxX) const {
    minX = std::numeric_limits<double>::infinity();
    maxX = -minX;
    for (const Outline &o : outlines)
        for (Vec2 v : o) {
            minX = std::min(minX, v.x);
            maxX = std::max(maxX, v.x);
        }
}

PolygonSet sanitize(const PolygonSet &p) { return fromTree(sanitizeTree(toPaths(p))); }

PolygonSet apply(const std::vector<PolygonSet> &operands, BoolOp op) {
    std::vector<Paths> paths;
    for (const PolygonSet &p : operands) {
        Paths pp = toPaths(p);
        if (!p.sanitized) ClipperLib::PolyTreeToPaths(sanitizeTree(pp), pp);
        paths.push_back(std::move(pp));
    }
    ClipperLib::Clipper clipper;
    PolyTree result;
    if (op == BoolOp::Intersection && paths.size() >= 2) {
        // Intersections go as a sequence of binary operations
        Paths source = paths[0];
        for (size_t i = 1; i < paths.size(); ++i) {
            clipper.AddPaths(source, ClipperLib::ptSubject, true);
            clipper.AddPaths(paths[i], ClipperLib::ptClip, true);
            clipper.Execute(ClipperLib::ctIntersection, result, ClipperLib::pftNonZero,
                            ClipperLib::pftNonZero);
            if (i + 1 != paths.size()) {
                ClipperLib::PolyTreeToPaths(result, source);
                clipper.Clear();
            }
        }
        return fromTree(result);
    }
    for (size_t i = 0; i < paths.size(); ++i)
        clipper.AddPaths(paths[i], i == 0 ? ClipperLib::ptSubject : ClipperLib::ptClip, true);
    ClipperLib::ClipType type = op == BoolOp::Union          ? ClipperLib::ctUnion
                                : op == BoolOp::Intersection ? ClipperLib::ctIntersection
                                                             : ClipperLib::ctDifference;
    clipper.Execute(type, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return fromTree(result);
}

PolygonSet offset(const PolygonSet &p, double delta, JoinType join, double miterLimit,
                  double arcTolerance) {
    ClipperLib::JoinType jt = join == JoinType::Round   ? ClipperLib::jtRound
                              : join == JoinType::Miter ? ClipperLib::jtMiter
                                                        : ClipperLib::jtSquare;
    toFixed(delta);  // the offset must be representable too
    ClipperLib::ClipperOffset co(miterLimit, arcTolerance * kScale);
    co.AddPaths(toPaths(p), jt, ClipperLib::etClosedPolygon);
    PolyTree result;
    co.Execute(result, delta * kScale);
    return fromTree(result);
}

std::vector<Outline> strokeOpenPath(const Outline &path, double scale, double halfWidth,
                                    LineEnd end) {
    Path line;
    for (Vec2 v : path)
        line.emplace_back(static_cast<ClipperLib::cInt>(v.x * scale),
                          static_cast<ClipperLib::cInt>(v.y * scale));
    ClipperLib::EndType et = end == LineEnd::Butt    ? ClipperLib::etOpenButt
                             : end == LineEnd::Round ? ClipperLib::etOpenRound
                                                     : ClipperLib::etOpenSquare;
    ClipperLib::ClipperOffset co;
    co.AddPath(line, ClipperLib::jtMiter, et);
    Paths result;
    co.Execute(result, halfWidth);
    std::vector<Outline> out;
    out.reserve(result.size());
    for (const auto &p : result) {
        Outline q;
        for (const auto &pt : p) q.push_back({pt.X / scale, pt.Y / scale});
        out.push_back(std::move(q));
    }
    return out;
}

namespace {

/// The quads swept by `poly` (placed at each corner of the closed path `path`) along each
/// edge of `path`, each turned counter-clockwise.
void convolve(const Path &poly, const Path &path, Paths &quads) {
    size_t n = path.size(), m = poly.size();
    if (n == 0 || m == 0) return;
    auto at = [&](size_t i, size_t j) {
        return IntPoint(path[i % n].X + poly[j % m].X, path[i % n].Y + poly[j % m].Y);
    };
    for (size_t i = 0; i < n; ++i)
        for (size_t j = 0; j < m; ++j) {
            Path quad{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
            if (!ClipperLib::Orientation(quad)) ClipperLib::ReversePath(quad);
            quads.push_back(std::move(quad));
        }
}

/// `a` translated to the first point of every positive (counter-clockwise) path of `b`.
void placeAtComponents(const Paths &a, const Paths &b, Paths &out) {
    for (const Path &component : b) {
        if (component.empty() || !ClipperLib::Orientation(component)) continue;
        for (const Path &path : a) {
            Path moved = path;
            for (IntPoint &p : moved) {
                p.X += component[0].X;
                p.Y += component[0].Y;
            }
            out.push_back(std::move(moved));
        }
    }
}

}  // namespace

PolygonSet minkowski(const std::vector<PolygonSet> &operands) {
    if (operands.empty()) return {};
    if (operands.size() == 1) return operands[0];
    Paths lhs = toPaths(operands[0]);
    ClipperLib::Clipper clipper;
    for (size_t i = 1; i < operands.size(); ++i) {
        Paths rhs = toPaths(operands[i]);
        Paths terms;
        for (const Path &r : rhs)
            for (const Path &l : lhs) convolve(l, r, terms);
        placeAtComponents(lhs, rhs, terms);
        placeAtComponents(rhs, lhs, terms);
        clipper.Clear();
        try {
            clipper.AddPaths(terms, ClipperLib::ptSubject, true);
        } catch (const ClipperLib::clipperException &) {
            throw RangeError(
                "a 2D Minkowski sum reaches beyond the range of OpenSCAD's 2D "
                "geometry (|x| <= 7e13)");
        }
        if (i + 1 != operands.size())
            clipper.Execute(ClipperLib::ctUnion, lhs, ClipperLib::pftNonZero,
                            ClipperLib::pftNonZero);
    }
    PolyTree result;
    clipper.Execute(ClipperLib::ctUnion, result, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return fromTree(result);
}

std::vector<Region> regions(const PolygonSet &p) {
    // Sanitized outlines are non-zero filled (holes run clockwise); others even-odd
    // Strictly simple: an outline that touches itself at a corner (a crossing of the
    // original outline) is split there, so that each region sweeps to a closed manifold mesh;
    // the points and edges stay OpenSCAD's
    PolyTree tree;
    ClipperLib::Clipper clipper;
    clipper.StrictlySimple(true);
    clipper.AddPaths(toPaths(p), ClipperLib::ptSubject, true);
    clipper.Execute(ClipperLib::ctUnion, tree,
                    p.sanitized ? ClipperLib::pftNonZero : ClipperLib::pftEvenOdd);
    std::vector<Region> out;
    for (const PolyNode *outer : tree.Childs) collectRegions(*outer, out);
    return out;
}

}  // namespace rt::scad::clipper2d
