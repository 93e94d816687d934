// SPDX-License-Identifier: MIT
// Hostile names and files around a render: scene names that POV-Ray, OpenSCAD or ffmpeg could
// read as options, pictures and curves that a check's figures name (links out, FIFOs,
// devices), outputs that would replace an input, output folders full of other files, terminal
// escapes in quoted file content, and an export that cannot finish.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "core/system/subprocess.h"
#include "tools/check.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class HostileNames : public test::CliTest {
  protected:
    HostileNames() : CliTest("scadray_names_") {}

    /// scadray with `args` and nothing on stdin, from inside the test folder (so that names
    /// are given as a user types them).
    test::CliRun runHere(const std::string &args) const {
        return run("--version >/dev/null; cd '" + dir.string() + "' && " +
                   std::string(SCADRAY_BINARY) + " " + args + " </dev/null");
    }
    /// `text` as one single-quoted shell word.
    static std::string quoted(const std::string &text) {
        std::string out = "'";
        for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
        return out + "'";
    }
    /// A small scene of its own (no library) in the test folder under `as`.
    void writeScene(const std::string &as) const {
        write(as, "sphere(4, $fn=24);\ntranslate([7, 0, 0]) cube(5, center=true);\n");
    }
    /// Every file below the test folder, relative names.
    std::vector<std::string> allFiles() const {
        std::vector<std::string> files;
        for (const auto &e : fs::recursive_directory_iterator(dir))
            files.push_back(fs::relative(e.path(), dir).string());
        return files;
    }
};

// ---- Names POV-Ray would read as options or cut -------------------------------------------

TEST_F(HostileNames, CheckNamesAreNeverPovRayOptions) {
    if (!programOnPath("povray")) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    // Each name once made `check` fail ("Problem with option setting") or made POV-Ray read
    // another file: a space splits the argument, KEY=VALUE and +X words are options, a '#'
    // or a quote ends a value
    const std::vector<std::string> names = {
        "my part", "evil +A0.3", "Include_Ini=evil", "a#b", "-x", "q\"uote", "[sq]", "semi;colon"};
    for (const std::string &name : names) {
        SCOPED_TRACE(name);
        std::string file = name + ".scad";
        writeScene(file);
        // The check's folder as an attacker ships it: an earlier check's figures beside an
        // .ini and a .pov that write a file if POV-Ray ever reads them
        fs::create_directories(dir / "out");
        write("out/stale_check.json", "{}");
        std::string trap = "#version 3.7;\n#fopen F \"pwned.txt\" write\n#write (F, \"x\")\n";
        for (const char *planted : {"evil.pov", "evil.ini", "povray.ini", "scene.pov"})
            write(std::string("out/") + planted,
                  std::string(planted).find(".ini") != std::string::npos
                      ? "Input_File_Name=evil.pov\nPre_Scene_Command=touch pwned.txt\n"
                      : trap);
        std::string arg = name[0] == '-' ? "./" + file : file;
        test::CliRun r = runHere("check " + quoted(arg) + " -W 32 -H 24 -s 2 -o out");
        EXPECT_TRUE(r.out.rfind("PASS: ", 0) == 0 || r.out.rfind("DIFFERENT: ", 0) == 0)
            << r.out << r.err;
        EXPECT_EQ(r.err.find("Problem with option"), std::string::npos) << r.err;
        for (const std::string &f : allFiles())
            EXPECT_EQ(f.find("pwned"), std::string::npos) << "POV-Ray read a planted file: " << f;
        // The figures are where report --from looks for them
        EXPECT_TRUE(fs::exists(cli::checkJsonPath((dir / "out").string(), file, false)));
        // No temporary folder of the run is left
        for (const auto &e : fs::directory_iterator(dir / "out"))
            EXPECT_EQ(e.path().filename().string().rfind(".scadray-", 0), std::string::npos)
                << e.path();
    }
}

