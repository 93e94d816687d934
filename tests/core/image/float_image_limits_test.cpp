// SPDX-License-Identifier: MIT
// Radiance and OpenEXR headers declaring more pixels than their files can hold: refused before the
// pixels are allocated (a 117-byte .hdr declaring 16384 x 16384 took 3.3 GB), while files at the
// formats' best compression still read.
#include "core/image/float_image_limits.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/image/image_io.h"
#include "support/temp_dir_test.h"

namespace rt {
namespace {

class FloatImageLimits : public test::TempDirTest {
  protected:
    FloatImageLimits() : TempDirTest("scadray_float_image_limits_") {}

    std::string write(const std::string &name, const std::string &bytes) {
        std::string path = (dir / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    /// readImage's error message (a test failure when it reads).
    static std::string readError(const std::string &path) {
        try {
            readImage(path);
        } catch (const std::runtime_error &e) {
            return e.what();
        }
        ADD_FAILURE() << path << " was read";
        return "";
    }
};

const std::string kRadianceHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

/// A run-length encoded Radiance scanline of `width` pixels of one colour (r, g, b, e): the marker,
/// then each byte channel in runs of at most 127, the format's most compact form.
std::string constantScanline(int width, const unsigned char rgbe[4]) {
    std::string s = {2, 2, static_cast<char>(width >> 8), static_cast<char>(width & 0xff)};
    for (int c = 0; c < 4; ++c)
        for (int left = width; left > 0; left -= 127) {
            s.push_back(static_cast<char>(128 + std::min(left, 127)));
            s.push_back(static_cast<char>(rgbe[c]));
        }
    return s;
}

TEST_F(FloatImageLimits, HdrDeclaringMoreThanItsFileCanHoldIsRefused) {
    // 117 bytes declaring 16384 x 16384 (at the pixel limit): 3.3 GB were allocated before the
    // first scanline failed to read
    std::string header = kRadianceHeader + "-Y 16384 +X 16384\n";
    const unsigned char grey[4] = {128, 128, 128, 129};
    std::string hdr = header + constantScanline(16384, grey);
    hdr.resize(117);
    std::string path = write("huge.hdr", hdr);
    // Each scanline needs its 4-byte marker and, for each of 4 channels, 130 runs of 2 bytes
    std::string msg = readError(path);
    EXPECT_NE(msg.find("image '" + path +
                       "' (Radiance HDR) declares 16384 x 16384 pixels, which "
                       "need at least 17104949 bytes"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("more than its 117 bytes"), std::string::npos) << msg;
    // Flat scanlines (narrower than 8 pixels) take 4 bytes a pixel
    msg = readError(write("narrow.hdr", kRadianceHeader + "-Y 1000 +X 4\n" + std::string(64, 1)));
    EXPECT_NE(msg.find("declares 4 x 1000 pixels, which need at least 16048 bytes"),
              std::string::npos)
        << msg;
}

TEST_F(FloatImageLimits, HdrAtItsBestCompressionStillReads) {
    // 254 pixels a scanline in runs of 127: exactly the least a scanline can take
    const unsigned char grey[4] = {128, 128, 128, 129};  // 0.5 * 2 = 1.0 in RGBE
    std::string header = kRadianceHeader + "-Y 3 +X 254\n";
    std::string data;
    for (int y = 0; y < 3; ++y) data += constantScanline(254, grey);
    ASSERT_EQ(data.size(), radianceMinDataBytes(3, 254));
    Image img = readImage(write("best.hdr", header + data));
    ASSERT_EQ(img.width(), 254);
    ASSERT_EQ(img.height(), 3);
    EXPECT_NEAR(img.at(253, 2)[0], 1.0, 0.01);
    // One byte short is refused before OpenImageIO reads it
    std::string msg = readError(write("short.hdr", header + data.substr(1)));
    EXPECT_NE(msg.find("declares 254 x 3 pixels, which need at least"), std::string::npos) << msg;
    // A picture OpenImageIO writes reads back
    Image small(9, 2);
    small.set(8, 1, Rgb(0.25, 0.5, 2.0));
    writeImage(small, (dir / "written.hdr").string());
    Image back = readImage((dir / "written.hdr").string());
    ASSERT_EQ(back.width(), 9);
    EXPECT_NEAR(back.at(8, 1)[2], 2.0, 0.02);
}

TEST_F(FloatImageLimits, HdrHeaderIsAlsoCheckedOnWhatOpenImageIOReads) {
    // OpenImageIO reads the resolution with sscanf, which ignores what follows it; the check before
    // it does not take such a line, and the size OpenImageIO reports decides
    std::string hdr = kRadianceHeader + "-Y 16384 +X 16384 and more\n" + std::string(64, 2);
    std::string msg = readError(write("trailing.hdr", hdr));
    EXPECT_NE(msg.find("declares 16384 x 16384 pixels, which need at least 17104896 bytes"),
              std::string::npos)
        << msg;
}

TEST(FloatImageHeader, ReadsRadianceResolutions) {
    std::istringstream in(kRadianceHeader + "+X 7 -Y 300\n");
    std::optional<FloatImageHeader> h = readFloatImageHeader(in);
    ASSERT_TRUE(h);
    // The first number counts the scanlines, as OpenImageIO reads it
    EXPECT_EQ(h->width, 300u);
    EXPECT_EQ(h->height, 7u);
    EXPECT_EQ(h->minFileBytes, kRadianceHeader.size() + 12 + 7 * (4 + 8 * 3));
    for (const char *bad : {"-Y 7\n", "-Y 7 -Y 3\n", "-Z 7 +X 3\n", "-Y x +X 3\n", "-Y 0 +X 3\n"}) {
        std::istringstream b(kRadianceHeader + bad);
        EXPECT_FALSE(readFloatImageHeader(b)) << bad;
    }
    std::istringstream png("\x89PNG\r\n\x1a\n");
    EXPECT_FALSE(readFloatImageHeader(png));
}

TEST(FloatImageHeader, SizesSaturateInsteadOfOverflowing) {
    EXPECT_EQ(radianceMinDataBytes(uint64_t(1) << 62, 100), UINT64_MAX);
    EXPECT_EQ(radianceMinDataBytes(1, 7), 28u);
    EXPECT_EQ(radianceMinDataBytes(1, 32768), 4u * 32768);
    EXPECT_EQ(exrMaxRatio(0), 1u);
    EXPECT_EQ(exrMaxRatio(3), 1032u);
    EXPECT_EQ(exrMaxRatio(42), 0u);
    EXPECT_EQ(exrLinesPerChunk(9), 256u);
}

}  // namespace
}  // namespace rt
