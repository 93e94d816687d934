// SPDX-License-Identifier: MIT
// The C interface between scadray and its OpenImageIO module (scadray_oiio.so), which is loaded
// with dlopen on first use so that a process that never reads or writes a non-PNG image does not
// load OpenImageIO's tree of some 260 shared libraries. Plain C types only: no exception, no
// std:: object crosses it.
#pragma once

#include <stddef.h>

extern "C" {

/// Changes whenever a struct or a function below changes; the loader refuses a module built
/// with another value.
#define SCADRAY_OIIO_ABI_VERSION 3
/// The one symbol the module exports.
#define SCADRAY_OIIO_ENTRY "scadray_oiio_api"
/// Most channel names a header carries (more channels are counted, not named).
#define SCADRAY_OIIO_MAX_NAMED_CHANNELS 16
#define SCADRAY_OIIO_NAME_SIZE 64
/// Most "scadray:" string attributes a header carries, and the room for each value.
#define SCADRAY_OIIO_MAX_ATTRIBUTES 16
#define SCADRAY_OIIO_VALUE_SIZE 2048

enum { SCADRAY_OIIO_UINT8 = 0, SCADRAY_OIIO_UINT16 = 1, SCADRAY_OIIO_FLOAT = 2 };

/// What an opened image file declares.
struct ScadrayOiioHeader {
    char format[SCADRAY_OIIO_NAME_SIZE];  ///< OpenImageIO's name of the reader ("hdr", "openexr")
    int width, height, channels;
    int integer;  ///< 8- or 16-bit unsigned samples
    int linear;   ///< its colour space is "linear" (any case)
    int batches;  ///< the "scadray:batches" attribute, 0 when absent
    char channelNames[SCADRAY_OIIO_MAX_NAMED_CHANNELS][SCADRAY_OIIO_NAME_SIZE];
    /// The pixels' place in the whole picture (OpenEXR's data window) and the picture's size
    /// (its display window); x = y = 0 and the image's own size where a format has no such thing.
    int x, y, fullWidth, fullHeight;
    /// String attributes whose names start with "scadray:" (values cut to fit).
    int attributeCount;
    char attributeNames[SCADRAY_OIIO_MAX_ATTRIBUTES][SCADRAY_OIIO_NAME_SIZE];
    char attributeValues[SCADRAY_OIIO_MAX_ATTRIBUTES][SCADRAY_OIIO_VALUE_SIZE];
};

/// What to write: interleaved pixels of `type`, top row first.
struct ScadrayOiioWriteSpec {
    int width, height, channels, type;
    const char *const *channelNames;  ///< `channels` names, or null for R, G, B, ...
    const char *colorSpace;           ///< "oiio:ColorSpace", or null
    float gamma;                      ///< "oiio:Gamma" when > 0
    int batches;                      ///< "scadray:batches" when >= 0
    /// The pixels' place in a larger picture of fullWidth x fullHeight (0: the image is the whole
    /// picture); formats without a data window ignore it.
    int x, y, fullWidth, fullHeight;
    /// String attributes written to the header.
    int attributeCount;
    const char *const *attributeNames;
    const char *const *attributeValues;
};

/// The module's functions. Each returns null or 0 on failure with a message (NUL-terminated,
/// cut to fit) in `error`.
struct ScadrayOiioApi {
    int abiVersion;
    /// Opens an image file for reading and fills `header`; the handle goes to readPixels and
    /// closeInput.
    void *(*openInput)(const char *path, struct ScadrayOiioHeader *header, char *error,
                       size_t errorSize);
    /// Reads every channel of every pixel as float (width * height * channels values).
    int (*readPixels)(void *input, float *pixels, char *error, size_t errorSize);
    void (*closeInput)(void *input);
    /// A writer for `target`, chosen by its extension; null when no format has that extension.
    void *(*createOutput)(const char *target, char *error, size_t errorSize);
    /// Writes the whole image into `file` (a temporary beside the target) with that writer.
    int (*writePixels)(void *output, const char *file, const struct ScadrayOiioWriteSpec *spec,
                       const void *pixels, char *error, size_t errorSize);
    void (*destroyOutput)(void *output);
};

typedef const struct ScadrayOiioApi *(*ScadrayOiioEntry)(void);

}  // extern "C"
