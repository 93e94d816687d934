// SPDX-License-Identifier: MIT
// PNG through libpng gives exactly what OpenImageIO gave: every kind of PNG (grey,
// palette, RGB, alpha; 1 to 16 bits; sRGB, gAMA 1.0, gAMA 2.2 or nothing; interlaced) reads to the
// same floats both ways, and PNGs written both ways decode to the same pixels.
#include "core/image/png_io.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/image/image_io.h"

#include "support/temp_dir_test.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

class PngIo : public test::TempDirTest {
  protected:
    PngIo() : TempDirTest("scadray_png_io_") {}
};

/// What a test PNG declares besides its pixels.
struct PngKind {
    int colorType;  ///< PNG_COLOR_TYPE_*
    int bits;
    enum Tag { None, Srgb, Gamma1, Gamma22, TextLinear, SrgbAndTextLinear } tag = None;
    bool trns = false;  ///< a tRNS chunk (transparency without an alpha channel)
    bool interlaced = false;

    std::string name() const {
        return "t" + std::to_string(colorType) + "_b" + std::to_string(bits) + "_g" +
               std::to_string(int(tag)) + (trns ? "_trns" : "") + (interlaced ? "_i" : "") + ".png";
    }
};

/// Writes a 23 x 7 PNG of `kind` whose samples sweep the whole range (both extremes included).
void writeTestPng(const std::string &path, const PngKind &k) {
    const int w = 23, h = 7;
    int channels = k.colorType == PNG_COLOR_TYPE_GRAY         ? 1
                   : k.colorType == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                   : k.colorType == PNG_COLOR_TYPE_PALETTE    ? 1
                   : k.colorType == PNG_COLOR_TYPE_RGB        ? 3
                                                              : 4;
    unsigned maxValue = (1u << k.bits) - 1;
    size_t rowBytes = (size_t(w) * channels * k.bits + 7) / 8;
    std::vector<unsigned char> data(rowBytes * h, 0);
    unsigned step = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < channels; ++c, step += 7919) {
                unsigned v = (x + y == 0)                 ? 0
                             : (x == w - 1 && y == h - 1) ? maxValue
                                                          : step % (maxValue + 1);
                size_t bit = (size_t(x) * channels + c) * k.bits;
                unsigned char *row = data.data() + y * rowBytes;
                if (k.bits == 16) {
                    row[bit / 8] = static_cast<unsigned char>(v >> 8);
                    row[bit / 8 + 1] = static_cast<unsigned char>(v);
                } else {
                    int shift = 8 - k.bits - int(bit % 8);
                    row[bit / 8] |= static_cast<unsigned char>(v << shift);
                }
            }
    std::FILE *f = std::fopen(path.c_str(), "wb");
    ASSERT_TRUE(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_FALSE(setjmp(png_jmpbuf(png)));
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, k.bits, k.colorType,
                 k.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    std::vector<png_color> palette;
    if (k.colorType == PNG_COLOR_TYPE_PALETTE) {
        for (unsigned i = 0; i <= maxValue; ++i)
            palette.push_back({static_cast<png_byte>(i * 37), static_cast<png_byte>(255 - i * 11),
                               static_cast<png_byte>(i * 97 + 3)});
        png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    }
    if (k.trns) {
        png_byte alphas[2] = {0, 128};
        png_color_16 colour{};
        colour.gray = static_cast<png_uint_16>(maxValue / 3);
        colour.red = colour.green = colour.blue = static_cast<png_uint_16>(maxValue / 3);
        if (k.colorType == PNG_COLOR_TYPE_PALETTE)
            png_set_tRNS(png, info, alphas, 2, nullptr);
        else
            png_set_tRNS(png, info, nullptr, 0, &colour);
    }
    if (k.tag == PngKind::Srgb || k.tag == PngKind::SrgbAndTextLinear)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    if (k.tag == PngKind::Gamma1) png_set_gAMA(png, info, 1.0);
    if (k.tag == PngKind::Gamma22) png_set_gAMA(png, info, 1 / 2.2);
    char key[] = "oiio:ColorSpace", value[] = "Linear";
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = key;
    text.text = value;
    if (k.tag == PngKind::TextLinear || k.tag == PngKind::SrgbAndTextLinear)
        png_set_text(png, info, &text, 1);
    png_write_info(png, info);
    std::vector<png_bytep> rows(h);
    for (int y = 0; y < h; ++y) rows[y] = data.data() + y * rowBytes;
    png_write_image(png, rows.data());
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

void expectSameFloats(const Image &a, const Image &b, const std::string &what) {
    ASSERT_EQ(a.width(), b.width()) << what;
    ASSERT_EQ(a.height(), b.height()) << what;
    ASSERT_EQ(a.data().size(), b.data().size()) << what;
    for (size_t i = 0; i < a.data().size(); ++i)
        ASSERT_EQ(std::memcmp(&a.data()[i], &b.data()[i], sizeof(float)), 0)
            << what << ": float " << i << " is " << a.data()[i] << " here, " << b.data()[i]
            << " through OpenImageIO";
}

std::vector<PngKind> everyKind() {
    std::vector<PngKind> kinds;
    auto add = [&](int type, std::initializer_list<int> depths) {
        for (int bits : depths)
            for (auto tag : {PngKind::None, PngKind::Srgb, PngKind::Gamma1, PngKind::Gamma22,
                             PngKind::TextLinear, PngKind::SrgbAndTextLinear})
                kinds.push_back({type, bits, tag});
    };
    add(PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16});
    add(PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8});
    add(PNG_COLOR_TYPE_RGB, {8, 16});
    add(PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16});
    add(PNG_COLOR_TYPE_RGB_ALPHA, {8, 16});
    for (int type : {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_PALETTE, PNG_COLOR_TYPE_RGB})
        kinds.push_back({type, 8, PngKind::None, /*trns=*/true});
    for (int bits : {8, 16})
        kinds.push_back({PNG_COLOR_TYPE_RGB, bits, PngKind::Gamma1, false, true});
    kinds.push_back({PNG_COLOR_TYPE_GRAY, 2, PngKind::Srgb, false, true});
    return kinds;
}

