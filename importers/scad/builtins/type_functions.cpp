// SPDX-License-Identifier: MIT
// Builtin type tests (is_undef, is_list, ...), version(), version_num() and parent_module().
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

/// is_undef(name) tests a variable without the unknown-variable warning (func.cc); any other
/// argument is evaluated as for the other type tests.
Value isUndefRaw(Evaluator &ev, const ArgumentList &args, const FramePtr &f, const SourceLoc &loc) {
    if (args.size() == 1 && args[0].expr->kind == ExprKind::Identifier) {
        const auto &id = static_cast<const IdentifierExpr &>(*args[0].expr);
        return Value::boolean(ev.lookupVariable(id.name, f.get(), id.loc, true).isUndef());
    }
    return ev.callBuiltinFunction(isType<testUndef>, args, f, loc);
}

}  // namespace

BuiltinFamily typeFunctionBuiltins() {
    static constexpr BuiltinFunctionEntry kFunctions[] = {
        {"version", fnVersion},
        {"version_num", fnVersionNum},
        {"parent_module", fnParentModule},
        {"is_undef", nullptr, isUndefRaw},
        {"is_list", isType<testList>},
        {"is_num", isType<testNum>},
        {"is_bool", isType<testBool>},
        {"is_string", isType<testString>},
        {"is_function", isType<testFunction>},
    };
    return {{}, kFunctions};
}

}  // namespace rt::scad
