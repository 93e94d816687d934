// SPDX-License-Identifier: MIT
// POV-Ray 3.7 classic reflectivity, highlight colour and fade formulas.
#include "core/materials/classic_shading.h"

#include <algorithm>
#include <cmath>

#include "core/math/float_util.h"

namespace rt {

Reflectivity reflectivity(const ir::Finish &f, double cosI, double relativeIor) {
    if (!f.fresnel) {
        // Falloff blend between min (facing) and max (grazing); weight independent of angle
        double frac = f.reflectionFalloff == 1 ? 1 - cosI : std::pow(1 - cosI, f.reflectionFalloff);
        Rgb value;
        if (std::abs(frac) < kPovEpsilon)
            value = f.reflectionMin;
        else if (std::abs(frac - 1) < kPovEpsilon)
            value = f.reflectionMax;
        else
            value = f.reflectionMax * frac + f.reflectionMin * (1 - frac);
        double w = std::max(f.reflectionMax.maxComponent(), f.reflectionMin.maxComponent());
        return {value, w};
    }
    // Fresnel for unpolarised light with g = sqrt(n^2 + c^2 - 1) (POV-Ray ComputeReflectivity)
    double n = relativeIor, c = cosI;
    double g2 = n * n + c * c - 1;
    double F;
    if (g2 <= 0) {
        F = 1;  // total internal reflection side
    } else {
        double g = std::sqrt(g2);
        double a = (g - c) / (g + c);
        double b = (c * (g + c) - 1) / (c * (g - c) + 1);
        F = clamp(0.5 * a * a * (1 + b * b), 0.0, 1.0);
    }
    Rgb value = g2 <= 0 ? f.reflectionMax : f.reflectionMax * F + f.reflectionMin * (1 - F);
    return {value, value.maxComponent()};
}

Rgb highlightColour(const ir::Finish &f, const Rgb &lightColour, const Rgb &pigment, double cosNL) {
    if (f.metallic == 0) return lightColour;
    double x = std::abs(std::acos(clamp(cosNL, -1.0, 1.0))) / (kPi / 2);
    double F = clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
    Rgb tint;
    for (int i = 0; i < 3; ++i) tint[i] = 1 + f.metallic * (1 - F) * (pigment[i] - 1);
    return lightColour * tint;
}

double lightFade(const ir::Light &light, double distance) {
    if (!(light.fadePower > 0) || !(std::abs(light.fadeDistance) > kPovEpsilon)) return 1;
    return 2 / (1 + std::pow(distance / light.fadeDistance, light.fadePower));
}

Rgb interiorFade(const ir::Interior &in, double depth, bool shadowPath) {
    if (!(std::abs(in.fadeDistance) > kPovEpsilon)) return Rgb(1);
    if (shadowPath && !(in.fadePower > 0)) return Rgb(1);
    double d = depth / in.fadeDistance;
    Rgb result;
    for (int i = 0; i < 3; ++i) {
        double fc = in.fadeColor[i];
        result[i] = in.fadePower >= 1000 ? std::exp(-(1 - fc) * d)
                                         : fc + (1 - fc) / (1 + std::pow(d, in.fadePower));
    }
    return result;
}

}  // namespace rt
