// SPDX-License-Identifier: MIT
// Student t and chi-square distributions, and Benjamini-Hochberg.
#include "core/math/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace rt {

namespace {

/// Continued fraction of the incomplete beta (Press et al., Numerical Recipes 6.4; modified
/// Lentz evaluation), valid for x < (a + 1) / (a + b + 2).
double betaContinuedFraction(double a, double b, double x) {
    constexpr int kMaxIterations = 300;
    constexpr double kTiny = 1e-300;
    constexpr double kTolerance = 1e-15;
    double qab = a + b, qap = a + 1, qam = a - 1;
    double c = 1, d = 1 - qab * x / qap;
    if (std::abs(d) < kTiny) d = kTiny;
    d = 1 / d;
    double h = d;
    for (int m = 1; m <= kMaxIterations; ++m) {
        int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1 + aa * d;
        if (std::abs(d) < kTiny) d = kTiny;
        c = 1 + aa / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1 + aa * d;
        if (std::abs(d) < kTiny) d = kTiny;
        c = 1 + aa / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (std::abs(del - 1) < kTolerance) break;
    }
    return h;
}

}  // namespace

double incompleteBeta(double a, double b, double x) {
    if (x <= 0) return 0;
    if (x >= 1) return 1;
    double lnFront =
        std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
    double front = std::exp(lnFront);
    // Use the symmetry I_x(a,b) = 1 - I_{1-x}(b,a) where the fraction converges faster
    if (x < (a + 1) / (a + b + 2)) return front * betaContinuedFraction(a, b, x) / a;
    return 1 - front * betaContinuedFraction(b, a, 1 - x) / b;
}

double studentTCdf(double t, double dof) {
    if (std::isnan(t)) return t;
    if (std::isinf(dof) || dof > 1e7) return 0.5 * std::erfc(-t / std::sqrt(2.0));
    double x = dof / (dof + t * t);
    double tail = 0.5 * incompleteBeta(dof / 2, 0.5, x);  // P(T > |t|)
    return t > 0 ? 1 - tail : tail;
}

double twoSidedPValue(double t, double dof) {
    if (std::isinf(t)) return 0;
    if (std::isinf(dof) || dof > 1e7) return std::erfc(std::abs(t) / std::sqrt(2.0));
    return incompleteBeta(dof / 2, 0.5, dof / (dof + t * t));
}

double studentTQuantile(double p, double dof) {
    double lo = -1e6, hi = 1e6;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (lo + hi);
        (studentTCdf(mid, dof) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::vector<bool> benjaminiHochberg(const std::vector<double> &p, double q) {
    size_t m = p.size();
    std::vector<size_t> order(m);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
    // Largest k with p_(k) <= k q / m; reject the k smallest
    size_t k = 0;
    for (size_t i = 0; i < m; ++i)
        if (p[order[i]] <= double(i + 1) * q / double(m)) k = i + 1;
    std::vector<bool> reject(m, false);
    for (size_t i = 0; i < k; ++i) reject[order[i]] = true;
    return reject;
}

double upperIncompleteGamma(double a, double x) {
    // Series for P below a + 1, Lentz's continued fraction for Q above (Numerical Recipes 6.2)
    constexpr int kMaxIterations = 1000;
    constexpr double kTiny = 1e-300;
    constexpr double kTolerance = 1e-15;
    if (!(a > 0) || !(x >= 0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0) return 1;
    double logPrefix = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        double term = 1 / a, sum = term;
        for (int n = 1; n < kMaxIterations; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * kTolerance) break;
        }
        return std::max(0.0, 1 - sum * std::exp(logPrefix));
    }
    double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1 / d;
        double del = d * c;
        h *= del;
        if (std::abs(del - 1) < kTolerance) break;
    }
    return std::exp(logPrefix) * h;
}

double chiSquareSf(double x, double dof) { return upperIncompleteGamma(dof / 2, x / 2); }

}  // namespace rt
