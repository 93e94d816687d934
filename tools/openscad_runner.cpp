// SPDX-License-Identifier: MIT
// OpenSCAD subprocess: the mesh export behind `check --openscad`.
#include "tools/openscad_runner.h"

#include <cstdio>
#include <filesystem>
#include <regex>
#include <stdexcept>

#include "core/system/subprocess.h"
#include "core/system/temp_file.h"
#include "importers/scad/lang/parser.h"

namespace rt::cli {

bool openscadAvailable() { return programOnPath("openscad"); }

double parseOpenScadRenderSeconds(const std::string &log) {
    std::regex re(R"(Total rendering time: (\d+):(\d+):(\d+(?:\.\d+)?))");
    std::smatch m;
    if (!std::regex_search(log, m, re)) return 0;
    return std::stod(m[1]) * 3600 + std::stod(m[2]) * 60 + std::stod(m[3]);
}

OpenScadRun exportWithOpenScad(const std::string &scene, const std::string &meshFile,
                               const std::vector<std::pair<std::string, std::string>> &defines,
                               const std::vector<std::string> &libraryPaths, int timeoutSeconds) {
    namespace fs = std::filesystem;
    if (!openscadAvailable())
        throw std::invalid_argument(
            "OpenSCAD (openscad) is not installed; scripts/setup.sh installs it");
    // Written under a short temporary name beside it and renamed on success: never a
    // half-written mesh, and removed on an interrupt
    TempFile partialFile(meshFile, ".stl");
    const std::string &partial = partialFile.path();
    // File names as arguments that cannot be options (a scene `-ofoo.scad`)
    std::vector<std::string> args = {"openscad", "-o", fileArgument(partial), "--export-format",
                                     "binstl"};
    for (const auto &[name, value] : defines) {
        args.push_back("-D");
        args.push_back(name + "=" + value);
    }
    args.push_back(fileArgument(scene));
    // The same include<>/use<> search as scadray's importer: -L folders, $OPENSCADPATH and
    // scadray's own library folder (OpenSCAD's is searched by OpenSCAD anyway)
    std::string searchPath;
    for (const auto &p : scad::defaultLibraryPaths(libraryPaths))
        searchPath += (searchPath.empty() ? "" : ":") + p;
    ProcessOptions po;
    po.logFile = meshFile + ".log";
    po.timeoutSeconds = timeoutSeconds;
    po.environment = {{"OPENSCADPATH", searchPath}};
    std::error_code ec;
    ProcessResult pr = runProcess(args, po);
    OpenScadRun run;
    run.wallSeconds = pr.wallSeconds;
    run.log = pr.log;
    run.renderSeconds = parseOpenScadRenderSeconds(pr.log);
    auto fail = [&](const std::string &why) {
        throw std::runtime_error("OpenSCAD " + why + " for " + scene + "; its last lines:\n" +
                                 lastLines(pr.log, 12));
    };
    if (pr.timedOut) fail("ran past " + std::to_string(timeoutSeconds) + " s and was stopped");
    if (pr.log.find("Current top level object is empty") != std::string::npos)
        fail("found an empty top level: nothing to compare");
    if (pr.log.find("Current top level object is not a 3D object") != std::string::npos)
        fail("found a 2D top level: nothing to compare");
    if (pr.exitCode != 0) fail("failed (exit " + std::to_string(pr.exitCode) + ")");
    if (!fs::exists(partial, ec) || fs::file_size(partial, ec) == 0) fail("wrote no mesh");
    partialFile.commit();
    return run;
}

}  // namespace rt::cli
