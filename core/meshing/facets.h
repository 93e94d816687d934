// SPDX-License-Identifier: MIT
// OpenSCAD 2021.01's tessellation of spheres, cylinders and cones as exact convex polytopes,
// and the `--facets` pass that decides which primitives are drawn faceted (core/ir/facet_mode.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/ir/diagnostics.h"
#include "core/ir/facet_mode.h"
#include "core/ir/node.h"

namespace rt::ir {
struct Scene;
}

namespace rt::meshing {

using ir::CylinderPrim;
using ir::FacetMode;
using ir::Fragments;
using ir::PolytopePrim;
using ir::Scene;

/// OpenSCAD's GRID_FINE (2^-20): circles smaller than this get 3 fragments, and extrusions of
/// outlines smaller than this the fewest slices.
constexpr double kGridFine = 1.0 / (1 << 20);

/// A polytope larger than this (faces) stays smooth, with a warning: `$fn=100000` would
/// otherwise make a sphere of 5e9 faces.
constexpr size_t kMaxPolytopeFaces = 1'000'000;

/// OpenSCAD 2021.01's fragment count for a circle of radius r (Calc::get_fragments_from_r):
/// 3 below 2^-20; max(trunc($fn), 3) when $fn > 0; else ceil(max(min(360/$fa, 2 pi r/$fs), 5)).
int openscadFragments(double r, const Fragments &f);

/// OpenSCAD's sphere: (n + 1) / 2 rings at polar angles 180 (i + 0.5) / rings, each an n-gon
/// starting on +X, flat caps on the first and last ring; no pole vertices.
PolytopePrim openscadSphere(double radius, int fragments);

/// OpenSCAD's cylinder or cone: n-gons at z0 and z1 (a single apex where a radius is 0).
PolytopePrim openscadCylinder(const CylinderPrim &c, int fragments);

/// The plane of a polytope face: inside is normal . x <= offset.
struct FacePlane {
    Vec3 normal;  ///< unit, pointing out of the solid
    double offset = 0;
    int axis = -1;  ///< 0, 1 or 2 when the face lies exactly in a plane x, y or z = offset
};

/// The planes of a polytope's faces, oriented away from the centroid of its vertices (so a
/// face listed clockwise still bounds the solid). Degenerate faces (no area) are left out.
/// `faceOfPlane`, when given, receives the index of each plane's face.
std::vector<FacePlane> polytopePlanes(const PolytopePrim &p,
                                      std::vector<int> *faceOfPlane = nullptr);

/// Whether `mode` draws a primitive with these $-values and fragment count faceted.
bool drawsFaceted(FacetMode mode, const Fragments &f, int fragments);

/// Replaces the spheres and cylinders of `scene` that `mode` draws faceted by OpenSCAD's
/// polytopes, and its tori and lathes (rotate_extrude) by OpenSCAD's meshes added to
/// scene.meshes; records the counts in scene.stats.facets. A torus or lathe is faceted with
/// its own `fragments` (never when 0); `auto` asks for $fn at the rotate_extrude.
void applyFacets(Scene &scene, FacetMode mode, DiagnosticSink &diag);

}  // namespace rt::meshing
