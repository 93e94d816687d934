// SPDX-License-Identifier: MIT
// `-e` end to end: glTF models get the studio sky by default (a mirror sphere is not black and
// shows the gradient), `-e none` turns it off, `-e FILE.exr` lights the scene with a picture
// written by the project's image writer, and a bad environment file is an error that names it
// and writes nothing.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/image/image_io.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class EnvironmentCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              (std::string("scadray_env_") +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    /// Runs scadray with `args`; returns the exit code, stderr in `err`.
    int run(const std::string &args, std::string *err) {
        std::string cmd = std::string(SCADRAY_BINARY) + " " + args + " 2>" + (dir / "err").string();
        int status = std::system(cmd.c_str());
        std::ifstream in(dir / "err");
        std::stringstream ss;
        ss << in.rdbuf();
        *err = ss.str();
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    Image render(const std::string &extra, const std::string &format = ".png") {
        std::string out = (dir / ("out" + format)).string(), err;
        EXPECT_EQ(run("render -q -W 64 -H 48 -s 1 " + sphere + " -o " + out + " " + extra, &err), 0)
            << err;
        return readImage(out);
    }
    std::string sphere = std::string(SCADRAY_SOURCE_DIR) + "/scenes/gltf/mirror_sphere.gltf";
    fs::path dir;
};

/// Mean green over a small square of pixels around (x, y).
double greenAround(const Image &img, int x, int y) {
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += img.at(x + dx, y + dy).g;
    return sum / 9;
}

// The automatic viewer framing puts the mirror sphere's centre near (27, 26) of a 64 x 48
// picture, its top near row 13 and its bottom near row 38
TEST_F(EnvironmentCli, GltfMirrorSphereShowsTheStudioSky) {
    Image img = render("");
    double top = greenAround(img, 27, 16), middle = greenAround(img, 27, 26),
           bottom = greenAround(img, 27, 35);
    EXPECT_GT(middle, 0.2) << "the mirror must not be black";
    EXPECT_GT(top, bottom + 0.1) << "the sky above is brighter than the ground below";
    // The background is the sky itself: the bottom row looks below the horizon
    EXPECT_GT(img.at(63, 0).g, img.at(63, 47).g);
    Image none = render("-e none");
    EXPECT_LT(greenAround(none, 27, 26), 0.1) << "-e none: the mirror reflects black";
    EXPECT_EQ(none.at(63, 0).g, 0);
}

TEST_F(EnvironmentCli, ExrEnvironmentIsSeenAndReflected) {
    Image env(16, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 16; ++x) env.set(x, y, Rgb(0.25, 0.5, 1.5));
    std::string exr = (dir / "sky.exr").string();
    writeImage(env, exr);
    Image img = render("-e " + exr + " --env-rotate 30", ".exr");
    EXPECT_NEAR(img.at(63, 0).r, 0.25, 1e-4);
    EXPECT_NEAR(img.at(63, 0).b, 1.5, 1e-4);
    Rgb mirror = img.at(27, 26);
    EXPECT_GT(mirror.b, 2 * mirror.r) << "the mirror shows the blue environment";
}

TEST_F(EnvironmentCli, BadEnvironmentFileIsAnErrorNamingIt) {
    std::string bad = (dir / "broken.hdr").string();
    std::ofstream(bad) << "#?RADIANCE\nnot really\n";
    std::string out = (dir / "never.png").string();
    for (const std::string &env : {bad, (dir / "missing.exr").string()}) {
        std::string err;
        EXPECT_EQ(run("render -q -W 8 -H 8 " + sphere + " -o " + out + " -e " + env, &err), 1) << err;
        EXPECT_NE(err.find(fs::path(env).filename().string()), std::string::npos) << err;
        EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace rt
