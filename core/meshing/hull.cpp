// SPDX-License-Identifier: MIT
// Quickhull (Barber, Dobkin and Huhdanpaa 1996) in 3D with a distance tolerance scaled to the
// input, and the point gathering for OpenSCAD 2021.01's hull() (GeometryEvaluator::applyHull,
// CGALUtils::applyHull: the vertices of every child's geometry, hulled together).
#include "core/meshing/hull.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <unordered_map>

#include "core/ir/prism.h"
#include "core/ir/scene_ir.h"
#include "core/meshing/facets.h"
#include "core/meshing/revolved_mesh.h"

namespace rt::meshing {

using namespace ir;

const char *hullKindName(HullKind kind) {
    switch (kind) {
        case HullKind::Empty:
            return "empty";
        case HullKind::Point:
            return "a single point";
        case HullKind::Line:
            return "collinear";
        case HullKind::Flat:
            return "coplanar";
        case HullKind::Solid:
            return "solid";
    }
    return "?";
}

double hullTolerance(const std::vector<Vec3> &points) {
    Vec3 extent(0);
    for (const Vec3 &p : points) extent = max(extent, abs(p));
    return kHullToleranceUlps * DBL_EPSILON * (extent.x + extent.y + extent.z);
}

namespace {

/// A hull triangle; nbr[i] is the face across the edge v[i] -> v[(i + 1) % 3].
struct Face {
    int v[3];
    int nbr[3] = {-1, -1, -1};
    Vec3 normal;
    double offset = 0;
    std::vector<int> outside;  ///< points farther than the tolerance in front of this face
    bool alive = true;
};

class QuickHull {
  public:
    QuickHull(const std::vector<Vec3> &p, double tol)
        : p_(p), tol_(tol), startEdge_(p.size(), -1) {}

    HullResult build() {
        HullResult r;
        r.kind = initialSimplex();
        if (r.kind != HullKind::Solid) return r;
        // One pass suffices: a face's outside points only ever move to faces made later
        for (size_t fi = 0; fi < faces_.size(); ++fi) {
            while (faces_[fi].alive && !faces_[fi].outside.empty())
                addFarthest(static_cast<int>(fi));
        }
        r.unsettledPoints = unsettled_;
        r.polytope = output();
        return r;
    }

  private:
    double dist(const Face &f, int i) const { return dot(f.normal, p_[i]) - f.offset; }

    int makeFace(int a, int b, int c) {
        Face f;
        f.v[0] = a;
        f.v[1] = b;
        f.v[2] = c;
        // Plane through the centroid: the three corners round alike
        Vec3 n = cross(p_[b] - p_[a], p_[c] - p_[a]);
        f.normal = n / length(n);
        f.offset = dot(f.normal, (p_[a] + p_[b] + p_[c]) / 3.0);
        faces_.push_back(std::move(f));
        return static_cast<int>(faces_.size()) - 1;
    }

    /// Assigns point i to the face among `candidates` it is farthest in front of, if any.
    void assign(int i, const std::vector<int> &candidates) {
        int best = -1;
        double bestDist = tol_;
        for (int f : candidates) {
            double d = dist(faces_[f], i);
            if (d > bestDist) {
                bestDist = d;
                best = f;
            }
        }
        if (best >= 0) faces_[best].outside.push_back(i);
    }

