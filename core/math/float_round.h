// SPDX-License-Identifier: MIT
// A double rounded to the float nearest below it (floatBelow) or above it (floatAbove): the
// outward rounding of the float BVH's boxes and of a ray's origin for its float node test.
// Without a branch on the data: a mesh's item boxes take six each, and with a branch about
// half of them mispredicted.
#pragma once

#include <cstdint>
#include <cstring>

namespace rt {

/// The largest float not above x (x is not NaN). When x itself is no float, that is the float
/// conversion's result or one unit of its bits below: towards zero from a positive float, away
/// from it from a negative one (from -0 to the smallest negative denormal), and from +inf (x
/// beyond the largest float) to the largest finite float.
inline float floatBelow(double x) {
    float f = static_cast<float>(x);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    // Where f is above x it has x's sign (a conversion keeps it, a zero's too): a negative f,
    // -0 included, steps away from zero (+1), a positive one towards it (-1, mod 2^32)
    uint32_t step = (bits >> 31) * 2 - 1;
    bits += static_cast<uint32_t>(static_cast<double>(f) > x) * step;
    float below;
    std::memcpy(&below, &bits, 4);
    return static_cast<double>(f) > x ? below : f;
}

/// The smallest float not below x (x is not NaN); the mirror image of floatBelow.
inline float floatAbove(double x) {
    float f = static_cast<float>(x);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    uint32_t step = 1 - (bits >> 31) * 2;
    bits += static_cast<uint32_t>(static_cast<double>(f) < x) * step;
    float above;
    std::memcpy(&above, &bits, 4);
    return static_cast<double>(f) < x ? above : f;
}

}  // namespace rt
