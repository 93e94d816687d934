// SPDX-License-Identifier: MIT
// Image files: PNG with the sRGB curve at 8 or 16 bits through libpng, EXR as linear float and
// every other format through OpenImageIO, in a module loaded only when such a file is first read
// or written; written to a temporary file and renamed, so an output file is either complete or
// untouched.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/image/image.h"

namespace rt {

enum class PngDepth { Bits8, Bits16 };

struct WriteOptions {
    PngDepth pngDepth = PngDepth::Bits8;
    /// PNG only: write linear values instead of sRGB-encoded ones (for 16-bit comparisons).
    bool linearPng = false;
};

/// Encodes a linear value with the piecewise sRGB curve (IEC 61966-2-1).
double srgbEncode(double linear);
/// Inverse of srgbEncode.
double srgbDecode(double encoded);
/// The 8-bit code a PNG stores for a linear value: floor(srgbEncode(clamp(v, 0, 1)) * 255 + 0.5),
/// 0 for a value that is not finite (POV-Ray's IntEncode), exactly, from a table of where the
/// code steps (values within 1e-9 of a step take the formula).
int srgbByte(double linear);

/// Writes by extension (.png through libpng; .exr, also .tif/.ppm as OpenImageIO knows them,
/// through the OpenImageIO module). Throws std::runtime_error with the reason on failure,
/// including a module that cannot be loaded; the target is then left as it was.
void writeImage(const Image &img, const std::string &path, const WriteOptions &opts = {});

/// What an OpenEXR header says about an image beyond its pixels: its place in a larger picture
/// (a tile of `render --tile`) and scadray's string attributes.
struct ImageMetadata {
    /// The image's top-left pixel in the picture (the data window) and the picture's size (the
    /// display window); fullWidth = fullHeight = 0 when writing: the image is the whole picture.
    int x = 0, y = 0, fullWidth = 0, fullHeight = 0;
    /// Attributes named "scadray:...", in the order written (at most 16, values up to 2047 bytes).
    std::vector<std::pair<std::string, std::string>> attributes;
    /// The value of attribute `name`, empty when absent.
    std::string attribute(const std::string &name) const;
};

/// Writes an estimate as OpenEXR: channels R, G, B (the mean), var.R/G/B, spread.R/G/B and
/// ties.R/G/B when present, the batch count as the header attribute "scadray:batches", and
/// `meta`'s place in the picture and attributes.
void writeEstimate(const ImageEstimate &est, const std::string &path,
                   const ImageMetadata &meta = {});

/// Reads an image written by writeEstimate, or any image (then only the mean is filled); checked
/// as readImage is. `meta`, when given, receives the header's place and attributes (a format
/// without them: the image as the whole picture and none).
ImageEstimate readEstimate(const std::string &path, bool assumeLinear = false,
                           ImageMetadata *meta = nullptr);

/// Box-filters each k x k block into one pixel; `spread` receives max - min over the block and
/// the ring of sub-samples bordering it.
ImageEstimate downsample(const Image &img, int k);

/// Reads an image as linear float RGB. The header is checked before any pixel memory is
/// allocated: at most kMaxReadImagePixels pixels, kMaxReadImageSide per side and
/// kMaxReadImageChannels channels (image_limits.h), a regular file, and for PNG a size its
/// compressed data can hold. 8/16-bit files are decoded with the sRGB curve unless
/// they declare themselves linear (gAMA 1.0, as POV-Ray's File_Gamma=1.0 output and scadray's
/// --linear PNGs do) or `assumeLinear` is set. A PNG without alpha is decoded by libpng, any other
/// file by OpenImageIO (chosen by content); both give the same floats. Throws
/// std::runtime_error.
Image readImage(const std::string &path, bool assumeLinear = false);

/// readImage and writeImage through OpenImageIO whatever the format, PNG included (the one path
/// before PNG went through libpng), so tests can check that both give the same pixels.
Image readImageWithOiio(const std::string &path, bool assumeLinear = false);
void writeImageWithOiio(const Image &img, const std::string &path, const WriteOptions &opts = {});

}  // namespace rt