    HullKind initialSimplex() {
        if (p_.empty()) return HullKind::Empty;
        // Two farthest apart of the six axis extremes. Ties are broken on the following axes:
        // the lexicographically least or greatest point is a corner of the hull, never a
        // point in the middle of an edge or face
        int ext[6];
        std::fill(ext, ext + 6, 0);
        auto less = [&](int i, int j, int a) {
            const Vec3 &p = p_[i], &q = p_[j];
            for (int k = 0; k < 3; ++k)
                if (p[(a + k) % 3] != q[(a + k) % 3]) return p[(a + k) % 3] < q[(a + k) % 3];
            return false;
        };
        for (int i = 0; i < static_cast<int>(p_.size()); ++i)
            for (int a = 0; a < 3; ++a) {
                if (less(i, ext[a], a)) ext[a] = i;
                if (less(ext[a + 3], i, a)) ext[a + 3] = i;
            }
        int v0 = ext[0], v1 = ext[0];
        double best = -1;
        for (int i = 0; i < 6; ++i)
            for (int j = i + 1; j < 6; ++j) {
                double d = lengthSquared(p_[ext[i]] - p_[ext[j]]);
                if (d > best) {
                    best = d;
                    v0 = ext[i];
                    v1 = ext[j];
                }
            }
        if (std::sqrt(best) <= tol_) return HullKind::Point;
        // Farthest from the line v0 v1
        Vec3 dir = normalize(p_[v1] - p_[v0]);
        int v2 = -1;
        best = tol_;
        for (int i = 0; i < static_cast<int>(p_.size()); ++i) {
            double d = length(cross(p_[i] - p_[v0], dir));
            if (d > best) {
                best = d;
                v2 = i;
            }
        }
        if (v2 < 0) return HullKind::Line;
        // Farthest from the plane v0 v1 v2
        int base = makeFace(v0, v1, v2);
        int v3 = -1;
        best = tol_;
        for (int i = 0; i < static_cast<int>(p_.size()); ++i) {
            double d = std::abs(dist(faces_[base], i));
            if (d > best) {
                best = d;
                v3 = i;
            }
        }
        if (v3 < 0) return HullKind::Flat;
        // A tetrahedron with v3 behind its base; faces oriented consistently
        if (dist(faces_[base], v3) > 0) std::swap(v1, v2);
        faces_.clear();
        makeFace(v0, v1, v2);
        makeFace(v1, v0, v3);
        makeFace(v2, v1, v3);
        makeFace(v0, v2, v3);
        for (int f = 0; f < 4; ++f)
            for (int e = 0; e < 3; ++e)
                faces_[f].nbr[e] = findEdge(f, faces_[f].v[(e + 1) % 3], faces_[f].v[e]);
        isVertex_.assign(p_.size(), false);
        for (int v : {v0, v1, v2, v3}) isVertex_[v] = true;
        std::vector<int> all = {0, 1, 2, 3};
        for (int i = 0; i < static_cast<int>(p_.size()); ++i)
            if (!isVertex_[i]) assign(i, all);
        return HullKind::Solid;
    }

    /// The face among the first four holding the directed edge a -> b.
    int findEdge(int self, int a, int b) const {
        for (int f = 0; f < 4; ++f)
            for (int e = 0; e < 3; ++e)
                if (f != self && faces_[f].v[e] == a && faces_[f].v[(e + 1) % 3] == b) return f;
        return -1;
    }

    struct HorizonEdge {
        int a, b;       ///< directed as in the visible face
        int outer;      ///< the face beyond it, which stays
        int outerEdge;  ///< the edge's index in `outer`
    };

    void addFarthest(int fi) {
        // The eye: the point farthest in front of the face
        std::vector<int> &out = faces_[fi].outside;
        size_t eyeAt = 0;
        for (size_t k = 1; k < out.size(); ++k)
            if (dist(faces_[fi], out[k]) > dist(faces_[fi], out[eyeAt])) eyeAt = k;
        int eye = out[eyeAt];
        out[eyeAt] = out.back();
        out.pop_back();

        // The faces it sees, connected to fi, and the horizon around them
        ++stamp_;
        visible_.resize(faces_.size(), 0);
        std::vector<int> seen = {fi}, stack = {fi};
        std::vector<HorizonEdge> horizon;
        visible_[fi] = stamp_;
        while (!stack.empty()) {
            int f = stack.back();
            stack.pop_back();
            for (int e = 0; e < 3; ++e) {
                int g = faces_[f].nbr[e];
                if (visible_[g] == stamp_) continue;
                if (dist(faces_[g], eye) > tol_) {
                    visible_[g] = stamp_;
                    seen.push_back(g);
                    stack.push_back(g);
                    continue;
                }
                int a = faces_[f].v[e], b = faces_[f].v[(e + 1) % 3];
                int ge = 0;
                while (faces_[g].v[ge] != b) ++ge;
                horizon.push_back({a, b, g, ge});
            }
        }
        if (!simpleLoop(horizon)) {
            // The tolerance made the visible region other than a disc: leave the point out
            // rather than build an inconsistent surface
            ++unsettled_;
            return;
        }

        // A cone of new faces from the horizon to the eye
        std::vector<int> made;
        made.reserve(horizon.size());
        for (const HorizonEdge &h : horizon) {
            int nf = makeFace(h.a, h.b, eye);
            faces_[nf].nbr[0] = h.outer;
            faces_[h.outer].nbr[h.outerEdge] = nf;
            startEdge_[h.a] = nf;
            made.push_back(nf);
        }
        for (int nf : made) {
            int next = startEdge_[faces_[nf].v[1]];
            faces_[nf].nbr[1] = next;
            faces_[next].nbr[2] = nf;
        }
        for (const HorizonEdge &h : horizon) startEdge_[h.a] = -1;
        isVertex_[eye] = true;

        // The seen faces go; their points move to the new faces or lie inside now
        for (int f : seen) {
            faces_[f].alive = false;
            std::vector<int> pts = std::move(faces_[f].outside);
            for (int i : pts) assign(i, made);
        }
    }

