// SPDX-License-Identifier: MIT
#include "importers/scad/geometry2d/projection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/ir/scene_ir.h"
#include "core/math/bounds3.h"
#include "core/meshing/hull.h"
#include "core/meshing/revolved_mesh.h"

namespace rt::scad {

namespace {

using clipper2d::BoolOp;
using clipper2d::PolygonSet;

using Leaf = TessellatedLeaf;

/// The plane dot(normal, p) = offset.
struct Plane {
    Vec3 normal;
    double offset = 0;
};

/// Newell's normal of a planar face (not normalised).
Vec3 faceNormal(const std::vector<Vec3> &v, const std::vector<int> &face) {
    Vec3 n(0, 0, 0);
    for (size_t i = 0; i < face.size(); ++i) {
        const Vec3 &a = v[face[i]], &b = v[face[(i + 1) % face.size()]];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

/// Whether the plane meets the box (closed).
bool planeMeetsBox(const Plane &pl, const Bounds3 &b) {
    if (b.isEmpty()) return false;
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < 8; ++i) {
        double s = dot(pl.normal, b.corner(i)) - pl.offset;
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    return lo <= 0 && hi >= 0;
}

/// The loops where the plane cuts the mesh's faces, as points map(p) in the plane. A vertex on the
/// plane counts as above it when onPlaneAbove, else as below (a consistent rule, so every face
/// meets the plane in pairs of crossings and the loops close). A crossing on an edge is
/// computed from the edge's lower-numbered end, so the two faces sharing the edge agree on it.
template <typename Map>
std::vector<Outline> sliceLoops(const ir::PolytopePrim &mesh, const Plane &pl, bool onPlaneAbove,
                                const Map &map) {
    const auto &v = mesh.vertices;
    std::vector<double> s(v.size());
    std::vector<char> above(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
        s[i] = dot(pl.normal, v[i]) - pl.offset;
        above[i] = onPlaneAbove ? s[i] >= 0 : s[i] > 0;
    }
    std::unordered_map<uint64_t, int> ids;
    std::vector<Vec3> points;
    std::vector<std::vector<int>> adjacent;
    auto crossing = [&](int a, int b) {
        if (a > b) std::swap(a, b);
        uint64_t key = static_cast<uint64_t>(a) << 32 | static_cast<uint32_t>(b);
        auto [it, inserted] = ids.try_emplace(key, static_cast<int>(points.size()));
        if (inserted) {
            double t = s[a] / (s[a] - s[b]);
            points.push_back(v[a] + (v[b] - v[a]) * t);
            adjacent.emplace_back();
        }
        return it->second;
    };
    auto link = [&](int a, int b) {
        if (a == b) return;
        adjacent[a].push_back(b);
        adjacent[b].push_back(a);
    };
    std::vector<int> cut;
    for (const auto &face : mesh.faces) {
        cut.clear();
        for (size_t k = 0; k < face.size(); ++k) {
            int a = face[k], b = face[(k + 1) % face.size()];
            if (above[a] != above[b]) cut.push_back(crossing(a, b));
        }
        if (cut.size() == 2) {
            link(cut[0], cut[1]);
        } else if (cut.size() > 2) {
            // A non-convex face: its crossings in order along the line where it meets the
            // plane, paired from the first
            Vec3 along = cross(pl.normal, faceNormal(v, face));
            std::sort(cut.begin(), cut.end(),
                      [&](int p, int q) { return dot(along, points[p]) < dot(along, points[q]); });
            for (size_t k = 0; k + 1 < cut.size(); k += 2) link(cut[k], cut[k + 1]);
        }
    }
    // Walk the loops (every crossing of a closed mesh has two neighbours; anything else, from
    // an open or non-manifold mesh, ends the walk, and an open chain is closed as it is)
    std::vector<Outline> loops;
    std::vector<char> seen(points.size(), 0);
    for (size_t start = 0; start < points.size(); ++start) {
        if (seen[start] || adjacent[start].empty()) continue;
        Outline loop;
        int prev = -1, cur = static_cast<int>(start);
        while (cur >= 0 && !seen[cur]) {
            seen[cur] = 1;
            loop.push_back(map(points[cur]));
            int next = -1;
            for (int n : adjacent[cur])
                if (n != prev && !seen[n]) {
                    next = n;
                    break;
                }
            prev = cur;
            cur = next;
        }
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

/// The section of a closed solid with the plane: the even-odd fill of its loops, with points
/// on the plane counted as inside (the union of both rules for them).
template <typename Map>
PolygonSet section(const Leaf &leaf, const Plane &pl, const Map &map) {
    if (!planeMeetsBox(pl, leaf.bounds)) return {};
    PolygonSet above{sliceLoops(leaf.mesh, pl, true, map), false};
    PolygonSet below{sliceLoops(leaf.mesh, pl, false, map), false};
    if (above.empty() && below.empty()) return {};
    return clipper2d::apply({above, below}, BoolOp::Union);
}

/// The tree evaluated over polygon sets: each primitive is the set `sets` gives it.
PolygonSet evaluate(const ir::Node &n,
                    const std::unordered_map<const ir::Node *, PolygonSet> &sets) {
    if (n.kind == ir::NodeKind::Primitive) {
        auto it = sets.find(&n);
        return it == sets.end() ? PolygonSet{} : it->second;
    }
    std::vector<PolygonSet> operands;
    operands.reserve(n.children.size());
    for (const auto &c : n.children) operands.push_back(evaluate(*c, sets));
    if (operands.empty()) return {};
    switch (n.kind) {
        case ir::NodeKind::Intersection:
            for (const PolygonSet &p : operands)
                if (p.empty()) return {};
            return operands.size() == 1 ? operands[0]
                                        : clipper2d::apply(operands, BoolOp::Intersection);
        case ir::NodeKind::Difference:
            if (operands[0].empty()) return {};
            return clipper2d::apply(operands, BoolOp::Difference);
        default: {
            operands.erase(std::remove_if(operands.begin(), operands.end(),
                                          [](const PolygonSet &p) { return p.empty(); }),
                           operands.end());
            if (operands.empty()) return {};
            if (operands.size() == 1) return operands[0];
            return clipper2d::apply(operands, BoolOp::Union);
        }
    }
}

/// Projection on z = 0: the plane coordinates of a point are its x and y.
struct TopView {
    Vec2 operator()(const Vec3 &p) const { return {p.x, p.y}; }
};

/// An orthonormal frame of a face's plane, scaled so that the solid's extent spans about 2^30
/// of Clipper's 2^-16 grid steps (a relative precision near 1e-14, whatever the model's size).
struct PlaneFrame {
    Vec3 origin, u, v;
    double scale = 1;
    Vec2 operator()(const Vec3 &p) const {
        Vec3 d = p - origin;
        return {dot(d, u) * scale, dot(d, v) * scale};
    }
    Vec3 back(Vec2 q) const { return origin + u * (q.x / scale) + v * (q.y / scale); }
};

/// The face's outline in plane coordinates, or nothing when it has no area there.
template <typename Map>
bool mappedFace(const ir::PolytopePrim &mesh, const std::vector<int> &face, const Map &map,
                PolygonSet &out) {
    Outline o;
    for (int i : face) o.push_back(map(mesh.vertices[i]));
    if (!(std::abs(twiceSignedArea(o)) > 0)) return false;
    out = clipper2d::sanitize(PolygonSet{{std::move(o)}, false});
    return !out.empty();
}

/// For every face of the tree's primitives (frameOf(mesh, face) gives its plane's map, or
/// nothing to pass it over), the part of it on the boundary of the tree's solid, in plane
/// coordinates: where the tree, evaluated in the face's plane with every other primitive as
/// its section there, changes when the face's primitive is taken away.
template <typename FrameOf, typename Visit>
void boundaryParts(const Tessellation &tess, const ir::Node &tree, const FrameOf &frameOf,
                   const Visit &visit) {
    std::vector<const Leaf *> leaves = tess.leavesUnder(tree);
    std::unordered_map<const ir::Node *, PolygonSet> sets;
    for (const Leaf *leaf : leaves) {
        const Leaf &p = *leaf;
        // The primitive's faces by plane (a prism's cap is many triangles in one plane): each
        // plane is evaluated once, for the union of its faces
        double extent = std::max(length(p.bounds.diagonal()), 1e-300);
        struct PlaneFaces {
            Vec3 normal;  ///< Newell normal of the first face (not normalised)
            std::vector<size_t> faces;
        };
        std::map<std::array<long long, 4>, PlaneFaces> planes;
        for (size_t f = 0; f < p.mesh.faces.size(); ++f) {
            const auto &face = p.mesh.faces[f];
            Vec3 newell = faceNormal(p.mesh.vertices, face);
            if (!(length(newell) > 0)) continue;
            Vec3 n = normalize(newell);
            double d = dot(n, p.mesh.vertices[face[0]]) / extent;
            constexpr double q = 1099511627776.0;  // 2^40: equal up to rounding
            PlaneFaces &group = planes[{std::llround(n.x * q), std::llround(n.y * q),
                                        std::llround(n.z * q), std::llround(d * q)}];
            if (group.faces.empty()) group.normal = newell;
            group.faces.push_back(f);
        }
        for (const auto &[key, group] : planes) {
            const std::vector<size_t> &faces = group.faces;
            const auto &face = p.mesh.faces[faces[0]];
            auto frame = frameOf(p.mesh, face);
            if (!frame) continue;
            std::vector<PolygonSet> pieces;
            for (size_t f : faces) {
                PolygonSet one;
                if (mappedFace(p.mesh, p.mesh.faces[f], *frame, one))
                    pieces.push_back(std::move(one));
            }
            if (pieces.empty()) continue;
            PolygonSet mapped =
                pieces.size() == 1 ? pieces[0] : clipper2d::apply(pieces, BoolOp::Union);
            const Vec3 &n = group.normal;
            Plane pl{n, 0};
            for (int i : face) pl.offset += dot(n, p.mesh.vertices[i]);
            pl.offset /= static_cast<double>(face.size());
            sets.clear();
            for (const Leaf *q : leaves)
                if (q != &p) sets[q->node] = section(*q, pl, *frame);
            sets[p.node] = mapped;
            PolygonSet with = evaluate(tree, sets);
            sets[p.node] = PolygonSet{};
            PolygonSet without = evaluate(tree, sets);
            if (!with.empty()) visit(*frame, clipper2d::apply({with, without}, BoolOp::Difference));
            if (!without.empty())
                visit(*frame, clipper2d::apply({without, with}, BoolOp::Difference));
        }
    }
}

/// The shadow of a difference or intersection subtree: the parts of its primitives' faces on
/// the result's boundary, projected (vertical faces have no area there).
void boundaryShadow(const Tessellation &tess, const ir::Node &tree, std::vector<PolygonSet> &out) {
    auto topView = [](const ir::PolytopePrim &, const std::vector<int> &) {
        return std::optional<TopView>(TopView{});
    };
    boundaryParts(tess, tree, topView, [&](const TopView &, PolygonSet part) {
        if (!part.empty()) out.push_back(std::move(part));
    });
}

void shadow(const Tessellation &tess, const ir::Node &n, std::vector<PolygonSet> &out) {
    switch (n.kind) {
        case ir::NodeKind::Group:
        case ir::NodeKind::Union:
        case ir::NodeKind::Transform:
            for (const auto &c : n.children) shadow(tess, *c, out);
            return;
        case ir::NodeKind::Intersection:
        case ir::NodeKind::Difference:
            boundaryShadow(tess, n, out);
            return;
        case ir::NodeKind::Primitive:
            break;
    }
    const ir::PolytopePrim &mesh = tess.leaf(n).mesh;
    for (const auto &face : mesh.faces) {
        PolygonSet projected;
        if (mappedFace(mesh, face, TopView{}, projected)) out.push_back(std::move(projected));
    }
}

/// The even-odd region of the outlines as convex polygons (counter-clockwise vertex
/// references): its ear-clipped triangles merged across shared edges wherever the merged
/// polygon stays convex (Hertel and Mehlhorn's greedy pass: at most four times the fewest
/// convex pieces).
std::vector<std::vector<std::pair<int, int>>> convexPieces(
    const std::vector<ir::ProfileOutline> &outlines) {
    using Ref = std::pair<int, int>;
    auto at = [&](const Ref &r) { return outlines[r.first][r.second]; };
    auto turn = [&](const Ref &a, const Ref &b, const Ref &c) {
        ir::ProfilePoint p = at(a), q = at(b), r = at(c);
        return (q.r - p.r) * (r.z - q.z) - (q.z - p.z) * (r.r - q.r);
    };
    std::vector<std::vector<Ref>> polys;
    for (const auto &t : meshing::triangulateProfile(outlines)) polys.push_back({t[0], t[1], t[2]});
    std::vector<int> parent(polys.size());
    for (size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
    auto find = [&](int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    };
    // Each interior edge once: the triangle that runs it b -> a is the other side of a -> b
    std::map<std::pair<Ref, Ref>, int> edges;
    for (size_t i = 0; i < polys.size(); ++i)
        for (int k = 0; k < 3; ++k)
            edges[{polys[i][k], polys[i][(k + 1) % 3]}] = static_cast<int>(i);
    for (size_t i = 0; i < polys.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            Ref a = polys[i][k], b = polys[i][(k + 1) % 3];
            auto other = edges.find({b, a});
            if (other == edges.end() || other->second < static_cast<int>(i)) continue;
            int p = find(static_cast<int>(i)), q = find(other->second);
            if (p == q) continue;
            std::vector<Ref> &P = polys[p], &Q = polys[q];
            // P runs a -> b and Q runs b -> a (both still edges of the merged polygons, since an
            // edge inside a merged polygon has both its triangles in it)
            size_t ia = std::find(P.begin(), P.end(), a) - P.begin();
            size_t jb = std::find(Q.begin(), Q.end(), b) - Q.begin();
            if (ia == P.size() || jb == Q.size() || P[(ia + 1) % P.size()] != b ||
                Q[(jb + 1) % Q.size()] != a)
                continue;
            // The merged polygon: P from b round to a, then Q after a up to before b
            std::vector<Ref> merged;
            for (size_t n = 0; n < P.size(); ++n) merged.push_back(P[(ia + 1 + n) % P.size()]);
            for (size_t n = 2; n < Q.size(); ++n) merged.push_back(Q[(jb + n) % Q.size()]);
            bool convex = true;
            for (size_t n = 0; n < merged.size() && convex; ++n)
                convex = turn(merged[n], merged[(n + 1) % merged.size()],
                              merged[(n + 2) % merged.size()]) >= 0;
            if (!convex) continue;
            P = std::move(merged);
            Q.clear();
            parent[q] = p;
        }
    std::vector<std::vector<Ref>> out;
    for (size_t i = 0; i < polys.size(); ++i)
        if (find(static_cast<int>(i)) == static_cast<int>(i) && !polys[i].empty())
            out.push_back(std::move(polys[i]));
    return out;
}

}  // namespace

Tessellation::Tessellation(const ir::Node &root, const Mat4 &rootFromNode, const ir::Scene &scene) {
    add(root, rootFromNode, scene);
}

void Tessellation::add(const ir::Node &n, const Mat4 &rootFromNode, const ir::Scene &scene) {
    if (n.kind == ir::NodeKind::Primitive) {
        Leaf leaf;
        leaf.node = &n;
        leaf.mesh = meshing::openscadPolyhedron(n, scene);
        for (Vec3 &v : leaf.mesh.vertices) {
            v = rootFromNode.transformPoint(v);
            leaf.bounds = unionBounds(leaf.bounds, v);
        }
        faces_ += leaf.mesh.faces.size();
        index_[&n] = leaves_.size();
        leaves_.push_back(std::move(leaf));
        return;
    }
    Mat4 m = n.kind == ir::NodeKind::Transform ? rootFromNode * n.matrix : rootFromNode;
    for (const auto &c : n.children) add(*c, m, scene);
}

std::vector<const TessellatedLeaf *> Tessellation::leavesUnder(const ir::Node &subtree) const {
    std::vector<const TessellatedLeaf *> out;
    auto walk = [&](const auto &self, const ir::Node &n) -> void {
        if (n.kind == ir::NodeKind::Primitive) {
            out.push_back(&leaf(n));
            return;
        }
        for (const auto &c : n.children) self(self, *c);
    };
    walk(walk, subtree);
    return out;
}

clipper2d::PolygonSet projectCut(const Tessellation &tess, const ir::Node &root) {
    const Plane z0{Vec3(0, 0, 1), 0};
    std::unordered_map<const ir::Node *, PolygonSet> sets;
    for (const Leaf *leaf : tess.leavesUnder(root))
        sets[leaf->node] = section(*leaf, z0, TopView{});
    return evaluate(root, sets);
}

clipper2d::PolygonSet projectShadow(const Tessellation &tess, const ir::Node &root) {
    std::vector<PolygonSet> parts;
    shadow(tess, root, parts);
    parts.erase(
        std::remove_if(parts.begin(), parts.end(), [](const PolygonSet &p) { return p.empty(); }),
        parts.end());
    if (parts.empty()) return {};
    return clipper2d::apply(parts, BoolOp::Union);
}

std::vector<std::vector<Vec3>> solidBoundary(const Tessellation &tess, const ir::Node &node) {
    std::vector<std::vector<Vec3>> out;
    std::vector<const Leaf *> leaves = tess.leavesUnder(node);
    if (node.kind != ir::NodeKind::Difference && node.kind != ir::NodeKind::Intersection) {
        // Every face of the primitives: a face inside a union is still inside the solid
        for (const Leaf *leaf : leaves)
            for (const auto &face : leaf->mesh.faces) {
                std::vector<Vec3> pts;
                for (int i : face) pts.push_back(leaf->mesh.vertices[i]);
                out.push_back(std::move(pts));
            }
        return out;
    }
    Bounds3 extent;
    for (const Leaf *leaf : leaves) extent = unionBounds(extent, leaf->bounds);
    if (extent.isEmpty()) return out;
    double size = std::max(length(extent.diagonal()), 1e-300);
    double scale = std::ldexp(1.0, 30 - std::ilogb(size) - 1);
    auto frameOf = [&](const ir::PolytopePrim &mesh, const std::vector<int> &face) {
        Vec3 n = faceNormal(mesh.vertices, face);
        if (!(length(n) > 0)) return std::optional<PlaneFrame>();
        n = normalize(n);
        Vec3 axis = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? Vec3(1, 0, 0)
                    : std::abs(n.y) <= std::abs(n.z)                                 ? Vec3(0, 1, 0)
                                                     : Vec3(0, 0, 1);
        PlaneFrame f;
        f.origin = mesh.vertices[face[0]];
        f.u = normalize(cross(n, axis));
        f.v = cross(n, f.u);
        f.scale = scale;
        return std::optional<PlaneFrame>(f);
    };
    boundaryParts(tess, node, frameOf, [&](const PlaneFrame &f, const PolygonSet &part) {
        std::vector<ir::ProfileOutline> outlines;
        for (const Outline &o : part.outlines) {
            ir::ProfileOutline po;
            for (Vec2 q : o) po.push_back({q.x, q.y});
            outlines.push_back(std::move(po));
        }
        for (const auto &piece : convexPieces(outlines)) {
            std::vector<Vec3> pts;
            for (const auto &[k, i] : piece)
                pts.push_back(f.back({outlines[k][i].r, outlines[k][i].z}));
            out.push_back(std::move(pts));
        }
    });
    return out;
}

}  // namespace rt::scad
