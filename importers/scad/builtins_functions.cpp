// SPDX-License-Identifier: MIT
// Builtin functions of OpenSCAD 2021.01 (func.cc): math in degrees, strings, lists, search.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

#include "core/math/degree_trig.h"
#include "importers/scad/evaluator.h"
#include "importers/scad/lexer.h"
#include "core/system/utf8.h"

namespace rt::scad {

namespace {

using Args = std::vector<Value>;

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;

Value undefWarn(Evaluator &ev, const SourceLoc &loc, const char *name, bool countProblem) {
    ev.warn(loc, std::string(name) + (countProblem ? "() number of parameters does not match"
                                                   : "() parameter could not be converted"));
    return Value();
}

/// One numeric argument mapped through `f`.
template <typename F>
Value unaryMath(Evaluator &ev, const Args &a, const SourceLoc &loc, const char *name, F f) {
    if (a.size() != 1) return undefWarn(ev, loc, name, true);
    if (!a[0].isNumber()) return undefWarn(ev, loc, name, false);
    return Value::number(f(a[0].toNumber()));
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
    ev.checkElementBudget(count > budget ? static_cast<size_t>(budget) + 1 : static_cast<size_t>(count), l);
    std::mt19937 rng(a.size() == 4 ? static_cast<uint32_t>(hashSeed(a[3].toNumber()))
                                   : static_cast<uint32_t>(ev.randomSeed()));
    std::uniform_real_distribution<> dist(lo, hi);
    std::vector<Value> out;
    auto n = static_cast<size_t>(count);
    out.reserve(n);
    for (size_t i = 0; i < n; ++i) out.push_back(Value::number(dist(rng)));
    return Value::vector(std::move(out));
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
Value fnMin(Evaluator &ev, const Args &a, const SourceLoc &l) { return minMax(ev, a, l, true); }
Value fnMax(Evaluator &ev, const Args &a, const SourceLoc &l) { return minMax(ev, a, l, false); }

Value fnLen(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 1) return undefWarn(ev, l, "len", true);
    if (a[0].isVector()) return Value::number(static_cast<double>(a[0].toVector().size()));
    if (a[0].isString()) return Value::number(static_cast<double>(utf8Length(a[0].toStr())));
    return undefWarn(ev, l, "len", false);
}

Value fnStr(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // Formatted only up to one byte past the longest string: makeString then refuses it
    const size_t limit = ev.limits().maxStringLength + 1;
    std::string s;
    for (const auto &v : a) {
        if (v.isString())
            s.append(v.toStr(), 0, std::min(v.toStr().size(), limit - std::min(limit, s.size())));
        else if (v.isVector())
            v.appendEchoString(s, limit);
        else
            s += v.toString(false);
        if (s.size() >= limit) break;
    }
    return ev.makeString(std::move(s), l);
}

void appendChr(Evaluator &ev, const Value &v, std::string &out, const SourceLoc &l) {
    if (v.isNumber()) {
        double d = v.toNumber();
        if (d >= 1 && d <= 0x10FFFF && !(d >= 0xD800 && d <= 0xDFFF) && d == std::trunc(d)) {
            appendUtf8(out, static_cast<unsigned>(d));
        } else {
            ev.warn(l, "Invalid codepoint " + formatNumber(d) + " in chr()");
        }
    } else if (v.isVector()) {
        for (const auto &e : v.toVector()) appendChr(ev, e, out, l);
    } else if (v.isRange()) {
        const auto &r = v.toRange();
        uint64_t n = r.numValues();
        ev.checkElementBudget(static_cast<size_t>(n), l);
        for (uint64_t i = 0; i < n; ++i) appendChr(ev, Value::number(r.at(i)), out, l);
    }
}
Value fnChr(Evaluator &ev, const Args &a, const SourceLoc &l) {
    std::string s;
    for (const auto &v : a) appendChr(ev, v, s, l);
    return ev.makeString(std::move(s), l);
}

Value fnOrd(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 1) return undefWarn(ev, l, "ord", true);
    if (!a[0].isString()) {
        ev.warn(l, "ord() argument " + a[0].toEchoString() + " is not of type string");
        return Value();
    }
    // The first code point counts (a longer string is accepted as in 2021.01)
    auto chars = utf8Chars(a[0].toStr());
    if (chars.empty()) return Value();
    long cp = utf8Decode(chars[0]);
    if (cp < 0) {
        ev.warn(l, "ord() argument " + a[0].toEchoString() + " is not valid utf8 string");
        return Value();
    }
    return Value::number(static_cast<double>(cp));
}

Value fnConcat(Evaluator &ev, const Args &a, const SourceLoc &l) {
    size_t total = 0;
    for (const auto &v : a) total += v.isVector() ? v.toVector().size() : 1;
    ev.checkElementBudget(total, l);
    std::vector<Value> out;
    out.reserve(total);
    for (const auto &v : a) {
        if (v.isVector())
            out.insert(out.end(), v.toVector().begin(), v.toVector().end());
        else
            out.push_back(v);
    }
    return Value::vector(std::move(out));
}

bool getPair(const Value &v, double &k, double &x) {
    if (!v.isVector() || v.toVector().size() < 2) return false;
    const auto &p = v.toVector();
    if (!p[0].isNumber() || !p[1].isNumber()) return false;
    k = p[0].toNumber();
    x = p[1].toNumber();
    return true;
}

Value fnLookup(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // Linear interpolation between the nearest keys on each side, clamped at the table's
    // ends; the table need not be sorted (func.cc builtin_lookup).
    if (a.size() != 2) return undefWarn(ev, l, "lookup", true);
    double p, lowP, lowV;
    if (!a[0].getNumber(p) || !a[1].isVector() || a[1].toVector().empty() ||
        !getPair(a[1].toVector()[0], lowP, lowV))
        return undefWarn(ev, l, "lookup", false);
    double highP = lowP, highV = lowV;
    const auto &table = a[1].toVector();
    for (size_t i = 1; i < table.size(); ++i) {
        double k, x;
        if (!getPair(table[i], k, x)) continue;
        if (k <= p && (k > lowP || lowP > p)) {
            lowP = k;
            lowV = x;
        }
        if (k >= p && (k < highP || highP < p)) {
            highP = k;
            highV = x;
        }
    }
    if (p <= lowP) return Value::number(highV);
    if (p >= highP) return Value::number(lowV);
    double f = (p - lowP) / (highP - lowP);
    return Value::number(highV * f + lowV * (1 - f));
}

/// One match list per searched item (func.cc search helpers).
Value fnSearch(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() < 2 || a.size() > 4) return undefWarn(ev, l, "search", true);
    const Value &find = a[0], &table = a[1];
    auto toCount = [](const Value &v, double dflt) {
        double d = v.isNumber() ? v.toNumber() : dflt;
        return d >= 0 && d < 4e9 ? static_cast<size_t>(d) : static_cast<size_t>(dflt);
    };
    size_t perMatch = a.size() > 2 ? toCount(a[2], 1) : 1;
    size_t column = a.size() > 3 ? toCount(a[3], 0) : 0;
    auto matchesEntry = [&](const Value &needle, const Value &entry) {
        if (column == 0 && needle == entry) return true;
        return entry.isVector() && column < entry.toVector().size() &&
               needle == entry.toVector()[column];
    };
    // All indices of `table` (a vector) matching `needle`, at most perMatch unless 0
    auto matchAll = [&](const Value &needle) {
        std::vector<Value> hits;
        if (!table.isVector()) return hits;
        const auto &t = table.toVector();
        for (size_t j = 0; j < t.size(); ++j) {
            // Each comparison is a step: searching n needles in m entries takes n * m
            ev.step(l);
            if (!matchesEntry(needle, t[j])) continue;
            hits.push_back(Value::number(static_cast<double>(j)));
            if (perMatch != 0 && hits.size() >= perMatch) break;
        }
        return hits;
    };
    if (find.isNumber() || find.isBool()) return Value::vector(matchAll(find));
    if (find.isString()) {
        // Each character of the string is searched for separately
        std::vector<std::string> tableChars;
        if (table.isString()) {
            tableChars = utf8Chars(table.toStr());
        } else if (table.isVector()) {
            for (size_t j = 0; j < table.toVector().size(); ++j) {
                const Value &entry = table.toVector()[j];
                if (!entry.isVector() || entry.toVector().size() <= column) {
                    ev.warn(l, "Invalid entry in search vector at index " + std::to_string(j) +
                                   ", required number of values in the entry: " +
                                   std::to_string(column + 1) +
                                   ". Invalid entry: " + entry.toEchoString());
                    return Value::emptyVector();
                }
                auto first = utf8Chars(entry.toVector()[column].toString(false));
                tableChars.push_back(first.empty() ? std::string() : first[0]);
            }
        } else {
            return Value();
        }
        std::vector<Value> out;
        for (const auto &ch : utf8Chars(find.toStr())) {
            std::vector<Value> hits;
            for (size_t j = 0; j < tableChars.size(); ++j) {
                ev.step(l);
                if (tableChars[j] != ch) continue;
                hits.push_back(Value::number(static_cast<double>(j)));
                if (perMatch != 0 && hits.size() >= perMatch) break;
            }
            if (hits.empty()) ev.warn(l, "search term not found: \"" + ch + "\"");
            if (perMatch == 1) {
                if (!hits.empty()) out.push_back(hits[0]);
            } else {
                out.push_back(Value::vector(std::move(hits)));
            }
        }
        return Value::vector(std::move(out));
    }
    if (find.isVector()) {
        std::vector<Value> out;
        for (const auto &needle : find.toVector()) {
            std::vector<Value> hits = matchAll(needle);
            if (perMatch == 1)
                out.push_back(hits.empty() ? Value::emptyVector() : hits[0]);
            else
                out.push_back(Value::vector(std::move(hits)));
        }
        return Value::vector(std::move(out));
    }
    return Value();
}

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

