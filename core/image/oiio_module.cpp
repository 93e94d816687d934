// SPDX-License-Identifier: MIT
// scadray_oiio.so: every image format but scadray's own PNG path, through OpenImageIO, behind
// the C interface of oiio_abi.h. The only code that includes OpenImageIO; built as a CMake MODULE
// and loaded by oiio_loader.cpp when a non-PNG image is first read or written.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <memory>
#include <string>

#include "core/image/oiio_abi.h"

namespace {

void setError(char *error, size_t size, const std::string &message) {
    if (!error || size == 0) return;
    size_t n = std::min(size - 1, message.size());
    std::memcpy(error, message.data(), n);
    error[n] = '\0';
}

void *openInput(const char *path, ScadrayOiioHeader *header, char *error, size_t errorSize) {
    try {
        auto in = OIIO::ImageInput::open(path);
        if (!in) {
            setError(error, errorSize, OIIO::geterror());
            return nullptr;
        }
        const OIIO::ImageSpec &spec = in->spec();
        std::memset(header, 0, sizeof *header);
        setError(header->format, SCADRAY_OIIO_NAME_SIZE, in->format_name());
        header->width = spec.width;
        header->height = spec.height;
        header->channels = spec.nchannels;
        header->integer = spec.format.basetype == OIIO::TypeDesc::UINT8 ||
                          spec.format.basetype == OIIO::TypeDesc::UINT16;
        // Integer files are sRGB-encoded unless they say they are linear (OpenImageIO reports
        // a PNG's gAMA 1.0 as the colour space "linear")
        std::string space = spec.get_string_attribute("oiio:ColorSpace");
        std::transform(space.begin(), space.end(), space.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        header->linear = space == "linear";
        header->batches = spec.get_int_attribute("scadray:batches", 0);
        int named = std::min(spec.nchannels, SCADRAY_OIIO_MAX_NAMED_CHANNELS);
        for (int i = 0; i < named && i < int(spec.channelnames.size()); ++i)
            setError(header->channelNames[i], SCADRAY_OIIO_NAME_SIZE, spec.channelnames[i]);
        header->x = spec.x - spec.full_x;
        header->y = spec.y - spec.full_y;
        header->fullWidth = spec.full_width;
        header->fullHeight = spec.full_height;
        for (const OIIO::ParamValue &p : spec.extra_attribs) {
            std::string name = p.name().string();
            if (name.rfind("scadray:", 0) != 0 || p.type() != OIIO::TypeDesc::STRING) continue;
            if (header->attributeCount == SCADRAY_OIIO_MAX_ATTRIBUTES) break;
            int i = header->attributeCount++;
            setError(header->attributeNames[i], SCADRAY_OIIO_NAME_SIZE, name);
            setError(header->attributeValues[i], SCADRAY_OIIO_VALUE_SIZE, p.get_string());
        }
        return in.release();
    } catch (const std::exception &e) {
        setError(error, errorSize, e.what());
        return nullptr;
    }
}

int readPixels(void *input, float *pixels, char *error, size_t errorSize) {
    auto *in = static_cast<OIIO::ImageInput *>(input);
    try {
        const OIIO::ImageSpec &spec = in->spec();
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels)) {
            setError(error, errorSize, in->geterror());
            return 0;
        }
        return 1;
    } catch (const std::exception &e) {
        setError(error, errorSize, e.what());
        return 0;
    }
}

void closeInput(void *input) {
    auto *in = static_cast<OIIO::ImageInput *>(input);
    if (!in) return;
    in->close();
    delete in;
}

void *createOutput(const char *target, char *error, size_t errorSize) {
    try {
        auto out = OIIO::ImageOutput::create(target);
        if (!out) {
            setError(error, errorSize, OIIO::geterror());
            return nullptr;
        }
        return out.release();
    } catch (const std::exception &e) {
        setError(error, errorSize, e.what());
        return nullptr;
    }
}

int writePixels(void *output, const char *file, const ScadrayOiioWriteSpec *ws, const void *pixels,
                char *error, size_t errorSize) {
    auto *out = static_cast<OIIO::ImageOutput *>(output);
    try {
        OIIO::TypeDesc type = ws->type == SCADRAY_OIIO_FLOAT    ? OIIO::TypeDesc::FLOAT
                              : ws->type == SCADRAY_OIIO_UINT16 ? OIIO::TypeDesc::UINT16
                                                                : OIIO::TypeDesc::UINT8;
        OIIO::ImageSpec spec(ws->width, ws->height, ws->channels, type);
        if (ws->channelNames) {
            spec.channelnames.clear();
            for (int c = 0; c < ws->channels; ++c) spec.channelnames.push_back(ws->channelNames[c]);
        }
        if (ws->colorSpace) spec.attribute("oiio:ColorSpace", ws->colorSpace);
        if (ws->batches >= 0) spec.attribute("scadray:batches", ws->batches);
        if (ws->fullWidth > 0 && ws->fullHeight > 0) {
            spec.x = ws->x;
            spec.y = ws->y;
            spec.full_x = spec.full_y = 0;
            spec.full_width = ws->fullWidth;
            spec.full_height = ws->fullHeight;
        }
        for (int i = 0; i < ws->attributeCount; ++i)
            spec.attribute(ws->attributeNames[i], ws->attributeValues[i]);
        spec.attribute("Software", "scadray");
        if (ws->gamma > 0) spec.attribute("oiio:Gamma", ws->gamma);
        bool ok = out->open(file, spec) && out->write_image(type, pixels);
        ok = out->close() && ok;
        if (!ok) setError(error, errorSize, out->geterror());
        return ok ? 1 : 0;
    } catch (const std::exception &e) {
        setError(error, errorSize, e.what());
        return 0;
    }
}

void destroyOutput(void *output) { delete static_cast<OIIO::ImageOutput *>(output); }

const ScadrayOiioApi kApi = {SCADRAY_OIIO_ABI_VERSION,
                             openInput,
                             readPixels,
                             closeInput,
                             createOutput,
                             writePixels,
                             destroyOutput};

}  // namespace

extern "C" __attribute__((visibility("default"))) const ScadrayOiioApi *scadray_oiio_api(void) {
    return &kApi;
}
