// SPDX-License-Identifier: MIT
// PNG through libpng directly: scadray's default output and POV-Ray's, read and written without
// loading OpenImageIO. Decodes exactly as OpenImageIO 2.4 does (same libpng transforms, same
// sample scaling, same colour-space rules), so a file reads to the same floats either way.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rt {

/// True when the file starts with the 8-byte PNG signature.
bool hasPngSignature(const std::string &path);

/// A PNG opened for reading: the header is parsed on construction, the pixels are decoded by
/// readPixels() after the caller has checked the header.
class PngReader {
  public:
    /// Opens `path` and reads everything before the image data. Throws std::runtime_error
    /// ("cannot read image '<path>': <reason>").
    explicit PngReader(const std::string &path);
    ~PngReader();
    PngReader(const PngReader &) = delete;
    PngReader &operator=(const PngReader &) = delete;

    uint64_t width() const { return width_; }
    uint64_t height() const { return height_; }
    /// Channels once palettes and low bit depths are expanded: 1 (grey) or 3 (RGB); with
    /// hasAlpha() one more.
    int channels() const { return channels_; }
    /// An alpha channel or a tRNS chunk (OpenImageIO premultiplies such pixels).
    bool hasAlpha() const { return hasAlpha_; }
    /// What IHDR declares (a palette image has one channel), for the deflate-ratio check.
    int fileChannels() const { return fileChannels_; }
    int fileBitDepth() const { return fileBitDepth_; }
    /// The file declares linear values, as OpenImageIO 2.4 decides it: no sRGB chunk and a gAMA
    /// whose inverse rounds to 1.00, unless a text chunk "oiio:ColorSpace" says otherwise.
    bool linear() const { return linear_; }

    /// Decodes every pixel as float, channels() values a pixel, each sample divided by its
    /// maximum (255 or 65535) as OpenImageIO does. Throws std::runtime_error.
    std::vector<float> readPixels();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::string path_;
    uint64_t width_ = 0, height_ = 0;
    int channels_ = 0, fileChannels_ = 0, fileBitDepth_ = 0;
    bool hasAlpha_ = false, linear_ = false;
};

/// Writes interleaved RGB `pixels` (uint8_t for 8 bits, uint16_t for 16) as a PNG into `file`,
/// tagged sRGB (sRGB, gAMA and cHRM chunks) or, when `linear`, gAMA 1.0, with the text
/// Software=scadray. Throws std::runtime_error with libpng's or the system's reason.
void writePng(const std::string &file, int width, int height, int bits, const void *pixels,
              bool linear);

}  // namespace rt
