// SPDX-License-Identifier: MIT
// What a Radiance RGBE (.hdr) or OpenEXR header declares, read before OpenImageIO opens the file,
// and the fewest bytes the file needs for those pixels, so a 117-byte .hdr declaring 16384 x 16384
// pixels is refused before 3 GB are allocated for them.
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace rt {

/// Fewest bytes of pixel data a Radiance file of `scanlines` scanlines of `length` pixels holds, as
/// OpenImageIO reads it: a scanline 8 to 32767 pixels long may be run-length encoded (a 4-byte
/// marker, then each of its 4 byte channels in runs of at most 127 bytes, each run 2 bytes), any
/// other is flat (4 bytes a pixel).
uint64_t radianceMinDataBytes(uint64_t scanlines, uint64_t length);

/// Most raw pixel bytes one byte of an OpenEXR chunk's data decodes to with compression
/// `compression` (the header's code): its compressor's largest ratio; 0 for an unknown code.
uint64_t exrMaxRatio(int compression);

/// Scanlines an OpenEXR chunk holds with compression `compression` (256, the most any compressor
/// takes, for an unknown code).
uint64_t exrLinesPerChunk(int compression);

/// What the header of a Radiance or OpenEXR file declares.
struct FloatImageHeader {
    const char *format = "";  ///< "Radiance HDR", "OpenEXR"
    uint64_t width = 0, height = 0;
    int channels = 0;
    /// Fewest bytes the whole file takes with those pixels: its header, and for OpenEXR the chunk
    /// offset table, each chunk's own header and the raw pixels over the compressor's largest
    /// ratio.
    uint64_t minFileBytes = 0;
    std::string layout;  ///< how minFileBytes was reached, for messages
};

/// The header of the Radiance or OpenEXR file `in`: nothing for any other file (or a Radiance
/// header this reader does not follow). Throws std::runtime_error for an OpenEXR header that cannot
/// be read (OpenEXR sizes its offset table from it when the file is opened).
std::optional<FloatImageHeader> readFloatImageHeader(std::istream &in);

/// Empty when a file of `fileBytes` bytes can hold what `header` declares, else the reason
/// ("declares 16384 x 16384 pixels, which need at least ... bytes, more than its 117").
std::string floatImagePlausibilityProblem(const FloatImageHeader &header, uint64_t fileBytes);

}  // namespace rt
