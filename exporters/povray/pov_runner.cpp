// SPDX-License-Identifier: MIT
// POV-Ray subprocess with a time limit.
#include "exporters/povray/pov_runner.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/system/subprocess.h"

namespace rt::pov {

namespace fs = std::filesystem;

bool povrayAvailable() { return programOnPath("povray"); }

double parseStatisticsSeconds(const std::string &log, const std::string &label) {
    std::regex re(label + R"( Time:[^(\n]*\(([0-9.]+) seconds\))");
    std::smatch m;
    if (std::regex_search(log, m, re)) return std::stod(m[1]);
    return 0;
}

namespace {

/// POV-Ray's I/O restrictions for the scenes scadray runs: file I/O only in the current
/// folder (the run's own), no shell-out commands.
constexpr const char *kRestrictedConf =
    "; written by scadray for this run: file I/O only in this folder, no shell-outs\n"
    "[File I/O Security]\n"
    "restricted\n"
    "[Shellout Security]\n"
    "forbidden\n"
    "[Permitted Paths]\n"
    "read+write = .\n";

}  // namespace

PovRunResult runPovRay(const std::string &dir, const std::string &iniFile, int threads,
                       int timeoutSeconds) {
    if (!povrayAvailable())
        throw std::runtime_error("POV-Ray (povray) is not installed; tools/setup.sh installs it");
    std::vector<std::string> args = {"povray", iniFile};
    if (threads > 0) args.push_back("+WT" + std::to_string(threads));
    // POV-Ray reads a user povray.conf from $HOME/.povray/3.7 on top of the system one; with
    // HOME at the run's own folder and this file there, an exported scene may read and write
    // files only in that folder (the system file's %HOME% is no longer the user's home) and
    // never shell out
    fs::path conf = fs::path(dir.empty() ? "." : dir) / ".povray" / "3.7";
    fs::create_directories(conf);
    std::ofstream(conf / "povray.conf") << kRestrictedConf;
    ProcessOptions po;
    po.workingDir = dir;
    po.environment.push_back({"HOME", fs::absolute(dir.empty() ? "." : dir).string()});
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
