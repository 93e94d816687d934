// SPDX-License-Identifier: MIT
// `-e` end to end: glTF models get the studio sky by default (a mirror sphere is not black and
// shows the gradient), `-e none` turns it off, `-e FILE.hdr` (a Radiance file written here,
// read through OpenImageIO) is seen and reflected, and a bad environment file is an error that
// names it and writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/image/image_io.h"
#include "tools/cli_fixture.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class EnvironmentCli : public test::CliTest {
  protected:
    EnvironmentCli() : CliTest("scadray_env_") {}

    Image render(const std::string &extra) {
        std::string out = (dir / "out.png").string();
        test::CliRun r = run("render -q -W 64 -H 48 -s 1 " + sphere + " -o " + out + " " + extra);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return readImage(out);
    }
    std::string sphere = scene("gltf/mirror_sphere.gltf");
};

/// Mean green over a small square of pixels around (x, y).
double greenAround(const Image &img, int x, int y) {
    double sum = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) sum += img.at(x + dx, y + dy).g;
    return sum / 9;
}

// The automatic viewer framing puts the mirror sphere's centre near (27.5, 23.6) of a 64 x 48
// picture, its top near row 14 and its bottom near row 32
TEST_F(EnvironmentCli, GltfMirrorSphereShowsTheStudioSky) {
    Image img = render("");
    double top = greenAround(img, 27, 17), middle = greenAround(img, 27, 24),
           bottom = greenAround(img, 27, 30);
    EXPECT_GT(middle, 0.2) << "the mirror must not be black";
    EXPECT_GT(top, bottom + 0.1) << "the sky above is brighter than the ground below";
    // The background is the sky itself: the bottom row looks below the horizon
    EXPECT_GT(img.at(63, 0).g, img.at(63, 47).g);
    Image none = render("-e none");
    EXPECT_LT(greenAround(none, 27, 24), 0.1) << "-e none: the mirror reflects black";
    EXPECT_EQ(none.at(63, 0).g, 0);
}

/// A flat Radiance .hdr file (uncompressed RGBE scanlines) of one colour.
void writeFlatHdr(const std::string &path, int w, int h, const Rgb &c) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << h << " +X " << w << "\n";
    int e;
    double m = std::frexp(std::max({c.r, c.g, c.b}), &e);
    double scale = m * 256 / std::max({c.r, c.g, c.b});
    unsigned char px[4] = {
        static_cast<unsigned char>(c.r * scale), static_cast<unsigned char>(c.g * scale),
        static_cast<unsigned char>(c.b * scale), static_cast<unsigned char>(e + 128)};
    for (int i = 0; i < w * h; ++i) out.write(reinterpret_cast<const char *>(px), 4);
}

TEST_F(EnvironmentCli, HdrEnvironmentIsSeenAndReflected) {
    // (0.25, 0.5, 0.875) is exact in RGBE
    std::string hdr = (dir / "sky.hdr").string();
    writeFlatHdr(hdr, 16, 8, Rgb(0.25, 0.5, 0.875));
    Image img = render("-e " + hdr + " --env-rotate 30");
    EXPECT_NEAR(img.at(63, 0).r, 0.25, 0.005);  // 8-bit PNG
    EXPECT_NEAR(img.at(63, 0).b, 0.875, 0.005);
    Rgb mirror = img.at(27, 24);
    EXPECT_GT(mirror.b, 2 * mirror.r) << "the mirror shows the blue environment";
}

TEST_F(EnvironmentCli, BadEnvironmentFileIsAnErrorNamingIt) {
    std::string bad = (dir / "broken.hdr").string();
    std::ofstream(bad) << "#?RADIANCE\nnot really\n";
    std::string out = (dir / "never.png").string();
    for (const std::string &env : {bad, (dir / "missing.exr").string()}) {
        test::CliRun r = run("render -q -W 8 -H 8 " + sphere + " -o " + out + " -e " + env);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_NE(r.err.find(fs::path(env).filename().string()), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace rt
