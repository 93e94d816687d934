// SPDX-License-Identifier: MIT
// Checks that a scene can be rendered and exported faithfully: finite values, and coordinates
// and sizes within the range double-precision geometry handles (squares must neither overflow
// nor underflow). Problems are SceneErrors at the offending node's SourceLoc.
#pragma once

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"

namespace rt::ir {

/// Largest coordinate magnitude and smallest primitive extent accepted. Squared lengths of such
/// values (1e200, 1e-200) stay far inside double's range, with room for products in the
/// intersection routines.
constexpr double kMaxCoordinate = 1e100;
constexpr double kMinExtent = 1e-100;
/// Area light grids: POV-Ray itself allows any size, but 256 x 256 shadow rays per shaded
/// point already takes minutes a frame; more is a mistake in the scene.
constexpr int kMaxAreaLightGrid = 256;
/// Glossy and frosted spreads (degrees): beyond 90 the lobe covers the hemisphere.
constexpr double kMaxBlurDegrees = 90;
/// Rays a blurred surface spreads where a path first meets it.
constexpr int kMaxBlurSamples = 4096;

/// The first node (in depth-first order, root at depth 1) deeper than `maxDepth`, or null.
/// Iterative, so it runs safely before any recursive walk over a tree of unknown depth.
const Node *firstNodeDeeperThan(const Node &root, int maxDepth);

/// Throws SceneError for non-finite or out-of-range geometry, lights, camera or settings;
/// warns when the scene has no geometry at all. A tree deeper than kMaxTreeDepth is an error at
/// its first node past the limit.
void validateScene(const Scene &scene, DiagnosticSink &diag);

}  // namespace rt::ir
