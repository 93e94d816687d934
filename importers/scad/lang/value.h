// SPDX-License-Identifier: MIT
// OpenSCAD runtime values (undef, bool, number, string, vector, range, function) with shared,
// immutable vector and string storage so copies are cheap.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace rt::scad {

struct Frame;
struct FunctionLiteralExpr;
class Value;

/// `[begin : step : end]` with an inclusive end (OpenSCAD RangeType).
struct RangeValue {
    double begin = 0, step = 1, end = 0;

    /// Number of elements, saturated at UINT32_MAX as OpenSCAD's RangeType::numValues does
    /// (infinite or zero steps count as "too many").
    uint64_t numValues() const;
    double at(uint64_t i) const { return begin + static_cast<double>(i) * step; }
};

/// Thrown by value operations that run into the calling thread's ValueLimits; the evaluator
/// turns it into a located EvalError.
struct ValueLimitError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// Bounds of value operations on the calling thread (see setValueLimits). Values shared by
/// reference make a small program able to describe a huge value (`v = [v, v]` sixty times
/// over): operations that expand or visit it stop at these bounds instead of running out of
/// memory or time.
struct ValueLimits {
    int64_t maxLiveElements = INT64_MAX;  ///< vector elements alive at once
    int64_t maxVisits = INT64_MAX;        ///< elements one comparison may visit
    int maxDepth = INT32_MAX;             ///< nesting of vectors
};
/// Sets the bounds for the calling thread; returns the previous ones.
ValueLimits setValueLimits(const ValueLimits &limits);

/// Storage of a vector value. The live element count of the evaluating thread is tracked so the
/// evaluator can stop a memory blow-up with a located error instead of exhausting memory;
/// constructing one past ValueLimits::maxLiveElements or maxDepth throws ValueLimitError.
struct VectorData {
    std::vector<Value> items;
    int depth = 1;  ///< 1 + the deepest nesting of the vectors among items

    explicit VectorData(std::vector<Value> v);
    ~VectorData();
    VectorData(const VectorData &) = delete;
    VectorData &operator=(const VectorData &) = delete;
};

/// Storage of a string value; live bytes are tracked like VectorData's elements.
struct StringData {
    std::string text;

    explicit StringData(std::string s);
    ~StringData();
    StringData(const StringData &) = delete;
    StringData &operator=(const StringData &) = delete;
};

/// A function literal bound to the scope it was created in.
struct FunctionValue {
    const FunctionLiteralExpr *def = nullptr;
    std::shared_ptr<Frame> closure;
};

/// Vector elements alive on the calling thread (see VectorData).
int64_t liveVectorElements();
/// String bytes alive on the calling thread (see StringData).
int64_t liveStringBytes();

class Value {
  public:
    enum class Type : uint8_t { Undef, Bool, Number, String, Vector, Range, Function };
    using StringPtr = std::shared_ptr<const StringData>;
    using VectorPtr = std::shared_ptr<const VectorData>;
    using RangePtr = std::shared_ptr<const RangeValue>;
    using FunctionPtr = std::shared_ptr<const FunctionValue>;

    Value() = default;
    static Value undef() { return Value(); }
    static Value boolean(bool b) { return Value(Storage(b)); }
    static Value number(double d) { return Value(Storage(d)); }
    static Value string(std::string s);
    static Value vector(std::vector<Value> items);
    static Value vector(VectorPtr v) { return Value(Storage(std::move(v))); }
    static Value range(double begin, double step, double end);
    static Value function(FunctionPtr f) { return Value(Storage(std::move(f))); }
    static const Value &emptyVector();

    Type type() const { return static_cast<Type>(v_.index()); }
    bool isUndef() const { return type() == Type::Undef; }
    bool isBool() const { return type() == Type::Bool; }
    bool isNumber() const { return type() == Type::Number; }
    bool isString() const { return type() == Type::String; }
    bool isVector() const { return type() == Type::Vector; }
    bool isRange() const { return type() == Type::Range; }
    bool isFunction() const { return type() == Type::Function; }

    bool toBool() const;  ///< OpenSCAD truthiness
    bool boolValue() const { return std::get<bool>(v_); }
    double toNumber() const { return std::get<double>(v_); }
    const std::string &toStr() const { return std::get<StringPtr>(v_)->text; }
    const std::vector<Value> &toVector() const { return std::get<VectorPtr>(v_)->items; }
    const VectorPtr &vectorPtr() const { return std::get<VectorPtr>(v_); }
    const RangeValue &toRange() const { return *std::get<RangePtr>(v_); }
    const FunctionValue &toFunction() const { return *std::get<FunctionPtr>(v_); }

    /// Number if this is a number (finite or not).
    bool getNumber(double &out) const;
    /// Finite number.
    bool getFiniteNumber(double &out) const;
    /// Numeric vector of exactly 3 (or 2, z = `defaultZ`, when allow2) elements.
    bool getVec3(double &x, double &y, double &z, bool allow2 = false, double defaultZ = 0) const;

    /// Deep equality (`==`): different types are unequal; numbers compare as doubles.
    bool operator==(const Value &o) const;
    bool operator!=(const Value &o) const { return !(*this == o); }

    /// OpenSCAD's echo/str formatting: strings quoted when `quoteStrings`. Text past `limit`
    /// bytes is cut, ending in " ..." (so a huge shared vector is never formatted whole).
    std::string toString(bool quoteStrings, size_t limit = kMaxTextBytes) const;
    std::string toEchoString(size_t limit = kMaxTextBytes) const { return toString(true, limit); }
    /// Default cut of toString: values quoted in messages.
    static constexpr size_t kMaxTextBytes = 64 << 10;
    /// Nesting of vectors: 0 for other values.
    int depth() const { return isVector() ? vectorPtr()->depth : 0; }
    /// Appends the echo form to `out`, stopping soon after `out` reaches `limit` bytes (the
    /// text is then cut short, mid-element), so a huge value is never formatted whole.
    void appendEchoString(std::string &out, size_t limit) const;
    /// Name of the type in OpenSCAD's warnings ("number", "vector", "undefined", ...).
    static const char *typeName(Type t);
    const char *typeName() const { return typeName(type()); }

  private:
    using Storage =
        std::variant<std::monostate, bool, double, StringPtr, VectorPtr, RangePtr, FunctionPtr>;
    explicit Value(Storage s) : v_(std::move(s)) {}
    Storage v_;
};

/// Formats a number as OpenSCAD 2021.01 prints it: 6 significant digits, ties away from zero,
/// plain notation for decimal exponents -5..5, otherwise `1.23457e+8` / `1e-7`.
std::string formatNumber(double d);

/// Binary operators of the language; the result is undef (and `warning` is set) when the
/// operation is undefined for the operand types.
enum class BinaryOp { Add, Sub, Mul, Div, Mod, Pow, Less, LessEqual, Greater, GreaterEqual };
Value applyBinary(BinaryOp op, const Value &a, const Value &b, std::string &warning);
Value negate(const Value &a, std::string &warning);
const char *binaryOpSpelling(BinaryOp op);

}  // namespace rt::scad
