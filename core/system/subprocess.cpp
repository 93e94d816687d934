// SPDX-License-Identifier: MIT
// fork/exec with a polling time limit; the child runs in its own process group so a time-out
// stops everything it started.
#include "core/system/subprocess.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/system/temp_file.h"

extern char **environ;

namespace rt {

bool programOnPath(const std::string &program) {
    const char *path = std::getenv("PATH");
    std::stringstream ss(path ? path : "/usr/bin:/bin");
    std::string dir;
    while (std::getline(ss, dir, ':'))
        if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
    return false;
}

std::string fileArgument(const std::string &path) {
    if (!path.empty() && (path[0] == '-' || path[0] == '+')) return "./" + path;
    return path;
}

std::string lastLines(const std::string &text, size_t lines) {
    if (text.empty()) return text;
    size_t pos = text.size();
    for (size_t n = 0; n <= lines && pos > 0; ++n) {
        size_t nl = text.rfind('\n', pos - 1);
        if (nl == std::string::npos) return text;
        pos = nl;
    }
    return text.substr(pos + 1);
}

ProcessResult runProcess(const std::vector<std::string> &args, const ProcessOptions &opts) {
    if (args.empty()) throw std::runtime_error("runProcess: no program given");
    // Everything the child needs is built before fork: only async-signal-safe calls after it
    std::vector<std::string> argStore = args, envStore;
    for (char **e = environ; *e; ++e) {
        std::string entry = *e;
        bool replaced = false;
        for (const auto &kv : opts.environment)
            replaced = replaced || entry.compare(0, kv.first.size() + 1, kv.first + "=") == 0;
        if (!replaced) envStore.push_back(entry);
    }
    for (const auto &[name, value] : opts.environment) envStore.push_back(name + "=" + value);
    std::vector<char *> argv, envp;
    for (auto &a : argStore) argv.push_back(a.data());
    argv.push_back(nullptr);
    for (auto &e : envStore) envp.push_back(e.data());
    envp.push_back(nullptr);
    const char *logFile = opts.logFile.empty() ? "/dev/null" : opts.logFile.c_str();
    auto start = std::chrono::steady_clock::now();
    pid_t pid = ::fork();
    if (pid < 0) throw std::runtime_error("cannot start " + args[0] + ": fork failed");
    if (pid == 0) {
        // Child: own process group (so a time-out can stop all of it), cwd, output to the log
        ::setpgid(0, 0);
        if (!opts.workingDir.empty() && ::chdir(opts.workingDir.c_str()) != 0) ::_exit(126);
        int fd = ::open(logFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            ::dup2(fd, STDOUT_FILENO);
            ::dup2(fd, STDERR_FILENO);
            ::close(fd);
        }
        ::execvpe(argv[0], argv.data(), envp.data());
        ::_exit(127);
    }
    // Its own group from here on whichever of the two runs first, so that an interrupt of
    // scadray can stop all of it
    ::setpgid(pid, pid);
    ChildGroupGuard guard(pid);
    int status = 0;
    ProcessResult res;
    while (true) {
        pid_t r = ::waitpid(pid, &status, WNOHANG);
        if (r == pid) break;
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(opts.timeoutSeconds)) {
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            res.timedOut = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    res.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    res.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    if (!opts.logFile.empty()) {
        std::string logPath = opts.logFile;
        if (!opts.workingDir.empty() && logPath.front() != '/')
            logPath = opts.workingDir + "/" + logPath;
        std::ifstream in(logPath);
        std::stringstream ss;
        ss << in.rdbuf();
        res.log = ss.str();
    }
    return res;
}

}  // namespace rt