    /// True when the horizon edges chain into one loop through distinct vertices.
    bool simpleLoop(const std::vector<HorizonEdge> &horizon) {
        bool ok = horizon.size() >= 3;
        for (size_t k = 0; k < horizon.size() && ok; ++k) {
            if (startEdge_[horizon[k].a] >= 0) ok = false;
            startEdge_[horizon[k].a] = static_cast<int>(k);
        }
        if (ok) {
            size_t steps = 0;
            int k = 0;
            do {
                int next = startEdge_[horizon[k].b];
                if (next < 0) break;
                k = next;
                ++steps;
            } while (k != 0 && steps <= horizon.size());
            ok = k == 0 && steps == horizon.size();
        }
        for (const HorizonEdge &h : horizon) startEdge_[h.a] = -1;
        return ok;
    }

    /// Removes the corners of a convex polygon that lie on the segment between their
    /// neighbours: points on a hull edge are no vertices of it (OpenSCAD's exact hull has
    /// none there either). The neighbouring face sees the same segment, so it drops them too.
    void dropCollinear(std::vector<int> &loop) const {
        for (size_t k = 0; loop.size() > 3 && k < loop.size();) {
            const Vec3 &a = p_[loop[(k + loop.size() - 1) % loop.size()]], &v = p_[loop[k]],
                       &b = p_[loop[(k + 1) % loop.size()]];
            double span = length(b - a);
            if (span > 0 && length(cross(b - a, v - a)) / span <= tol_) {
                loop.erase(loop.begin() + static_cast<long>(k));
                k = k > 0 ? k - 1 : 0;
            } else {
                ++k;
            }
        }
    }

    int findRoot(std::vector<int> &parent, int f) {
        while (parent[f] != f) f = parent[f] = parent[parent[f]];
        return f;
    }

    /// The live faces, coplanar neighbours merged into polygons, on compacted vertices.
    PolytopePrim output() {
        std::vector<int> parent(faces_.size());
        std::iota(parent.begin(), parent.end(), 0);
        for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
            if (!faces_[f].alive) continue;
            for (int e = 0; e < 3; ++e) {
                int g = faces_[f].nbr[e];
                if (g < f) continue;
                // Coplanar when each face's far corner lies on the other's plane
                int gFar = 0;
                while (faces_[g].v[gFar] == faces_[f].v[e] ||
                       faces_[g].v[gFar] == faces_[f].v[(e + 1) % 3])
                    ++gFar;
                int fFar = faces_[f].v[(e + 2) % 3];
                if (std::abs(dist(faces_[f], faces_[g].v[gFar])) <= tol_ &&
                    std::abs(dist(faces_[g], fFar)) <= tol_ &&
                    dot(faces_[f].normal, faces_[g].normal) > 0)
                    parent[findRoot(parent, g)] = findRoot(parent, f);
            }
        }
        std::unordered_map<int, std::vector<int>> groups;
        for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
            if (faces_[f].alive) groups[findRoot(parent, f)].push_back(f);