Value fnVersion(Evaluator &, const Args &, const SourceLoc &) {
    return Value::vector({Value::number(2021), Value::number(1), Value::number(0)});
}
Value fnVersionNum(Evaluator &, const Args &, const SourceLoc &) { return Value::number(20210100); }

Value fnParentModule(Evaluator &ev, const Args &a, const SourceLoc &l) {
    // parent_module() is parent_module(1); index 0 is the current module
    double d = 1;
    if (!a.empty()) {
        if (!a[0].isNumber()) return undefWarn(ev, l, "parent_module", false);
        d = a[0].toNumber();
    }
    double n = std::trunc(d);
    const auto &stack = ev.moduleStack();
    if (n < 0) {
        ev.warn(l, "Negative parent module index (" + formatNumber(n) + ") not allowed");
        return Value();
    }
    if (!(n < static_cast<double>(stack.size()))) {
        ev.warn(l, "Parent module index (" + formatNumber(n) +
                       ") greater than the number of modules on the stack");
        return Value();
    }
    return Value::string(stack[stack.size() - 1 - static_cast<size_t>(n)].str());
}

template <bool (*Test)(const Value &)>
Value isType(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 1) return undefWarn(ev, l, "is_*", true);
    return Value::boolean(Test(a[0]));
}
bool testUndef(const Value &v) { return v.isUndef(); }
bool testList(const Value &v) { return v.isVector(); }
bool testNum(const Value &v) { return v.isNumber() && !std::isnan(v.toNumber()); }
bool testBool(const Value &v) { return v.isBool(); }
bool testString(const Value &v) { return v.isString(); }
bool testFunction(const Value &v) { return v.isFunction(); }

}  // namespace

