// SPDX-License-Identifier: MIT
// End-to-end tests of `scadray render --frames`: frame names, $t reaching the geometry and the
// $vp* camera (against `openscad --animate` where it is installed), single frames of a job
// array, the ffmpeg video, --encode-only, and the usage errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <vector>

#include "core/image/image_io.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;
using test::CliRun;

bool onPath(const std::string &program) {
    return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

/// A box sliding along +X with $t, seen by a camera that does not move.
const char *kSlidingBox = R"(
$vpr = [0, 0, 0];
$vpt = [10, 0, 0];
$vpd = 60;
translate([20 * $t, 0, 0]) cube([4, 4, 1], center = true);
)";

/// A still, asymmetric model with the camera turning about it.
const char *kTurningCamera = R"(
$vpr = [60, 0, 360 * $t];
$vpt = [0, 0, 0];
$vpd = 50;
cube([10, 3, 2]);
)";

class Animation : public test::CliTest {
  protected:
    Animation() : CliTest("scadray_anim_") {}

    /// Files in the test folder, sorted.
    std::vector<std::string> files() const {
        std::vector<std::string> names;
        for (const auto &e : fs::directory_iterator(dir))
            names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    /// Frames of a video, counted by decoding them all.
    int videoFrames(const std::string &video) {
        std::string out = path("ffprobe.txt");
        std::string cmd =
            "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=nb_read_frames -of csv=p=0 " +
            video + " >" + out + " 2>&1";
        if (std::system(cmd.c_str()) != 0) return -1;
        return std::atoi(slurp(out).c_str());
    }
};

/// Mean x of the pixels that differ from the top-left (background) pixel; -1 when none.
double objectCentreX(const Image &img) {
    double sum = 0;
    int count = 0;
    Rgb bg = img.at(0, 0);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            Rgb c = img.at(x, y);
            if (std::abs(c.r - bg.r) + std::abs(c.g - bg.g) + std::abs(c.b - bg.b) > 0.1) {
                sum += x;
                ++count;
            }
        }
    return count ? sum / count : -1;
}

/// Share of pixels whose colours differ by more than `tol` in some channel.
double differingShare(const Image &a, const Image &b, double tol = 0.02) {
    EXPECT_EQ(a.width(), b.width());
    EXPECT_EQ(a.height(), b.height());
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            Rgb p = a.at(x, y), q = b.at(x, y);
            if (std::abs(p.r - q.r) > tol || std::abs(p.g - q.g) > tol || std::abs(p.b - q.b) > tol)
                ++n;
        }
    return double(n) / (double(a.width()) * a.height());
}