        PolytopePrim poly;
        std::vector<int> index(p_.size(), -1);
        auto vertex = [&](int i) {
            if (index[i] < 0) {
                index[i] = static_cast<int>(poly.vertices.size());
                poly.vertices.push_back(p_[i]);
            }
            return index[i];
        };
        auto emitTriangle = [&](int f) {
            const Face &t = faces_[f];
            poly.faces.push_back({vertex(t.v[0]), vertex(t.v[1]), vertex(t.v[2])});
        };
        // Deterministic output: groups in the order of their first face
        std::vector<int> roots;
        for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
            if (faces_[f].alive && findRoot(parent, f) == f) roots.push_back(f);
        std::sort(roots.begin(), roots.end(),
                  [&](int a, int b) { return groups[a].front() < groups[b].front(); });
        for (int root : roots) {
            const std::vector<int> &group = groups[root];
            if (group.size() == 1) {
                emitTriangle(group[0]);
                continue;
            }
            // The group's boundary, walked from one of its edges
            std::unordered_map<int, int> next;
            int first = -1;
            bool ok = true;
            for (int f : group)
                for (int e = 0; e < 3; ++e) {
                    if (findRoot(parent, faces_[f].nbr[e]) == root) continue;
                    int a = faces_[f].v[e];
                    ok = ok && next.emplace(a, faces_[f].v[(e + 1) % 3]).second;
                    first = a;
                }
            std::vector<int> loop;
            for (int v = first; ok && loop.size() <= next.size();) {
                loop.push_back(v);
                auto it = next.find(v);
                if (it == next.end()) break;
                v = it->second;
                if (v == first) break;
            }
            if (ok && loop.size() == next.size()) {
                dropCollinear(loop);
                std::vector<int> face;
                for (int v : loop) face.push_back(vertex(v));
                poly.faces.push_back(std::move(face));
            } else {
                for (int f : group) emitTriangle(f);
            }
        }
        return poly;
    }

    const std::vector<Vec3> &p_;
    double tol_;
    std::vector<Face> faces_;
    std::vector<bool> isVertex_;
    std::vector<int> startEdge_;  ///< per point: a horizon edge or new face starting there
    std::vector<int> visible_;    ///< per face: stamp_ when seen from the current eye
    int stamp_ = 0;
    int unsettled_ = 0;
};

}  // namespace

HullResult convexHull(const std::vector<Vec3> &points) {
    return QuickHull(points, hullTolerance(points)).build();
}

namespace {

/// The tessellated polytope of a sphere or cylinder, as OpenSCAD hulls it, or none.
std::optional<PolytopePrim> roundPolytope(const Node &n) {
    if (const auto *s = std::get_if<SpherePrim>(&n.shape))
        return openscadSphere(s->radius, openscadFragments(s->radius, n.fragments));
    if (const auto *c = std::get_if<CylinderPrim>(&n.shape))
        return openscadCylinder(*c, openscadFragments(std::max(c->r1, c->r2), n.fragments));
    return std::nullopt;
}

/// The vertices of OpenSCAD's rotate_extrude mesh of a torus or lathe, or none.
std::optional<std::vector<Vec3>> revolvedPoints(const Node &n) {
    if (const auto *l = std::get_if<LathePrim>(&n.shape))
        return openscadRevolvePoints(l->outlines, l->angle, l->fragments);
    if (const auto *t = std::get_if<TorusPrim>(&n.shape))
        return openscadRevolvePoints({t->facetOutline}, t->angle, t->fragments);
    return std::nullopt;
}

/// How many points a primitive contributes (computed without making them).
size_t primitivePointCount(const Node &n, const Scene &scene) {
    if (auto pts = revolvedPoints(n)) return pts->size();
    if (std::holds_alternative<BoxPrim>(n.shape)) return 8;
    if (const auto *s = std::get_if<SpherePrim>(&n.shape)) {
        size_t f = static_cast<size_t>(openscadFragments(s->radius, n.fragments));
        return f * ((f + 1) / 2);
    }
    if (const auto *c = std::get_if<CylinderPrim>(&n.shape))
        return 2 * static_cast<size_t>(openscadFragments(std::max(c->r1, c->r2), n.fragments));
    if (const auto *m = std::get_if<MeshPrim>(&n.shape))
        return m->mesh >= 0 && m->mesh < static_cast<int>(scene.meshes.size())
                   ? scene.meshes[m->mesh]->positions.size()
                   : 0;
    if (const auto *p = std::get_if<PrismPrim>(&n.shape)) return prismPoints(*p).size();
    return std::get<PolytopePrim>(n.shape).vertices.size();
}

/// A primitive's points in its own coordinates.
std::vector<Vec3> primitivePoints(const Node &n, const Scene &scene) {
    if (const auto *b = std::get_if<BoxPrim>(&n.shape)) {
        std::vector<Vec3> corners;
        for (int i = 0; i < 8; ++i) corners.push_back(Bounds3(b->min, b->max).corner(i));
        return corners;
    }
    if (auto round = roundPolytope(n)) return std::move(round->vertices);
    if (auto pts = revolvedPoints(n)) return std::move(*pts);
    if (const auto *m = std::get_if<MeshPrim>(&n.shape)) {
        // The corners of its triangles: OpenSCAD builds a polyhedron from its faces only
        if (m->mesh < 0 || m->mesh >= static_cast<int>(scene.meshes.size())) return {};
        const Mesh &mesh = *scene.meshes[m->mesh];
        std::vector<bool> used(mesh.positions.size(), false);
        for (const auto &t : mesh.triangles)
            for (uint32_t i : t) used[i] = true;
        std::vector<Vec3> pts;
        for (size_t i = 0; i < used.size(); ++i)
            if (used[i]) pts.push_back(mesh.positions[i]);
        return pts;
    }
    if (const auto *p = std::get_if<PrismPrim>(&n.shape)) return prismPoints(*p);
    return std::get<PolytopePrim>(n.shape).vertices;
}

}  // namespace

