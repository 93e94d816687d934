// SPDX-License-Identifier: MIT
// Linear RGB float image, row-major with the top row first.
#pragma once

#include <vector>

#include "core/math/rgb.h"

namespace rt {

class Image {
  public:
    Image() = default;
    Image(int width, int height) : width_(width), height_(height), data_(3 * size_t(width) * height) {}

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

}  // namespace rt
