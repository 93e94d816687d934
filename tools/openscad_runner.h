// SPDX-License-Identifier: MIT
// Runs OpenSCAD 2021.01 headless to export a scene's mesh (the referee of `check --openscad`)
// with the scene's -D defines and library folders, and reads its timing.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rt::cli {

struct OpenScadRun {
    double wallSeconds = 0;    ///< the whole process, start-up included
    double renderSeconds = 0;  ///< OpenSCAD's own "Total rendering time" (CGAL evaluation)
    std::string log;           ///< everything it printed
};

/// True when an openscad executable is on PATH.
bool openscadAvailable();

/// Exports `scene` to `meshFile` (binary STL: float32 vertices, where ASCII STL and OFF keep
/// only 6 significant digits). The file appears only when OpenSCAD succeeded. Throws
/// std::runtime_error quoting OpenSCAD's output when it fails, runs past `timeoutSeconds`,
/// or the top level is empty or 2D.
OpenScadRun exportWithOpenScad(const std::string &scene, const std::string &meshFile,
                               const std::vector<std::pair<std::string, std::string>> &defines,
                               const std::vector<std::string> &libraryPaths, int timeoutSeconds);

/// Seconds in OpenSCAD's "Total rendering time: h:mm:ss.mmm" line; 0 when absent.
double parseOpenScadRenderSeconds(const std::string &log);

}  // namespace rt::cli