PolytopePrim openscadPolyhedron(const Node &n, const Scene &scene) {
    auto fromMesh = [](const Mesh &m) {
        PolytopePrim p;
        p.vertices = m.positions;
        for (const auto &t : m.triangles)
            p.faces.push_back(
                {static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
        return p;
    };
    auto meshAt = [&](int index) -> const Mesh * {
        return index >= 0 && index < static_cast<int>(scene.meshes.size())
                   ? scene.meshes[index].get()
                   : nullptr;
    };
    if (const auto *b = std::get_if<BoxPrim>(&n.shape)) {
        PolytopePrim p;
        for (int i = 0; i < 8; ++i) p.vertices.push_back(Bounds3(b->min, b->max).corner(i));
        p.faces = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                   {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
        return p;
    }
    if (auto round = roundPolytope(n)) return std::move(*round);
    if (const auto *l = std::get_if<LathePrim>(&n.shape))
        return fromMesh(openscadRevolve(l->outlines, l->angle, l->fragments));
    if (const auto *t = std::get_if<TorusPrim>(&n.shape))
        return fromMesh(openscadRevolve({t->facetOutline}, t->angle, t->fragments));
    if (const auto *m = std::get_if<MeshPrim>(&n.shape)) {
        const Mesh *mesh = meshAt(m->mesh);
        return mesh ? fromMesh(*mesh) : PolytopePrim{};
    }
    if (const auto *p = std::get_if<PrismPrim>(&n.shape)) {
        if (const Mesh *mesh = meshAt(p->mesh)) return fromMesh(*mesh);
        return prismPolytope(*p);
    }
    return std::get<PolytopePrim>(n.shape);
}

namespace {

/// True for a subtree that is one convex solid: a box, sphere, cylinder, polytope (a hull) or
/// prism of a convex outline under transforms, or an intersection of such.
bool isConvexSolid(const Node &n) {
    switch (n.kind) {
        case NodeKind::Primitive:
            if (const auto *p = std::get_if<PrismPrim>(&n.shape)) return p->mesh < 0;
            return !std::holds_alternative<MeshPrim>(n.shape) &&
                   !std::holds_alternative<LathePrim>(n.shape) &&
                   !std::holds_alternative<TorusPrim>(n.shape);
        case NodeKind::Intersection:
            return std::all_of(n.children.begin(), n.children.end(),
                               [](const NodePtr &c) { return isConvexSolid(*c); });
        case NodeKind::Group:
        case NodeKind::Union:
        case NodeKind::Transform:
            return n.children.size() == 1 && isConvexSolid(*n.children[0]);
        case NodeKind::Difference:
            return false;
    }
    return false;
}

/// Sets maybeInside[i] for each point (in n's parent's coordinates) that is not clearly
/// outside OpenSCAD's geometry of n. Conservative: a mesh is its bounding box and a
/// difference its first operand.
void markMaybeInside(const Node &n, const Mat4 &parentFromNode, const std::vector<Vec3> &pts,
                     const Scene &scene, std::vector<char> &maybeInside) {
    switch (n.kind) {
        case NodeKind::Group:
        case NodeKind::Union:
            for (const auto &c : n.children)
                markMaybeInside(*c, parentFromNode, pts, scene, maybeInside);
            return;
        case NodeKind::Transform:
            for (const auto &c : n.children)
                markMaybeInside(*c, parentFromNode * n.matrix, pts, scene, maybeInside);
            return;
        case NodeKind::Difference:
            if (!n.children.empty())
                markMaybeInside(*n.children[0], parentFromNode, pts, scene, maybeInside);
            return;
        case NodeKind::Intersection: {
            // Inside an intersection only when maybe inside every operand
            std::vector<char> all(pts.size(), !n.children.empty());
            for (const auto &c : n.children) {
                std::vector<char> one(pts.size(), 0);
                markMaybeInside(*c, parentFromNode, pts, scene, one);
                for (size_t i = 0; i < pts.size(); ++i) all[i] = all[i] && one[i];
            }
            for (size_t i = 0; i < pts.size(); ++i) maybeInside[i] = maybeInside[i] || all[i];
            return;
        }
        case NodeKind::Primitive:
            break;
    }
    // A singular placement flattens the primitive: it has no inside
    std::optional<Mat4> nodeFromParent = parentFromNode.affineInverse();
    if (!nodeFromParent) return;
    std::vector<Vec3> local;
    for (const Vec3 &p : pts) local.push_back(nodeFromParent->transformPoint(p));
    std::vector<Vec3> own = primitivePoints(n, scene);
    std::vector<Vec3> scale = local;
    scale.insert(scale.end(), own.begin(), own.end());
    double tol = hullTolerance(scale);
    std::optional<PolytopePrim> round = roundPolytope(n);
    if (const auto *poly = std::get_if<PolytopePrim>(&n.shape)) round = *poly;
    if (const auto *prism = std::get_if<PrismPrim>(&n.shape); prism && prism->mesh < 0)
        round = prismPolytope(*prism);
    std::vector<FacePlane> planes;
    if (round) planes = polytopePlanes(*round);
    Bounds3 box = primitiveBounds(n.shape, &scene);
    for (size_t i = 0; i < local.size(); ++i) {
        bool inside;
        if (round) {
            inside = std::all_of(planes.begin(), planes.end(), [&](const FacePlane &pl) {
                return dot(pl.normal, local[i]) - pl.offset <= tol;
            });
        } else {
            // Boxes exactly; meshes, non-convex prisms, tori and lathes by their bounds
            inside = true;
            for (int a = 0; a < 3; ++a)
                inside =
                    inside && local[i][a] >= box.min[a] - tol && local[i][a] <= box.max[a] + tol;
        }
        if (inside) maybeInside[i] = 1;
    }
}

/// The hull of `poly` cut by the half-space normal . x <= offset (of the hull's planes).
HullResult clipHull(const PolytopePrim &poly, const FacePlane &plane) {
    double tol = hullTolerance(poly.vertices);
    std::vector<double> d;
    bool cuts = false;
    for (const Vec3 &v : poly.vertices) {
        d.push_back(dot(plane.normal, v) - plane.offset);
        cuts = cuts || d.back() > tol;
    }
    if (!cuts) return {HullKind::Solid, poly, 0};
    // The corners behind the plane and the points where edges cross it
    std::vector<Vec3> kept;
    for (size_t i = 0; i < poly.vertices.size(); ++i)
        if (d[i] <= tol) kept.push_back(poly.vertices[i]);
    for (const auto &f : poly.faces)
        for (size_t k = 0; k < f.size(); ++k) {
            int a = f[k], b = f[(k + 1) % f.size()];
            if (a < b && ((d[a] > tol && d[b] < -tol) || (d[a] < -tol && d[b] > tol))) {
                double t = d[a] / (d[a] - d[b]);
                kept.push_back(poly.vertices[a] + (poly.vertices[b] - poly.vertices[a]) * t);
            }
        }
    return convexHull(kept);
}

class HullGatherer {
  public:
    HullGatherer(const Scene &scene, DiagnosticSink &diag, const char *op)
        : scene_(scene), diag_(diag), op_(op) {}

    /// Appends n's points in its parent's coordinates; false once there are too many.
    bool gather(const Node &n, const Mat4 &parentFromNode, std::vector<Vec3> &out) {
        switch (n.kind) {
            case NodeKind::Group:
            case NodeKind::Union:
                // The hull of a union is the hull of its operands' points
                for (const auto &c : n.children)
                    if (!gather(*c, parentFromNode, out)) return false;
                return true;
            case NodeKind::Transform:
                for (const auto &c : n.children)
                    if (!gather(*c, parentFromNode * n.matrix, out)) return false;
                return true;
            case NodeKind::Primitive:
                return gatherPrimitive(n, parentFromNode, out);
            case NodeKind::Intersection:
                return gatherIntersection(n, parentFromNode, out);
            case NodeKind::Difference:
                return gatherDifference(n, parentFromNode, out);
        }
        return true;
    }

  private:
    bool gatherPrimitive(const Node &n, const Mat4 &parentFromNode, std::vector<Vec3> &out) {
        size_t count = primitivePointCount(n, scene_);
        total_ += count;
        if (total_ > kMaxHullPoints) {
            diag_.warning(n.loc, std::string(op_) + ": this part gives " + std::to_string(count) +
                                     " points, more than the " + std::to_string(kMaxHullPoints) +
                                     " it may take; its result is left out");
            return false;
        }
        for (const Vec3 &p : primitivePoints(n, scene_))
            out.push_back(parentFromNode.transformPoint(p));
        return true;
    }

    bool gatherIntersection(const Node &n, const Mat4 &parentFromNode, std::vector<Vec3> &out) {
        // Cut the first operand's hull by every plane of the others' hulls: exact when every
        // operand is convex, else an outer bound of OpenSCAD's result (its hull can be smaller)
        std::optional<HullResult> cut;
        bool convex = true;
        for (const auto &c : n.children) {
            std::vector<Vec3> pts;
            if (!gather(*c, parentFromNode, pts)) return false;
            convex = convex && isConvexSolid(*c);
            HullResult h = convexHull(pts);
            if (h.kind != HullKind::Solid) return true;  // a flat or empty operand: no volume
            if (!cut) {
                cut = std::move(h);
                continue;
            }
            for (const FacePlane &pl : polytopePlanes(h.polytope)) {
                cut = clipHull(cut->polytope, pl);
                if (cut->kind != HullKind::Solid) return true;
            }
        }
        if (!convex)
            diag_.warning(n.loc, std::string(op_) +
                                     " of an intersection() whose operands are not all single "
                                     "convex solids: taken as the intersection of the operands' "
                                     "hulls, which can be larger than OpenSCAD's");
        if (cut)
            out.insert(out.end(), cut->polytope.vertices.begin(), cut->polytope.vertices.end());
        return true;
    }

    bool gatherDifference(const Node &n, const Mat4 &parentFromNode, std::vector<Vec3> &out) {
        if (n.children.empty()) return true;
        std::vector<Vec3> pts;
        if (!gather(*n.children[0], parentFromNode, pts)) return false;
        HullResult h = convexHull(pts);
        if (h.kind != HullKind::Solid) return true;  // no volume to subtract from
        // Exact when no corner of the first operand's hull is in what is subtracted: those
        // corners stay in the result, so its hull is the whole first hull
        const std::vector<Vec3> &corners = h.polytope.vertices;
        std::vector<char> maybeInside(corners.size(), 0);
        for (size_t i = 1; i < n.children.size(); ++i)
            markMaybeInside(*n.children[i], parentFromNode, corners, scene_, maybeInside);
        if (std::find(maybeInside.begin(), maybeInside.end(), 1) != maybeInside.end())
            diag_.warning(n.loc, std::string(op_) +
                                     " of a difference() that cuts corners of its first "
                                     "operand's hull: taken as the first operand's hull, which "
                                     "can be larger than OpenSCAD's result");
        out.insert(out.end(), corners.begin(), corners.end());
        return true;
    }

    const Scene &scene_;
    DiagnosticSink &diag_;
    const char *op_;
    size_t total_ = 0;
};

/// Whether the mesh's surface is that of its convex hull: every triangle lies in the plane of
/// a hull face (within the hull's tolerance), which holds for a closed convex mesh only. A
/// triangle is tried first against the planes of the hull faces around its corners (a convex
/// mesh's corners are hull vertices), so a convex mesh costs linear time; a triangle that
/// fails there is tried against every plane, which happens at most once for a mesh that is
/// not convex.
bool meshIsConvex(const Mesh &mesh, const HullResult &hull) {
    std::vector<int> faceOfPlane;
    std::vector<FacePlane> planes = polytopePlanes(hull.polytope, &faceOfPlane);
    double tol = 4 * hullTolerance(hull.polytope.vertices);
    auto key = [](const Vec3 &v) { return std::array<double, 3>{v.x, v.y, v.z}; };
    std::map<std::array<double, 3>, std::vector<size_t>> planesAtCorner;
    for (size_t k = 0; k < planes.size(); ++k)
        for (int i : hull.polytope.faces[static_cast<size_t>(faceOfPlane[k])])
            planesAtCorner[key(hull.polytope.vertices[static_cast<size_t>(i)])].push_back(k);
    auto onPlane = [&](const std::array<uint32_t, 3> &t, const FacePlane &pl) {
        for (uint32_t i : t)
            if (std::abs(dot(pl.normal, mesh.positions[i]) - pl.offset) > tol) return false;
        return true;
    };
    for (const auto &t : mesh.triangles) {
        bool onSomeFace = false;
        for (uint32_t i : t) {
            auto at = planesAtCorner.find(key(mesh.positions[i]));
            if (at == planesAtCorner.end()) continue;
            for (size_t k : at->second)
                if ((onSomeFace = onPlane(t, planes[k]))) break;
            if (onSomeFace) break;
        }
        if (!onSomeFace)
            onSomeFace = std::any_of(planes.begin(), planes.end(),
                                     [&](const FacePlane &pl) { return onPlane(t, pl); });
        if (!onSomeFace) return false;
    }
    return true;
}

class ConvexPartGatherer {
  public:
    using Solid = std::function<void(const Node &, const Mat4 &)>;
    ConvexPartGatherer(const Scene &scene, DiagnosticSink &diag, const char *op, const Solid &solid)
        : scene_(scene), points_(scene, diag, op), solid_(solid) {}

    bool gather(const Node &n, const Mat4 &parentFromNode, std::vector<std::vector<Vec3>> &out) {
        switch (n.kind) {
            case NodeKind::Group:
            case NodeKind::Union:
                for (const auto &c : n.children)
                    if (!gather(*c, parentFromNode, out)) return false;
                return true;
            case NodeKind::Transform:
                for (const auto &c : n.children)
                    if (!gather(*c, parentFromNode * n.matrix, out)) return false;
                return true;
            case NodeKind::Intersection:
                if (isConvexSolid(n)) return onePart(n, parentFromNode, out);
                solid_(n, parentFromNode);
                return true;
            case NodeKind::Difference:
                solid_(n, parentFromNode);
                return true;
            case NodeKind::Primitive:
                break;
        }
        if (isConvexSolid(n)) return onePart(n, parentFromNode, out);
        if (const auto *m = std::get_if<MeshPrim>(&n.shape)) {
            if (m->mesh < 0 || m->mesh >= static_cast<int>(scene_.meshes.size())) return true;
            std::vector<Vec3> pts;
            if (!points_.gather(n, Mat4(), pts)) return false;
            HullResult h = convexHull(pts);
            if (h.kind != HullKind::Solid) return true;
            if (meshIsConvex(*scene_.meshes[m->mesh], h)) {
                for (Vec3 &p : h.polytope.vertices) p = parentFromNode.transformPoint(p);
                out.push_back(std::move(h.polytope.vertices));
                return true;
            }
        }
        solid_(n, parentFromNode);
        return true;
    }

  private:
    bool onePart(const Node &n, const Mat4 &parentFromNode, std::vector<std::vector<Vec3>> &out) {
        std::vector<Vec3> pts;
        if (!points_.gather(n, parentFromNode, pts)) return false;
        if (!pts.empty()) out.push_back(std::move(pts));
        return true;
    }

    const Scene &scene_;
    HullGatherer points_;
    const Solid &solid_;
};

}  // namespace

bool gatherHullPoints(const Node &node, const Scene &scene, DiagnosticSink &diag,
                      std::vector<Vec3> &out, const char *op) {
    return HullGatherer(scene, diag, op).gather(node, Mat4(), out);
}

bool gatherConvexParts(const Node &node, const Scene &scene, DiagnosticSink &diag,
                       std::vector<std::vector<Vec3>> &out,
                       const std::function<void(const Node &, const Mat4 &)> &solid,
                       const char *op) {
    return ConvexPartGatherer(scene, diag, op, solid).gather(node, Mat4(), out);
}

}  // namespace rt::meshing