TEST_F(Animation, FramesAreNamedAndCounted) {
    std::string scene = write("box.scad", kSlidingBox);
    // Without ffmpeg on PATH: the frames, one warning naming ffmpeg, exit 0
    CliRun r = run("render -q -W 16 -H 12 --frames 3 " + scene + " -o " + path("a.png"),
                   "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ((std::vector<std::string>{"a_0000.png", "a_0001.png", "a_0002.png", "box.scad",
                                        "stderr", "stdout"}),
              files());
    std::regex warning("warning:.*ffmpeg");
    auto begin = std::sregex_iterator(r.err.begin(), r.err.end(), warning);
    EXPECT_EQ(std::distance(begin, std::sregex_iterator()), 1) << r.err;
    // EXR frames likewise
    r = run("render -q -W 16 -H 12 --frames 2 " + scene + " -o " + path("lin.exr"),
            "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "lin_0000.exr"));
    EXPECT_TRUE(fs::exists(dir / "lin_0001.exr"));
    // More than 10,000 frames: as many digits as the last frame needs
    r = run("render -q -W 8 -H 6 --frames 10001 --frame 5 " + scene + " -o " + path("long.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "long_00005.png"));
    r = run("render -q -W 8 -H 6 --frames 10000 --frame 9999 " + scene + " -o " + path("four.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "four_9999.png"));
}

TEST_F(Animation, TimeMovesTheGeometry) {
    std::string scene = write("box.scad", kSlidingBox);
    CliRun r = run("render -q -W 64 -H 48 --frames 4 " + scene + " -o " + path("a.png"),
                   "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The box moves right by 5 units a frame; the camera stays
    double previous = -1;
    for (int i = 0; i < 4; ++i) {
        double x = objectCentreX(readImage(path("a_000" + std::to_string(i) + ".png")));
        SCOPED_TRACE(i);
        ASSERT_GE(x, 0);
        if (i > 0) {
            EXPECT_GT(x, previous + 3);
        }
        previous = x;
    }
}

TEST_F(Animation, ViewportVariablesMoveTheCamera) {
    std::string scene = write("turn.scad", kTurningCamera);
    CliRun r = run("render -q -W 48 -H 36 --frames 4 " + scene + " -o " + path("a.png"),
                   "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Image f0 = readImage(path("a_0000.png")), f1 = readImage(path("a_0001.png"));
    // The model does not move, the pictures do
    EXPECT_GT(differingShare(f0, f1), 0.02);
    // Frame 1 ($t = 0.25) is the still picture with the camera at $vpr = [60, 0, 90], bit
    // for bit (-D '$t=0.25' would not do: like OpenSCAD, $vpr reads $t before -D sets it)
    std::string still = std::string(kTurningCamera);
    still.replace(still.find("360 * $t"), 8, "90");
    r = run("render -q -W 48 -H 36 " + write("still.scad", still) + " -o " + path("still.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(differingShare(f1, readImage(path("still.png")), 0), 0);
}

TEST_F(Animation, OneFrameOfAJobArrayEqualsTheFullRun) {
    std::string scene = write("turn.scad", kTurningCamera);
    CliRun r = run("render -q -W 40 -H 30 -s 4 --frames 5 " + scene + " -o " + path("all.png"),
                   "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    r = run("render -q -W 40 -H 30 -s 4 --frames 5 --frame 3 " + scene + " -o " + path("one.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Only that frame, and no video
    EXPECT_EQ(
        (std::vector<std::string>{"all_0000.png", "all_0001.png", "all_0002.png", "all_0003.png",
                                  "all_0004.png", "one_0003.png", "stderr", "stdout", "turn.scad"}),
        files());
    EXPECT_EQ(slurp(dir / "all_0003.png"), slurp(dir / "one_0003.png"));
    EXPECT_EQ(differingShare(readImage(path("all_0003.png")), readImage(path("one_0003.png")), 0),
              0);
}

TEST_F(Animation, FailingFrameIsNamed) {
    std::string scene = write("fails.scad", "assert($t < 0.5, \"too late\");\ncube(1);\n");
    CliRun r = run("render -q -W 8 -H 6 --frames 4 " + scene + " -o " + path("a.png"));
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("frame 2 of 4"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("too late"), std::string::npos) << r.err;
    // The frames before it are written, nothing of it or after it (no temporary left)
    EXPECT_EQ(
        (std::vector<std::string>{"a_0000.png", "a_0001.png", "fails.scad", "stderr", "stdout"}),
        files());
}

TEST_F(Animation, VideoHasEveryFrame) {
    if (!onPath("ffmpeg") || !onPath("ffprobe"))
        GTEST_SKIP() << "ffmpeg (with ffprobe) is not installed";
    std::string scene = write("box.scad", kSlidingBox);
    // An odd width and height: H.264 in yuv420p needs them even
    CliRun r = run("render -q -W 17 -H 13 --frames 5 --fps 10 " + scene + " -o " + path("a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(videoFrames(path("a.mp4")), 5);
    r = run("render -q -W 17 -H 13 --frames 5 --video " + path("b.gif") + " " + scene + " -o " +
            path("b.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(videoFrames(path("b.gif")), 5);
    // EXR frames make a video too
    r = run("render -q -W 16 -H 12 --frames 3 " + scene + " -o " + path("c.exr"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(videoFrames(path("c.mp4")), 3);
}

TEST_F(Animation, EncodeOnlyUsesTheFramesThere) {
    if (!onPath("ffmpeg") || !onPath("ffprobe"))
        GTEST_SKIP() << "ffmpeg (with ffprobe) is not installed";
    std::string scene = write("box.scad", kSlidingBox);
    // Frames rendered one by one, as a job array does, then encoded by a last job
    for (int i = 0; i < 4; ++i) {
        CliRun r = run("render -q -W 16 -H 12 --frames 4 --frame " + std::to_string(i) + " " +
                       scene + " -o " + path("a.png"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir / "a.mp4"));
    // A stray later frame is not taken in
    fs::copy_file(dir / "a_0000.png", dir / "a_0004.png");
    CliRun r = run("render --frames 4 --encode-only -o " + path("a.png"));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(videoFrames(path("a.mp4")), 4);
    // A missing frame is named, and no video is written
    fs::remove(dir / "a_0002.png");
    r = run("render --frames 4 --encode-only --video " + path("b.mp4") + " -o " + path("a.png"));
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("frame 2 of 4"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("a_0002.png"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "b.mp4"));
}

TEST_F(Animation, BadCombinationsAreUsageErrors) {
    std::string scene = write("box.scad", kSlidingBox);
    std::string mesh = write("tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    std::string o = " -o " + path("a.png");
    for (const std::string &args : std::vector<std::string>{
             "--frame 1 " + scene + o,                      // --frame needs --frames
             "--fps 10 " + scene + o,                       // so do --fps,
             "--video " + path("v.mp4") + " " + scene + o,  // --video
             "--encode-only" + o,                           // and --encode-only
             "--frames 0 " + scene + o,                     // at least one frame
             "--frames 4 --frame 4 " + scene + o,           // frames 0..3
             "--frames 4 --frame 1 --video " + path("v.mp4") + " " + scene + o,  // no video then
             "--frames 4 --frame 1 --encode-only" + o, "--frames 4 --fps 0 " + scene + o,
             "--frames 4 --video " + path("v.avi") + " " + scene + o,  // .mp4 or .gif
             "--frames 4 " + scene + " -o " + path("a.jpg"),           // .png or .exr frames
             "--frames 4 " + mesh + o,                                 // static scene
             std::string("--frames 4 --encode-only"),                  // which frames?
             "--frames 4",                                             // no scene
         }) {
        CliRun r = run("render -q -W 8 -H 6 " + args);
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.err;
    }
    EXPECT_EQ((std::vector<std::string>{"box.scad", "stderr", "stdout", "tri.off"}), files());
}

/// `openscad --animate N` as the oracle: the same $t (bit for bit: 3 * (1.0 / 10) is not
/// 3 / 10) and $vpr per frame, and per frame the same geometry.
TEST_F(Animation, MatchesOpenScadAnimate) {
    if (!onPath("openscad")) GTEST_SKIP() << "OpenSCAD (openscad) is not installed";
    std::string scene = write("anim.scad", R"(mesh = "";
echo(t = $t, exact = $t == round($t * 10) * (1 / 10), divided = $t == round($t * 10) / 10,
     vpr = $vpr);
$vpr = [60, 0, 30 + 90 * $t];
$vpt = [10, 0, 2];
$vpd = 80;
if (mesh == "")
    translate([20 * $t, 0, 0]) rotate([0, 0, 90 * $t]) {
        cube([8, 4, 3]);
        translate([0, 0, 3]) cylinder(r = 2, h = 4 + 4 * $t, $fn = 8);
    }
else
    import(mesh);
)");
    // The ECHO lines of each frame, in order
    auto echoes = [](const std::string &text) {
        std::vector<std::string> lines;
        std::regex re("ECHO: [^\n]*");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), re);
             it != std::sregex_iterator(); ++it)
            lines.push_back(it->str());
        return lines;
    };
    std::string cmd = "cd " + dir.string() +
                      " && openscad --animate 10 -o anim.echo anim.scad "
                      ">openscad.log 2>&1 && openscad --animate 10 -o g.stl anim.scad "
                      ">>openscad.log 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir / "openscad.log");
    std::vector<std::string> theirs = echoes(slurp(dir / "anim.echo"));
    ASSERT_EQ(theirs.size(), 10u);
    EXPECT_NE(theirs[3].find("divided = false"), std::string::npos) << theirs[3];

    CliRun r =
        run("render -W 64 -H 48 --facets openscad --frames 10 " + scene + " -o " + path("ours.png"),
            "PATH=/nonexistent");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(echoes(r.err), theirs);

    // OpenSCAD's mesh of frame k (g0000k.stl), traced through frame k's camera, against
    // scadray's frame k; and, to show the comparison can fail, frame 3's mesh in frame 1
    auto theirsFrame = [&](int k, int meshFrame) {
        std::string out = "theirs" + std::to_string(k) + "m" + std::to_string(meshFrame) + ".png";
        CliRun t = run("render -q -W 64 -H 48 --facets openscad --frames 10 --frame " +
                       std::to_string(k) + " " + scene + " -o " + path(out) + " -D 'mesh=\"" +
                       path("g0000" + std::to_string(meshFrame) + ".stl") + "\"'");
        EXPECT_EQ(t.exitCode, 0) << t.err;
        return readImage(path(out.substr(0, out.size() - 4) + "_000" + std::to_string(k) + ".png"));
    };
    for (int k = 0; k < 10; k += 3) {
        SCOPED_TRACE(k);
        Image ours = readImage(path("ours_000" + std::to_string(k) + ".png"));
        EXPECT_LT(differingShare(ours, theirsFrame(k, k)), 0.01);
    }
    EXPECT_GT(differingShare(readImage(path("ours_0001.png")), theirsFrame(1, 3)), 0.05);
}

}  // namespace
}  // namespace rt
