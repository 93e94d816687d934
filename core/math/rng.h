// SPDX-License-Identifier: MIT
// PCG32 random number generator (O'Neill 2014) and seed mixing, so each (pixel, sample, user seed)
// has its own stream and renders are identical under any thread count.
#pragma once

#include <cstdint>

namespace rt {

/// 64-bit finaliser of MurmurHash3: a bijective mix used to derive stream seeds.
constexpr uint64_t mixBits(uint64_t v) {
    v ^= v >> 33;
    v *= 0xff51afd7ed558ccdULL;
    v ^= v >> 33;
    v *= 0xc4ceb9fe1a85ec53ULL;
    v ^= v >> 33;
    return v;
}

class Rng {
  public:
    Rng() { setSequence(0, kDefaultStream); }
    Rng(uint64_t seed, uint64_t stream = kDefaultStream) { setSequence(seed, stream); }

    /// Seeds from a pixel, a sample index and a user seed.
    static Rng forSample(uint64_t pixelIndex, uint64_t sampleIndex, uint64_t userSeed) {
        return forPixelSample(pixelSeed(pixelIndex, userSeed), sampleIndex);
    }
    /// forSample() in two steps, the first shared by a pixel's samples.
    static uint64_t pixelSeed(uint64_t pixelIndex, uint64_t userSeed) {
        return mixBits(pixelIndex ^ mixBits(userSeed + 0x9e3779b97f4a7c15ULL));
    }
    static Rng forPixelSample(uint64_t pixelSeed, uint64_t sampleIndex) {
        return Rng(pixelSeed, mixBits(sampleIndex + 1));
    }

    void setSequence(uint64_t seed, uint64_t stream) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        uniformU32();
        state_ += seed;
        uniformU32();
    }

    uint32_t uniformU32() {
        uint64_t old = state_;
        state_ = old * 0x5851f42d4c957f2dULL + inc_;
        uint32_t xorShifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorShifted >> rot) | (xorShifted << ((~rot + 1u) & 31));
    }

    /// Uniform double in [0, 1) with 53 random bits.
    double uniform() {
        uint64_t hi = uniformU32(), lo = uniformU32();
        uint64_t bits = ((hi << 32) | lo) >> 11;
        return static_cast<double>(bits) * 0x1.0p-53;
    }

  private:
    static constexpr uint64_t kDefaultStream = 0xda3e39cb94b95bdbULL;
    uint64_t state_ = 0, inc_ = 0;
};

}  // namespace rt
