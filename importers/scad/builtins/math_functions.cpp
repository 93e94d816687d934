// SPDX-License-Identifier: MIT
// Builtin math functions: abs, sign, trigonometry, rounding, powers, rands, min, max, norm, cross
// (func.cc).
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

#include "core/math/degree_trig.h"
#include "core/system/utf8.h"
#include "importers/scad/builtins/families.h"
#include "importers/scad/builtins/function_support.h"
#include "importers/scad/lang/lexer.h"

namespace rt::scad {

namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

/// One numeric argument mapped through `f`.
template <typename F>
Value unaryMath(Evaluator &ev, const Args &a, const SourceLoc &loc, const char *name, F f) {
    if (a.size() != 1) return undefWarn(ev, loc, name, true);
    if (!a[0].isNumber()) return undefWarn(ev, loc, name, false);
    return Value::number(f(a[0].toNumber()));
}

/// OpenSCAD 2021.01's seed hash (linalg.cc hash_floating_point, after Python's hash of a
/// float): the value modulo 2^31 - 1 computed exactly from its binary digits, so whole seeds
/// map to themselves and every double, infinities and NaN included, has a defined seed.
int32_t hashSeed(double v) {
    constexpr int kBits = 31;
    constexpr uint32_t kModulus = (uint32_t{1} << kBits) - 1;
    if (std::isnan(v)) return 0;
    if (std::isinf(v)) return v > 0 ? 314159 : -314159;
    int e = 0;
    double m = std::frexp(v, &e);
    uint32_t sign = 1;
    if (m < 0) {
        sign = UINT32_MAX;  // -1: the product below negates modulo 2^32
        m = -m;
    }
    uint32_t x = 0;
    while (m != 0) {
        // 28 bits at a time: x = x * 2^28 + the next digits, modulo kModulus
        x = ((x << 28) & kModulus) | x >> (kBits - 28);
        m *= 268435456.0;
        e -= 28;
        auto y = static_cast<uint32_t>(m);  // m < 2^28
        m -= y;
        x += y;
        if (x >= kModulus) x -= kModulus;
    }
    e = e >= 0 ? e % kBits : kBits - 1 - ((-1 - e) % kBits);
    x = ((x << e) & kModulus) | x >> (kBits - e);
    x *= sign;
    if (x == UINT32_MAX) x = UINT32_MAX - 1;
    return static_cast<int32_t>(x);
}

Value minMax(Evaluator &ev, const Args &a, const SourceLoc &l, bool isMin) {
    const char *name = isMin ? "min" : "max";
    if (a.empty()) return undefWarn(ev, l, name, true);
    std::string ignored;
    BinaryOp better = isMin ? BinaryOp::Less : BinaryOp::Greater;
    if (a.size() == 1 && a[0].isVector() && !a[0].toVector().empty()) {
        // Elements compare with the language's ordering; incomparable ones never win
        const auto &v = a[0].toVector();
        Value best = v[0];
        for (size_t i = 1; i < v.size(); ++i) {
            Value c = applyBinary(better, v[i], best, ignored);
            if (c.isBool() && c.boolValue()) best = v[i];
        }
        return best;
    }
    if (!a[0].isNumber()) return undefWarn(ev, l, name, false);
    double best = a[0].toNumber();
    for (size_t i = 1; i < a.size(); ++i) {
        if (!a[i].isNumber()) return undefWarn(ev, l, name, false);
        double x = a[i].toNumber();
        if (isMin ? x < best : x > best) best = x;
    }
    return Value::number(best);
}

Value fnAbs(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "abs", [](double x) { return std::fabs(x); });
}

Value fnSign(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "sign", [](double x) { return x < 0 ? -1.0 : (x > 0 ? 1.0 : 0.0); });
}

Value fnSin(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "sin", [](double x) { return sinDegrees(x); });
}

Value fnCos(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "cos", [](double x) { return cosDegrees(x); });
}

Value fnTan(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // Exact at multiples of 45 degrees (and +-inf at 90 + 180k), like degree_trig.cc
    return unaryMath(ev, a, l, "tan", [](double x) { return sinDegrees(x) / cosDegrees(x); });
}

Value fnAsin(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "asin", [](double x) { return std::asin(x) * kRadToDeg; });
}

Value fnAcos(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "acos", [](double x) { return std::acos(x) * kRadToDeg; });
}

Value fnAtan(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "atan", [](double x) { return std::atan(x) * kRadToDeg; });
}

Value fnAtan2(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 2) return undefWarn(ev, l, "atan2", true);
    if (!a[0].isNumber() || !a[1].isNumber()) return undefWarn(ev, l, "atan2", false);
    return Value::number(std::atan2(a[0].toNumber(), a[1].toNumber()) * kRadToDeg);
}

Value fnRound(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // std::round rounds halfway cases away from zero: round(-2.5) = -3
    return unaryMath(ev, a, l, "round", [](double x) { return std::round(x); });
}

Value fnCeil(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "ceil", [](double x) { return std::ceil(x); });
}

Value fnFloor(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "floor", [](double x) { return std::floor(x); });
}

Value fnSqrt(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "sqrt", [](double x) { return std::sqrt(x); });
}

Value fnExp(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "exp", [](double x) { return std::exp(x); });
}

Value fnLn(Evaluator &ev, const Args &a, const SourceLoc &l) {
    return unaryMath(ev, a, l, "ln", [](double x) { return std::log(x); });
}

