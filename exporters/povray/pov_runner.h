// SPDX-License-Identifier: MIT
// Runs the povray binary on an exported scene, headless and with a time limit, and reads its
// timing statistics.
#pragma once

#include <stdexcept>
#include <string>

namespace rt::pov {

struct PovRunResult {
    double wallSeconds = 0;   ///< the whole process, POV-Ray's fixed start-up included
    double parseSeconds = 0;  ///< POV-Ray's own "Parse Time"
    double traceSeconds = 0;  ///< POV-Ray's own "Trace Time"
    std::string log;          ///< everything POV-Ray printed
    int warnings = 0;         ///< lines of the log with "Warning" (parse and render warnings)
};

/// True when a povray executable is on PATH.
bool povrayAvailable();

/// Runs `povray <iniFile>` with `dir` as working folder (so relative names in the .ini resolve
/// there), refusing (std::runtime_error) an .ini with options scadray does not write or a scene
/// with directives it does not write (sdlDirectiveProblem). Throws std::runtime_error with the tail
/// of POV-Ray's output when it fails, is not installed, or runs past `timeoutSeconds`.
PovRunResult runPovRay(const std::string &dir, const std::string &iniFile, int threads,
                       int timeoutSeconds);

/// Seconds in POV-Ray's statistics line `<label> Time: ... (x seconds)`; 0 when absent.
double parseStatisticsSeconds(const std::string &log, const std::string &label);

}  // namespace rt::pov
