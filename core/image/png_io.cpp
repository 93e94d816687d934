// SPDX-License-Identifier: MIT
// libpng reading and writing. libpng reports errors by longjmp: every function that calls it
// sets its own jump point and holds no object with a destructor across the calls.
#include "core/image/png_io.h"

#include <png.h>

#include <strings.h>
#include <bit>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace rt {

namespace {

/// libpng's message, kept where its error handler can reach it.
struct ErrorBuffer {
    char text[512] = "";
};

[[noreturn]] void onPngError(png_structp png, png_const_charp message) {
    auto *buf = static_cast<ErrorBuffer *>(png_get_error_ptr(png));
    std::snprintf(buf->text, sizeof buf->text, "%s", message ? message : "libpng error");
    png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}

/// The transforms OpenImageIO 2.4 asks for (png_set_expand: palette to RGB, 1/2/4-bit grey to
/// 8 bits, tRNS to alpha), then the header as transformed. False on a libpng error.
bool readInfo(png_structp png, png_infop info, png_uint_32 *size, int *raw, int *expanded,
              int *linearState) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    int depth = 0, colorType = 0;
    png_get_IHDR(png, info, &size[0], &size[1], &depth, &colorType, nullptr, nullptr, nullptr);
    raw[0] = png_get_channels(png, info);
    raw[1] = depth;
    raw[2] = (colorType & PNG_COLOR_MASK_ALPHA) || png_get_valid(png, info, PNG_INFO_tRNS);
    // OpenImageIO's colour space: an sRGB chunk wins; else gAMA, whose inverse is rounded to
    // hundredths ("2.2, not 2.19998") and means linear when that is exactly 1
    int intent = 0;
    double gamma = 0;
    *linearState = 0;
    if (png_get_sRGB(png, info, &intent)) {
        *linearState = 0;
    } else if (png_get_gAMA(png, info, &gamma) && gamma > 0.0) {
        float g = float(1.0 / gamma);
        g = roundf(float(100.0 * g)) / 100.0f;
        *linearState = g == 1.0f;
    }
    // A text chunk "oiio:ColorSpace" (OpenImageIO writes one) overrides both
    png_textp text = nullptr;
    int count = png_get_text(png, info, &text, nullptr);
    for (int i = 0; i < count; ++i)
        if (text[i].key && strcasecmp(text[i].key, "oiio:ColorSpace") == 0)
            *linearState = text[i].text && strcasecmp(text[i].text, "linear") == 0;
    png_set_expand(png);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    expanded[0] = png_get_channels(png, info);
    expanded[1] = png_get_bit_depth(png, info);
    expanded[2] = static_cast<int>(png_get_rowbytes(png, info));
    expanded[3] = png_get_interlace_type(png, info) != PNG_INTERLACE_NONE;
    return true;
}

/// Decodes every row. Like OpenImageIO, reads the chunks after the image data only for an
/// interlaced file (OpenImageIO reads other files row by row and stops after the last).
bool readRows(png_structp png, png_bytepp rows, bool interlaced) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    if (interlaced) png_read_end(png, nullptr);
    return true;
}

bool writeRows(png_structp png, png_infop info, png_uint_32 width, png_uint_32 height, int bits,
               bool linear, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, width, height, bits, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    // The chunks OpenImageIO wrote: sRGB with its gAMA and cHRM, or gAMA 1.0 for linear values
    if (linear)
        png_set_gAMA(png, info, 1.0);
    else
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_ABSOLUTE);
    char key[] = "Software", value[] = "scadray";
    png_text text{};
    text.compression = PNG_TEXT_COMPRESSION_NONE;
    text.key = key;
    text.text = value;
    png_set_text(png, info, &text, 1);
    // One filter, SUB, for every row instead of libpng's choice per row among all five: on
    // rendered pictures it halves the time deflate takes with files no larger (default.scad at
    // 640x480: 158 M -> 85 M instructions, 55.2 kB -> 55.2 kB; glass, csg_part and
    // openscad_model 2 to 5 % smaller; a noisy Monte Carlo picture 5 % larger)
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    png_write_info(png, info);
    // Samples are in host order; PNG's are big-endian
    if (bits == 16 && std::endian::native == std::endian::little) png_set_swap(png);
    png_write_image(png, rows);
    png_write_end(png, info);
    return true;
}

uint32_t be32(const unsigned char *p) {
    return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3];
}

/// Empty, or why the file cannot hold a chunk libpng would read into memory. libpng allocates
/// (and zeroes) what an ancillary chunk declares before reading it, so a 170-byte PNG whose text
/// chunk declared 1.5 GB cost 1.5 GB and seconds before "Read Error". Image data (IDAT) is
/// streamed, not held; chunks after it are read only for an interlaced image (see readRows).
std::string chunkOverrun(std::FILE *f, uint64_t fileBytes) {
    unsigned char head[8];
    bool interlaced = false, afterData = false;
    for (uint64_t at = 8; at + 8 <= fileBytes;) {
        if (std::fseek(f, long(at), SEEK_SET) != 0 || std::fread(head, 1, 8, f) != 8) break;
        uint64_t length = be32(head), end = at + 12 + length;
        std::string type(reinterpret_cast<char *>(head + 4), 4);
        if (type == "IHDR" && length >= 13 && at + 21 <= fileBytes) {
            unsigned char method = 0;
            if (std::fseek(f, long(at + 20), SEEK_SET) == 0 && std::fread(&method, 1, 1, f) == 1)
                interlaced = method != 0;
        }
        if (type == "IDAT") {
            afterData = true;
        } else if (end > fileBytes && (!afterData || interlaced)) {
            return "chunk " + type + " at byte " + std::to_string(at) + " declares " +
                   std::to_string(length) + " bytes, more than the " +
                   std::to_string(fileBytes - std::min(fileBytes, at + 8)) +
                   " left in the file (corrupt or truncated)";
        }
        if (type == "IEND" || end > fileBytes) break;
        at = end;
    }
    std::rewind(f);
    return "";
}