TEST_F(HostileNames, ReportChecksNamesWithSpacesHashesAndDashes) {
    if (!programOnPath("povray")) GTEST_SKIP() << "POV-Ray (povray) is not installed";
    for (const char *name : {"my part.scad", "a#b.scad", "-x.scad"}) writeScene(name);
    // Through a list too, where the '#' inside a name is part of it
    write("list.txt", "# three awkward names\na#b.scad\n-x.scad\n");
    test::CliRun r = runHere("report -q -W 24 -H 18 'my part.scad' list.txt -o r.html");
    std::string page = slurp(dir / "r.html");
    ASSERT_FALSE(page.empty()) << r.err;
    for (const char *name : {"my part.scad", "a#b.scad", "-x.scad"}) {
        SCOPED_TRACE(name);
        EXPECT_NE(page.find(name), std::string::npos);
    }
    // Every scene has its verdict: none ended in an error
    EXPECT_EQ(page.find("data-verdict=\"error\""), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Problem with option"), std::string::npos) << r.err;
}

TEST_F(HostileNames, SafeFileStemsCannotBeOptions) {
    EXPECT_EQ(cli::safeFileStem("dir/my part.scad"), "my_part");
    EXPECT_EQ(cli::safeFileStem("-ofoo.scad"), "_ofoo");
    EXPECT_EQ(cli::safeFileStem("+A0.3.scad"), "_A0.3");
    EXPECT_EQ(cli::safeFileStem("Include_Ini=evil.scad"), "Include_Ini_evil");
    EXPECT_EQ(cli::safeFileStem(".hidden.scad"), "_hidden");
    EXPECT_EQ(cli::safeFileStem("a#b.scad"), "a_b");
    EXPECT_EQ(cli::safeFileStem(".scad"), "_scad");
    EXPECT_EQ(cli::safeFileStem(""), "scene");
    EXPECT_TRUE(cli::isSafeFileStem("evil__A0.3"));
    for (const char *unsafe : {"", "-x", ".x", "a b", "a=b", "+A", "a\"b"})
        EXPECT_FALSE(cli::isSafeFileStem(unsafe)) << unsafe;
    EXPECT_EQ(fileArgument("-ofoo.scad"), "./-ofoo.scad");
    EXPECT_EQ(fileArgument("+A.ini"), "./+A.ini");
    EXPECT_EQ(fileArgument("/abs/-x"), "/abs/-x");
}

TEST_F(HostileNames, ReportHandsOpenScadNoOptionForAName) {
    if (!programOnPath("openscad")) GTEST_SKIP() << "OpenSCAD (openscad) is not installed";
    // A list's line relative to a list in the working folder once reached OpenSCAD as
    // `-ofoo.scad`: an output option, which wrote foo.scad
    write("-ofoo.scad", "cube(5);\n");
    write("list.txt", "-ofoo.scad\n");
    test::CliRun r = runHere("report --openscad -q -W 24 -H 18 list.txt -o r.html");
    EXPECT_FALSE(fs::exists(dir / "foo.scad")) << r.err;
    std::string page = slurp(dir / "r.html");
    EXPECT_NE(page.find("-ofoo.scad"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Unknown option"), std::string::npos) << r.err;
}

// ---- What report --from embeds ---------------------------------------------------------------

TEST_F(HostileNames, ReportFromEmbedsOnlyPicturesInsideTheFolder) {
    write("secret.txt", "TOP-SECRET-CONTENT");
    fs::create_directories(dir / "checks");
    cli::CheckResult r;
    r.scene = "x.scad";
    r.referee = "povray";
    r.width = 4;
    r.height = 3;
    r.refereePicture = "link.png";
    r.scadrayPicture = "fifo.png";
    r.diffPicture = "zero.png";
    write("checks/x_check.json", cli::checkResultJson(r));
    fs::create_symlink(dir / "secret.txt", dir / "checks/link.png");
    ASSERT_EQ(::mkfifo((dir / "checks/fifo.png").c_str(), 0600), 0);
    fs::create_symlink("/dev/zero", dir / "checks/zero.png");
    // Converge's files beside it: a CSV linked to /dev/zero, an SVG that is a FIFO
    fs::create_symlink("/dev/zero", dir / "checks/x_converge.csv");
    ASSERT_EQ(::mkfifo((dir / "checks/x_converge.svg").c_str(), 0600), 0);
    auto start = std::chrono::steady_clock::now();
    test::CliRun run = runHere("report --from checks -o page.html");
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, 60) << "a FIFO or /dev/zero was read";
    std::string page = slurp(dir / "page.html");
    ASSERT_FALSE(page.empty()) << run.err;
    // "TOP-SECRET-CONTENT" in base64, at either alignment the page could hold it
    EXPECT_EQ(page.find("VE9QLVNFQ1JFVC1DT05URU5U"), std::string::npos);
    EXPECT_EQ(page.find("TOP-SECRET"), std::string::npos);
    EXPECT_NE(run.err.find("link.png"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("not a regular file"), std::string::npos) << run.err;
}

TEST_F(HostileNames, ReportFromRefusesPicturesNamedOutsideTheFolder) {
    write("secret.png", "TOP-SECRET-CONTENT");
    fs::create_directories(dir / "checks");
    cli::CheckResult r;
    r.scene = "y.scad";
    r.width = 4;
    r.height = 3;
    r.refereePicture = "../secret.png";
    r.scadrayPicture = (dir / "secret.png").string();
    write("checks/y_check.json", cli::checkResultJson(r));
    test::CliRun run = runHere("report --from checks -o page.html");
    std::string page = slurp(dir / "page.html");
    ASSERT_FALSE(page.empty()) << run.err;
    EXPECT_EQ(page.find("VE9QLVNFQ1JFVC1DT05URU5U"), std::string::npos);
    // A name that is a path is no picture of the check's at all: not even linked
    EXPECT_EQ(page.find("secret.png"), std::string::npos);
}

// ---- Outputs that would replace inputs -------------------------------------------------------

TEST_F(HostileNames, CompareNeverWritesItsHeatMapOverAnInput) {
    test::CliRun made =
        runHere("render " + scene("crosscheck/primitives.scad") + " -W 16 -H 12 -s 1 -o a.png");
    ASSERT_EQ(made.exitCode, 0) << made.err;
    fs::copy_file(dir / "a.png", dir / "b.png");
    fs::create_symlink("a.png", dir / "alias.png");
    std::string before = slurp(dir / "a.png");
    for (const char *target : {"a.png", "alias.png", "./b.png"}) {
        SCOPED_TRACE(target);
        test::CliRun r = runHere(std::string("compare a.png b.png --heat-map ") + target);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find("it is a file this command reads"), std::string::npos) << r.err;
    }
    EXPECT_EQ(slurp(dir / "a.png"), before);
    EXPECT_TRUE(fs::is_symlink(dir / "alias.png"));
}

TEST_F(HostileNames, RenderNeverWritesOverAFileTheSceneReads) {
    // A height map the scene reads is no place for its picture
    test::CliRun made =
        runHere("render " + scene("crosscheck/primitives.scad") + " -W 8 -H 8 -s 1 -o map.png");
    ASSERT_EQ(made.exitCode, 0) << made.err;
    write("s.scad", "surface(file=\"map.png\");\n");
    std::string before = slurp(dir / "map.png");
    test::CliRun r = runHere("render s.scad -W 8 -H 8 -s 1 -o map.png");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("it is a file this command reads"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "map.png"), before);
}

TEST_F(HostileNames, CheckRefusesAFolderOfOtherFiles) {
    // A model's own folder: its texture is named like one of the check's pictures
    fs::create_directories(dir / "model");
    writeScene("model/part.scad");
    write("model/part_diff.png", "texture");
    test::CliRun r = runHere("check model/part.scad -W 8 -H 6 -o model");
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("-o: 'model' holds other files"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir / "model/part_diff.png"), "texture");
    std::vector<std::string> inModel;
    for (const auto &e : fs::directory_iterator(dir / "model"))
        inModel.push_back(e.path().filename().string());
    EXPECT_EQ(inModel.size(), 2u) << "check wrote into the model's folder";
}