TEST_F(PngIo, EveryKindReadsToTheFloatsOpenImageIOGives) {
    for (const PngKind &k : everyKind()) {
        std::string path = (dir / k.name()).string();
        writeTestPng(path, k);
        for (bool assumeLinear : {false, true})
            expectSameFloats(readImage(path, assumeLinear), readImageWithOiio(path, assumeLinear),
                             k.name() + (assumeLinear ? " (assumed linear)" : ""));
        expectSameFloats(readEstimate(path).mean, readImageWithOiio(path), k.name() + " estimate");
    }
}

TEST_F(PngIo, LinearTagsAreReadAsOpenImageIOReadsThem) {
    auto linear = [&](PngKind::Tag tag) {
        std::string path = (dir / ("tag" + std::to_string(int(tag)) + ".png")).string();
        writeTestPng(path, {PNG_COLOR_TYPE_RGB, 8, tag});
        return PngReader(path).linear();
    };
    EXPECT_FALSE(linear(PngKind::None));
    EXPECT_FALSE(linear(PngKind::Srgb));
    EXPECT_TRUE(linear(PngKind::Gamma1));
    EXPECT_FALSE(linear(PngKind::Gamma22));
    EXPECT_TRUE(linear(PngKind::TextLinear));
    EXPECT_TRUE(linear(PngKind::SrgbAndTextLinear));
}

TEST_F(PngIo, WrittenPngsDecodeLikeOpenImageIOs) {
    Image img(19, 6);
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            img.set(x, y, Rgb(x / 18.0, y / 5.0 - 0.1, std::sin(x * y) * 1.2));
    img.set(0, 0, Rgb(std::nan(""), 1e30, -0.0));
    for (auto depth : {PngDepth::Bits8, PngDepth::Bits16})
        for (bool linear : {false, true}) {
            WriteOptions o;
            o.pngDepth = depth;
            o.linearPng = linear;
            std::string what = std::string(depth == PngDepth::Bits8 ? "8" : "16") + " bits" +
                               (linear ? ", linear" : "");
            std::string ours = (dir / "ours.png").string(), theirs = (dir / "theirs.png").string();
            writeImage(img, ours, o);
            writeImageWithOiio(img, theirs, o);
            EXPECT_EQ(PngReader(ours).linear(), linear) << what;
            for (bool assumeLinear : {false, true}) {
                Image expected = readImageWithOiio(theirs, assumeLinear);
                expectSameFloats(readImageWithOiio(ours, assumeLinear), expected, what);
                expectSameFloats(readImage(ours, assumeLinear), expected, what);
            }
        }
}

TEST_F(PngIo, BrokenPngsFailWithTheirReason) {
    std::string good = (dir / "good.png").string();
    writeImage(Image(40, 30), good);
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string cut = (dir / "cut.png").string();
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    try {
        readImage(cut);
        ADD_FAILURE() << "a truncated PNG was read";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("cannot read image '" + cut + "': "),
                  std::string::npos)
            << e.what();
    }
    // A write into a folder that does not exist leaves nothing behind
    EXPECT_THROW(writeImage(Image(2, 2), (dir / "missing" / "x.png").string()), std::runtime_error);
}

TEST_F(PngIo, DamagedPngsReadOrFailCleanly) {
    // Every truncation and a flipped byte at every offset after the signature of a small 16-bit
    // PNG: libpng's errors come back as exceptions, never a crash (a file without the signature
    // goes to OpenImageIO, which tries every format it knows: slow, and not what this tests)
    std::string good = (dir / "good.png").string();
    WriteOptions o;
    o.pngDepth = PngDepth::Bits16;
    Image img(9, 4);
    for (int x = 0; x < 9; ++x) img.set(x, x % 4, Rgb(x / 8.0, 0.25, 1));
    writeImage(img, good, o);
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string bad = (dir / "bad.png").string();
    int read = 0, refused = 0;
    auto attempt = [&](const std::string &content) {
        std::ofstream(bad, std::ios::binary | std::ios::trunc) << content;
        try {
            Image back = readImage(bad);
            EXPECT_EQ(back.data().size(), 3u * size_t(back.width()) * size_t(back.height()));
            ++read;
        } catch (const std::runtime_error &) {
            ++refused;
        }
    };
    for (size_t n = 8; n < bytes.size(); ++n) attempt(bytes.substr(0, n));
    for (size_t at = 8; at < bytes.size(); ++at) {
        std::string flipped = bytes;
        flipped[at] = static_cast<char>(flipped[at] ^ 0x5A);
        attempt(flipped);
    }
    EXPECT_GT(refused, 0);
    EXPECT_GT(read, 0);  // flips in ancillary chunks are only warnings

    // A text chunk declaring 1.5 GB in a 170-byte file: refused before libpng allocates it
    std::string text = bytes;
    size_t at = text.find("tEXt");
    ASSERT_NE(at, std::string::npos);
    text[at - 4] = 0x5A;
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << text;
    try {
        readImage(bad);
        ADD_FAILURE() << "a chunk longer than its file was read";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("chunk tEXt at byte " + std::to_string(at - 4) +
                                             " declares 1509949"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rt
