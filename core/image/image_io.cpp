// SPDX-License-Identifier: MIT
// OpenImageIO-based image reading and atomic writing.
#include "core/image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>
#include <stdexcept>

#include "core/image/image_limits.h"
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
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

/// Quantises like POV-Ray's IntEncode: floor(clamp(v,0,1) * max + 0.5).
template <typename T>
std::vector<T> quantise(const Image &img, double maxValue, bool srgb) {
    std::vector<T> out(img.data().size());
    for (size_t i = 0; i < out.size(); ++i) {
        double v = img.data()[i];
        if (!std::isfinite(v)) v = 0;
        v = std::clamp(v, 0.0, 1.0);
        if (srgb) v = srgbEncode(v);
        out[i] = static_cast<T>(std::floor(std::clamp(v, 0.0, 1.0) * maxValue + 0.5));
    }
    return out;
}

/// Writes pixels of `spec.format` through a temporary file beside `path` and a rename, so the
/// target is either complete or untouched; an interrupt removes the temporary too.
void writeWithSpec(const OIIO::ImageSpec &spec, const void *pixels, const std::string &path) {
    // The writer is chosen by the target's extension, before any temporary exists
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
        throw std::runtime_error("no image writer for '" + path + "' (use .png or .exr): " +
                                 OIIO::geterror());
    // The temporary keeps the extension too
    TempFile tmp(path, lowerExtension(path));
    bool ok = out->open(tmp.path(), spec) && out->write_image(spec.format, pixels);
    ok = out->close() && ok;
    if (!ok) throw std::runtime_error("cannot write '" + path + "': " + out->geterror());
    tmp.commit();
}

/// Opens an image file for reading after checking what its header declares against the limits
/// (image_limits.h) and, for PNG, against the file's size: the pixel buffers are allocated from
/// the declared size, before a pixel is read.
std::unique_ptr<OIIO::ImageInput> openForReading(const std::string &path) {
    std::error_code ec;
    fs::file_status st = fs::status(path, ec);
    if (fs::exists(st) && !fs::is_regular_file(st))
        throw std::runtime_error("cannot read image '" + path + "': not a regular file");
    uint64_t fileBytes = fs::exists(st) ? fs::file_size(path, ec) : 0;
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1)
        throw std::runtime_error("image '" + path + "' has no pixels");
    if (spec.nchannels > kMaxReadImageChannels)
        throw std::runtime_error("image '" + path + "' has " + std::to_string(spec.nchannels) +
                                 " channels, more than the limit of " +
                                 std::to_string(kMaxReadImageChannels));
    std::string problem = imageSizeProblem(uint64_t(spec.width), uint64_t(spec.height),
                                           kMaxReadImagePixels, kMaxReadImageSide);
    if (problem.empty() && std::string(in->format_name()) == "png") {
        // The header's own fields (a palette image has one channel before expansion)
        unsigned char head[64] = {};
        std::ifstream file(path, std::ios::binary);
        file.read(reinterpret_cast<char *>(head), sizeof head);
        if (auto header = readImageHeader(std::span(head, size_t(file.gcount()))))
            problem = pngPlausibilityProblem(*header, fileBytes);
    }
    if (!problem.empty()) throw std::runtime_error("image '" + path + "' " + problem);
    return in;
}

}  // namespace

void writeImage(const Image &img, const std::string &path, const WriteOptions &opts) {
    if (img.empty()) throw std::runtime_error("cannot write an empty image");
    std::string ext = lowerExtension(path);
    bool isPng = ext == ".png";
    bool isFloat = ext == ".exr" || ext == ".hdr" || ext == ".pfm";
    OIIO::TypeDesc type = isFloat ? OIIO::TypeDesc::FLOAT
                          : (opts.pngDepth == PngDepth::Bits16 ? OIIO::TypeDesc::UINT16
                                                               : OIIO::TypeDesc::UINT8);
    OIIO::ImageSpec spec(img.width(), img.height(), 3, type);
    bool srgb = !isFloat && !(isPng && opts.linearPng);
    spec.attribute("oiio:ColorSpace", srgb ? "sRGB" : "Linear");
    spec.attribute("Software", "scadray");
    if (isPng && !srgb) spec.attribute("oiio:Gamma", 1.0f);
    if (isFloat) {
        writeWithSpec(spec, img.data().data(), path);
    } else if (type == OIIO::TypeDesc::UINT16) {
        auto px = quantise<uint16_t>(img, 65535, srgb);
        writeWithSpec(spec, px.data(), path);
    } else {
        auto px = quantise<uint8_t>(img, 255, srgb);
        writeWithSpec(spec, px.data(), path);
    }
}

