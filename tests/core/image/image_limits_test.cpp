// SPDX-License-Identifier: MIT
// Image headers declaring more than the file can hold or than the limits allow: the
// reader refuses them before allocating the declared pixels.
#include "core/image/image_limits.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "core/image/float_image_limits.h"
#include "core/image/image_io.h"

#include "support/temp_dir_test.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class ImageLimits : public test::TempDirTest {
  protected:
    ImageLimits() : TempDirTest("scadray_image_limits_") {}

    std::string write(const std::string &name, const std::vector<unsigned char> &bytes) {
        std::string path = (dir / name).string();
        std::ofstream out(path, std::ios::binary);
        out.write(reinterpret_cast<const char *>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
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

uint32_t crc32(const unsigned char *p, size_t n) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

void putBe32(std::vector<unsigned char> &out, uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

/// A PNG chunk with its CRC (libpng checks it).
void chunk(std::vector<unsigned char> &png, const char *type,
           const std::vector<unsigned char> &data) {
    putBe32(png, static_cast<uint32_t>(data.size()));
    size_t start = png.size();
    png.insert(png.end(), type, type + 4);
    png.insert(png.end(), data.begin(), data.end());
    putBe32(png, crc32(png.data() + start, png.size() - start));
}

/// Signature, IHDR (8-bit RGB, or the colour type given), an IDAT holding an empty zlib stream
/// and an IEND: 65 bytes declaring width x height.
std::vector<unsigned char> pngHeader(uint32_t width, uint32_t height,
                                     unsigned char colourType = 2) {
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<unsigned char> ihdr;
    putBe32(ihdr, width);
    putBe32(ihdr, height);
    for (unsigned char c : {8, int(colourType), 0, 0, 0}) ihdr.push_back(c);
    chunk(png, "IHDR", ihdr);
    chunk(png, "IDAT", {0x78, 0x9C, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});
    chunk(png, "IEND", {});
    return png;
}

TEST_F(ImageLimits, PngDeclaringTooManyPixelsIsRefused) {
    // 30000 x 30000: 10.8 GB of float pixels were allocated before reading one
    std::string msg = readError(write("huge.png", pngHeader(30000, 30000)));
    EXPECT_NE(msg.find("declares 30000 x 30000 pixels, more than the limit of 268435456 pixels"),
              std::string::npos)
        << msg;
    msg = readError(write("wide.png", pngHeader(40000, 10)));
    EXPECT_NE(msg.find("a side longer than the limit of 32768"), std::string::npos) << msg;
}

TEST_F(ImageLimits, PngDeclaringMoreThanItsFileCanHoldIsRefused) {
    // 8000 x 8000 RGB within the limits, but 192 MB cannot inflate from 65 bytes
    std::string msg = readError(write("short.png", pngHeader(8000, 8000)));
    EXPECT_NE(msg.find("more than its 65 bytes can hold"), std::string::npos) << msg;
    // The same with alpha, which OpenImageIO decodes (it allocated 1 GB of float pixels)
    msg = readError(write("alpha.png", pngHeader(8000, 8000, 6)));
    EXPECT_NE(msg.find("more than its 65 bytes can hold"), std::string::npos) << msg;
}

/// A 4 x 4 EXR written by scadray with its dataWindow changed to `width` x `height` and its
/// chunk offset table lengthened to match (OpenEXR checks the table when it opens the file), all
/// entries pointing to the one real chunk.
std::vector<unsigned char> exrDeclaring(const fs::path &dir, int32_t width, int32_t height) {
    Image img(4, 4);
    std::string path = (dir / "small.exr").string();
    writeImage(img, path);
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> exr((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
    // dataWindow box2i: xmin, ymin, xmax, ymax after name, type and size
    const char key[] = "dataWindow\0box2i";
    auto at = std::search(exr.begin(), exr.end(), key, key + sizeof key);
    EXPECT_NE(at, exr.end());
    if (at == exr.end()) return exr;
    size_t box = static_cast<size_t>(at - exr.begin()) + sizeof key + 4;
    int32_t corner[2] = {width - 1, height - 1};
    std::memcpy(exr.data() + box + 8, corner, sizeof corner);
    // The one-entry offset table: the 8 bytes whose value is their own position + 8
    size_t table = 0;
    for (size_t p = box; p + 8 <= exr.size() && !table; ++p) {
        uint64_t v;
        std::memcpy(&v, exr.data() + p, 8);
        if (v == p + 8) table = p;
    }
    EXPECT_NE(table, 0u);
    size_t chunks = (static_cast<size_t>(height) + 15) / 16;  // zip: 16 scanlines a chunk
    uint64_t target = table + 8 * chunks;
    std::vector<unsigned char> out(exr.begin(), exr.begin() + static_cast<long>(table));
    for (size_t i = 0; i < chunks; ++i)
        out.insert(out.end(), reinterpret_cast<unsigned char *>(&target),
                   reinterpret_cast<unsigned char *>(&target) + 8);
    out.insert(out.end(), exr.begin() + static_cast<long>(table + 8), exr.end());
    return out;
}

TEST_F(ImageLimits, ExrDeclaringTooManyPixelsIsRefused) {
    std::string msg = readError(write("huge.exr", exrDeclaring(dir, 30000, 30000)));
    EXPECT_NE(msg.find("declares 30000 x 30000 pixels, more than the limit"), std::string::npos)
        << msg;
    msg = readError(write("wide.exr", exrDeclaring(dir, 40000, 4)));
    EXPECT_NE(msg.find("declares 40000 x 4 pixels, a side longer"), std::string::npos) << msg;
}

TEST_F(ImageLimits, ExrDeclaringMoreThanItsFileCanHoldIsRefused) {
    // 8192 x 8192 float RGB (805 MB raw) within the limits, its offset table complete, but zip
    // (deflate, 1032 : 1) cannot hold them in 4 kB: 805 MB of pixels were allocated
    std::string path = write("window.exr", exrDeclaring(dir, 8192, 8192));
    std::string msg = readError(path);
    EXPECT_NE(msg.find("image '" + path +
                       "' (OpenEXR) declares 8192 x 8192 pixels, which need "
                       "at least"),
              std::string::npos)
        << msg;
    EXPECT_NE(msg.find("512 chunks of at least 16 bytes with their offsets, and 805306368 bytes "
                       "of pixels at most 1032 : 1 compressed), more than its " +
                       std::to_string(fs::file_size(path)) + " bytes"),
              std::string::npos)
        << msg;
    // The offset table alone: 8 bytes a chunk must be there
    std::vector<unsigned char> cut = exrDeclaring(dir, 4, 4096);
    cut.resize(cut.size() - 8 * 200);
    msg = readError(write("cut.exr", cut));
    EXPECT_NE(msg.find("declares 4 x 4096 pixels, which need at least"), std::string::npos) << msg;
    // The written 4 x 4 picture reads, its header as OpenImageIO reports it
    std::ifstream in((dir / "small.exr").string(), std::ios::binary);
    std::optional<FloatImageHeader> h = readFloatImageHeader(in);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->width, 4u);
    EXPECT_EQ(h->channels, 3);
    EXPECT_LE(h->minFileBytes, fs::file_size(dir / "small.exr"));
    EXPECT_EQ(readImage((dir / "small.exr").string()).width(), 4);
}

TEST_F(ImageLimits, UnreadableExrHeadersAreRefusedBeforeOpenExrReadsThem) {
    std::vector<unsigned char> exr = exrDeclaring(dir, 4, 4);
    for (size_t keep : {size_t(6), size_t(20), size_t(60)}) {
        std::vector<unsigned char> cut(exr.begin(), exr.begin() + static_cast<long>(keep));
        std::string msg = readError(write("cut" + std::to_string(keep) + ".exr", cut));
        EXPECT_NE(msg.find("its OpenEXR header ends inside"), std::string::npos) << msg;
    }
}

TEST_F(ImageLimits, NonRegularFilesAreRefused) {
    std::string fifo = (dir / "fifo.png").string();
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_NE(readError(fifo).find("not a regular file"), std::string::npos);
    EXPECT_NE(readError(dir.string()).find("not a regular file"), std::string::npos);
}

TEST(ImageHeader, ReadsPngJpegAndBmpHeaders) {
    std::vector<unsigned char> png = pngHeader(640, 480);
    auto h = readImageHeader(png);
    ASSERT_TRUE(h);
    EXPECT_STREQ(h->format, "PNG");
    EXPECT_EQ(h->width, 640u);
    EXPECT_EQ(h->height, 480u);
    EXPECT_EQ(h->channels, 3);
    // Cut inside IHDR: nothing
    EXPECT_FALSE(readImageHeader(std::span(png.data(), 20)));

    // SOI, an APP0 segment, SOF0 (8 bits, 300 high, 200 wide, 3 components)
    std::vector<unsigned char> jpeg = {0xFF, 0xD8, 0xFF, 0xE0, 0, 4,  'J', 'F', 0xFF,
                                       0xC0, 0,    17,   8,    1, 44, 0,   200, 3};
    jpeg.resize(40, 0);
    h = readImageHeader(jpeg);
    ASSERT_TRUE(h);
    EXPECT_STREQ(h->format, "JPEG");
    EXPECT_EQ(h->width, 200u);
    EXPECT_EQ(h->height, 300u);
    // A segment length running past the end, or a scan before any frame: nothing
    std::vector<unsigned char> noFrame = {0xFF, 0xD8, 0xFF, 0xDA, 0, 8, 0, 0, 0, 0};
    EXPECT_FALSE(readImageHeader(noFrame));
    std::vector<unsigned char> runaway = {0xFF, 0xD8, 0xFF, 0xE0, 0xFF, 0xFF, 0, 0};
    EXPECT_FALSE(readImageHeader(runaway));

    std::vector<unsigned char> bmp(54, 0);
    bmp[0] = 'B';
    bmp[1] = 'M';
    bmp[14] = 40;
    int32_t size[2] = {100, -50};  // negative height: rows top first
    std::memcpy(bmp.data() + 18, size, sizeof size);
    h = readImageHeader(bmp);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->width, 100u);
    EXPECT_EQ(h->height, 50u);
    int32_t most[2] = {INT32_MIN, INT32_MIN};
    std::memcpy(bmp.data() + 18, most, sizeof most);
    h = readImageHeader(bmp);
    ASSERT_TRUE(h);
    EXPECT_EQ(h->width, 2147483648u);
}

TEST(ImageHeader, SizesDoNotOverflow) {
    EXPECT_EQ(pngRawBytes(0xFFFFFFFFu, 0xFFFFFFFFu, 4, 16), UINT64_MAX);
    EXPECT_EQ(pngRawBytes(3, 2, 3, 8), 2u * (1 + 9));
    EXPECT_NE(imageSizeProblem(0xFFFFFFFFu, 0xFFFFFFFFu, kMaxReadImagePixels, UINT64_MAX), "");
    EXPECT_EQ(imageSizeProblem(16384, 16384, kMaxReadImagePixels, kMaxReadImageSide), "");
    EXPECT_NE(imageSizeProblem(0, 5, kMaxReadImagePixels, kMaxReadImageSide), "");
}

}  // namespace
}  // namespace rt
