// SPDX-License-Identifier: MIT
#include "core/image/environment_image.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include "core/image/image_io.h"
#include "core/ir/scene_ir.h"

namespace rt {

ir::Environment loadEnvironmentImage(const std::string &path, double rotateDegrees,
                                     DiagnosticSink &diag) {
    Image img;
    try {
        img = readImage(path);
    } catch (const std::exception &e) {
        std::string what = e.what();
        // readImage's reasons usually name the file already
        throw std::runtime_error(what.find(path) != std::string::npos
                                     ? "environment image: " + what
                                     : "environment image '" + path + "': " + what);
    }
    if (img.width() <= 0 || img.height() <= 0)
        throw std::runtime_error("environment image '" + path + "': the picture is empty");
    auto tex = std::make_shared<ir::Texture>();
    tex->width = img.width();
    tex->height = img.height();
    tex->name = path;
    tex->rgba.resize(4 * size_t(img.width()) * img.height());
    long negative = 0;
    const std::vector<float> &src = img.data();
    for (size_t i = 0, n = size_t(img.width()) * img.height(); i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            float x = src[3 * i + c];
            if (!std::isfinite(x))
                throw std::runtime_error(
                    "environment image '" + path + "': has NaN or infinite pixel values (pixel " +
                    std::to_string(i % img.width()) + ", " + std::to_string(i / img.width()) + ")");
            if (x < 0) {
                ++negative;
                x = 0;
            }
            tex->rgba[4 * i + c] = x;
        }
        tex->rgba[4 * i + 3] = 1;
    }
    if (negative > 0)
        diag.warning({}, "environment image '" + path + "': " + std::to_string(negative) +
                             " negative channel values read as 0");
    ir::Environment env;
    env.kind = ir::EnvironmentKind::Image;
    env.image = std::move(tex);
    env.imagePath = path;
    env.rotateDegrees = rotateDegrees;
    return env;
}

}  // namespace rt
