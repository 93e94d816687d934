// SPDX-License-Identifier: MIT
// A double rounded to the float nearest below it (floatBelow) or above it (floatAbove): the
// outward rounding of the float BVH's boxes and of a ray's origin for its float node test.
// Without a branch on the data: a mesh's item boxes take six each, and a branch on whether
// the conversion went the wrong way, which goes either way at random, was that pass's hot spot.
#pragma once

#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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
    std::memcpy(&f, &bits, 4);
    return f;
}

/// The smallest float not below x (x is not NaN); the mirror image of floatBelow.
inline float floatAbove(double x) {
    float f = static_cast<float>(x);
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    uint32_t step = 1 - (bits >> 31) * 2;
    bits += static_cast<uint32_t>(static_cast<double>(f) < x) * step;
    std::memcpy(&f, &bits, 4);
    return f;
}

#if defined(__SSE2__)
/// floatBelow of both lanes of x, in the two low lanes of the result (the two high lanes are
/// left unspecified): the same floats, with two conversions and a few integer steps for both.
inline __m128 floatsBelow(__m128d x) {
    __m128 f = _mm_cvtpd_ps(x);
    // Per float lane, whether its conversion went above x: the low half of each lane's mask
    __m128i above = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmpgt_pd(_mm_cvtps_pd(f), x)),
                                      _MM_SHUFFLE(3, 3, 2, 0));
    __m128i bits = _mm_castps_si128(f);
    // 2 * -sign - 1: +1 for a negative float (-0 included), -1 for a positive one
    __m128i negative = _mm_srai_epi32(bits, 31);
    __m128i step = _mm_sub_epi32(_mm_slli_epi32(_mm_sub_epi32(_mm_setzero_si128(), negative), 1),
                                 _mm_set1_epi32(1));
    return _mm_castsi128_ps(_mm_add_epi32(bits, _mm_and_si128(step, above)));
}

/// floatAbove of both lanes of x, as floatsBelow.
inline __m128 floatsAbove(__m128d x) {
    __m128 f = _mm_cvtpd_ps(x);
    __m128i below = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmplt_pd(_mm_cvtps_pd(f), x)),
                                      _MM_SHUFFLE(3, 3, 2, 0));
    __m128i bits = _mm_castps_si128(f);
    // 2 * sign + 1: -1 for a negative float, +1 for a positive one (+0 included)
    __m128i negative = _mm_srai_epi32(bits, 31);
    __m128i step = _mm_add_epi32(_mm_add_epi32(negative, negative), _mm_set1_epi32(1));
    return _mm_castsi128_ps(_mm_add_epi32(bits, _mm_and_si128(step, below)));
}
#endif

}  // namespace rt