void writeEstimate(const ImageEstimate &est, const std::string &path) {
    if (lowerExtension(path) != ".exr")
        throw std::runtime_error("image estimates are written as .exr, not '" + path + "'");
    const Image &m = est.mean;
    std::vector<std::pair<const Image *, std::string>> layers = {{&m, ""}};
    if (!est.variance.empty()) layers.push_back({&est.variance, "var."});
    if (!est.spread.empty()) layers.push_back({&est.spread, "spread."});
    if (!est.ties.empty()) layers.push_back({&est.ties, "ties."});
    int nch = 3 * static_cast<int>(layers.size());
    OIIO::ImageSpec spec(m.width(), m.height(), nch, OIIO::TypeDesc::FLOAT);
    spec.channelnames.clear();
    for (const auto &[img, prefix] : layers)
        for (const char *c : {"R", "G", "B"}) spec.channelnames.push_back(prefix + c);
    spec.attribute("scadray:batches", est.batches);
    spec.attribute("Software", "scadray");
    std::vector<float> px(size_t(m.width()) * m.height() * nch);
    for (size_t p = 0; p < size_t(m.width()) * m.height(); ++p)
        for (size_t l = 0; l < layers.size(); ++l)
            for (int c = 0; c < 3; ++c) px[p * nch + 3 * l + c] = layers[l].first->data()[3 * p + c];
    writeWithSpec(spec, px.data(), path);
}

ImageEstimate readEstimate(const std::string &path, bool assumeLinear) {
    std::unique_ptr<OIIO::ImageInput> in = openForReading(path);
    const OIIO::ImageSpec &spec = in->spec();
    auto channel = [&](const std::string &name) {
        for (int i = 0; i < spec.nchannels; ++i)
            if (spec.channelnames[i] == name) return i;
        return -1;
    };
    ImageEstimate est;
    est.mean = readImage(path, assumeLinear);
    if (channel("var.R") < 0 && channel("spread.R") < 0 && channel("ties.R") < 0) return est;
    std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
        throw std::runtime_error("cannot read image '" + path + "': " + in->geterror());
    auto layer = [&](const std::string &prefix) {
        int r = channel(prefix + "R"), g = channel(prefix + "G"), b = channel(prefix + "B");
        Image img;
        if (r < 0 || g < 0 || b < 0) return img;
        img = Image(spec.width, spec.height);
        for (int y = 0; y < spec.height; ++y)
            for (int x = 0; x < spec.width; ++x) {
                const float *p = &px[(size_t(y) * spec.width + x) * spec.nchannels];
                img.set(x, y, Rgb(p[r], p[g], p[b]));
            }
        return img;
    };
    est.variance = layer("var.");
    est.spread = layer("spread.");
    est.ties = layer("ties.");
    est.batches = spec.get_int_attribute("scadray:batches", 0);
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
                for (int i = std::max(0, x * k - 1); i <= std::min(img.width() - 1, x * k + k); ++i) {
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
    std::unique_ptr<OIIO::ImageInput> in = openForReading(path);
    const OIIO::ImageSpec &spec = in->spec();
    std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
        throw std::runtime_error("cannot read image '" + path + "': " + in->geterror());
    bool integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                   spec.format.basetype == OIIO::TypeDesc::UINT16;
    // Integer files are sRGB-encoded unless they say they are linear (e.g. POV-Ray's
    // File_Gamma=1.0 PNGs carry gAMA 1.0, which OpenImageIO reports as a linear colour space)
    std::string space = spec.get_string_attribute("oiio:ColorSpace");
    std::transform(space.begin(), space.end(), space.begin(), [](unsigned char c) { return std::tolower(c); });
    bool decode = integer && !assumeLinear && space != "linear";
    Image img(spec.width, spec.height);
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            const float *p = &px[(size_t(y) * spec.width + x) * spec.nchannels];
            Rgb c;
            for (int ch = 0; ch < 3; ++ch) {
                double v = p[std::min(ch, spec.nchannels - 1)];
                c[ch] = decode ? srgbDecode(v) : v;
            }
            img.set(x, y, c);
        }
    in->close();
    return img;
}

}  // namespace rt
