// SPDX-License-Identifier: MIT
// POV-Ray subprocess with a time limit.
#include "exporters/povray/pov_runner.h"

#include <regex>
#include <sstream>

#include "core/system/subprocess.h"

namespace rt::pov {

bool povrayAvailable() { return programOnPath("povray"); }

double parseStatisticsSeconds(const std::string &log, const std::string &label) {
    std::regex re(label + R"( Time:[^(\n]*\(([0-9.]+) seconds\))");
    std::smatch m;
    if (std::regex_search(log, m, re)) return std::stod(m[1]);
    return 0;
}

PovRunResult runPovRay(const std::string &dir, const std::string &iniFile, int threads,
                       int timeoutSeconds) {
    if (!povrayAvailable())
        throw std::runtime_error("POV-Ray (povray) is not installed; tools/setup.sh installs it");
    std::vector<std::string> args = {"povray", iniFile};
    if (threads > 0) args.push_back("+WT" + std::to_string(threads));
    ProcessOptions po;
    po.workingDir = dir;
    po.logFile = iniFile + ".log";
    po.timeoutSeconds = timeoutSeconds;
    ProcessResult run = runProcess(args, po);
    PovRunResult res;
    res.wallSeconds = run.wallSeconds;
    res.log = run.log;
    if (run.timedOut)
        throw std::runtime_error("povray ran past " + std::to_string(timeoutSeconds) + " s and was stopped");
    if (run.exitCode != 0)
        throw std::runtime_error("povray failed (exit " + std::to_string(run.exitCode) +
                                 "); its last lines:\n" + lastLines(res.log, 12));
    std::istringstream lines(res.log);
    for (std::string line; std::getline(lines, line);) res.warnings += line.find("Warning") != std::string::npos;
    res.parseSeconds = parseStatisticsSeconds(res.log, "Parse");
    res.traceSeconds = parseStatisticsSeconds(res.log, "Trace");
    return res;
}

}  // namespace rt::pov
