// SPDX-License-Identifier: MIT
// Image reading and atomic writing: PNG through libpng (png_io.h), every other format through
// the OpenImageIO module, loaded on first use (oiio_loader.h).
#include "core/image/image_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "core/image/float_image_limits.h"
#include "core/image/image_limits.h"
#include "core/image/oiio_loader.h"
#include "core/image/png_io.h"
#include "core/system/temp_file.h"

namespace rt {

namespace fs = std::filesystem;

double srgbEncode(double x) {
    if (!(x > 0.0031308)) return x > 0 ? 12.92 * x : 0;
    return 1.055 * std::pow(x, 1 / 2.4) - 0.055;
}

double srgbDecode(double v) {
    if (v <= 0.04045) return v / 12.92;
    return std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {

constexpr double kHuge = 1e300;

std::string lowerExtension(const std::string &path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext;
}

/// Quantises like POV-Ray's IntEncode: floor(clamp(v,0,1) * max + 0.5).
double quantiseValue(double v, double maxValue, bool srgb) {
    if (!std::isfinite(v)) v = 0;
    v = std::clamp(v, 0.0, 1.0);
    if (srgb) v = srgbEncode(v);
    return std::floor(std::clamp(v, 0.0, 1.0) * maxValue + 0.5);
}

/// Where the 8-bit sRGB code steps: step[k] is the least double v in [0, 1] whose code is at
/// least k (k = 1 ... 255), found by bisecting the doubles with the formula itself; first[i] is
/// the code of i / kBins.
struct SrgbSteps {
    static constexpr int kBins = 4096;
    /// A value this close (relative) to a step takes the formula: only there could the rounding
    /// of pow, ~1e-16, put a value on the other side of the step than the table says
    static constexpr double kNear = 1e-9;
    std::array<double, 257> step;  // step[0] = -inf, step[256] = +inf as sentinels
    std::array<uint8_t, kBins + 1> first;

    static int formula(double v) { return static_cast<int>(quantiseValue(v, 255, true)); }

    /// The code of v: the table's, or the formula's within kNear of a step.
    int code(double v) const {
        if (!(v > 0)) return 0;  // and NaN
        if (!(v < 1)) return v == INFINITY ? 0 : 255;
        int k = first[static_cast<int>(v * kBins)];
        while (step[k + 1] <= v) ++k;
        if ((k > 0 && v - step[k] <= step[k] * kNear) ||
            (k < 255 && step[k + 1] - v <= step[k + 1] * kNear))
            return formula(v);
        return k;
    }

    SrgbSteps() {
        step[0] = -INFINITY;
        step[256] = INFINITY;
        for (int k = 1; k <= 255; ++k) {
            auto reaches = [k](double v) { return formula(v) >= k; };
            // Bracket the step around the analytic inverse, widening until it holds (the
            // formula's code is 0 at 0 and 255 at 1)
            double guess = srgbDecode((k - 0.5) / 255);
            double lo = 0, hi = 1;
            for (double width : {1e-12, 1e-9, 1e-6, 1e-3}) {
                double a = std::max(0.0, guess * (1 - width)),
                       b = std::min(1.0, guess * (1 + width));
                if (!reaches(a) && reaches(b)) {
                    lo = a;
                    hi = b;
                    break;
                }
            }
            // Non-negative doubles order as their bit patterns
            uint64_t loBits = std::bit_cast<uint64_t>(lo), hiBits = std::bit_cast<uint64_t>(hi);
            while (hiBits - loBits > 1) {
                uint64_t midBits = loBits + (hiBits - loBits) / 2;
                (reaches(std::bit_cast<double>(midBits)) ? hiBits : loBits) = midBits;
            }
            step[k] = std::bit_cast<double>(hiBits);
        }
        int k = 0;
        for (int i = 0; i <= kBins; ++i) {
            double v = double(i) / kBins;
            while (k < 255 && step[k + 1] <= v) ++k;
            first[i] = static_cast<uint8_t>(k);
        }
    }
};

const SrgbSteps &srgbSteps() {
    static const SrgbSteps steps;
    return steps;
}

template <typename T>
std::vector<T> quantise(const Image &img, double maxValue, bool srgb) {
    std::vector<T> out(img.data().size());
    // 8-bit sRGB, every PNG scadray writes by default: by the table (a pow a channel was half
    // the cost of writing the file), where there are more values than the ~5,000 formula
    // evaluations that build it
    if (srgb && maxValue == 255 && out.size() >= 16384) {
        const SrgbSteps &steps = srgbSteps();
        for (size_t i = 0; i < out.size(); ++i) out[i] = static_cast<T>(steps.code(img.data()[i]));
        return out;
    }
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = static_cast<T>(quantiseValue(img.data()[i], maxValue, srgb));
    return out;
}

}  // namespace

int srgbByte(double v) { return srgbSteps().code(v); }

namespace {

/// What an image file holds, as OpenImageIO's read_image(FLOAT) gives it: `channels` floats a
/// pixel (integer samples divided by their maximum).
struct RawImage {
    int width = 0, height = 0, channels = 0;
    bool integer = false;  ///< 8- or 16-bit samples
    bool linear = false;   ///< declares a linear colour space
    int batches = 0;
    std::vector<std::string> channelNames;
    std::vector<float> pixels;
    ImageMetadata meta;
};

/// Refuses what a header declares beyond the limits (image_limits.h), before any pixel memory is
/// allocated.
void checkDeclared(const std::string &path, uint64_t width, uint64_t height, int channels) {
    if (width == 0 || height == 0 || channels < 1)
        throw std::runtime_error("image '" + path + "' has no pixels");
    if (channels > kMaxReadImageChannels)
        throw std::runtime_error("image '" + path + "' has " + std::to_string(channels) +
                                 " channels, more than the limit of " +
                                 std::to_string(kMaxReadImageChannels));
    std::string problem = imageSizeProblem(width, height, kMaxReadImagePixels, kMaxReadImageSide);
    if (!problem.empty()) throw std::runtime_error("image '" + path + "' " + problem);
}

/// A PNG without alpha through libpng; nothing for one with alpha, whose pixels OpenImageIO
/// premultiplies (left to it, so they read exactly as before).
std::optional<RawImage> readPngRaw(const std::string &path, uint64_t fileBytes) {
    PngReader png(path);
    // Checked for OpenImageIO's reading too, which allocates the declared pixels as well
    checkDeclared(path, png.width(), png.height(), png.channels());
    // The header's own fields (a palette image has one channel before expansion)
    ImageHeader header;
    header.format = "PNG";
    header.width = png.width();
    header.height = png.height();
    header.channels = png.fileChannels();
    header.bitDepth = png.fileBitDepth();
    std::string problem = pngPlausibilityProblem(header, fileBytes);
    if (!problem.empty()) throw std::runtime_error("image '" + path + "' " + problem);
    if (png.hasAlpha()) return std::nullopt;
    RawImage raw;
    raw.width = static_cast<int>(png.width());
    raw.height = static_cast<int>(png.height());
    raw.channels = png.channels();
    raw.integer = true;
    raw.linear = png.linear();
    raw.pixels = png.readPixels();
    raw.meta.fullWidth = raw.width;
    raw.meta.fullHeight = raw.height;
    return raw;
}

/// Refuses a Radiance or OpenEXR file whose header declares more pixels than the limits allow
/// or than the file can hold, before OpenImageIO reads it (OpenEXR sizes its chunk offset
/// table from the header as it opens the file).
void checkFloatImageHeader(const std::string &path, uint64_t fileBytes) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return;  // OpenImageIO says why
    std::optional<FloatImageHeader> h;
    try {
        h = readFloatImageHeader(in);
    } catch (const std::runtime_error &e) {
        throw std::runtime_error("cannot read image '" + path + "': " + e.what());
    }
    if (!h) return;
    checkDeclared(path, h->width, h->height, h->channels);
    std::string problem = floatImagePlausibilityProblem(*h, fileBytes);
    if (!problem.empty())
        throw std::runtime_error("image '" + path + "' (" + h->format + ") " + problem);
}

/// Any other image through the OpenImageIO module.
RawImage readOiioRaw(const std::string &path, uint64_t fileBytes) {
    checkFloatImageHeader(path, fileBytes);
    const ScadrayOiioApi &oiio = oiioModule("read image '" + path + "'");
    char error[4096] = "";
    ScadrayOiioHeader h{};
    void *in = oiio.openInput(path.c_str(), &h, error, sizeof error);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + error);
    std::unique_ptr<void, void (*)(void *)> closer(in, oiio.closeInput);
    uint64_t width = uint64_t(std::max(h.width, 0)), height = uint64_t(std::max(h.height, 0));
    checkDeclared(path, width, height, h.channels);
    // OpenImageIO also reads a Radiance file whose header lacks the "#?" line, and splits long
    // header lines where the check above does not: its own size decides here
    if (std::string_view(h.format) == "hdr" && radianceMinDataBytes(height, width) > fileBytes)
        throw std::runtime_error(
            "image '" + path + "' (Radiance HDR) declares " + std::to_string(width) + " x " +
            std::to_string(height) + " pixels, which need at least " +
            std::to_string(radianceMinDataBytes(height, width)) + " bytes, more than its " +
            std::to_string(fileBytes) + " bytes (corrupt or truncated)");
    RawImage raw;
    raw.width = h.width;
    raw.height = h.height;
    raw.channels = h.channels;
    raw.integer = h.integer != 0;
    raw.linear = h.linear != 0;
    raw.batches = h.batches;
    for (int c = 0; c < std::min(h.channels, SCADRAY_OIIO_MAX_NAMED_CHANNELS); ++c)
        raw.channelNames.emplace_back(h.channelNames[c]);
    raw.meta.x = h.x;
    raw.meta.y = h.y;
    raw.meta.fullWidth = h.fullWidth;
    raw.meta.fullHeight = h.fullHeight;
    for (int i = 0; i < std::min(h.attributeCount, SCADRAY_OIIO_MAX_ATTRIBUTES); ++i)
        raw.meta.attributes.emplace_back(h.attributeNames[i], h.attributeValues[i]);
    raw.pixels.resize(size_t(h.width) * size_t(h.height) * size_t(h.channels));
    if (!oiio.readPixels(in, raw.pixels.data(), error, sizeof error))
        throw std::runtime_error("cannot read image '" + path + "': " + error);
    return raw;
}

/// Reads an image file: PNG through libpng, the rest through OpenImageIO, chosen by content.
RawImage readRaw(const std::string &path, bool forceOiio = false) {
    std::error_code ec;
    fs::file_status st = fs::status(path, ec);
    if (!fs::exists(st)) throw std::runtime_error("cannot read image '" + path + "': no such file");
    if (!fs::is_regular_file(st))
        throw std::runtime_error("cannot read image '" + path + "': not a regular file");
    uint64_t fileBytes = fs::file_size(path, ec);
    if (!forceOiio && hasPngSignature(path))
        if (std::optional<RawImage> raw = readPngRaw(path, fileBytes)) return std::move(*raw);
    return readOiioRaw(path, fileBytes);
}

/// The first three channels (grey repeated) as linear RGB: integer samples are sRGB-encoded
/// unless the file says it is linear (e.g. POV-Ray's File_Gamma=1.0 PNGs carry gAMA 1.0) or
/// `assumeLinear` is set.
Image toImage(const RawImage &raw, bool assumeLinear) {
    bool decode = raw.integer && !assumeLinear && !raw.linear;
    Image img(raw.width, raw.height);
    for (int y = 0; y < raw.height; ++y)
        for (int x = 0; x < raw.width; ++x) {
            const float *p = &raw.pixels[(size_t(y) * raw.width + x) * raw.channels];
            Rgb c;
            for (int ch = 0; ch < 3; ++ch) {
                double v = p[std::min(ch, raw.channels - 1)];
                c[ch] = decode ? srgbDecode(v) : v;
            }
            img.set(x, y, c);
        }
    return img;
}

/// Writes `pixels` of `spec` through the OpenImageIO module into a temporary file beside
/// `path` and a rename, so the target is either complete or untouched.
void writeOiio(const ScadrayOiioWriteSpec &spec, const void *pixels, const std::string &path) {
    const ScadrayOiioApi &oiio = oiioModule("write '" + path + "'");
    char error[4096] = "";
    // The writer is chosen by the target's extension, before any temporary exists
    void *out = oiio.createOutput(path.c_str(), error, sizeof error);
    if (!out)
        throw std::runtime_error("no image writer for '" + path + "' (use .png or .exr): " + error);
    std::unique_ptr<void, void (*)(void *)> destroyer(out, oiio.destroyOutput);
    // The temporary keeps the extension too
    TempFile tmp(path, lowerExtension(path));
    if (!oiio.writePixels(out, tmp.path().c_str(), &spec, pixels, error, sizeof error))
        throw std::runtime_error("cannot write '" + path + "': " + error);
    tmp.commit();
}

/// writeImage through the OpenImageIO module, PNG included.
void writeImageOiio(const Image &img, const std::string &path, const WriteOptions &opts) {
    std::string ext = lowerExtension(path);
    bool isPng = ext == ".png";
    bool isFloat = ext == ".exr" || ext == ".hdr" || ext == ".pfm";
    bool bits16 = opts.pngDepth == PngDepth::Bits16;
    bool srgb = !isFloat && !(isPng && opts.linearPng);
    ScadrayOiioWriteSpec spec{};
    spec.width = img.width();
    spec.height = img.height();
    spec.channels = 3;
    spec.type = isFloat ? SCADRAY_OIIO_FLOAT : bits16 ? SCADRAY_OIIO_UINT16 : SCADRAY_OIIO_UINT8;
    spec.colorSpace = srgb ? "sRGB" : "Linear";
    spec.gamma = isPng && !srgb ? 1.0f : 0.0f;
    spec.batches = -1;
    if (isFloat)
        writeOiio(spec, img.data().data(), path);
    else if (bits16)
        writeOiio(spec, quantise<uint16_t>(img, 65535, srgb).data(), path);
    else
        writeOiio(spec, quantise<uint8_t>(img, 255, srgb).data(), path);
}

}  // namespace

