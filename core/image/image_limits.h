// SPDX-License-Identifier: MIT
// Size limits for images read from files, and what an encoded image's header declares, so a
// hostile header (a 68-byte PNG declaring 30000 x 30000 pixels) is refused before any pixel
// memory is allocated.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace rt {

/// Most pixels an image file read by scadray (compare's inputs, POV-Ray references) may
/// declare: 2^28 (16384 x 16384), about 3 GiB as float RGB.
constexpr uint64_t kMaxReadImagePixels = uint64_t(1) << 28;
/// Longest side of such an image (the renderer's own limit).
constexpr uint64_t kMaxReadImageSide = 32768;
/// Most channels such an image may have (an estimate written by scadray has 12).
constexpr int kMaxReadImageChannels = 16;
/// Deflate (PNG) expands at most 1032 : 1; a PNG declaring more raw bytes than this many times
/// its file size cannot hold its pixels.
constexpr uint64_t kMaxDeflateRatio = 1032;

/// What an encoded image declares in its header.
struct ImageHeader {
    const char *format = "";  ///< "PNG", "JPEG", "BMP"
    uint64_t width = 0, height = 0;
    int channels = 0;  ///< 0 when the header does not say (BMP)
    int bitDepth = 8;  ///< per channel
};

/// The header of a PNG, JPEG or BMP image in memory; nothing for anything else or a header
/// cut short.
std::optional<ImageHeader> readImageHeader(std::span<const unsigned char> bytes);

/// Raw (filtered, before deflate) bytes of a non-interlaced PNG of these dimensions: one filter
/// byte per row plus the packed samples.
uint64_t pngRawBytes(uint64_t width, uint64_t height, int channels, int bitDepth);

/// Empty when an image of `width` x `height` fits `maxPixels` and `maxSide`, else the reason
/// ("is 30000 x 30000 pixels, more than the limit of ...").
std::string imageSizeProblem(uint64_t width, uint64_t height, uint64_t maxPixels, uint64_t maxSide);

/// Empty when a PNG declaring `header` can plausibly be held by `fileBytes` bytes (deflate's
/// ratio bound), else the reason.
std::string pngPlausibilityProblem(const ImageHeader &header, uint64_t fileBytes);

}  // namespace rt