// ---- Terminal escapes ------------------------------------------------------------------------

TEST_F(HostileNames, DiagnosticsEscapeControlCharacters) {
    // A warning quoting its line, a name with escapes, and echo() text
    write("esc.scad",
          "x = undefined_thing; // \x1b]0;pwned\x07\x1b[2J\n"
          "echo(\"\\x1b[31mred\");\n"
          "import(\"\x1b[2Jmissing.stl\");\n");
    test::CliRun r = runHere("render esc.scad -W 8 -H 6 -s 1 -o esc.png");
    EXPECT_EQ(r.err.find('\x1b'), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\x07'), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\\x1b]0;pwned\\x07"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\\x1b[31mred"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("\\x1b[2Jmissing"), std::string::npos) << r.err;
}

// ---- The tools around a render: ffmpeg, the export ------------------------------------------

TEST_F(HostileNames, FramesUnderAFolderWithAPercentMakeAVideo) {
    if (!programOnPath("ffmpeg")) GTEST_SKIP() << "ffmpeg (with ffprobe) is not installed";
    write("spin.scad", "rotate([0, 0, 360 * $t]) cube([4, 2, 1], center=true);\n");
    fs::create_directories(dir / "50%d");
    test::CliRun r = runHere("render spin.scad --frames 3 -W 16 -H 12 -s 1 -o '50%d/f.png'");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "50%d/f_0002.png"));
    EXPECT_GT(fs::file_size(dir / "50%d/f.mp4"), 0u) << r.err;
}

