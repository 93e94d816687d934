// SPDX-License-Identifier: MIT
// The fixture of the end-to-end tests of the scadray binary (tests/tools/*_test.cpp): a fresh
// folder per test (TempDirTest: named after the fixture's prefix, the process and the test, so
// parallel ctest runs never collide; removed when the test ends), scadray run through the shell
// with its stdout and stderr caught in that folder, and the file helpers those tests share.
// Needs SCADRAY_BINARY and SCADRAY_SOURCE_DIR (tests/CMakeLists.txt defines both for cli_tests).
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/temp_dir_test.h"

namespace rt::test {

/// What one run of scadray left: its exit code (-1 when it did not exit, e.g. killed by a
/// signal), its stdout and its stderr, byte for byte.
struct CliRun {
    int exitCode;
    std::string out, err;
};

class CliTest : public TempDirTest {
  protected:
    using TempDirTest::TempDirTest;

    /// scadray with `args` (shell words after the binary); `env` (e.g. "PATH=/nonexistent")
    /// goes before the binary through env(1). stdout and stderr are caught in the files
    /// `stdout` and `stderr` of the test folder, which tests listing the folder see.
    CliRun run(const std::string &args, const std::string &env = "") const {
        std::string cmd = (env.empty() ? "" : "/usr/bin/env " + env + " ") +
                          std::string(SCADRAY_BINARY) + " " + args + " >" + path("stdout") + " 2>" +
                          path("stderr");
        int status = std::system(cmd.c_str());
        return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stdout"),
                slurp(dir / "stderr")};
    }
    /// Writes `text` to `name` in the test folder; its path.
    std::string write(const std::string &name, const std::string &text) const {
        std::string p = path(name);
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    /// The path of `name` in the test folder.
    std::string path(const std::string &name) const { return (dir / name).string(); }
    /// The whole file, byte for byte ("" when it cannot be read).
    static std::string slurp(const std::filesystem::path &p) {
        std::ifstream in(p, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }
    /// The path of scenes/`name` in the source tree.
    static std::string scene(const std::string &name) {
        return std::string(SCADRAY_SOURCE_DIR) + "/scenes/" + name;
    }
};

}  // namespace rt::test
