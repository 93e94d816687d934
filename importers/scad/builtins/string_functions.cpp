// SPDX-License-Identifier: MIT
// Builtin string functions: str, chr, ord (func.cc).
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

}  // namespace

BuiltinFamily stringFunctionBuiltins() {
    static constexpr BuiltinFunctionEntry kFunctions[] = {
        {"str", fnStr},
        {"chr", fnChr},
        {"ord", fnOrd},
    };
    return {{}, kFunctions};
}

}  // namespace rt::scad