void writeImage(const Image &img, const std::string &path, const WriteOptions &opts) {
    if (img.empty()) throw std::runtime_error("cannot write an empty image");
    std::string ext = lowerExtension(path);
    if (ext != ".png") return writeImageOiio(img, path, opts);
    // libpng, through a temporary beside the target and a rename
    bool linear = opts.linearPng;
    TempFile tmp(path, ext);
    if (opts.pngDepth == PngDepth::Bits16)
        writePng(tmp.path(), img.width(), img.height(), 16,
                 quantise<uint16_t>(img, 65535, !linear).data(), linear);
    else
        writePng(tmp.path(), img.width(), img.height(), 8,
                 quantise<uint8_t>(img, 255, !linear).data(), linear);
    tmp.commit();
}

void writeImageWithOiio(const Image &img, const std::string &path, const WriteOptions &opts) {
    if (img.empty()) throw std::runtime_error("cannot write an empty image");
    writeImageOiio(img, path, opts);
}

std::string ImageMetadata::attribute(const std::string &name) const {
    for (const auto &[n, v] : attributes)
        if (n == name) return v;
    return {};
}

void writeEstimate(const ImageEstimate &est, const std::string &path, const ImageMetadata &meta) {
    if (lowerExtension(path) != ".exr")
        throw std::runtime_error("image estimates are written as .exr, not '" + path + "'");
    const Image &m = est.mean;
    std::vector<std::pair<const Image *, std::string>> layers = {{&m, ""}};
    if (!est.variance.empty()) layers.push_back({&est.variance, "var."});
    if (!est.spread.empty()) layers.push_back({&est.spread, "spread."});
    if (!est.ties.empty()) layers.push_back({&est.ties, "ties."});
    int nch = 3 * static_cast<int>(layers.size());
    std::vector<std::string> names;
    for (const auto &[img, prefix] : layers)
        for (const char *c : {"R", "G", "B"}) names.push_back(prefix + c);
    std::vector<const char *> namePtrs;
    for (const std::string &n : names) namePtrs.push_back(n.c_str());
    ScadrayOiioWriteSpec spec{};
    spec.width = m.width();
    spec.height = m.height();
    spec.channels = nch;
    spec.type = SCADRAY_OIIO_FLOAT;
    spec.channelNames = namePtrs.data();
    spec.batches = est.batches;
    spec.x = meta.x;
    spec.y = meta.y;
    spec.fullWidth = meta.fullWidth;
    spec.fullHeight = meta.fullHeight;
    std::vector<const char *> attrNames, attrValues;
    for (const auto &[n, v] : meta.attributes) {
        if (n.size() >= SCADRAY_OIIO_NAME_SIZE || v.size() >= SCADRAY_OIIO_VALUE_SIZE)
            throw std::runtime_error("image attribute '" + n + "' is too long to keep");
        attrNames.push_back(n.c_str());
        attrValues.push_back(v.c_str());
    }
    if (attrNames.size() > SCADRAY_OIIO_MAX_ATTRIBUTES)
        throw std::runtime_error("more than " + std::to_string(SCADRAY_OIIO_MAX_ATTRIBUTES) +
                                 " image attributes");
    spec.attributeCount = static_cast<int>(attrNames.size());
    spec.attributeNames = attrNames.data();
    spec.attributeValues = attrValues.data();
    std::vector<float> px(size_t(m.width()) * m.height() * nch);
    for (size_t p = 0; p < size_t(m.width()) * m.height(); ++p)
        for (size_t l = 0; l < layers.size(); ++l)
            for (int c = 0; c < 3; ++c)
                px[p * nch + 3 * l + c] = layers[l].first->data()[3 * p + c];
    writeOiio(spec, px.data(), path);
}

