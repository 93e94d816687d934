// SPDX-License-Identifier: MIT
// Image files: sRGB encoding, PNG/EXR round trips, and atomic writes that never leave a
// half-written or partial file behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

#include "core/image/image_io.h"

#include "support/temp_dir_test.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class ImageIo : public test::TempDirTest {
  protected:
    ImageIo() : TempDirTest("scadray_image_io_") {}

    static Image gradient() {
        Image img(17, 5);
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 17; ++x) img.set(x, y, Rgb(x / 16.0, y / 4.0, 0.5));
        return img;
    }
};

TEST(Srgb, MatchesTheStandardCurve) {
    EXPECT_DOUBLE_EQ(srgbEncode(0), 0);
    EXPECT_DOUBLE_EQ(srgbEncode(1), 1);
    EXPECT_NEAR(srgbEncode(0.0031308), 0.0031308 * 12.92, 1e-12);
    EXPECT_NEAR(srgbEncode(0.5), 0.735356983, 1e-8);
    for (double v : {0.001, 0.02, 0.3, 0.9}) EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-12);
}

/// The formula srgbByte stands for (POV-Ray's IntEncode of the sRGB value).
int srgbByteFormula(double v) {
    if (!std::isfinite(v)) v = 0;
    v = std::clamp(v, 0.0, 1.0);
    return static_cast<int>(std::floor(std::clamp(srgbEncode(v), 0.0, 1.0) * 255 + 0.5));
}

TEST(Srgb, ByteTableEqualsTheFormula) {
    // Around every step of the code: the formula's own step (found here by a scan of 0.5 ulp
    // steps from the analytic inverse, independently of the table's bisection) and the 64
    // doubles on either side of it
    for (int k = 1; k <= 255; ++k) {
        double v = srgbDecode((k - 0.5) / 255);
        while (srgbByteFormula(v) >= k) v = std::nextafter(v, 0.0);
        while (srgbByteFormula(v) < k) v = std::nextafter(v, 1.0);
        EXPECT_EQ(srgbByteFormula(v), k);
        double down = v, up = v;
        for (int i = 0; i < 64; ++i) {
            down = std::nextafter(down, 0.0);
            up = std::nextafter(up, 1.0);
            ASSERT_EQ(srgbByte(down), srgbByteFormula(down)) << "k " << k << " v " << down;
            ASSERT_EQ(srgbByte(up), srgbByteFormula(up)) << "k " << k << " v " << up;
        }
        ASSERT_EQ(srgbByte(v), k);
    }
    // A million values spread over [0, 1] and beyond it, and a million over the dark end (the
    // linear segment and the start of the power curve)
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> wide(-0.1, 1.1), dark(0, 0.01);
    for (int i = 0; i < 1000000; ++i) {
        double a = wide(rng), b = dark(rng);
        ASSERT_EQ(srgbByte(a), srgbByteFormula(a)) << a;
        ASSERT_EQ(srgbByte(b), srgbByteFormula(b)) << b;
    }
    // Every bin edge of the table, and the special values
    for (int i = 0; i <= 4096; ++i) {
        double v = i / 4096.0;
        for (double w : {std::nextafter(v, 0.0), v, std::nextafter(v, 1.0)})
            ASSERT_EQ(srgbByte(w), srgbByteFormula(w)) << w;
    }
    for (double v :
         {0.0, -0.0, 1.0, -1.0, 2.0, 0.0031308, 1e-300, 5e-324, 1 - 1e-16,
          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::quiet_NaN()})
        EXPECT_EQ(srgbByte(v), srgbByteFormula(v)) << v;
}

TEST_F(ImageIo, EightBitPngOfAPictureHoldsTheFormulasCodes) {
    // 128 x 128 x 3 values: enough for writeImage to take the table
    Image img(128, 128);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-0.05, 1.05);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) img.set(x, y, Rgb(u(rng), u(rng) * u(rng), u(rng) * 0.01));
    writeImage(img, (dir / "p.png").string());
    Image back = readImage((dir / "p.png").string(), true);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(std::lround(back.at(x, y)[c] * 255), srgbByteFormula(img.at(x, y)[c]))
                    << x << " " << y << " " << c;
}

TEST_F(ImageIo, Png16RoundTripsWithinOneStep) {
    Image img = gradient();
    std::string path = (dir / "g.png").string();
    WriteOptions o;
    o.pngDepth = PngDepth::Bits16;
    writeImage(img, path, o);
    Image back = readImage(path);
    ASSERT_EQ(back.width(), 17);
    ASSERT_EQ(back.height(), 5);
    for (int x = 0; x < 17; ++x) EXPECT_NEAR(back.at(x, 2).r, img.at(x, 2).r, 2e-4);
}

TEST_F(ImageIo, LinearPngAndExrKeepValues) {
    Image img = gradient();
    WriteOptions lin;
    lin.pngDepth = PngDepth::Bits16;
    lin.linearPng = true;
    writeImage(img, (dir / "l.png").string(), lin);
    Image back = readImage((dir / "l.png").string(), true);
    EXPECT_NEAR(back.at(8, 1).r, 0.5, 1.0 / 65535);
    writeImage(img, (dir / "f.exr").string());
    Image exr = readImage((dir / "f.exr").string());
    EXPECT_EQ(exr.at(3, 4).r, img.at(3, 4).r);
    EXPECT_EQ(exr.at(3, 4).g, img.at(3, 4).g);
}

TEST_F(ImageIo, EightBitQuantisesLikePovRay) {
    Image img(1, 1);
    img.set(0, 0, Rgb(0.5, 2.0, -1));  // out-of-range values clip
    writeImage(img, (dir / "q.png").string());
    Image back = readImage((dir / "q.png").string(), true);
    EXPECT_NEAR(back.at(0, 0).r, std::floor(srgbEncode(0.5) * 255 + 0.5) / 255, 1e-6);
    EXPECT_EQ(back.at(0, 0).g, 1.0f);
    EXPECT_EQ(back.at(0, 0).b, 0.0f);
}

TEST_F(ImageIo, FailedWriteLeavesNoFile) {
    Image img = gradient();
    EXPECT_THROW(writeImage(img, (dir / "missing" / "x.png").string()), std::runtime_error);
    EXPECT_THROW(writeImage(img, (dir / "x.unknownformat").string()), std::runtime_error);
    // An existing file is replaced whole or kept
    std::string path = (dir / "keep.png").string();
    writeImage(img, path);
    auto size = fs::file_size(path);
    EXPECT_THROW(writeImage(Image(), path), std::runtime_error);
    EXPECT_EQ(fs::file_size(path), size);
    // No temporary (".scadray-XXXXXX.png") left beside it
    for (const auto &e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string(), "keep.png") << e.path();
}

TEST_F(ImageIo, ReadingGarbageFailsClearly) {
    std::string path = (dir / "bad.png").string();
    FILE *f = std::fopen(path.c_str(), "wb");
    std::fputs("not a png", f);
    std::fclose(f);
    EXPECT_THROW(readImage(path), std::runtime_error);
    EXPECT_THROW(readImage((dir / "none.png").string()), std::runtime_error);
}

}  // namespace
}  // namespace rt
