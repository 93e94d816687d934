// SPDX-License-Identifier: MIT
// Hostile input to the command line and its diagnostics: a flood of warnings stays
// bounded in memory and output, every numeric option refuses out-of-range values, NaN and
// infinities before converting them, a FIFO or a device as a scene is refused before it is
// opened, and neither an interrupt nor a long output name leaves a temporary file behind.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/image/image_io.h"
#include "core/ir/diagnostics.h"
#include "core/system/subprocess.h"
#include "core/system/temp_file.h"
#include "tools/cli_common.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class Hostile : public test::CliTest {
  protected:
    Hostile() : CliTest("scadray_hostile_") {}

    using Run = test::CliRun;
    /// scadray with `args` and nothing on stdin.
    Run run(const std::string &args) const { return CliTest::run(args + " </dev/null"); }
    /// Files in the test folder other than the ones named.
    std::vector<std::string> strayFiles(const std::vector<std::string> &expected) const {
        std::vector<std::string> stray;
        for (const auto &e : fs::directory_iterator(dir)) {
            std::string name = e.path().filename().string();
            if (name == "stdout" || name == "stderr") continue;
            if (std::find(expected.begin(), expected.end(), name) == expected.end())
                stray.push_back(name);
        }
        return stray;
    }
    static int countOf(const std::string &text, const std::string &what) {
        int n = 0;
        for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
        return n;
    }
};

// ---- 1. Warning floods ----------------------------------------------------------------------

TEST(DiagnosticSinkFlood, RepeatsAreCountedNotKept) {
    DiagnosticSink diag;
    int heard = 0;
    diag.setListener([&](const Diagnostic &) { ++heard; });
    auto file = std::make_shared<const std::string>("flood.scad");
    constexpr int kWarnings = 1'000'000;
    for (int i = 0; i < kWarnings; ++i)
        diag.warning({file, 1, i + 1},
                     "Ignoring unknown variable 'x" + std::to_string(i % 7) + "'");
    EXPECT_EQ(heard, kWarningsShownPerKind);
    EXPECT_EQ(diag.all().size(), static_cast<size_t>(kWarningsShownPerKind));
    EXPECT_EQ(diag.count(Severity::Warning), kWarnings);
    EXPECT_EQ(diag.countContaining("unknown variable"), kWarnings);
    EXPECT_EQ(diag.suppressed(), kWarnings - kWarningsShownPerKind);
    ASSERT_EQ(diag.summary().size(), 1u);
    EXPECT_EQ(diag.summary()[0],
              "999995 more warnings like: flood.scad:1:1: Ignoring unknown variable 'x0'");
}

