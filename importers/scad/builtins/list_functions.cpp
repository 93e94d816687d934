// SPDX-License-Identifier: MIT
// Builtin list functions: len, concat, lookup, search (func.cc).
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

bool getPair(const Value &v, double &k, double &x) {
    if (!v.isVector() || v.toVector().size() < 2) return false;
    const auto &p = v.toVector();
    if (!p[0].isNumber() || !p[1].isNumber()) return false;
    k = p[0].toNumber();
    x = p[1].toNumber();
    return true;
}

Value fnLen(Evaluator &ev, const Args &a, const SourceLoc &l) {
    if (a.size() != 1) return undefWarn(ev, l, "len", true);
    if (a[0].isVector()) return Value::number(static_cast<double>(a[0].toVector().size()));
    if (a[0].isString()) return Value::number(static_cast<double>(utf8Length(a[0].toStr())));
    return undefWarn(ev, l, "len", false);
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

}  // namespace

BuiltinFamily listFunctionBuiltins() {
    static constexpr BuiltinFunctionEntry kFunctions[] = {
        {"len", fnLen},
        {"concat", fnConcat},
        {"lookup", fnLookup},
        {"search", fnSearch},
    };
    return {{}, kFunctions};
}

}  // namespace rt::scad
