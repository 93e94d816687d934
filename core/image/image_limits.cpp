// SPDX-License-Identifier: MIT
// Image headers read without decoding (PNG IHDR, JPEG SOFn, BMP info header) and size limits.
#include "core/image/image_limits.h"

#include <cstring>

namespace rt {

namespace {

uint32_t be32(const unsigned char *p) {
    return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | p[3];
}
uint32_t be16(const unsigned char *p) { return (uint32_t(p[0]) << 8) | p[1]; }
uint32_t le32(const unsigned char *p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
uint32_t le16(const unsigned char *p) { return uint32_t(p[0]) | (uint32_t(p[1]) << 8); }

std::optional<ImageHeader> pngHeader(std::span<const unsigned char> b) {
    static const unsigned char kSig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    // signature, IHDR length and type, width, height, bit depth, colour type
    if (b.size() < 26 || std::memcmp(b.data(), kSig, 8) != 0 ||
        std::memcmp(b.data() + 12, "IHDR", 4) != 0)
        return std::nullopt;
    ImageHeader h;
    h.format = "PNG";
    h.width = be32(b.data() + 16);
    h.height = be32(b.data() + 20);
    h.bitDepth = b[24];
    switch (b[25]) {
        case 0:
            h.channels = 1;
            break;  // grey
        case 2:
            h.channels = 3;
            break;  // RGB
        case 3:
            h.channels = 1;
            break;  // palette index
        case 4:
            h.channels = 2;
            break;  // grey + alpha
        case 6:
            h.channels = 4;
            break;  // RGBA
        default:
            return std::nullopt;
    }
    return h;
}

std::optional<ImageHeader> jpegHeader(std::span<const unsigned char> b) {
    if (b.size() < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
    size_t at = 2;
    while (at + 4 <= b.size()) {
        if (b[at] != 0xFF) return std::nullopt;
        unsigned char marker = b[at + 1];
        if (marker == 0xFF) {  // fill byte
            ++at;
            continue;
        }
        if (marker == 0xD8 || marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {
            at += 2;  // markers without a length
            continue;
        }
        size_t length = be16(b.data() + at + 2);
        bool sof =
            marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
        if (sof) {
            if (at + 10 > b.size()) return std::nullopt;
            ImageHeader h;
            h.format = "JPEG";
            h.bitDepth = b[at + 4];
            h.height = be16(b.data() + at + 5);
            h.width = be16(b.data() + at + 7);
            h.channels = b[at + 9];
            return h;
        }
        if (marker == 0xDA || marker == 0xD9 || length < 2) return std::nullopt;  // no frame
        at += 2 + length;
    }
    return std::nullopt;
}

std::optional<ImageHeader> bmpHeader(std::span<const unsigned char> b) {
    if (b.size() < 26 || b[0] != 'B' || b[1] != 'M') return std::nullopt;
    ImageHeader h;
    h.format = "BMP";
    uint32_t infoSize = le32(b.data() + 14);
    if (infoSize == 12) {  // OS/2 BITMAPCOREHEADER: 16-bit sizes
        h.width = le16(b.data() + 18);
        h.height = le16(b.data() + 20);
        return h;
    }
    auto width = static_cast<int32_t>(le32(b.data() + 18));
    auto height = static_cast<int32_t>(le32(b.data() + 22));  // negative: top-down rows
    h.width = width < 0 ? uint64_t(-int64_t(width)) : uint64_t(width);
    h.height = height < 0 ? uint64_t(-int64_t(height)) : uint64_t(height);
    return h;
}

}  // namespace

std::optional<ImageHeader> readImageHeader(std::span<const unsigned char> bytes) {
    if (auto h = pngHeader(bytes)) return h;
    if (auto h = jpegHeader(bytes)) return h;
    return bmpHeader(bytes);
}

uint64_t pngRawBytes(uint64_t width, uint64_t height, int channels, int bitDepth) {
    // width and height come from 32-bit fields: a row has at most 2^38 bits; the product is
    // saturated
    if (width > 0xFFFFFFFFull || channels < 0 || channels > 4 || bitDepth < 0 || bitDepth > 16)
        return UINT64_MAX;
    uint64_t rowBytes = 1 + (width * uint64_t(channels) * uint64_t(bitDepth) + 7) / 8;
    return height > UINT64_MAX / rowBytes ? UINT64_MAX : height * rowBytes;
}

std::string imageSizeProblem(uint64_t width, uint64_t height, uint64_t maxPixels,
                             uint64_t maxSide) {
    std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
    if (width == 0 || height == 0) return "declares " + size;
    if (width > maxSide || height > maxSide)
        return "declares " + size + ", a side longer than the limit of " + std::to_string(maxSide);
    if (width * height > maxPixels)
        return "declares " + size + ", more than the limit of " + std::to_string(maxPixels) +
               " pixels";
    return "";
}

std::string pngPlausibilityProblem(const ImageHeader &h, uint64_t fileBytes) {
    uint64_t raw = pngRawBytes(h.width, h.height, h.channels, h.bitDepth);
    if (raw / kMaxDeflateRatio > fileBytes)
        return "declares " + std::to_string(h.width) + " x " + std::to_string(h.height) +
               " pixels (" + std::to_string(raw) + " bytes once inflated), more than its " +
               std::to_string(fileBytes) + " bytes can hold (corrupt or truncated)";
    return "";
}

}  // namespace rt