TEST(DiagnosticSinkFlood, ManyKindsAndNotesStayBounded) {
    DiagnosticSink diag;
    int heardWarnings = 0, heardNotes = 0;
    diag.setListener([&](const Diagnostic &d) {
        (d.severity == Severity::Note ? heardNotes : heardWarnings)++;
    });
    // Kinds made of letters (digits would make them one kind): more than are told apart
    auto name = [](int i) {
        std::string s;
        for (; i > 0 || s.empty(); i /= 26) s += static_cast<char>('a' + i % 26);
        return s;
    };
    constexpr int kKinds = 5000, kEach = 20;
    for (int r = 0; r < kEach; ++r)
        for (int k = 0; k < kKinds; ++k) diag.warning({}, "unknown variable '" + name(k) + "'");
    for (int i = 0; i < 100'000; ++i) diag.note({}, "ECHO: " + std::to_string(i));
    EXPECT_EQ(diag.count(Severity::Warning), kKinds * kEach);
    EXPECT_EQ(diag.count(Severity::Note), 100'000);
    // Echo output all reaches the printer; warnings only the first few of each kind, and of
    // the kinds past the limit, the first few in all
    EXPECT_EQ(heardNotes, 100'000);
    EXPECT_EQ(heardWarnings, static_cast<int>(kMaxWarningKinds + 1) * kWarningsShownPerKind);
    EXPECT_LE(diag.all().size(), kMaxKeptDiagnostics);
    EXPECT_EQ(diag.summary().size(), kMaxWarningKinds + 1);
    EXPECT_NE(diag.summary().back().find("more warnings of other kinds"), std::string::npos);
    EXPECT_EQ(diag.countContaining("unknown variable"), kKinds * kEach);
}

TEST(DiagnosticSinkFlood, KindIgnoresNumbers) {
    EXPECT_EQ(DiagnosticSink::kindOf("Point index 12 is out of 3"), "Point index # is out of #");
    EXPECT_EQ(DiagnosticSink::kindOf("a 1.5e10 b"), "a #.#e# b");
    EXPECT_NE(DiagnosticSink::kindOf("unknown 'a'"), DiagnosticSink::kindOf("unknown 'b'"));
}

TEST_F(Hostile, ExcerptOfALongLineReadsAWindow) {
    // One 300 000-byte line; the excerpt around column 200 000 is the window, with the caret
    // under the column and "..." on both sides
    std::string line(300'000, 'x');
    line.replace(200'000 - 1, 3, "ABC");
    std::string path = write("long.scad", "first line\n" + line + "\r\nlast\n");
    auto file = std::make_shared<const std::string>(path);
    std::string text = formatDiagnostic({Severity::Warning, {file, 2, 200'000}, "here"});
    auto lines = [&] {
        std::vector<std::string> v;
        std::stringstream ss(text);
        for (std::string l; std::getline(ss, l);) v.push_back(l);
        return v;
    }();
    ASSERT_EQ(lines.size(), 3u) << text;
    EXPECT_EQ(lines[1].substr(0, 7), "    ...");
    EXPECT_EQ(lines[1].substr(lines[1].size() - 3), "...");
    EXPECT_EQ(lines[1].find('\r'), std::string::npos);
    size_t caret = lines[2].find('^');
    ASSERT_NE(caret, std::string::npos);
    EXPECT_EQ(lines[1].substr(caret, 3), "ABC");
    // The last line, a short one, and a line past the end
    std::string last = formatDiagnostic({Severity::Warning, {file, 3, 2}, "end"});
    EXPECT_NE(last.find("\n    last\n     ^"), std::string::npos) << last;
    EXPECT_EQ(formatDiagnostic({Severity::Warning, {file, 9, 1}, "past"}),
              path + ":9:1: warning: past");
    // The file changes: the excerpt follows it
    write("long.scad", "changed\n");
    EXPECT_NE(formatDiagnostic({Severity::Warning, {file, 1, 1}, "x"}).find("changed"),
              std::string::npos);
}

TEST_F(Hostile, ExcerptNeverOpensAFifo) {
    std::string fifo = (dir / "pipe.scad").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto file = std::make_shared<const std::string>(fifo);
    // Opening the FIFO for reading would block for ever: the excerpt is left out instead
    EXPECT_EQ(formatDiagnostic({Severity::Warning, {file, 1, 1}, "x"}), fifo + ":1:1: warning: x");
}

TEST_F(Hostile, MillionWarningsOnOneLineAreSummarised) {
    // The evaluator warns once per iteration, all at one column of one line (a range holds
    // fewer than a million elements: two nested)
    std::string in =
        write("flood.scad", "a = [for (i = [0:999], j = [0:999]) undef_var];\ncube(1);\n");
    Run r = run("dump " + in);
    EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 2000);
    EXPECT_EQ(countOf(r.err, "warning: Ignoring unknown variable 'undef_var'"), 5);
    EXPECT_NE(r.err.find("scadray: 999995 more warnings like: " + in +
                         ":1:37: Ignoring unknown variable 'undef_var'"),
              std::string::npos)
        << r.err.substr(0, 2000);
    EXPECT_LT(r.err.size(), 4000u);
}

TEST_F(Hostile, WarningsAcrossALongLineAreSummarised) {
    // 20 000 warnings at different columns of one 220 000-byte line
    std::string src = "a = [";
    for (int i = 0; i < 20'000; ++i) src += "undef_var, ";
    std::string in = write("wide.scad", src + "0];\ncube(1);\n");
    Run r = run("render -q -W 8 -H 8 " + in + " -o " + (dir / "w.png").string());
    EXPECT_EQ(r.exitCode, 0) << r.err.substr(0, 2000);
    EXPECT_EQ(countOf(r.err, "warning: Ignoring unknown variable"), 5);
    EXPECT_NE(r.err.find("19995 more warnings like: " + in + ":1:6:"), std::string::npos)
        << r.err.substr(0, 2000);
    // The summary also comes when an error ends the command
    Run e = run("dump " + write("then_error.scad", src + "0];\ncube(1);\nfrobnicate(3);\n"));
    EXPECT_EQ(e.exitCode, 1);
    EXPECT_NE(e.err.find("19995 more warnings like:"), std::string::npos) << e.err.substr(0, 2000);
    EXPECT_NE(e.err.find("then_error.scad:3:1: error"), std::string::npos) << e.err.substr(0, 2000);
}

// ---- 2. Numeric options ---------------------------------------------------------------------

TEST(NumericOptions, RangeRefusesOverflowNanAndInfinityBeforeConverting) {
    auto parse = [](const std::vector<std::string> &args) -> std::string {
        CLI::App app;
        int width = 640;
        long long steps = 0;
        uint64_t seed = 0;
        double margin = 0, alpha = 0.01;
        cli::addNumber(app, "-W", width, "", 1, 32768);
        cli::addNumber(app, "--steps", steps, "", 0LL, std::numeric_limits<long long>::max());
        cli::addNumber(app, "--seed", seed, "", uint64_t{0}, std::numeric_limits<uint64_t>::max());
        cli::addNumber(app, "--margin", margin, "", 0.0, std::numeric_limits<double>::max());
        cli::addNumber(app, "--alpha", alpha, "", 0.0, 1.0, true);
        std::vector<std::string> argv(args.rbegin(), args.rend());
        try {
            app.parse(argv);
        } catch (const CLI::ParseError &e) {
            return e.what();
        }
        return "ok";
    };
    for (const auto &good :
         std::vector<std::vector<std::string>>{{"-W", "1"},
                                               {"-W", "32768"},
                                               {"--steps", "9223372036854775807"},
                                               {"--seed", "18446744073709551615"},
                                               {"--margin", "0"},
                                               {"--margin", "1e300"},
                                               {"--alpha", "1"},
                                               {"--alpha", "1e-300"}})
        EXPECT_EQ(parse(good), "ok") << good[0] << " " << good[1];
    struct Bad {
        std::vector<std::string> args;
        std::string message;
    };
    for (const auto &bad :
         std::vector<Bad>{{{"-W", "0"}, "-W: must be [1, 32768], not 0"},
                          {{"-W", "32769"}, "must be [1, 32768], not 32769"},
                          {{"-W", "2147483648"}, "must be an integer [1, 32768], not '2147483648'"},
                          {{"-W", "1e3"}, "must be an integer"},
                          {{"-W", "12abc"}, "must be an integer"},
                          {{"-W", ""}, "must be an integer"},
                          {{"--steps", "-1"}, "must be >= 0, not -1"},
                          {{"--steps", "9223372036854775808"}, "must be an integer"},
                          {{"--seed", "-1"}, "must be an integer >= 0, not '-1'"},
                          {{"--seed", "18446744073709551616"}, "must be an integer"},
                          {{"--margin", "nan"}, "--margin: must be a number >= 0, not 'nan'"},
                          {{"--margin", "inf"}, "must be a number"},
                          {{"--margin", "-inf"}, "must be a number"},
                          {{"--margin", "1e999"}, "must be a number"},
                          {{"--margin", "-0.5"}, "must be >= 0, not -0.5"},
                          {{"--alpha", "0"}, "must be (0, 1], not 0"},
                          {{"--alpha", "NaN"}, "must be a number"}}) {
        std::string err = parse(bad.args);
        EXPECT_NE(err.find(bad.message), std::string::npos)
            << bad.args[0] << " " << bad.args[1] << ": " << err;
    }
}

TEST_F(Hostile, EveryNumericOptionHasARange) {
    // Every option of every subcommand whose value is a number shows its range in --help:
    // "INT:[1, 32768]", "FLOAT:>= 0", "UINT:>= 0", or a list of values "INT:{8,16}"
    for (const char *cmd : {"render", "export", "check", "converge", "compare", "dump"}) {
        Run r = run(std::string(cmd) + " --help");
        ASSERT_EQ(r.exitCode, 0) << cmd;
        std::stringstream ss(r.out);
        int numeric = 0;
        for (std::string line; std::getline(ss, line);) {
            for (const char *type : {" INT", " UINT", " FLOAT"}) {
                size_t at = line.find(type);
                if (at == std::string::npos || line.find("-") > at) continue;
                ++numeric;
                size_t after = at + std::strlen(type);
                EXPECT_EQ(line.substr(after, 1), ":") << cmd << ": " << line;
                EXPECT_NE(std::string("[(>{").find(line.substr(after + 1, 1)), std::string::npos)
                    << cmd << ": " << line;
            }
        }
        EXPECT_GT(numeric, 0) << cmd;
    }
}

TEST_F(Hostile, ReportedOverflowsAreUsageErrors) {
    // The cases of the issue: each a usage error naming the option, before any file is read
    // or written
    std::string in = write("s.scad", "cube(1);\n");
    std::string out = (dir / "o").string();
    struct Case {
        std::string args, mention;
    };
    for (const auto &c : std::vector<Case>{
             {"export -W 30000 -H 30000 --supersample 100000 -o " + out + ".pov " + in,
              "--supersample: must be [1, 16], not 100000"},
             {"compare --tile 2147483647 " + in + " " + in, "--tile: must be [1, 32768]"},
             {"check --margin nan -o " + out + " " + in, "--margin: must be a number >= 0"},
             {"render --seed -1 -o " + out + ".png " + in, "--seed: must be an integer >= 0"},
             {"converge --timeout 2147483647 -o " + out + " " + in, "--timeout: must be"}}) {
        SCOPED_TRACE(c.args);
        Run r = run(c.args);
        EXPECT_EQ(r.exitCode, 2);
        EXPECT_NE(r.err.find(c.mention), std::string::npos) << r.err;
        EXPECT_EQ(strayFiles({"s.scad"}), std::vector<std::string>{});
    }
    // The largest values in range do not overflow: the .ini holds the product in full
    Run big = run("export -q -W 32768 -H 32768 --supersample 16 -o " + out + ".pov " + in);
    ASSERT_EQ(big.exitCode, 0) << big.err;
    EXPECT_NE(slurp(out + ".ini").find("Width=524288"), std::string::npos);
}

// ---- 3. Scenes that are not regular files ---------------------------------------------------

TEST_F(Hostile, FifoDeviceAndFolderScenesAreRefusedBeforeOpening) {
    std::string fifo = (dir / "pipe.scad").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    std::string zero = (dir / "zero.stl").string();
    fs::create_symlink("/dev/zero", zero);
    std::string folder = (dir / "folder.scad").string();
    fs::create_directory(folder);
    // A FIFO nobody writes to would block for ever if it were opened; /dev/zero never ends
    struct Case {
        std::string cmd, scene;
    };
    for (const auto &c :
         std::vector<Case>{{"render -W 8 -H 8 -o " + (dir / "x.png").string(), fifo},
                           {"dump", zero},
                           {"export -o " + (dir / "x.pov").string(), folder}}) {
        SCOPED_TRACE(c.cmd + " " + c.scene);
        Run r = run(c.cmd + " " + c.scene);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find(c.scene + ": is "), std::string::npos) << r.err;
    }
    EXPECT_EQ(strayFiles({"pipe.scad", "zero.stl", "folder.scad"}), std::vector<std::string>{});
    Run pipe = run("compare " + fifo + " " + zero);
    EXPECT_EQ(pipe.exitCode, 2);
    EXPECT_NE(pipe.err.find(fifo + ": is not a regular file"), std::string::npos) << pipe.err;
    Run empty = run("render ''");
    EXPECT_EQ(empty.exitCode, 2);
    EXPECT_NE(empty.err.find("empty file name"), std::string::npos) << empty.err;
}

/// In a forked child: interrupts at their default action, as on a terminal. A shell that starts
/// the tests in the background (`cmd &` in a script) ignores SIGINT, and a child would inherit
/// that, so neither it nor scadray (which leaves ignored signals ignored) would react.
void defaultInterruptSignals() {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, SIG_DFL);
}

/// waitpid, but a child still running after two minutes is killed and reported: a test must
/// fail, never hang the suite.
int waitOrKill(pid_t pid) {
    int status = 0;
    for (int i = 0; i < 24000; ++i) {
        if (::waitpid(pid, &status, WNOHANG) == pid) return status;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, &status, 0);
    ADD_FAILURE() << "child " << pid << " did not end within two minutes of the interrupt";
    return status;
}

// ---- 4. Temporaries: interrupts and long names ----------------------------------------------

TEST_F(Hostile, InterruptRemovesTheTemporaryOfAWrite) {
    // A child makes the temporary of an atomic write, then is interrupted mid-write; the
    // handler unlinks it and the child dies of SIGINT as if nothing had caught it
    std::string target = (dir / "picture.png").string();
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        defaultInterruptSignals();
        installInterruptCleanup();
        TempFile tmp(target, ".png");
        std::ofstream(tmp.path()) << "half";
        ::write(ready[1], "1", 1);
        for (;;) ::pause();
    }
    ::close(ready[1]);
    char c = 0;
    ASSERT_EQ(::read(ready[0], &c, 1), 1);
    ::close(ready[0]);
    EXPECT_EQ(strayFiles({}).size(), 1u);  // the temporary, while the write goes on
    ::kill(pid, SIGINT);
    int status = waitOrKill(pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
    EXPECT_TRUE(strayFiles({}).empty());
}

TEST_F(Hostile, InterruptedRenderLeavesNothing) {
    // A render long enough to be interrupted whenever the signal lands: in the evaluation,
    // the render or the write, nothing but the scene may remain
    std::string in = write("slow.scad", "sphere(1);\n");
    std::string out = (dir / "slow.exr").string();
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        defaultInterruptSignals();
        int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::dup2(null, 2);
        ::execl(SCADRAY_BINARY, SCADRAY_BINARY, "render", "-q", "-t", "1", "-W", "4000", "-H",
                "4000", "-s", "256", in.c_str(), "-o", out.c_str(), static_cast<char *>(nullptr));
        ::_exit(127);
    }
    // Interrupt once scadray catches SIGINT (its handler is installed): a signal earlier
    // would end it before it could write anything, proving nothing
    auto catchesSigint = [pid] {
        std::ifstream status("/proc/" + std::to_string(pid) + "/status");
        for (std::string line; std::getline(status, line);)
            if (line.rfind("SigCgt:", 0) == 0)
                return (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1) & 1) != 0;
        return false;
    };
    for (int i = 0; i < 2000 && !catchesSigint(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_TRUE(catchesSigint());
    ::kill(pid, SIGINT);
    int status = waitOrKill(pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
    EXPECT_EQ(strayFiles({"slow.scad"}), std::vector<std::string>{});
}

TEST_F(Hostile, InterruptStopsAnExternalRenderer) {
    // POV-Ray or OpenSCAD runs in its own process group, stopped by scadray at its time
    // limit; an interrupt of scadray must stop it too, or it runs on unbounded
    std::string pidFile = (dir / "child.pid").string();
    pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        defaultInterruptSignals();
        installInterruptCleanup();
        ProcessOptions po;
        po.timeoutSeconds = 60;
        runProcess({"sh", "-c",
                    "echo $$ > " + pidFile + ".tmp && mv " + pidFile + ".tmp " + pidFile +
                        " && exec sleep 60"},
                   po);
        ::_exit(0);
    }
    for (int i = 0; i < 2000 && !fs::exists(pidFile); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_TRUE(fs::exists(pidFile));
    pid_t child = std::stoi(slurp(pidFile));
    ::kill(pid, SIGINT);
    int status = waitOrKill(pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
    // The renderer is gone (or a zombie its new parent has yet to reap)
    auto running = [child] {
        std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
        std::string text((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
        size_t paren = text.rfind(')');
        return paren != std::string::npos && paren + 2 < text.size() && text[paren + 2] != 'Z';
    };
    for (int i = 0; i < 2000 && running(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    EXPECT_FALSE(running());
    if (running()) ::kill(child, SIGKILL);
}

TEST_F(Hostile, OutputNamesUpToTheFileSystemLimitWork) {
    std::string in = write("s.scad", "cube(1);\n");
    // 255 bytes is the longest name most file systems take; a temporary named after it
    // (".name.partial-PID.png") was refused
    std::string name = std::string(255 - 4, 'n') + ".png";
    Run r = run("render -q -W 8 -H 8 " + in + " -o " + (dir / name).string());
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / name));
    std::string pov = std::string(255 - 4, 'p') + ".pov";
    Run e = run("export -q " + in + " -o " + (dir / pov).string());
    EXPECT_EQ(e.exitCode, 0) << e.err;
    EXPECT_TRUE(fs::exists(dir / pov));
    EXPECT_EQ(strayFiles({"s.scad", name, pov, std::string(255 - 4, 'p') + ".ini"}),
              std::vector<std::string>{});
    // The new file has the permissions of any new file, not mkstemp's 0600
    mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(fs::status(dir / name).permissions(), static_cast<fs::perms>(0666 & ~mask));
}

// ---- 5. Other hostile arguments -------------------------------------------------------------

TEST_F(Hostile, BadOutputsAreUsageErrorsBeforeAnyWork) {
    std::string in = write("s.scad", "cube(1);\n");
    Run folder = run("render -W 8 -H 8 " + in + " -o " + dir.string());
    EXPECT_EQ(folder.exitCode, 2);
    EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
    Run slash = run("render -W 8 -H 8 " + in + " -o " + (dir / "sub/").string());
    EXPECT_EQ(slash.exitCode, 2) << slash.err;
    Run missing = run("render -W 8 -H 8 " + in + " -o " + (dir / "no/such/x.png").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.err.find("does not exist"), std::string::npos) << missing.err;
    Run pov = run("export " + in + " -o " + (dir / "nowhere" / "x.pov").string());
    EXPECT_EQ(pov.exitCode, 2) << pov.err;
    Run heat = run("compare --heat-map " + dir.string() + " " + in + " " + in);
    EXPECT_EQ(heat.exitCode, 2) << heat.err;
    Run define = run("dump -D =1 " + in);
    EXPECT_EQ(define.exitCode, 2) << define.err;
    // A non-UTF-8 file name is just bytes
    std::string odd = write("caf\xe9.scad", "cube(1);\n");
    Run o = run("render -q -W 8 -H 8 '" + odd + "' -o '" + (dir / "caf\xe9.png").string() + "'");
    EXPECT_EQ(o.exitCode, 0) << o.err;
    EXPECT_TRUE(fs::exists(dir / "caf\xe9.png"));
}

}  // namespace
}  // namespace rt
