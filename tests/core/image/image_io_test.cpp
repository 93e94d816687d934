// SPDX-License-Identifier: MIT
// Image files: sRGB encoding, PNG/EXR round trips, and atomic writes that never leave a
// half-written or partial file behind.
#include <gtest/gtest.h>

#include <filesystem>

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
