// SPDX-License-Identifier: MIT
// POV-Ray subprocess with a time limit.
#include "exporters/povray/pov_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

namespace rt::pov {

namespace {

std::string tail(const std::string &text, size_t lines) {
    size_t pos = text.size();
    for (size_t n = 0; n <= lines && pos > 0; ++n) {
        size_t nl = text.rfind('\n', pos - 1);
        if (nl == std::string::npos) return text;
        pos = nl;
    }
    return text.substr(pos + 1);
}

}  // namespace

bool povrayAvailable() {
    const char *path = std::getenv("PATH");
    std::stringstream ss(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(ss, dir, ':'))
        if (!dir.empty() && ::access((dir + "/povray").c_str(), X_OK) == 0) return true;
    return false;
}

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
    std::string logPath = dir + "/" + iniFile + ".log";
    std::vector<std::string> args = {"povray", iniFile};
    if (threads > 0) args.push_back("+WT" + std::to_string(threads));
    auto start = std::chrono::steady_clock::now();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot start povray: fork failed");
    if (pid == 0) {
        // Child: own process group (so a time-out can stop all of it), cwd, output to the log
        ::setpgid(0, 0);
        if (::chdir(dir.c_str()) != 0) ::_exit(126);
        int fd = ::open((iniFile + ".log").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ::dup2(fd, STDOUT_FILENO);
            ::dup2(fd, STDERR_FILENO);
            ::close(fd);
        }
        std::vector<char *> argv;
        for (auto &a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        ::execvp("povray", argv.data());
        ::_exit(127);
    }
    int status = 0;
    bool timedOut = false;
    while (true) {
        pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid) break;
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(timeoutSeconds)) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    PovRunResult res;
    res.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::ifstream in(logPath);
    std::stringstream ss;
    ss << in.rdbuf();
    res.log = ss.str();
    if (timedOut)
        throw std::runtime_error("povray ran past " + std::to_string(timeoutSeconds) + " s and was stopped");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw std::runtime_error("povray failed (exit " +
                                 std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                                 "); its last lines:\n" + tail(res.log, 12));
    std::istringstream lines(res.log);
    for (std::string line; std::getline(lines, line);) res.warnings += line.find("Warning") != std::string::npos;
    res.parseSeconds = parseStatisticsSeconds(res.log, "Parse");
    res.traceSeconds = parseStatisticsSeconds(res.log, "Trace");
    return res;
}

}  // namespace rt::pov
