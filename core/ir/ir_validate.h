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

/// Throws SceneError for non-finite or out-of-range geometry, lights, camera or settings;
/// warns when the scene has no geometry at all.
void validateScene(const Scene &scene, DiagnosticSink &diag);

}  // namespace rt::ir