ImageEstimate readEstimate(const std::string &path, bool assumeLinear, ImageMetadata *meta) {
    RawImage raw = readRaw(path);
    if (meta) *meta = raw.meta;
    auto channel = [&](const std::string &name) {
        for (size_t i = 0; i < raw.channelNames.size(); ++i)
            if (raw.channelNames[i] == name) return static_cast<int>(i);
        return -1;
    };
    ImageEstimate est;
    est.mean = toImage(raw, assumeLinear);
    auto layer = [&](const std::string &prefix) {
        int r = channel(prefix + "R"), g = channel(prefix + "G"), b = channel(prefix + "B");
        Image img;
        if (r < 0 || g < 0 || b < 0) return img;
        img = Image(raw.width, raw.height);
        for (int y = 0; y < raw.height; ++y)
            for (int x = 0; x < raw.width; ++x) {
                const float *p = &raw.pixels[(size_t(y) * raw.width + x) * raw.channels];
                img.set(x, y, Rgb(p[r], p[g], p[b]));
            }
        return img;
    };
    est.variance = layer("var.");
    est.spread = layer("spread.");
    est.ties = layer("ties.");
    if (!est.variance.empty() || !est.spread.empty() || !est.ties.empty())
        est.batches = raw.batches;
    return est;
}

