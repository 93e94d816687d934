// SPDX-License-Identifier: MIT
// Value construction, OpenSCAD number/echo formatting and the arithmetic of value.cc (2021.01).
#include "importers/scad/lang/value.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "importers/scad/lang/ast.h"

namespace rt::scad {

namespace {

thread_local int64_t tlLiveElements = 0;
thread_local int64_t tlLiveStringBytes = 0;
thread_local ValueLimits tlLimits;

}  // namespace

ValueLimits setValueLimits(const ValueLimits &limits) {
    ValueLimits old = tlLimits;
    tlLimits = limits;
    return old;
}

int64_t liveVectorElements() { return tlLiveElements; }
int64_t liveStringBytes() { return tlLiveStringBytes; }

StringData::StringData(std::string s) : text(std::move(s)) {
    tlLiveStringBytes += static_cast<int64_t>(text.size());
}

StringData::~StringData() { tlLiveStringBytes -= static_cast<int64_t>(text.size()); }

VectorData::VectorData(std::vector<Value> v) : items(std::move(v)) {
    if (tlLiveElements + static_cast<int64_t>(items.size()) > tlLimits.maxLiveElements)
        throw ValueLimitError(
            "too many elements: vectors would hold more than " +
            std::to_string(tlLimits.maxLiveElements) +
            " values; if the model needs more, raise the cap with --max-elements N");
    for (const auto &e : items) depth = std::max(depth, e.depth() + 1);
    if (depth > tlLimits.maxDepth)
        throw ValueLimitError("vectors nested too deep: more than " +
                              std::to_string(tlLimits.maxDepth) + " levels");
    tlLiveElements += static_cast<int64_t>(items.size());
}

VectorData::~VectorData() { tlLiveElements -= static_cast<int64_t>(items.size()); }

uint64_t RangeValue::numValues() const {
    constexpr uint64_t kMax = std::numeric_limits<uint32_t>::max();
    if (std::isnan(begin) || std::isnan(end) || std::isnan(step)) return 0;
    if (step < 0) {
        if (begin < end) return 0;
    } else if (begin > end) {
        return 0;
    }
    if (begin == end || std::isinf(step)) return 1;
    if (std::isinf(begin) || std::isinf(end) || step == 0) return kMax;
    // One ULP upwards compensates quotients that land just below a whole number.
    double steps = std::floor(std::nextafter((end - begin) / step, kMax + 1.0));
    if (!(steps < static_cast<double>(kMax))) return kMax;
    return static_cast<uint64_t>(steps) + 1;
}

Value Value::string(std::string s) {
    return Value(Storage(StringPtr(std::make_shared<const StringData>(std::move(s)))));
}

Value Value::vector(std::vector<Value> items) {
    return Value(Storage(VectorPtr(std::make_shared<const VectorData>(std::move(items)))));
}

Value Value::range(double begin, double step, double end) {
    return Value(
        Storage(RangePtr(std::make_shared<const RangeValue>(RangeValue{begin, step, end}))));
}

const Value &Value::emptyVector() {
    static const Value kEmpty = Value::vector(std::vector<Value>());
    return kEmpty;
}

bool Value::toBool() const {
    switch (type()) {
        case Type::Undef:
            return false;
        case Type::Bool:
            return boolValue();
        case Type::Number:
            return toNumber() != 0;
        case Type::String:
            return !toStr().empty();
        case Type::Vector:
            return !toVector().empty();
        case Type::Range:
            return true;
        case Type::Function:
            return true;
    }
    return false;
}

bool Value::getNumber(double &out) const {
    if (!isNumber()) return false;
    out = toNumber();
    return true;
}

bool Value::getFiniteNumber(double &out) const {
    if (!isNumber() || !std::isfinite(toNumber())) return false;
    out = toNumber();
    return true;
}

bool Value::getVec3(double &x, double &y, double &z, bool allow2, double defaultZ) const {
    if (!isVector()) return false;
    const auto &v = toVector();
    if (v.size() == 3 && v[0].isNumber() && v[1].isNumber() && v[2].isNumber()) {
        x = v[0].toNumber();
        y = v[1].toNumber();
        z = v[2].toNumber();
        return true;
    }
    if (allow2 && v.size() == 2 && v[0].isNumber() && v[1].isNumber()) {
        x = v[0].toNumber();
        y = v[1].toNumber();
        z = defaultZ;
        return true;
    }
    return false;
}

namespace {

/// Deep equality counting the vector elements it visits against ValueLimits::maxVisits: shared
/// sub-vectors are compared once per reference, which may be exponentially many.
bool equalValues(const Value &a, const Value &b, int64_t &visits) {
    if (a.type() != b.type()) return false;
    if (!a.isVector()) return a == b;
    if (a.vectorPtr() == b.vectorPtr()) return true;
    const auto &x = a.toVector(), &y = b.toVector();
    if (x.size() != y.size()) return false;
    visits += static_cast<int64_t>(x.size());
    if (visits > tlLimits.maxVisits)
        throw ValueLimitError(
            "comparison too large: more than " + std::to_string(tlLimits.maxVisits) +
            " elements compared (vectors sharing sub-vectors?); raise the cap with "
            "--max-elements N");
    for (size_t i = 0; i < x.size(); ++i)
        if (!equalValues(x[i], y[i], visits)) return false;
    return true;
}

}  // namespace

bool Value::operator==(const Value &o) const {
    if (type() != o.type()) return false;
    switch (type()) {
        case Type::Undef:
            return true;
        case Type::Bool:
            return boolValue() == o.boolValue();
        case Type::Number:
            return toNumber() == o.toNumber();
        case Type::String:
            return toStr() == o.toStr();
        case Type::Vector: {
            int64_t visits = 0;
            return equalValues(*this, o, visits);
        }
        case Type::Range: {
            const auto &a = toRange(), &b = o.toRange();
            return a.begin == b.begin && a.step == b.step && a.end == b.end;
        }
        case Type::Function:
            return std::get<FunctionPtr>(v_) == std::get<FunctionPtr>(o.v_);
    }
    return false;
}

const char *Value::typeName(Type t) {
    switch (t) {
        case Type::Undef:
            return "undefined";
        case Type::Bool:
            return "bool";
        case Type::Number:
            return "number";
        case Type::String:
            return "string";
        case Type::Vector:
            return "vector";
        case Type::Range:
            return "range";
        case Type::Function:
            return "function";
    }
    return "?";
}

std::string formatNumber(double d) {
    if (std::isnan(d)) return "nan";
    if (std::isinf(d)) return d < 0 ? "-inf" : "inf";
    if (d == 0) return "0";
    // The exact decimal expansion (glibc prints it exactly) rounded half away from zero to six
    // significant digits, as double-conversion's precision mode does in OpenSCAD.
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.40e", std::fabs(d));
    std::string digits;
    digits += buf[0];
    const char *p = buf + 2;
    while (*p >= '0' && *p <= '9') digits += *p++;
    int exp = std::atoi(p + 1);
    constexpr int kPrecision = 6;
    std::string sig = digits.substr(0, kPrecision);
    if (digits[kPrecision] >= '5') {
        int i = kPrecision - 1;
        while (i >= 0 && sig[i] == '9') sig[i--] = '0';
        if (i >= 0) {
            ++sig[i];
        } else {
            sig.insert(sig.begin(), '1');
            sig.pop_back();
            ++exp;
        }
    }
    while (sig.size() > 1 && sig.back() == '0') sig.pop_back();
    std::string out = d < 0 ? "-" : "";
    if (exp < -5 || exp >= kPrecision) {
        out += sig[0];
        if (sig.size() > 1) out += "." + sig.substr(1);
        out += exp < 0 ? "e-" : "e+";
        out += std::to_string(std::abs(exp));
    } else if (exp >= 0) {
        std::string intPart = sig.substr(0, std::min<size_t>(sig.size(), exp + 1));
        while (static_cast<int>(intPart.size()) < exp + 1) intPart += '0';
        out += intPart;
        if (static_cast<int>(sig.size()) > exp + 1) out += "." + sig.substr(exp + 1);
    } else {
        out += "0." + std::string(-exp - 1, '0') + sig;
    }
    return out;
}

std::string Value::toString(bool quoteStrings, size_t limit) const {
    switch (type()) {
        case Type::Undef:
            return "undef";
        case Type::Bool:
            return boolValue() ? "true" : "false";
        case Type::Number:
            return formatNumber(toNumber());
        case Type::String:
            return quoteStrings ? "\"" + toStr() + "\"" : toStr();
        case Type::Vector: {
            std::string s;
            appendEchoString(s, limit);
            if (s.size() > limit) {
                s.resize(limit);
                s += " ...";
            }
            return s;
        }
        case Type::Range: {
            const auto &r = toRange();
            return "[" + formatNumber(r.begin) + " : " + formatNumber(r.step) + " : " +
                   formatNumber(r.end) + "]";
        }
        case Type::Function:
            return functionLiteralToString(*toFunction().def);
    }
    return "";
}

void Value::appendEchoString(std::string &out, size_t limit) const {
    if (!isVector()) {
        if (!isString()) {
            out += toString(true);
        } else if (out.size() < limit) {
            // Only what fits (and one byte more, so the caller sees the cut)
            const std::string &t = toStr();
            out += '"';
            out.append(t, 0, std::min(t.size(), limit - out.size() + 1));
            if (out.size() <= limit) out += '"';
        }
        return;
    }
    out += '[';
    bool first = true;
    for (const auto &e : toVector()) {
        if (out.size() >= limit) return;
        if (!first) out += ", ";
        first = false;
        e.appendEchoString(out, limit);
    }
    out += ']';
}

const char *binaryOpSpelling(BinaryOp op) {
    switch (op) {
        case BinaryOp::Add:
            return "+";
        case BinaryOp::Sub:
            return "-";
        case BinaryOp::Mul:
            return "*";
        case BinaryOp::Div:
            return "/";
        case BinaryOp::Mod:
            return "%";
        case BinaryOp::Pow:
            return "^";
        case BinaryOp::Less:
            return "<";
        case BinaryOp::LessEqual:
            return "<=";
        case BinaryOp::Greater:
            return ">";
        case BinaryOp::GreaterEqual:
            return ">=";
    }
    return "?";
}

namespace {

std::string undefinedOperation(BinaryOp op, const Value &a, const Value &b) {
    return std::string("undefined operation (") + a.typeName() + " " + binaryOpSpelling(op) + " " +
           b.typeName() + ")";
}

/// Element-wise operation on the shorter length (OpenSCAD truncates).
Value elementwise(BinaryOp op, const std::vector<Value> &a, const std::vector<Value> &b) {
    std::vector<Value> out;
    size_t n = std::min(a.size(), b.size());
    out.reserve(n);
    std::string ignored;
    for (size_t i = 0; i < n; ++i) out.push_back(applyBinary(op, a[i], b[i], ignored));
    return Value::vector(std::move(out));
}

/// Each element of `v` combined with the scalar `s` (on the right unless `scalarLeft`).
Value withScalar(BinaryOp op, const std::vector<Value> &v, const Value &s, bool scalarLeft) {
    std::vector<Value> out;
    out.reserve(v.size());
    std::string ignored;
    for (const auto &e : v)
        out.push_back(scalarLeft ? applyBinary(op, s, e, ignored) : applyBinary(op, e, s, ignored));
    return Value::vector(std::move(out));
}

bool allNumbers(const std::vector<Value> &v) {
    for (const auto &e : v)
        if (!e.isNumber()) return false;
    return true;
}

/// Checks that every row of a matrix is a numeric vector of `cols` entries.
bool rectangular(const std::vector<Value> &m, size_t cols, std::string &warning) {
    for (size_t r = 0; r < m.size(); ++r) {
        if (!m[r].isVector() || m[r].toVector().size() != cols || !allNumbers(m[r].toVector())) {
            warning = "Matrix must be rectangular. Problem at row " + std::to_string(r);
            return false;
        }
    }
    return true;
}

Value multiply(const Value &a, const Value &b, std::string &warning) {
    if (a.isNumber() && b.isNumber()) return Value::number(a.toNumber() * b.toNumber());
    if (a.isVector() && b.isNumber()) return withScalar(BinaryOp::Mul, a.toVector(), b, false);
    if (a.isNumber() && b.isVector()) return withScalar(BinaryOp::Mul, b.toVector(), a, true);
    if (!a.isVector() || !b.isVector()) {
        warning = undefinedOperation(BinaryOp::Mul, a, b);
        return Value();
    }
    const auto &va = a.toVector(), &vb = b.toVector();
    if (va.empty() || vb.empty()) {
        warning = undefinedOperation(BinaryOp::Mul, a, b);
        return Value();
    }
    bool aMat = va[0].isVector(), bMat = vb[0].isVector();
    if (!aMat && !bMat) {
        // Dot product
        if (va.size() != vb.size()) {
            warning = "vector*vector requires matching lengths (" + std::to_string(va.size()) +
                      " != " + std::to_string(vb.size()) + ")";
            return Value();
        }
        if (!allNumbers(va) || !allNumbers(vb)) return Value();
        double s = 0;
        for (size_t i = 0; i < va.size(); ++i) s += va[i].toNumber() * vb[i].toNumber();
        return Value::number(s);
    }
    if (aMat && !bMat) {
        // Matrix * column vector
        size_t cols = va[0].toVector().size();
        if (!rectangular(va, cols, warning)) return Value();
        if (cols != vb.size()) {
            warning = "matrix*vector requires matching lengths (" + std::to_string(cols) +
                      " != " + std::to_string(vb.size()) + ")";
            return Value();
        }
        if (!allNumbers(vb)) return Value();
        std::vector<Value> out;
        for (const auto &row : va) {
            double s = 0;
            for (size_t j = 0; j < cols; ++j) s += row.toVector()[j].toNumber() * vb[j].toNumber();
            out.push_back(Value::number(s));
        }
        return Value::vector(std::move(out));
    }
    if (!aMat && bMat) {
        // Row vector * matrix
        size_t cols = vb[0].toVector().size();
        if (!rectangular(vb, cols, warning)) return Value();
        if (va.size() != vb.size()) {
            warning = "vector*matrix requires matching lengths (" + std::to_string(va.size()) +
                      " != " + std::to_string(vb.size()) + ")";
            return Value();
        }
        if (!allNumbers(va)) return Value();
        std::vector<Value> out;
        for (size_t j = 0; j < cols; ++j) {
            double s = 0;
            for (size_t i = 0; i < va.size(); ++i)
                s += va[i].toNumber() * vb[i].toVector()[j].toNumber();
            out.push_back(Value::number(s));
        }
        return Value::vector(std::move(out));
    }
    // Matrix * matrix
    size_t aCols = va[0].toVector().size();
    if (!rectangular(va, aCols, warning)) return Value();
    size_t bCols = vb[0].toVector().size();
    if (!rectangular(vb, bCols, warning)) return Value();
    if (aCols != vb.size()) {
        warning =
            "matrix*matrix requires left operand column count to match right operand row "
            "count (" +
            std::to_string(aCols) + " != " + std::to_string(vb.size()) + ")";
        return Value();
    }
    std::vector<Value> out;
    for (const auto &rowV : va) {
        const auto &row = rowV.toVector();
        std::vector<Value> r;
        for (size_t j = 0; j < bCols; ++j) {
            double s = 0;
            for (size_t k = 0; k < aCols; ++k)
                s += row[k].toNumber() * vb[k].toVector()[j].toNumber();
            r.push_back(Value::number(s));
        }
        out.push_back(Value::vector(std::move(r)));
    }
    return Value::vector(std::move(out));
}

/// Three-way comparison for <, <=, >, >=; returns undef for incomparable operands.
Value compare(BinaryOp op, const Value &a, const Value &b, std::string &warning) {
    auto result = [op](int c) {
        switch (op) {
            case BinaryOp::Less:
                return c < 0;
            case BinaryOp::LessEqual:
                return c <= 0;
            case BinaryOp::Greater:
                return c > 0;
            default:
                return c >= 0;
        }
    };
    if (a.isNumber() && b.isNumber()) {
        double x = a.toNumber(), y = b.toNumber();
        switch (op) {
            case BinaryOp::Less:
                return Value::boolean(x < y);
            case BinaryOp::LessEqual:
                return Value::boolean(x <= y);
            case BinaryOp::Greater:
                return Value::boolean(x > y);
            default:
                return Value::boolean(x >= y);
        }
    }
    if (a.isString() && b.isString()) return Value::boolean(result(a.toStr().compare(b.toStr())));
    if (a.isBool() && b.isBool())
        return Value::boolean(
            result(static_cast<int>(a.boolValue()) - static_cast<int>(b.boolValue())));
    if (a.isVector() && b.isVector()) {
        // Lexicographic: the first unequal element decides, else the shorter vector is smaller
        const auto &va = a.toVector(), &vb = b.toVector();
        size_t n = std::min(va.size(), vb.size());
        for (size_t i = 0; i < n; ++i) {
            if (va[i] == vb[i]) continue;
            Value lt = compare(BinaryOp::Less, va[i], vb[i], warning);
            if (lt.isUndef()) {
                warning += " in vector comparison at index " + std::to_string(i);
                return Value();
            }
            return Value::boolean(result(lt.boolValue() ? -1 : 1));
        }
        int c = va.size() < vb.size() ? -1 : (va.size() > vb.size() ? 1 : 0);
        return Value::boolean(result(c));
    }
    warning = undefinedOperation(op, a, b);
    return Value();
}

}  // namespace

Value applyBinary(BinaryOp op, const Value &a, const Value &b, std::string &warning) {
    switch (op) {
        case BinaryOp::Add:
        case BinaryOp::Sub:
            if (a.isNumber() && b.isNumber())
                return Value::number(op == BinaryOp::Add ? a.toNumber() + b.toNumber()
                                                         : a.toNumber() - b.toNumber());
            if (a.isVector() && b.isVector()) return elementwise(op, a.toVector(), b.toVector());
            break;
        case BinaryOp::Mul:
            return multiply(a, b, warning);
        case BinaryOp::Div:
            if (a.isNumber() && b.isNumber()) return Value::number(a.toNumber() / b.toNumber());
            if (a.isVector() && b.isNumber()) return withScalar(op, a.toVector(), b, false);
            if (a.isNumber() && b.isVector()) return withScalar(op, b.toVector(), a, true);
            break;
        case BinaryOp::Mod:
            if (a.isNumber() && b.isNumber())
                return Value::number(std::fmod(a.toNumber(), b.toNumber()));
            break;
        case BinaryOp::Pow:
            if (a.isNumber() && b.isNumber())
                return Value::number(std::pow(a.toNumber(), b.toNumber()));
            break;
        default:
            return compare(op, a, b, warning);
    }
    warning = undefinedOperation(op, a, b);
    return Value();
}

Value negate(const Value &a, std::string &warning) {
    if (a.isNumber()) return Value::number(-a.toNumber());
    if (a.isVector()) {
        std::vector<Value> out;
        out.reserve(a.toVector().size());
        std::string ignored;
        for (const auto &e : a.toVector()) out.push_back(negate(e, ignored));
        return Value::vector(std::move(out));
    }
    warning = std::string("undefined operation (-") + a.typeName() + ")";
    return Value();
}

}  // namespace rt::scad
