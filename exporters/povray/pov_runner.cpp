// SPDX-License-Identifier: MIT
// POV-Ray subprocess with a time limit.
#include "exporters/povray/pov_runner.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/system/subprocess.h"
#include "exporters/povray/pov_format.h"

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

/// The .ini options scadray writes (pov_writer.cpp writeIni); any other could make POV-Ray read
/// or run something (Include_Header, Pre_Scene_Command, ...).
bool knownIniKey(const std::string &key) {
    static const char *kKeys[] = {
        "Input_File_Name",  "Output_File_Name", "Width",       "Height",  "Antialias",
        "Output_File_Type", "Bits_Per_Color",   "File_Gamma",  "Display", "Verbose",
        "Render_Console",   "Pause_When_Done",  "Work_Threads"};
    for (const char *k : kKeys)
        if (key == k) return true;
    return false;
}

/// Refuses an .ini or scene that is not what the exporter writes (see sdlDirectiveProblem).
void vetExportedScene(const fs::path &dir, const std::string &iniFile) {
    std::ifstream ini(dir / iniFile, std::ios::binary);
    if (!ini) throw std::runtime_error("cannot read " + (dir / iniFile).string());
    std::string pov;
    for (std::string line; std::getline(ini, line);) {
        if (line.empty() || line[0] == ';') continue;
        size_t eq = line.find('=');
        std::string key = line.substr(0, eq);
        if (eq == std::string::npos || !knownIniKey(key) ||
            !iniSafe(iniFileName(line.substr(eq + 1))))
            throw std::runtime_error(
                "refusing to run POV-Ray: " + iniFile +
                " has an option scadray does not write: " + commentText(line.substr(0, 80)));
        if (key == "Input_File_Name") pov = iniFileName(line.substr(eq + 1));
    }
    if (pov.empty())
        throw std::runtime_error("refusing to run POV-Ray: " + iniFile + " names no scene");
    std::ifstream in(dir / pov, std::ios::binary);
    std::ostringstream sdl;
    sdl << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read " + (dir / pov).string());
    std::string problem = sdlDirectiveProblem(sdl.str());
    if (!problem.empty())
        throw std::runtime_error("refusing to run POV-Ray on " + pov +
                                 ", which is not what scadray exports: " + problem);
}

}  // namespace

PovRunResult runPovRay(const std::string &dir, const std::string &iniFile, int threads,
                       int timeoutSeconds) {
    if (!povrayAvailable())
        throw std::runtime_error("POV-Ray (povray) is not installed; scripts/setup.sh installs it");
    vetExportedScene(dir.empty() ? "." : dir, iniFile);
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
        throw std::runtime_error("povray ran past " + std::to_string(timeoutSeconds) +
                                 " s and was stopped");
    if (run.exitCode != 0)
        throw std::runtime_error("povray failed (exit " + std::to_string(run.exitCode) +
                                 "); its last lines:\n" + lastLines(res.log, 12));
    std::istringstream lines(res.log);
    for (std::string line; std::getline(lines, line);)
        res.warnings += line.find("Warning") != std::string::npos;
    res.parseSeconds = parseStatisticsSeconds(res.log, "Parse");
    res.traceSeconds = parseStatisticsSeconds(res.log, "Trace");
    return res;
}

}  // namespace rt::pov
