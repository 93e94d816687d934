// SPDX-License-Identifier: MIT
// Fuzz target: image reading as `scadray compare` does it (readEstimate: PNG through libpng, PNG
// with alpha and OpenEXR through the OpenImageIO module), on PNG and OpenEXR files. The extension
// follows the input's magic number; other inputs are skipped, so OpenImageIO's other format
// readers stay out of scope. readEstimate's contract is std::runtime_error on a bad file.
#include <cstdint>
#include <cstring>

#include "core/image/image_io.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    static const uint8_t kPng[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    static const uint8_t kExr[4] = {0x76, 0x2f, 0x31, 0x01};
    const char *name = nullptr;
    if (size >= 8 && std::memcmp(data, kPng, 8) == 0) name = "in.png";
    if (size >= 4 && std::memcmp(data, kExr, 4) == 0) name = "in.exr";
    if (!name) return 0;
    std::string path = rt::fuzz::writeInput(data, size, name);
    rt::fuzz::expectCleanFailure(
        [&] {
            rt::ImageEstimate e = rt::readEstimate(path);
            const rt::Image &m = e.mean;
            if (m.width() < 0 || m.height() < 0) rt::fuzz::fail("negative image size");
            // Every pixel the image claims must be readable
            for (int y = 0; y < m.height(); y += std::max(1, m.height() / 8))
                for (int x = 0; x < m.width(); x += std::max(1, m.width() / 8)) (void)m.at(x, y);
        },
        /*plainExceptionsAllowed=*/true);
    return 0;
}
