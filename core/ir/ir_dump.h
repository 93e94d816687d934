// SPDX-License-Identifier: MIT
// Canonical text form of an ir::Scene: fixed number format, one node per line, indented by depth,
// source locations as file-name:line:col, so golden files are stable across machines.
#pragma once

#include <string>

#include "core/ir/scene_ir.h"

namespace rt::ir {

/// Formats a number with 10 significant digits; -0 prints as 0.
std::string formatNumber(double v);

std::string dump(const Scene &scene);
std::string dump(const Node &node, int indent = 0);

}  // namespace rt::ir
