// SPDX-License-Identifier: MIT
// An equirectangular picture read as the environment rays see when they leave the scene (`-e`).
#pragma once

#include <string>

#include "core/ir/diagnostics.h"
#include "core/ir/environment.h"

namespace rt {

/// An image environment read from `path` (any format readImage takes: .exr and .hdr through
/// OpenImageIO, loaded only now). Throws std::runtime_error naming the file when it cannot be
/// read or holds NaN or infinite values; negative values are clamped to 0 with a warning.
ir::Environment loadEnvironmentImage(const std::string &path, double rotateDegrees,
                                     DiagnosticSink &diag);

}  // namespace rt
