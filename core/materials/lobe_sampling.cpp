// SPDX-License-Identifier: MIT
// Lobe samplers and their densities.
#include "core/materials/lobe_sampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace rt {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = kPi / 2;
constexpr double kInverseGoldenRatio = 0.6180339887498949;

}  // namespace

Frame Frame::fromZ(const Vec3 &n) {
    double sign = std::copysign(1.0, n.z);
    double a = -1 / (sign + n.z);
    double b = n.x * n.y * a;
    return {Vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x),
            Vec3(b, sign + n.y * n.y * a, -n.y), n};
}

Lobe::Lobe(LobeShape shape, double sigma) : shape_(shape), sigma_(std::min(sigma, kMaxLobeSigma)) {
    // 90 degrees converted to radians may round a hair above pi/2
    if (!(sigma > 0 && sigma <= kMaxLobeSigma * (1 + 1e-12)))
        throw std::invalid_argument("lobe spread must be in (0, pi/2] radians");
    sigma = sigma_;
    if (shape == LobeShape::Phong) exponent_ = 1 / (sigma * sigma);
    // -expm1 keeps the kept mass exact when sigma is small (it is then 1 to the last bit)
    if (shape == LobeShape::Normal)
        truncatedMass_ = -std::expm1(-kHalfPi * kHalfPi / (2 * sigma * sigma));
}

Vec3 Lobe::sampleLocal(double u1, double u2) const {
    double phi = 2 * kPi * u2;
    double cosTheta, sinTheta;
    if (shape_ == LobeShape::Phong) {
        // CDF of cos(theta) is 1 - c^(n+1): invert 1 - u1 (in (0, 1]) so that u1 = 0 is the centre
        cosTheta = std::pow(1 - u1, 1 / (exponent_ + 1));
        sinTheta = std::sqrt(std::max(0.0, (1 - cosTheta) * (1 + cosTheta)));
    } else {
        // Truncated Rayleigh: F(theta) = (1 - exp(-theta^2 / 2 sigma^2)) / truncatedMass
        double theta = sigma_ * std::sqrt(-2 * std::log1p(-u1 * truncatedMass_));
        theta = std::min(theta, kHalfPi);
        cosTheta = std::cos(theta);
        sinTheta = std::sin(theta);
    }
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

double Lobe::pdfTheta(double theta) const {
    if (!(theta >= 0 && theta <= kHalfPi)) return 0;
    if (shape_ == LobeShape::Phong)
        return (exponent_ + 1) * std::pow(std::cos(theta), exponent_) * std::sin(theta);
    double s2 = sigma_ * sigma_;
    return theta / s2 * std::exp(-theta * theta / (2 * s2)) / truncatedMass_;
}

double Lobe::pdfLocal(const Vec3 &w) const {
    if (!(w.z >= 0)) return 0;
    double cosTheta = std::min(1.0, w.z);
    if (shape_ == LobeShape::Phong)
        return (exponent_ + 1) / (2 * kPi) * std::pow(cosTheta, exponent_);
    double sinTheta = std::sqrt(w.x * w.x + w.y * w.y);
    double theta = std::atan2(sinTheta, cosTheta);
    double s2 = sigma_ * sigma_;
    // theta / sin(theta) -> 1 at the centre
    double ratio = sinTheta > 0 ? theta / sinTheta : 1;
    return ratio / (2 * kPi * s2) * std::exp(-theta * theta / (2 * s2)) / truncatedMass_;
}

Vec3 sampleLobeAbout(const Lobe &lobe, const Vec3 &centre, const Vec3 &side, double u1, double u2) {
    Vec3 d = Frame::fromZ(centre).toWorld(lobe.sampleLocal(u1, u2));
    double k = dot(d, side);
    if (k <= 0) d = d - side * (2 * k);
    return normalize(d);
}

int latticeGenerator(int n) {
    int g = std::max(1, static_cast<int>(std::lround(n * kInverseGoldenRatio)));
    while (std::gcd(g, n) != 1) ++g;
    return g;
}

}  // namespace rt