TEST_F(HostileNames, FpsFfmpegCannotTakeIsAUsageErrorBeforeAnyFrame) {
    write("spin.scad", "rotate([0, 0, 360 * $t]) cube(1);\n");
    for (const char *fps : {"1e-300", "0.0001", "0"}) {
        SCOPED_TRACE(fps);
        test::CliRun r = runHere(std::string("render spin.scad --frames 2 --fps ") + fps +
                                 " -W 8 -H 6 -o f.png");
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find("--fps"), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir / "f_0000.png"));
    }
}

TEST_F(HostileNames, ExportThatCannotFinishLeavesNoFile) {
    // A textured model: its texture is written before its .pov; with a file-size limit that
    // the texture fits and the .pov does not, the export once left the texture behind
    std::string model = std::string(SCADRAY_SOURCE_DIR) + "/tests/data/gltf/texaddr_wrap.gltf";
    test::CliRun full = runHere("export " + model + " -o full.pov");
    ASSERT_EQ(full.exitCode, 0) << full.err;
    std::vector<std::string> written;
    uintmax_t smallest = UINTMAX_MAX, largest = 0;
    for (const auto &e : fs::directory_iterator(dir)) {
        std::string name = e.path().filename().string();
        if (name.rfind("full", 0) != 0) continue;
        written.push_back(name);
        smallest = std::min(smallest, fs::file_size(e.path()));
        largest = std::max(largest, fs::file_size(e.path()));
    }
    ASSERT_GE(written.size(), 3u) << "no texture was exported";
    // ulimit -f counts 1024-byte blocks: the smallest file fits, the largest does not
    uintmax_t blocks = (smallest + largest) / 2 / 1024;
    ASSERT_LT(smallest, blocks * 1024);
    ASSERT_GT(largest, blocks * 1024);
    // SIGXFSZ ignored, so that a write past the limit fails with EFBIG as on a full disk
    test::CliRun r =
        run("--version >/dev/null; cd '" + dir.string() + "' && trap '' XFSZ && ulimit -f " +
            std::to_string(blocks) + " && " + std::string(SCADRAY_BINARY) + " export " + model +
            " -o cut.pov </dev/null");
    EXPECT_NE(r.exitCode, 0);
    for (const std::string &f : allFiles()) {
        EXPECT_NE(f.rfind("cut", 0), 0u) << "left behind: " << f;
        EXPECT_NE(f.rfind(".scadray-", 0), 0u) << "left behind: " << f;
    }
}

}  // namespace
}  // namespace rt