Value fnPow(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 2) return undefWarn(ev, l, "pow", true);
    if (!a[0].isNumber() || !a[1].isNumber()) return undefWarn(ev, l, "pow", false);
    return Value::number(std::pow(a[0].toNumber(), a[1].toNumber()));
}

Value fnLog(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // log(x) is base 10; log(b, x) is base b
    if (a.size() == 1) return unaryMath(ev, a, l, "log", [](double x) { return std::log10(x); });
    if (a.size() != 2) return undefWarn(ev, l, "log", true);
    if (!a[0].isNumber() || !a[1].isNumber()) return undefWarn(ev, l, "log", false);
    return Value::number(std::log(a[1].toNumber()) / std::log(a[0].toNumber()));
}

Value fnRands(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // Same engine, seeding and distribution as OpenSCAD 2021.01 (std::mt19937 seeded with
    // hashSeed, uniform reals), so seeded sequences match. Unseeded calls use a per-import
    // counter so imports are reproducible.
    if (a.size() != 3 && a.size() != 4) return undefWarn(ev, l, "rands", true);
    for (const auto &v : a)
        if (!v.isNumber()) return undefWarn(ev, l, "rands", false);
    // An infinite or NaN bound becomes half the largest double, with OpenSCAD's warnings
    auto bound = [&](double d, const char *which, double reset) {
        if (std::isfinite(d)) return d;
        ev.warn(l, std::string("rands() range ") + which + " cannot be infinite");
        ev.warn(l, "resetting to " + formatNumber(reset));
        return reset;
    };
    constexpr double kHalfMax = std::numeric_limits<double>::max() / 2;
    double lo = bound(a[0].toNumber(), "min", -kHalfMax);
    double hi = bound(a[1].toNumber(), "max", kHalfMax);
    if (hi < lo) std::swap(lo, hi);
    double count = std::fabs(a[2].toNumber());
    if (!std::isfinite(count)) {
        ev.warn(l, "rands() cannot create an infinite number of results");
        ev.warn(l, "resetting number of results to 1");
        count = 1;
    }
    // Checked before the conversion: a count beyond size_t would be undefined behaviour
    double budget = static_cast<double>(ev.limits().maxLiveElements);
    ev.checkElementBudget(
        count > budget ? static_cast<size_t>(budget) + 1 : static_cast<size_t>(count), l);
    std::mt19937 rng(a.size() == 4 ? static_cast<uint32_t>(hashSeed(a[3].toNumber()))
                                   : static_cast<uint32_t>(ev.randomSeed()));
    std::uniform_real_distribution<> dist(lo, hi);
    std::vector<Value> out;
    auto n = static_cast<size_t>(count);
    out.reserve(n);
    for (size_t i = 0; i < n; ++i) out.push_back(Value::number(dist(rng)));
    return Value::vector(std::move(out));
}

Value fnMin(Evaluator &ev, const Args &a, const SourceLoc &l) { return minMax(ev, a, l, true); }

Value fnMax(Evaluator &ev, const Args &a, const SourceLoc &l) { return minMax(ev, a, l, false); }

Value fnNorm(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 1) return undefWarn(ev, l, "norm", true);
    if (!a[0].isVector()) return undefWarn(ev, l, "norm", false);
    double s = 0;
    for (const auto &v : a[0].toVector()) {
        if (!v.isNumber()) return undefWarn(ev, l, "norm", false);
        s += v.toNumber() * v.toNumber();
    }
    return Value::number(std::sqrt(s));
}

Value fnCross(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 2) return undefWarn(ev, l, "cross", true);
    if (!a[0].isVector() || !a[1].isVector()) return undefWarn(ev, l, "cross", false);
    const auto &u = a[0].toVector(), &v = a[1].toVector();
    auto numeric = [](const std::vector<Value> &x) {
        for (const auto &e : x)
            if (!e.isNumber() || !std::isfinite(e.toNumber())) return false;
        return true;
    };
    if (u.size() != v.size() || (u.size() != 2 && u.size() != 3) || !numeric(u) || !numeric(v)) {
        ev.warn(l, "Invalid vector parameter for cross()");
        return Value();
    }
    if (u.size() == 2)
        return Value::number(u[0].toNumber() * v[1].toNumber() - u[1].toNumber() * v[0].toNumber());
    double x0 = u[0].toNumber(), y0 = u[1].toNumber(), z0 = u[2].toNumber();
    double x1 = v[0].toNumber(), y1 = v[1].toNumber(), z1 = v[2].toNumber();
    return Value::vector({Value::number(y0 * z1 - z0 * y1), Value::number(z0 * x1 - x0 * z1),
                          Value::number(x0 * y1 - y0 * x1)});
}

}  // namespace

BuiltinFamily mathFunctionBuiltins() {
    static constexpr BuiltinFunctionEntry kFunctions[] = {
        {"abs", fnAbs},     {"sign", fnSign},   {"rands", fnRands}, {"min", fnMin},
        {"max", fnMax},     {"sin", fnSin},     {"cos", fnCos},     {"tan", fnTan},
        {"asin", fnAsin},   {"acos", fnAcos},   {"atan", fnAtan},   {"atan2", fnAtan2},
        {"round", fnRound}, {"ceil", fnCeil},   {"floor", fnFloor}, {"pow", fnPow},
        {"sqrt", fnSqrt},   {"exp", fnExp},     {"ln", fnLn},       {"log", fnLog},
        {"norm", fnNorm},   {"cross", fnCross},
    };
    return {{}, kFunctions};
}

}  // namespace rt::scad
