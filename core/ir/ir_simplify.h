// SPDX-License-Identifier: MIT
// Removes subtrees without volume by OpenSCAD's CSG rules, once, on the IR, so the ray tracer
// and the POV-Ray exporter see exactly the same solids.
#pragma once

#include "core/ir/diagnostics.h"
#include "core/ir/scene_ir.h"

namespace rt::ir {

/// Drops: transforms that are singular or not finite (with a located warning), groups and
/// unions with nothing left, intersections with an empty operand (the whole intersection),
/// differences with an empty minuend (the whole difference), and empty subtrahends.
/// Returns the number of subtrees removed.
int pruneEmpty(Scene &scene, DiagnosticSink &diag);

}  // namespace rt::ir
