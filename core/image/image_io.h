// SPDX-License-Identifier: MIT
// Image files through OpenImageIO (the only place it is used): PNG with the sRGB curve at 8 or
// 16 bits, EXR as linear float; written to a temporary file and renamed, so an output file is
// either complete or untouched.
#pragma once

#include <string>

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

/// Writes by extension (.png, .exr, also .tif/.ppm as OIIO knows them). Throws std::runtime_error
/// with the reason on failure; the target is then left as it was.
void writeImage(const Image &img, const std::string &path, const WriteOptions &opts = {});

/// Reads an image as linear float RGB. 8/16-bit files are decoded with the sRGB curve unless
/// `assumeLinear` (e.g. POV-Ray's File_Gamma=1.0 output). Throws std::runtime_error.
Image readImage(const std::string &path, bool assumeLinear = false);

}  // namespace rt
