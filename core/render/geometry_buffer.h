// SPDX-License-Identifier: MIT
// Per-pixel geometry of a compiled scene (hit or miss, distance along the camera ray, surface
// normal, tie) and the comparison of two such buffers: how `check --openscad` holds scadray's
// surfaces against OpenSCAD's mesh of the same scene, colour left out.
#pragma once

#include <string>
#include <vector>

#include "core/image/image.h"
#include "core/math/float_util.h"
#include "core/math/vec3.h"
#include "core/render/render_scene.h"

namespace rt {

/// What the camera ray through one pixel centre meets first.
struct GeometrySample {
    double depth = kInfinity;  ///< distance along the unit camera ray; infinite on a miss
    Vec3 point;                ///< where the ray hits
    Vec3 direction;            ///< the camera ray's unit direction
    Vec3 normal;               ///< unit geometric normal turned towards the camera
    bool tie = false;          ///< coincident surfaces within the tie tolerance at or before it

    bool hit() const { return depth < kInfinity; }
};

struct GeometryBuffer {
    int width = 0, height = 0;
    std::vector<GeometrySample> samples;  ///< row-major, top row first

    const GeometrySample &at(int x, int y) const { return samples[size_t(y) * width + x]; }
};

/// Traces one ray through each pixel centre with the scene's camera (the pixel centres an
/// unjittered single-sample render uses). threads = 0 uses every hardware thread.
GeometryBuffer renderGeometry(const RenderScene &scene, int width, int height, int threads = 0);

/// Normals as colours (n * 0.5 + 0.5), black where the ray missed: a picture of the geometry.
Image normalImage(const GeometryBuffer &g);

struct GeometryTolerances {
    /// Two hits agree in depth within this fraction of the reference depth. Meshes written by
    /// OpenSCAD carry float32 vertices (binary STL): about 6e-8 relative to the coordinates,
    /// which a view at up to ~80 degrees from the normal magnifies to ~1e-6; 1e-4 leaves room.
    double depthRel = 1e-4;
    /// Normals agree within this angle in degrees. A float32-rounded vertex tilts a facet by
    /// about 6e-8 x (coordinate / facet size) radians: 0.5 degrees covers slivers 1e-5 of the
    /// coordinates wide, while a wrongly chosen diagonal of a visibly skew face tilts by more.
    double normalDegrees = 0.5;
    /// Neighbouring hits whose depths differ by more than this many times their distance across
    /// the ray are a depth jump: an edge in front of a farther surface, or a surface seen at more
    /// than atan(5.67) = 80 degrees from its normal. Both pixels are silhouette pixels, masked.
    double jumpSlope = 5.67;
    /// The check passes with at most this many differing pixels outside the masks.
    long maxDiffering = 0;
};

struct GeometryCompareResult {
    bool pass = true;
    int width = 0, height = 0;
    long bothMiss = 0;        ///< background in both
    long agreeing = 0;        ///< unmasked hits that agree in depth and normal
    long silhouette = 0;      ///< masked: a neighbour differs in hit/miss or jumps in depth
    long tied = 0;            ///< masked: coincident surfaces in either buffer (not silhouette)
    long coverageDiffer = 0;  ///< unmasked pixels hit in one buffer and missed in the other
    long depthDiffer = 0;     ///< unmasked hits whose depth differs beyond the tolerance
    long normalDiffer = 0;    ///< unmasked hits whose depth agrees but normal differs
    /// Worst unmasked relative depth difference and normal angle (degrees) at the same pixel,
    /// before the one-pixel forgiveness along facet edges
    double maxDepthRel = 0, maxNormalDegrees = 0;
    /// Grey reference shading; red depth, yellow normal, magenta coverage differences; masked
    /// pixels blue.
    Image heatMap;

    long differing() const { return coverageDiffer + depthDiffer + normalDiffer; }
    std::string summary(const GeometryTolerances &tol) const;
};

/// Compares `test` with `reference` (same size, else std::invalid_argument). Silhouette and tie
/// pixels of either buffer are masked. An unmasked hit agrees when it matches the other buffer's
/// sample at the same pixel or at one of its 8 neighbours, both ways: facet edges may then move
/// by a pixel (vertex rounding), a differently triangulated face cannot hide.
GeometryCompareResult compareGeometry(const GeometryBuffer &test, const GeometryBuffer &reference,
                                      const GeometryTolerances &tol = {});

}  // namespace rt
