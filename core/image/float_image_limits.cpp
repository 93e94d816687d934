// SPDX-License-Identifier: MIT
// Radiance and OpenEXR headers read without decoding, and the fewest bytes their pixels take.
#include "core/image/float_image_limits.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/image/image_limits.h"

namespace rt {

namespace {

constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

uint64_t ceilDiv(uint64_t a, uint64_t b) { return a / b + (a % b != 0); }
uint64_t addSat(uint64_t a, uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }
uint64_t mulSat(uint64_t a, uint64_t b) { return b && a > kSaturated / b ? kSaturated : a * b; }

// Radiance RGBE

/// Longest Radiance header read before OpenImageIO opens the file (real ones take a few
/// hundred bytes); a longer one is left to the check on what OpenImageIO reports.
constexpr uint64_t kMaxRadianceHeaderBytes = 65536;

/// The next line without its '\n'; false at the end of the file or past `budget` bytes.
bool readLine(std::istream &in, std::string &line, uint64_t &budget) {
    line.clear();
    for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
        if (budget-- == 0) return false;
        if (c == '\n') return true;
        line.push_back(static_cast<char>(c));
    }
    return false;
}

/// A positive decimal number of at most 9 digits (OpenImageIO reads an int).
std::optional<uint64_t> dimension(const std::string &text) {
    if (text.empty() || text.size() > 9 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
    uint64_t v = std::stoull(text);
    return v > 0 ? std::optional<uint64_t>(v) : std::nullopt;
}

/// "#?RADIANCE" (or "#?RGBE"), lines of variables and comments, a blank line, then the
/// resolution "-Y 512 +X 768": the first number counts the scanlines, the second their pixels
/// (OpenImageIO reports them as height and width in all eight orientations).
std::optional<FloatImageHeader> radianceHeader(std::istream &in) {
    uint64_t budget = kMaxRadianceHeaderBytes;
    std::string line;
    if (!readLine(in, line, budget) || line.rfind("#?", 0) != 0) return std::nullopt;
    do {
        if (!readLine(in, line, budget)) return std::nullopt;
    } while (!line.empty());
    if (!readLine(in, line, budget)) return std::nullopt;
    std::array<std::string, 4> words;
    size_t n = 0;
    for (size_t at = 0; at < line.size();) {
        size_t start = line.find_first_not_of(" \t\r", at);
        if (start == std::string::npos) break;
        size_t end = std::min(line.find_first_of(" \t\r", start), line.size());
        if (n == words.size()) return std::nullopt;
        words[n++] = line.substr(start, end - start);
        at = end;
    }
    auto axis = [](const std::string &w) {
        return w.size() == 2 && (w[0] == '-' || w[0] == '+') ? w[1] : '\0';
    };
    char first = axis(words[0]), second = axis(words[2]);
    std::optional<uint64_t> scanlines = dimension(words[1]), length = dimension(words[3]);
    if (n != 4 || !scanlines || !length ||
        !((first == 'Y' && second == 'X') || (first == 'X' && second == 'Y')))
        return std::nullopt;
    FloatImageHeader h;
    h.format = "Radiance HDR";
    h.width = *length;
    h.height = *scanlines;
    h.channels = 3;
    uint64_t headerBytes = kMaxRadianceHeaderBytes - budget;
    h.minFileBytes = addSat(headerBytes, radianceMinDataBytes(*scanlines, *length));
    h.layout = "a header of " + std::to_string(headerBytes) + " bytes and " +
               std::to_string(*scanlines) + " scanlines of at least " +
               std::to_string(radianceMinDataBytes(1, *length)) + " bytes";
    return h;
}

// OpenEXR (the layout in "The OpenEXR File Layout", openexr.com)

constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr uint32_t kExrTiledFlag = 0x200, kExrLongNamesFlag = 0x400, kExrDeepFlag = 0x800,
                   kExrMultipartFlag = 0x1000;

/// Reads a file's bytes in order, failing with the reason.
class ExrReader {
  public:
    explicit ExrReader(std::istream &in) : in_(in) {}
    uint64_t at() const { return at_; }
    void bytes(void *out, size_t n, const char *what) {
        if (!in_.read(static_cast<char *>(out), static_cast<std::streamsize>(n)))
            throw std::runtime_error(std::string("its OpenEXR header ends inside ") + what);
        at_ += n;
    }
    template <typename T>
    T value(const char *what) {
        T v;
        bytes(&v, sizeof v, what);
        return v;
    }
    /// A NUL-terminated name of at most `maxLength` characters.
    std::string name(size_t maxLength, const char *what) {
        std::string s;
        for (char c; (c = value<char>(what)) != '\0';) {
            if (s.size() == maxLength)
                throw std::runtime_error(std::string("its OpenEXR header has a ") + what +
                                         " longer than " + std::to_string(maxLength) + " bytes");
            s.push_back(c);
        }
        return s;
    }
    void skip(uint64_t n, const char *what) {
        if (n > uint64_t(std::numeric_limits<std::streamoff>::max()) ||
            !in_.seekg(static_cast<std::streamoff>(n), std::ios::cur))
            throw std::runtime_error(std::string("its OpenEXR header ends inside ") + what);
        at_ += n;
    }

  private:
    std::istream &in_;
    uint64_t at_ = 0;
};

struct ExrChannel {
    int32_t type = 0;  ///< 0 UINT, 1 HALF, 2 FLOAT
    int32_t xSampling = 1, ySampling = 1;
};

/// The first part's header of an OpenEXR file (the part OpenImageIO reads), and the fewest
/// bytes the file needs for it.
FloatImageHeader exrHeader(std::istream &in) {
    ExrReader r(in);
    unsigned char magic[4];
    r.bytes(magic, 4, "its magic number");
    auto flags = r.value<uint32_t>("its version");
    size_t maxName = flags & kExrLongNamesFlag ? 255 : 31;
    std::optional<std::array<int32_t, 4>> window;
    std::optional<int> compression;
    std::optional<std::array<uint32_t, 2>> tiles;
    std::optional<int32_t> chunkCount;
    std::vector<ExrChannel> channels;
    bool haveChannels = false;
    std::string type;
    for (;;) {
        std::string attribute = r.name(maxName, "an attribute name");
        if (attribute.empty()) break;  // the end of the (first part's) header
        std::string kind = r.name(maxName, "an attribute type");
        auto size = r.value<int32_t>("an attribute size");
        if (size < 0)
            throw std::runtime_error("its OpenEXR attribute " + attribute + " has a negative size");
        uint64_t end = r.at() + uint64_t(size);
        if (attribute == "dataWindow" && kind == "box2i" && size == 16) {
            window.emplace();
            for (int32_t &v : *window) v = r.value<int32_t>("dataWindow");
        } else if (attribute == "compression" && kind == "compression" && size == 1) {
            compression = r.value<uint8_t>("compression");
        } else if (attribute == "tiles" && kind == "tiledesc" && size == 9) {
            tiles = {r.value<uint32_t>("tiles"), r.value<uint32_t>("tiles")};
        } else if (attribute == "chunkCount" && kind == "int" && size == 4) {
            chunkCount = r.value<int32_t>("chunkCount");
        } else if (attribute == "type" && kind == "string" && size <= 64) {
            type.resize(static_cast<size_t>(size));
            r.bytes(type.data(), type.size(), "type");
        } else if (attribute == "channels" && kind == "chlist") {
            // Each channel: its name, pixel type, pLinear and 3 reserved bytes, x and y
            // sampling; a NUL ends the list
            haveChannels = true;
            for (std::string name; !(name = r.name(255, "a channel name")).empty();) {
                ExrChannel c;
                c.type = r.value<int32_t>("channels");
                r.skip(4, "channels");
                c.xSampling = r.value<int32_t>("channels");
                c.ySampling = r.value<int32_t>("channels");
                if (c.type < 0 || c.type > 2 || c.xSampling < 1 || c.ySampling < 1)
                    throw std::runtime_error("its OpenEXR channel " + name +
                                             " has an invalid type or sampling");
                channels.push_back(c);
            }
        }
        if (r.at() > end)
            throw std::runtime_error("its OpenEXR attribute " + attribute + " runs past its size");
        r.skip(end - r.at(), attribute.c_str());
    }
    uint64_t headerEnd = r.at();
    if (!window || !compression || !haveChannels)
        throw std::runtime_error(
            "its OpenEXR header lacks the dataWindow, compression or channels attribute");
    int64_t width = int64_t((*window)[2]) - (*window)[0] + 1;
    int64_t height = int64_t((*window)[3]) - (*window)[1] + 1;
    if (width < 1 || height < 1) throw std::runtime_error("its OpenEXR dataWindow is empty");
    bool deep = (flags & kExrDeepFlag) || type.rfind("deep", 0) == 0;
    bool tiled = (!(flags & kExrMultipartFlag) && (flags & kExrTiledFlag)) ||
                 type == "tiledimage" || type == "deeptile";

    FloatImageHeader h;
    h.format = "OpenEXR";
    h.width = uint64_t(width);
    h.height = uint64_t(height);
    h.channels = static_cast<int>(channels.size());
    // The chunks of the full-resolution level: their offset table (8 bytes each) and each
    // chunk's own header (its coordinates and data size; more for multi-part and deep files)
    uint64_t chunks, chunkHeader;
    if (tiled) {
        if (!tiles || (*tiles)[0] == 0 || (*tiles)[1] == 0)
            throw std::runtime_error("its OpenEXR header lacks a valid tiles attribute");
        chunks = ceilDiv(h.width, (*tiles)[0]) * ceilDiv(h.height, (*tiles)[1]);
        chunkHeader = 20;
    } else {
        chunks = ceilDiv(h.height, exrLinesPerChunk(*compression));
        chunkHeader = 8;
    }
    if (chunkCount && *chunkCount > 0) chunks = std::max(chunks, uint64_t(*chunkCount));
    // The raw pixels (unknown for deep data) over the compressor's largest ratio
    uint64_t raw = 0;
    for (const ExrChannel &c : channels) {
        uint64_t samples =
            mulSat(h.width / uint64_t(c.xSampling), h.height / uint64_t(c.ySampling));
        raw = addSat(raw, mulSat(samples, c.type == 1 ? 2 : 4));
    }
    uint64_t ratio = exrMaxRatio(*compression);
    uint64_t data = deep || ratio == 0 ? 0 : ceilDiv(raw, ratio);
    h.minFileBytes = addSat(addSat(headerEnd, mulSat(chunks, 8 + chunkHeader)), data);
    h.layout = "a header of " + std::to_string(headerEnd) + " bytes, " + std::to_string(chunks) +
               " chunks of at least " + std::to_string(8 + chunkHeader) +
               " bytes with their offsets" +
               (data ? ", and " + std::to_string(raw) + " bytes of pixels at most " +
                           std::to_string(ratio) + " : 1 compressed"
                     : std::string());
    return h;
}

}  // namespace

uint64_t radianceMinDataBytes(uint64_t scanlines, uint64_t length) {
    uint64_t perScanline =
        length >= 8 && length <= 0x7fff ? 4 + 4 * 2 * ceilDiv(length, 127) : mulSat(4, length);
    return mulSat(scanlines, perScanline);
}

uint64_t exrMaxRatio(int compression) {
    switch (compression) {
        // None
        case 0:
            return 1;
        // RLE: a count byte and a value give at most 128 bytes
        case 1:
            return 64;
        // ZIPS (one scanline a chunk) and ZIP: deflate's largest ratio
        case 2:
        case 3:
            return kMaxDeflateRatio;
        // PIZ: Huffman codes of at least 1 bit; a run of 256 16-bit values takes at least 10
        // bits (the value's code, the run code and an 8-bit count)
        case 4:
            return 410;
        // PXR24: floats cut to 24 bits, then deflate
        case 5:
            return kMaxDeflateRatio * 4 / 3;
        // B44: a 4 x 4 block of halves (32 bytes) in 14 bytes; B44A: a flat block in 3
        case 6:
            return 3;
        case 7:
            return 11;
        // DWAA and DWAB: RLE (64 : 1) then deflate for alpha channels; an 8 x 8 block of
        // floats (256 bytes) as one DC value and one end-of-block code, each deflated, for
        // colour channels: the same ratio
        case 8:
        case 9:
            return 64 * kMaxDeflateRatio;
        default:
            return 0;
    }
}

uint64_t exrLinesPerChunk(int compression) {
    switch (compression) {
        case 0:
        case 1:
        case 2:
            return 1;
        case 3:
        case 5:
            return 16;
        case 4:
        case 6:
        case 7:
        case 8:
            return 32;
        default:
            return 256;  // DWAB, and the most any compressor takes
    }
}

std::optional<FloatImageHeader> readFloatImageHeader(std::istream &in) {
    unsigned char start[4] = {};
    in.read(reinterpret_cast<char *>(start), 4);
    bool exr = in.gcount() == 4 && std::memcmp(start, kExrMagic, 4) == 0;
    bool radiance = in.gcount() >= 2 && start[0] == '#' && start[1] == '?';
    in.clear();
    in.seekg(0);
    if (exr) return exrHeader(in);
    if (radiance) return radianceHeader(in);
    return std::nullopt;
}

std::string floatImagePlausibilityProblem(const FloatImageHeader &h, uint64_t fileBytes) {
    if (h.minFileBytes <= fileBytes) return "";
    return "declares " + std::to_string(h.width) + " x " + std::to_string(h.height) +
           " pixels, which need at least " +
           (h.minFileBytes == kSaturated ? std::string("2^64") : std::to_string(h.minFileBytes)) +
           " bytes (" + h.layout + "), more than its " + std::to_string(fileBytes) +
           " bytes (corrupt or truncated)";
}

}  // namespace rt
