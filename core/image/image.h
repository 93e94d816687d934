// SPDX-License-Identifier: MIT
// Linear RGB float image, row-major with the top row first.
#pragma once

#include <vector>

#include "core/math/rgb.h"

namespace rt {

class Image {
  public:
    Image() = default;
    Image(int width, int height)
        : width_(width), height_(height), data_(3 * size_t(width) * height) {}

    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return data_.empty(); }
    Rgb at(int x, int y) const {
        const float *p = &data_[3 * (size_t(y) * width_ + x)];
        return {p[0], p[1], p[2]};
    }
    void set(int x, int y, const Rgb &c) {
        float *p = &data_[3 * (size_t(y) * width_ + x)];
        p[0] = static_cast<float>(c.r);
        p[1] = static_cast<float>(c.g);
        p[2] = static_cast<float>(c.b);
    }
    const std::vector<float> &data() const { return data_; }
    std::vector<float> &data() { return data_; }

  private:
    int width_ = 0, height_ = 0;
    std::vector<float> data_;
};

/// A rendered image as an estimate, with what a statistical comparison needs to know about it.
struct ImageEstimate {
    Image mean;
    /// Variance of each pixel's mean, from independent batches (Monte Carlo renders); empty
    /// for deterministic images.
    Image variance;
    int batches = 0;  ///< number of batches behind `variance`
    /// Max - min of the sub-samples averaged into each pixel (supersampled references); large
    /// on silhouettes, shadow edges and coplanar speckle. Empty when unknown.
    Image spread;
    /// Fraction of each pixel's samples that met coincident surfaces (scadray renders); such
    /// pixels show a convention, not geometry, and are masked. Empty when unknown.
    Image ties;
};

}  // namespace rt
