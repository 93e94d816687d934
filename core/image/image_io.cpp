// SPDX-License-Identifier: MIT
// OpenImageIO-based image reading and atomic writing.
#include "core/image/image_io.h"

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

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

}  // namespace

void writeImage(const Image &img, const std::string &path, const WriteOptions &opts) {
    if (img.empty()) throw std::runtime_error("cannot write an empty image");
    std::string ext = lowerExtension(path);
    fs::path target(path);
    fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir))
        throw std::runtime_error("output folder '" + dir.string() + "' does not exist");
    // The temporary keeps the extension so OpenImageIO picks the same format
    fs::path tmp = dir / ("." + target.filename().string() + ".partial-" +
                          std::to_string(::getpid()) + ext);

    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out)
        throw std::runtime_error("no image writer for '" + path + "' (use .png or .exr): " +
                                 OIIO::geterror());
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

    bool ok = out->open(tmp.string(), spec);
    if (ok) {
        if (isFloat) {
            ok = out->write_image(OIIO::TypeDesc::FLOAT, img.data().data());
        } else if (type == OIIO::TypeDesc::UINT16) {
            auto px = quantise<uint16_t>(img, 65535, srgb);
            ok = out->write_image(OIIO::TypeDesc::UINT16, px.data());
        } else {
            auto px = quantise<uint8_t>(img, 255, srgb);
            ok = out->write_image(OIIO::TypeDesc::UINT8, px.data());
        }
        ok = out->close() && ok;
    }
    if (!ok) {
        std::string err = out->geterror();
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write '" + path + "': " + err);
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write '" + path + "': " + ec.message());
    }
}

Image readImage(const std::string &path, bool assumeLinear) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1)
        throw std::runtime_error("image '" + path + "' has no pixels");
    std::vector<float> px(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()))
        throw std::runtime_error("cannot read image '" + path + "': " + in->geterror());
    bool integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                   spec.format.basetype == OIIO::TypeDesc::UINT16;
    bool decode = integer && !assumeLinear;
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