BuiltinFunction findBuiltinFunction(Symbol name) {
    static const std::unordered_map<Symbol, BuiltinFunction, SymbolHash> kTable = {
        {Symbol::intern("abs"), fnAbs},
        {Symbol::intern("sign"), fnSign},
        {Symbol::intern("rands"), fnRands},
        {Symbol::intern("min"), fnMin},
        {Symbol::intern("max"), fnMax},
        {Symbol::intern("sin"), fnSin},
        {Symbol::intern("cos"), fnCos},
        {Symbol::intern("tan"), fnTan},
        {Symbol::intern("asin"), fnAsin},
        {Symbol::intern("acos"), fnAcos},
        {Symbol::intern("atan"), fnAtan},
        {Symbol::intern("atan2"), fnAtan2},
        {Symbol::intern("round"), fnRound},
        {Symbol::intern("ceil"), fnCeil},
        {Symbol::intern("floor"), fnFloor},
        {Symbol::intern("pow"), fnPow},
        {Symbol::intern("sqrt"), fnSqrt},
        {Symbol::intern("exp"), fnExp},
        {Symbol::intern("ln"), fnLn},
        {Symbol::intern("log"), fnLog},
        {Symbol::intern("len"), fnLen},
        {Symbol::intern("str"), fnStr},
        {Symbol::intern("chr"), fnChr},
        {Symbol::intern("ord"), fnOrd},
        {Symbol::intern("concat"), fnConcat},
        {Symbol::intern("lookup"), fnLookup},
        {Symbol::intern("search"), fnSearch},
        {Symbol::intern("norm"), fnNorm},
        {Symbol::intern("cross"), fnCross},
        {Symbol::intern("version"), fnVersion},
        {Symbol::intern("version_num"), fnVersionNum},
        {Symbol::intern("parent_module"), fnParentModule},
        {Symbol::intern("is_undef"), isType<testUndef>},
        {Symbol::intern("is_list"), isType<testList>},
        {Symbol::intern("is_num"), isType<testNum>},
        {Symbol::intern("is_bool"), isType<testBool>},
        {Symbol::intern("is_string"), isType<testString>},
        {Symbol::intern("is_function"), isType<testFunction>},
    };
    auto it = kTable.find(name);
    return it == kTable.end() ? nullptr : it->second;
}

}  // namespace rt::scad