/// A FILE that closes itself.
struct File {
    std::FILE *f = nullptr;
    ~File() {
        if (f) std::fclose(f);
    }
};

}  // namespace

bool hasPngSignature(const std::string &path) {
    File file{std::fopen(path.c_str(), "rb")};
    unsigned char sig[8];
    return file.f && std::fread(sig, 1, sizeof sig, file.f) == sizeof sig &&
           png_sig_cmp(sig, 0, sizeof sig) == 0;
}

struct PngReader::Impl {
    File file;
    png_structp png = nullptr;
    png_infop info = nullptr;
    ErrorBuffer error;
    size_t rowBytes = 0;
    int bitDepth = 8;
    bool interlaced = false;
    /// libpng's message, and whether the file ended before the image did.
    std::string why() const {
        return std::string(error.text) +
               (file.f && std::feof(file.f) ? " (the file ends early: truncated)" : "");
    }
    ~Impl() {
        if (png) png_destroy_read_struct(&png, info ? &info : nullptr, nullptr);
    }
};

PngReader::PngReader(const std::string &path) : impl_(std::make_unique<Impl>()), path_(path) {
    auto fail = [&](const std::string &why) {
        throw std::runtime_error("cannot read image '" + path + "': " + why);
    };
    impl_->file.f = std::fopen(path.c_str(), "rb");
    if (!impl_->file.f) fail(std::strerror(errno));
    std::error_code ec;
    if (std::string problem = chunkOverrun(impl_->file.f, std::filesystem::file_size(path, ec));
        !problem.empty())
        fail(problem);
    impl_->png =
        png_create_read_struct(PNG_LIBPNG_VER_STRING, &impl_->error, onPngError, onPngWarning);
    if (!impl_->png || !(impl_->info = png_create_info_struct(impl_->png)))
        fail("out of memory for libpng");
    png_init_io(impl_->png, impl_->file.f);
    png_uint_32 size[2] = {0, 0};
    int raw[3] = {0, 0, 0}, expanded[4] = {0, 0, 0, 0}, linear = 0;
    if (!readInfo(impl_->png, impl_->info, size, raw, expanded, &linear)) fail(impl_->why());
    width_ = size[0];
    height_ = size[1];
    fileChannels_ = raw[0];
    fileBitDepth_ = raw[1];
    hasAlpha_ = raw[2] != 0;
    channels_ = expanded[0];
    impl_->bitDepth = expanded[1];
    impl_->rowBytes = static_cast<size_t>(expanded[2]);
    impl_->interlaced = expanded[3] != 0;
    linear_ = linear != 0;
}

PngReader::~PngReader() = default;

std::vector<float> PngReader::readPixels() {
    size_t w = width_, h = height_;
    std::vector<unsigned char> data(impl_->rowBytes * h);
    std::vector<png_bytep> rows(h);
    for (size_t y = 0; y < h; ++y) rows[y] = data.data() + y * impl_->rowBytes;
    if (!readRows(impl_->png, rows.data(), impl_->interlaced))
        throw std::runtime_error("cannot read image '" + path_ + "': " + impl_->why());
    // OpenImageIO's integer-to-float conversion: the sample times the float 1 / max
    std::vector<float> px(w * h * size_t(channels_));
    if (impl_->bitDepth == 16) {
        const float scale = 1.0f / 65535;
        for (size_t i = 0; i < px.size(); ++i)
            px[i] = float((unsigned(data[2 * i]) << 8) | data[2 * i + 1]) * scale;
    } else {
        const float scale = 1.0f / 255;
        for (size_t i = 0; i < px.size(); ++i) px[i] = float(data[i]) * scale;
    }
    return px;
}

void writePng(const std::string &file, int width, int height, int bits, const void *pixels,
              bool linear) {
    auto fail = [&](const std::string &why) {
        throw std::runtime_error("cannot write '" + file + "': " + why);
    };
    File out{std::fopen(file.c_str(), "wb")};
    if (!out.f) fail(std::strerror(errno));
    ErrorBuffer error;
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, onPngError, onPngWarning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        fail("out of memory for libpng");
    }
    png_init_io(png, out.f);
    size_t rowBytes = size_t(width) * 3 * size_t(bits / 8);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    auto *base = static_cast<png_bytep>(const_cast<void *>(pixels));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = base + y * rowBytes;
    bool ok =
        writeRows(png, info, png_uint_32(width), png_uint_32(height), bits, linear, rows.data());
    png_destroy_write_struct(&png, &info);
    if (!ok) fail(error.text);
    // The last buffered bytes reach the file here: a full disk shows now
    std::FILE *f = out.f;
    out.f = nullptr;
    if (std::fflush(f) != 0 || std::ferror(f)) {
        int err = errno;
        std::fclose(f);
        fail(std::strerror(err));
    }
    if (std::fclose(f) != 0) fail(std::strerror(errno));
}

}  // namespace rt
