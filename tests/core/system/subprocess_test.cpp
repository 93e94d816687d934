// SPDX-License-Identifier: MIT
// The subprocess runner: exit codes, captured output, its own environment, the time limit, and
// the tail of a log quoted in error messages.
#include <gtest/gtest.h>

#include <filesystem>

#include "core/system/subprocess.h"

namespace rt {
namespace {

ProcessOptions logTo(const std::string &name) {
    ProcessOptions o;
    o.workingDir = ::testing::TempDir();
    o.logFile = name;
    o.timeoutSeconds = 30;
    return o;
}

TEST(Subprocess, ReportsExitCodeAndOutput) {
    ProcessResult r = runProcess({"sh", "-c", "echo out; echo err >&2; exit 3"}, logTo("a.log"));
    EXPECT_EQ(r.exitCode, 3);
    EXPECT_FALSE(r.timedOut);
    EXPECT_EQ(r.log, "out\nerr\n");
}

TEST(Subprocess, SetsItsOwnEnvironmentOnly) {
    ProcessOptions o = logTo("b.log");
    o.environment = {{"SCADRAY_TEST_VALUE", "x:y"}, {"HOME", "/nowhere"}};
    ProcessResult r = runProcess({"sh", "-c", "echo $SCADRAY_TEST_VALUE $HOME"}, o);
    EXPECT_EQ(r.log, "x:y /nowhere\n");
    EXPECT_EQ(std::getenv("SCADRAY_TEST_VALUE"), nullptr);
}

TEST(Subprocess, StopsAProgramAtTheTimeLimit) {
    ProcessOptions o = logTo("c.log");
    o.timeoutSeconds = 1;
    ProcessResult r = runProcess({"sh", "-c", "sleep 30"}, o);
    EXPECT_TRUE(r.timedOut);
    EXPECT_NE(r.exitCode, 0);
}

TEST(Subprocess, MissingProgramIsAFailedRun) {
    ProcessResult r = runProcess({"scadray-no-such-program"}, logTo("d.log"));
    EXPECT_EQ(r.exitCode, 127);
    EXPECT_FALSE(programOnPath("scadray-no-such-program"));
    EXPECT_TRUE(programOnPath("sh"));
}

TEST(Subprocess, LastLines) {
    EXPECT_EQ(lastLines("", 3), "");
    EXPECT_EQ(lastLines("one", 3), "one");
    EXPECT_EQ(lastLines("a\nb\nc\nd\n", 2), "c\nd\n");
    EXPECT_EQ(lastLines("\nb\n", 5), "b\n");
}

}  // namespace
}  // namespace rt