ImageEstimate downsample(const Image &img, int k) {
    if (k < 1 || img.width() % k || img.height() % k)
        throw std::runtime_error("image of " + std::to_string(img.width()) + "x" +
                                 std::to_string(img.height()) + " does not split into " +
                                 std::to_string(k) + "x" + std::to_string(k) + " blocks");
    int w = img.width() / k, h = img.height() / k;
    ImageEstimate est;
    est.mean = Image(w, h);
    est.spread = Image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Rgb sum(0);
            for (int j = 0; j < k; ++j)
                for (int i = 0; i < k; ++i) sum += img.at(x * k + i, y * k + j);
            est.mean.set(x, y, sum / double(k * k));
            // Spread over the block and the ring of neighbouring sub-samples around it: any
            // edge crossing the pixel then lies between two of these samples, even one that
            // passes between the block's last row and the pixel's border
            Rgb lo(kHuge), hi(-kHuge);
            for (int j = std::max(0, y * k - 1); j <= std::min(img.height() - 1, y * k + k); ++j)
                for (int i = std::max(0, x * k - 1); i <= std::min(img.width() - 1, x * k + k);
                     ++i) {
                    Rgb c = img.at(i, j);
                    for (int ch = 0; ch < 3; ++ch) {
                        lo[ch] = std::min(lo[ch], c[ch]);
                        hi[ch] = std::max(hi[ch], c[ch]);
                    }
                }
            est.spread.set(x, y, hi - lo);
        }
    return est;
}

Image readImage(const std::string &path, bool assumeLinear) {
    return toImage(readRaw(path), assumeLinear);
}

Image readImageWithOiio(const std::string &path, bool assumeLinear) {
    return toImage(readRaw(path, true), assumeLinear);
}

}  // namespace rt
