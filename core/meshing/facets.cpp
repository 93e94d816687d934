// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's tessellation of spheres, cylinders and cones (primitives.cc,
// calc.cc), and the pass that swaps them (and rotate_extrude's solids) in for the analytic
// primitives.
#include "core/meshing/facets.h"

#include <algorithm>
#include <cmath>

#include "core/ir/scene_ir.h"
#include "core/meshing/revolved_mesh.h"

namespace rt::meshing {

using namespace ir;

namespace {

/// An n-gon of radius r at height z, starting on +X, in OpenSCAD's radian arithmetic
/// (generate_circle): the same doubles as OpenSCAD's vertices.
void appendCircle(std::vector<Vec3> &out, double r, double z, int n) {
    for (int i = 0; i < n; ++i) {
        double phi = (M_PI * 2 * i) / n;
        out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
    }
}

/// A face from vertex indices first + (0..n-1), forwards or backwards.
std::vector<int> ring(int first, int n, bool reversed) {
    std::vector<int> f(n);
    for (int i = 0; i < n; ++i) f[i] = first + (reversed ? n - 1 - i : i);
    return f;
}

}  // namespace

int openscadFragments(double r, const Fragments &f) {
    if (r < kGridFine || !std::isfinite(f.fn)) return 3;
    if (f.fn > 0) return f.fn >= 3 ? static_cast<int>(std::min(f.fn, 2e9)) : 3;
    double n = std::ceil(std::max(std::min(360.0 / f.fa, r * 2 * M_PI / f.fs), 5.0));
    return static_cast<int>(std::min(n, 2e9));
}

PolytopePrim openscadSphere(double radius, int n) {
    PolytopePrim p;
    int rings = (n + 1) / 2;
    p.vertices.reserve(static_cast<size_t>(rings) * n);
    for (int i = 0; i < rings; ++i) {
        double phi = (M_PI * (i + 0.5)) / rings;
        appendCircle(p.vertices, radius * std::sin(phi), radius * std::cos(phi), n);
    }
    // Flat caps on the first (top) and last ring; between rings, planar trapezoids (2021.01
    // splits each into two triangles of the same plane)
    p.faces.push_back(ring(0, n, false));
    for (int i = 0; i + 1 < rings; ++i)
        for (int j = 0; j < n; ++j) {
            int k = (j + 1) % n;
            p.faces.push_back({i * n + j, (i + 1) * n + j, (i + 1) * n + k, i * n + k});
        }
    p.faces.push_back(ring((rings - 1) * n, n, true));
    return p;
}

PolytopePrim openscadCylinder(const CylinderPrim &c, int n) {
    PolytopePrim p;
    // Bottom ring (or apex), then top ring (or apex)
    int bottom = 0, top;
    if (c.r1 > 0)
        appendCircle(p.vertices, c.r1, c.z0, n);
    else
        p.vertices.emplace_back(0, 0, c.z0);
    top = static_cast<int>(p.vertices.size());
    if (c.r2 > 0)
        appendCircle(p.vertices, c.r2, c.z1, n);
    else
        p.vertices.emplace_back(0, 0, c.z1);
    auto at = [&](int first, double r, int j) { return r > 0 ? first + j % n : first; };
    for (int j = 0; j < n; ++j) {
        std::vector<int> f = {at(bottom, c.r1, j), at(bottom, c.r1, j + 1), at(top, c.r2, j + 1),
                              at(top, c.r2, j)};
        // A cone's side faces are triangles: drop the repeated apex
        f.erase(std::unique(f.begin(), f.end()), f.end());
        p.faces.push_back(f);
    }
    if (c.r1 > 0) p.faces.push_back(ring(bottom, n, true));
    if (c.r2 > 0) p.faces.push_back(ring(top, n, false));
    return p;
}

std::vector<FacePlane> polytopePlanes(const PolytopePrim &p, std::vector<int> *faceOfPlane) {
    Vec3 centroid(0);
    for (const Vec3 &v : p.vertices) centroid += v;
    if (!p.vertices.empty()) centroid = centroid / static_cast<double>(p.vertices.size());
    std::vector<FacePlane> planes;
    planes.reserve(p.faces.size());
    if (faceOfPlane) faceOfPlane->clear();
    for (size_t fi = 0; fi < p.faces.size(); ++fi) {
        const auto &f = p.faces[fi];
        if (f.size() < 3) continue;
        FacePlane pl;
        // A face whose vertices share one coordinate exactly lies in that axis plane: keep the
        // plane exact, so faces flush with a cube or another polytope tie exactly
        for (int axis = 0; axis < 3 && pl.axis < 0; ++axis) {
            double c = p.vertices[f[0]][axis];
            bool flat = true;
            for (int i : f) flat = flat && p.vertices[i][axis] == c;
            if (flat) {
                pl.axis = axis;
                pl.normal = Vec3(0);
                pl.normal[axis] = centroid[axis] <= c ? 1 : -1;
                pl.offset = pl.normal[axis] * c;
            }
        }
        if (pl.axis < 0) {
            // Newell's normal, relative to the first vertex so far-off faces keep their digits
            Vec3 n(0), base = p.vertices[f[0]];
            for (size_t i = 0; i < f.size(); ++i) {
                Vec3 a = p.vertices[f[i]] - base, b = p.vertices[f[(i + 1) % f.size()]] - base;
                n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                          (a.x - b.x) * (a.y + b.y));
            }
            double len = length(n);
            if (!(len > 0)) continue;
            n = n / len;
            double offset = 0;
            for (int i : f) offset += dot(n, p.vertices[i]);
            offset /= static_cast<double>(f.size());
            if (dot(n, centroid) > offset) {
                n = -n;
                offset = -offset;
            }
            pl.normal = n;
            pl.offset = offset;
        }
        planes.push_back(pl);
        if (faceOfPlane) faceOfPlane->push_back(static_cast<int>(fi));
    }
    return planes;
}

