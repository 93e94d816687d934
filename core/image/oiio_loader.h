// SPDX-License-Identifier: MIT
// Finds and loads the OpenImageIO module (scadray_oiio.so) on first use.
#pragma once

#include <string>
#include <vector>

#include "core/image/oiio_abi.h"

namespace rt {

/// File name of the module.
inline constexpr const char *kOiioModuleName = "scadray_oiio.so";
/// Environment variable that, when set, is the only path tried for the module.
inline constexpr const char *kOiioModuleEnv = "SCADRAY_OIIO_MODULE";

/// Where the module is looked for, in order: $SCADRAY_OIIO_MODULE alone when set; else beside
/// the running executable, then where this build tree put it.
std::vector<std::string> oiioModuleCandidates();

/// The module's functions, loading it on the first call (thread-safe; it stays loaded). Throws
/// std::runtime_error naming the module, every path tried with the reason, and `purpose`
/// ("to read 'x.exr'") when it cannot be loaded.
const ScadrayOiioApi &oiioModule(const std::string &purpose);

}  // namespace rt
