// SPDX-License-Identifier: MIT
// Runs an external program (POV-Ray, OpenSCAD) headless, with a time limit and its output in a
// log file, as the cross-renderer checks need.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rt {

struct ProcessResult {
    int exitCode = -1;       ///< the program's exit status; -1 when a signal ended it
    bool timedOut = false;   ///< stopped (with its whole process group) at the time limit
    double wallSeconds = 0;  ///< from start to exit, the program's start-up included
    std::string log;         ///< what it wrote to stdout and stderr
};

struct ProcessOptions {
    /// Working folder of the program; empty keeps the current one.
    std::string workingDir;
    /// Where stdout and stderr go (relative names resolve in workingDir); read back into
    /// ProcessResult::log.
    std::string logFile;
    int timeoutSeconds = 600;
    /// Environment variables set for the program only.
    std::vector<std::pair<std::string, std::string>> environment;
};

/// True when an executable of that name is on PATH.
bool programOnPath(const std::string &program);

/// Runs args[0] (looked up on PATH) with args. Throws std::runtime_error when it cannot be
/// started; a failure or time-out of the program itself is reported in the result.
ProcessResult runProcess(const std::vector<std::string> &args, const ProcessOptions &opts);

/// `path` as a program's file argument: a relative name starting with '-' or '+' gets "./"
/// before it, so that no program (OpenSCAD, POV-Ray, ffmpeg) reads a file name as an option.
std::string fileArgument(const std::string &path);

/// The last `lines` lines of a text (for error messages quoting a program's output).
std::string lastLines(const std::string &text, size_t lines);

}  // namespace rt
