// SPDX-License-Identifier: MIT
// The input reader: regular files only, never blocking, never past its cap, confined to a
// folder where asked; outputs that would replace an input; text made safe for a terminal.
#include "core/system/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/system/temp_file.h"
#include "support/temp_dir_test.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class InputFile : public test::TempDirTest {
  protected:
    // Each test starts with no file noted: an inode of an earlier test's deleted file may
    // come back as one of this test's
    InputFile() : TempDirTest("scadray_input_file_") { forgetInputFiles(); }
    std::string file(const std::string &name, const std::string &text) const {
        std::string p = (dir / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    /// The refusal of reading `path`, and that it came at once.
    static InputFileError refusal(const std::string &path, uint64_t cap = 1 << 20) {
        auto start = std::chrono::steady_clock::now();
        try {
            readInputFile(path, cap);
        } catch (const InputFileError &e) {
            EXPECT_LT(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                5.0);
            return e;
        }
        ADD_FAILURE() << path << " was read";
        return InputFileError(InputFileError::Reason::Unreadable, "");
    }
};

TEST_F(InputFile, ReadsARegularFileAndALinkToOne) {
    std::string p = file("a.txt", "hello");
    EXPECT_EQ(readInputFile(p, 5), "hello");
    fs::create_symlink(p, dir / "link.txt");
    EXPECT_EQ(readInputFile((dir / "link.txt").string(), 100), "hello");
    EXPECT_EQ(checkInputFile(p, 5), 5u);
}

TEST_F(InputFile, RefusesFifosDevicesFoldersAndLinksToThem) {
    std::string fifo = (dir / "fifo").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fs::create_symlink(fifo, dir / "fifo_link");
    fs::create_symlink("/dev/zero", dir / "zero_link");
    for (const std::string &p : {fifo, (dir / "fifo_link").string(), std::string("/dev/zero"),
                                 (dir / "zero_link").string(), dir.string()}) {
        SCOPED_TRACE(p);
        InputFileError e = refusal(p);
        EXPECT_EQ(e.reason(), InputFileError::Reason::NotRegular) << e.what();
        EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos);
    }
}

TEST_F(InputFile, ProcFilesReadAsTheirDeclaredSize) {
    // A /proc file declares size 0 and is cut there: nothing unbounded is read
    EXPECT_EQ(readInputFile("/proc/self/status", 1 << 20), "");
}

TEST_F(InputFile, RefusesAFileOverTheCapBeforeReading) {
    std::string p = file("big.txt", std::string(1000, 'x'));
    InputFileError e = refusal(p, 999);
    EXPECT_EQ(e.reason(), InputFileError::Reason::TooLarge);
    EXPECT_NE(std::string(e.what()).find("1000 bytes, more than the limit of 999"),
              std::string::npos);
    EXPECT_EQ(refusal((dir / "missing").string()).reason(), InputFileError::Reason::Missing);
}

TEST_F(InputFile, ConfinedReadsStayInTheirFolder) {
    fs::create_directories(dir / "in/sub");
    file("secret.txt", "secret");
    file("in/sub/ok.txt", "ok");
    std::string in = (dir / "in").string();
    EXPECT_EQ(readInputFileIn(in, "sub/ok.txt", 100), "ok");
    fs::create_symlink(dir / "in/sub/ok.txt", dir / "in/inner_link");
    EXPECT_EQ(readInputFileIn(in, "inner_link", 100), "ok");
    fs::create_symlink(dir / "secret.txt", dir / "in/outer_link");
    fs::create_symlink("/dev/zero", dir / "in/zero");
    for (const std::string &name :
         {std::string("../secret.txt"), (dir / "secret.txt").string(), std::string("outer_link"),
          std::string("zero"), std::string("sub/../../secret.txt"), std::string("")}) {
        SCOPED_TRACE(name);
        EXPECT_THROW(readInputFileIn(in, name, 100), InputFileError);
    }
}

TEST_F(InputFile, OutputsNeverReplaceAnInput) {
    std::string p = file("input.png", "pixels");
    fs::create_symlink(p, dir / "alias.png");
    fs::create_hard_link(p, dir / "hard.png");
    readInputFile(p, 100);
    for (const char *name : {"input.png", "alias.png", "hard.png"}) {
        SCOPED_TRACE(name);
        std::string target = (dir / name).string();
        EXPECT_THROW(refuseOverwritingInput(target), std::runtime_error);
        EXPECT_THROW(TempFile t(target), std::runtime_error);
    }
    EXPECT_NO_THROW(refuseOverwritingInput((dir / "other.png").string()));
    // Noted without reading (a name a library opens itself)
    std::string q = file("texture.png", "t");
    noteInputFile(q);
    EXPECT_THROW(refuseOverwritingInput(q), std::runtime_error);
    // A temporary written before its target was read is not renamed over it either
    std::string late = file("late.png", "l");
    {
        TempFile t(late);
        readInputFile(late, 10);
        EXPECT_THROW(t.commit(), std::runtime_error);
    }
    std::ifstream in(late);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(text, "l");
}

TEST_F(InputFile, PrintableEscapesTerminalControls) {
    EXPECT_EQ(printable("plain \xc3\xa9t\xc3\xa9\ttab"), "plain \xc3\xa9t\xc3\xa9\ttab");
    EXPECT_EQ(printable("\x1b]0;title\x07"), "\\x1b]0;title\\x07");
    EXPECT_EQ(printable("\x1b[2J\x7f"), "\\x1b[2J\\x7f");
    // CSI as a C1 control in UTF-8
    EXPECT_EQ(printable("a\xc2\x9b"
                        "31mb"),
              "a\\xc2\\x9b31mb");
    EXPECT_EQ(printable("line\nnext"), "line\\x0anext");
    EXPECT_EQ(printable("line\nnext", true), "line\nnext");
    EXPECT_EQ(printable("cr\r"), "cr\\x0d");
}

}  // namespace
}  // namespace rt