bool drawsFaceted(FacetMode mode, const Fragments &f, int fragments) {
    switch (mode) {
        case FacetMode::Smooth:
            return false;
        case FacetMode::OpenScad:
            return true;
        case FacetMode::Auto:
            return f.fn > 0 && fragments <= kAutoFacetMaxFragments;
    }
    return false;
}

namespace {

/// A solid of revolution drawn as OpenSCAD's rotate_extrude mesh, added to the scene.
bool facetRevolved(Node &n, Scene &scene, FacetMode mode, FacetStats &stats, DiagnosticSink &diag) {
    const auto *lathe = std::get_if<LathePrim>(&n.shape);
    const auto *torus = std::get_if<TorusPrim>(&n.shape);
    if (!lathe && !torus) return false;
    int fragments = lathe ? lathe->fragments : torus->fragments;
    // The importer gives the fragment count; without it there is no OpenSCAD polygon to draw
    if (fragments <= 0 || !drawsFaceted(mode, n.fragments, fragments)) {
        ++stats.smooth;
        return true;
    }
    std::vector<ProfileOutline> torusOutline;
    if (torus) torusOutline.push_back(torus->facetOutline);
    const std::vector<ProfileOutline> &outlines = lathe ? lathe->outlines : torusOutline;
    double angle = lathe ? lathe->angle : torus->angle;
    size_t points = 0;
    for (const auto &o : outlines) points += o.size();
    size_t faces = 2 * points * static_cast<size_t>(fragments);
    if (faces > kMaxPolytopeFaces) {
        diag.warning(n.loc, std::to_string(fragments) + " fragments would make " +
                                std::to_string(faces) + " faces (more than " +
                                std::to_string(kMaxPolytopeFaces) + "); drawn round");
        ++stats.smooth;
        return true;
    }
    auto mesh = std::make_shared<Mesh>(openscadRevolve(outlines, angle, fragments));
    mesh->name = lathe ? "rotate_extrude" : "rotate_extrude (circle)";
    mesh->loc = n.loc;
    scene.meshes.push_back(mesh);
    n.shape = MeshPrim{static_cast<int>(scene.meshes.size()) - 1};
    ++stats.faceted;
    return true;
}

void facetNode(Node &n, Scene &scene, FacetMode mode, FacetStats &stats, DiagnosticSink &diag) {
    for (auto &c : n.children) facetNode(*c, scene, mode, stats, diag);
    if (n.kind != NodeKind::Primitive) return;
    if (facetRevolved(n, scene, mode, stats, diag)) return;
    const auto *sphere = std::get_if<SpherePrim>(&n.shape);
    const auto *cyl = std::get_if<CylinderPrim>(&n.shape);
    if (!sphere && !cyl) return;
    int fragments =
        openscadFragments(sphere ? sphere->radius : std::max(cyl->r1, cyl->r2), n.fragments);
    if (!drawsFaceted(mode, n.fragments, fragments)) {
        ++stats.smooth;
        return;
    }
    size_t faces = sphere ? static_cast<size_t>(fragments) * ((fragments + 1) / 2)
                          : static_cast<size_t>(fragments) + 2;
    if (faces > kMaxPolytopeFaces) {
        diag.warning(n.loc, std::to_string(fragments) + " fragments would make " +
                                std::to_string(faces) + " faces (more than " +
                                std::to_string(kMaxPolytopeFaces) + "); drawn round");
        ++stats.smooth;
        return;
    }
    n.shape =
        sphere ? openscadSphere(sphere->radius, fragments) : openscadCylinder(*cyl, fragments);
    ++stats.faceted;
}

}  // namespace

void applyFacets(Scene &scene, FacetMode mode, DiagnosticSink &diag) {
    FacetStats stats;
    stats.mode = mode;
    facetNode(*scene.root, scene, mode, stats, diag);
    scene.stats.facets = stats;
}

}  // namespace rt::meshing
