// SPDX-License-Identifier: MIT
// Expression evaluation, function calls (with iterative tail calls), scopes, module
// instantiation and the control modules, following OpenSCAD 2021.01's contexts.
#include "importers/scad/lang/evaluator.h"

#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "core/ir/ir_validate.h"
#include "core/system/utf8.h"

namespace rt::scad {

namespace {

/// Smallest $fa/$fs OpenSCAD accepts (primitives.cc F_MINIMUM).
constexpr double kFragmentMinimum = 0.01;

/// Module-level `for` skips ranges this long (control.cc for_eval).
constexpr uint64_t kMaxModuleForRange = 10000;
/// List-comprehension `for`/`each` and C-style loops stop here (expr.cc LcFor/LcForC).
constexpr uint64_t kMaxComprehensionRange = 1000000;

constexpr double kPiValue = 3.14159265358979323846;

/// Most bytes one echo() prints: a runaway vector must not write tens of MB of diagnostics.
/// Longer output is cut here with a warning.
constexpr size_t kMaxEchoBytes = 64 << 10;

Symbol sym(const char *s) { return Symbol::intern(s); }

bool isScadrayLibrary(const SourceLoc &loc) {
    return loc.file && std::filesystem::path(*loc.file).filename() == "scadray.scad";
}

/// Calls f with each value OpenSCAD's for() and each take from `seq`: the numbers of a range
/// (none, with a warning at `loc`, when it holds `limit` or more), the items of a vector, the
/// characters of a string, nothing for undef, and any other value itself.
template <typename F>
void forEachElement(Evaluator &ev, const Value &seq, uint64_t limit, const SourceLoc &loc, F &&f) {
    if (seq.isRange()) {
        RangeValue r = seq.toRange();
        uint64_t n = r.numValues();
        if (n >= limit) {
            ev.warn(loc, "Bad range parameter in for statement: too many elements (" +
                             std::to_string(n) + ")");
            return;
        }
        for (uint64_t i = 0; i < n; ++i) f(Value::number(r.at(i)));
    } else if (seq.isVector()) {
        for (const auto &x : seq.toVector()) f(x);
    } else if (seq.isString()) {
        for (auto &ch : utf8Chars(seq.toStr())) f(Value::string(std::move(ch)));
    } else if (!seq.isUndef()) {
        f(seq);
    }
}

/// The call of the innermost user module body lexically around `f`: it owns the children.
const ModuleCallInfo *enclosingCall(const FramePtr &f) {
    for (const Frame *p = f.get(); p; p = p->parent.get())
        if (p->call) return p->call;
    return nullptr;
}

}  // namespace

Evaluator::Evaluator(DiagnosticSink &diag, EvalLimits limits)
    : diag_(diag),
      limits_(limits),
      builtins_(builtinTable()),
      stepCap_(limits.maxSteps > 0 ? limits.maxSteps : std::numeric_limits<int64_t>::max()) {}

Evaluator::~Evaluator() {
    // Every cycle runs through a closure's frame up its parent chain: clearing the variables
    // of those frames frees them.
    for (const auto &weak : capturedFrames_)
        if (FramePtr f = weak.lock())
            for (Frame *p = f.get(); p; p = p->parent.get()) p->clear();
}

// ---------------------------------------------------------------------------------------------
// Budgets

void Evaluator::checkStack(const SourceLoc &loc) {
    char here;
    if (stackLow_ && &here < stackLow_)
        throw EvalError(loc, "recursion too deep: the evaluation stack is exhausted");
}

void Evaluator::stepSlow(const SourceLoc &loc) {
    if (steps_ > stepCap_)
        throw EvalError(loc, "evaluation too long: more than " + std::to_string(limits_.maxSteps) +
                                 " steps (calls, loop iterations and module instances); "
                                 "runaway loop or recursion? If the model needs more, raise the "
                                 "cap with --max-steps N (0 = no cap)");
    if ((steps_ & kProgressStepMask) == 0 && progress_) progress_(steps_);
}

void Evaluator::checkElementBudget(size_t extra, const SourceLoc &loc) {
    if (liveVectorElements() + static_cast<int64_t>(extra) > limits_.maxLiveElements)
        throw EvalError(
            loc, "too many elements: vectors would hold more than " +
                     std::to_string(limits_.maxLiveElements) +
                     " values; if the model needs more, raise the cap with --max-elements N");
}

Value Evaluator::makeString(std::string s, const SourceLoc &loc) {
    if (s.size() > limits_.maxStringLength)
        throw EvalError(loc, "string too long: more than " +
                                 std::to_string(limits_.maxStringLength) + " bytes");
    if (liveStringBytes() + static_cast<int64_t>(s.size()) > limits_.maxLiveStringBytes)
        throw EvalError(loc, "too much string data: strings would hold more than " +
                                 std::to_string(limits_.maxLiveStringBytes) + " bytes");
    return Value::string(std::move(s));
}

void Evaluator::countNodes(int64_t n, const SourceLoc &loc) {
    nodes_ += n;
    if (nodes_ > limits_.maxNodes)
        throw EvalError(loc,
                        "too many geometry nodes: more than " + std::to_string(limits_.maxNodes));
}

ir::NodePtr Evaluator::newNode(ir::NodeKind kind, const SourceLoc &loc) {
    countNodes(1, loc);
    return ir::Node::makeGroup(kind, loc);
}

void Evaluator::checkNodeDepth(const ir::Node &root) const {
    if (const ir::Node *deep = ir::firstNodeDeeperThan(root, limits_.maxNodeDepth))
        throw EvalError(deep->loc, "geometry nested too deep: more than " +
                                       std::to_string(limits_.maxNodeDepth) +
                                       " levels of module instances, transforms and operations");
}

void Evaluator::chargeGeometryWork(const SourceLoc &loc, const std::string &what, double units,
                                   const char *noun) {
    // Estimates may exceed any integer (faces squared of a huge tessellation): compared as
    // doubles, and the total kept saturated
    double total = static_cast<double>(geometryWork_) + std::max(units, 0.0);
    if (limits_.maxGeometryWork > 0 && !(total <= static_cast<double>(limits_.maxGeometryWork))) {
        char amount[32];
        std::snprintf(amount, sizeof amount, "%.2g", units);
        std::string left =
            geometryWork_ > 0
                ? " the " + std::to_string(limits_.maxGeometryWork - geometryWork_) + " left of"
                : "";
        throw EvalError(loc, what + ": about " + amount + " " + noun + ", more than" + left +
                                 " the geometry budget of " +
                                 std::to_string(limits_.maxGeometryWork) +
                                 " (--max-geometry N raises it; 0 = no cap)");
    }
    geometryWork_ =
        total < 9e18 ? static_cast<int64_t>(total) : std::numeric_limits<int64_t>::max();
}

ir::Fragments Evaluator::currentFragments(const SourceLoc &loc) {
    static const Symbol kFn = Symbol::intern("$fn"), kFs = Symbol::intern("$fs"),
                        kFa = Symbol::intern("$fa");
    auto special = [&](Symbol name, double dflt) {
        const Value *v = dyn_.lookup(name);
        return v && v->isNumber() ? v->toNumber() : dflt;
    };
    ir::Fragments fr;
    fr.fn = special(kFn, 0);
    fr.fs = special(kFs, 2);
    fr.fa = special(kFa, 12);
    if (!std::isfinite(fr.fn)) fr.fn = 0;
    if (!(fr.fs >= kFragmentMinimum)) {
        warn(loc, "$fs too small - clamping to 0.010000");
        fr.fs = kFragmentMinimum;
    }
    if (!(fr.fa >= kFragmentMinimum)) {
        warn(loc, "$fa too small - clamping to 0.010000");
        fr.fa = kFragmentMinimum;
    }
    return fr;
}

ir::NodePtr Evaluator::groupOf(ir::NodeKind kind, const SourceLoc &loc,
                               std::vector<ir::NodePtr> children) {
    ir::NodePtr n = newNode(kind, loc);
    n->children = std::move(children);
    return n;
}

// ---------------------------------------------------------------------------------------------
// Top level

ir::Scene Evaluator::evaluate(const SourceFile &main, SourceLoader &loader) {
    // The lowest stack address evaluation may reach before failing with a located error. What
    // is left below serves the recursions that do not check (freeing, printing and comparing
    // values up to limits_.maxValueDepth deep): at least stackReserveBytes, a quarter of a
    // large stack.
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) == 0) {
        void *addr = nullptr;
        size_t size = 0;
        if (pthread_attr_getstack(&attr, &addr, &size) == 0 && size > 2 * limits_.stackReserveBytes)
            stackLow_ =
                static_cast<const char *>(addr) + std::max(limits_.stackReserveBytes, size / 4);
        pthread_attr_destroy(&attr);
    }
    // Value operations (vector arithmetic, comparisons) stop at the same element budget
    struct RestoreValueLimits {
        ValueLimits saved;
        ~RestoreValueLimits() { setValueLimits(saved); }
    } restoreValueLimits{setValueLimits(
        ValueLimits{limits_.maxLiveElements, limits_.maxLiveElements, limits_.maxValueDepth})};

    // Builtin constants and special variables (builtin.cc); $preview is false when rendering
    builtinFrame_ = makeFrame(nullptr);
    builtinFrame_->set(sym("PI"), Value::number(kPiValue));
    builtinFrame_->set(sym("$fn"), Value::number(0));
    builtinFrame_->set(sym("$fa"), Value::number(12));
    builtinFrame_->set(sym("$fs"), Value::number(2));
    builtinFrame_->set(sym("$t"), Value::number(time_));
    builtinFrame_->set(sym("$preview"), Value::boolean(false));
    builtinFrame_->set(sym("$vpt"),
                       Value::vector({Value::number(0), Value::number(0), Value::number(0)}));
    builtinFrame_->set(sym("$vpr"),
                       Value::vector({Value::number(0), Value::number(0), Value::number(0)}));
    builtinFrame_->set(sym("$vpd"), Value::number(500));
    builtinFrame_->set(sym("$vpf"), Value::number(22.5));
    FrameGuard builtinGuard(dyn_, builtinFrame_.get());

    // Files and their `use` lists; a later `use` wins, so the newest is searched first
    for (const auto &[path, file] : loader.usedFiles()) libraries_[file.get()].src = file.get();
    auto linkUses = [&](LoadedFile &lf) {
        for (auto it = lf.src->uses.rbegin(); it != lf.src->uses.rend(); ++it) {
            auto found = loader.usedFiles().find(it->path);
            if (found != loader.usedFiles().end())
                lf.uses.push_back(&libraries_[found->second.get()]);
        }
    };
    for (auto &[src, lf] : libraries_) linkUses(lf);
    mainFile_.src = &main;
    linkUses(mainFile_);

    // Fonts registered by use<x.ttf> (at parse time) serve text() while evaluating
    scene_.fontFiles = loader.fontFiles();

    FramePtr top = makeFrame(builtinFrame_);
    top->defs = &main.top;
    top->file = &mainFile_;
    mainFile_.frame = top;
    FrameGuard topGuard(dyn_, top.get());

    applyAssignments(main.top.assignments, top);
    std::vector<ir::NodePtr> nodes;
    instantiateScope(main.top, top, nodes);

    auto mainName = std::make_shared<const std::string>(main.path);
    scene_.root = newNode(ir::NodeKind::Group, SourceLoc(mainName, 1, 1));
    if (rootNode_)
        scene_.root->children.push_back(std::move(rootNode_));
    else
        scene_.root->children = std::move(nodes);
    for (BuiltinScenePass pass : builtins_.treePasses) pass(*this, main);
    checkNodeDepth(*scene_.root);
    for (BuiltinScenePass pass : builtins_.scenePasses) pass(*this, main);
    return std::move(scene_);
}

FramePtr Evaluator::libraryFrame(LoadedFile &lib) {
    if (lib.frame) return lib.frame;
    // A used library's top-level variables, evaluated once on first use; its geometry is not
    // instantiated (FileContext::initializeModule).
    lib.frame = makeFrame(builtinFrame_);
    lib.frame->defs = &lib.src->top;
    lib.frame->file = &lib;
    FrameGuard g(dyn_, lib.frame.get());
    applyAssignments(lib.src->top.assignments, lib.frame);
    return lib.frame;
}

// ---------------------------------------------------------------------------------------------
// Expressions

Value Evaluator::lookupVariable(Symbol name, const Frame *f, const SourceLoc &loc, bool silent) {
    if (name.isDollar()) {
        if (const Value *v = dyn_.lookup(name)) return *v;
    } else {
        for (const Frame *p = f; p; p = p->parent.get())
            if (const Value *v = p->findLocal(name)) return *v;
    }
    if (!silent) warn(loc, "Ignoring unknown variable '" + name.str() + "'");
    return Value();
}

Value Evaluator::eval(const Expr &e, const FramePtr &f) {
    checkStack(e.loc);
    try {
        return evalUnchecked(e, f);
    } catch (const ValueLimitError &err) {
        // The innermost expression names the place; outer ones see an EvalError
        throw EvalError(e.loc, err.what());
    }
}

Value Evaluator::evalUnchecked(const Expr &e, const FramePtr &f) {
    switch (e.kind) {
        case ExprKind::Literal:
            return static_cast<const LiteralExpr &>(e).value;
        case ExprKind::Identifier:
            return lookupVariable(static_cast<const IdentifierExpr &>(e).name, f.get(), e.loc);
        case ExprKind::Range:
            return evalRange(static_cast<const RangeExpr &>(e), f);
        case ExprKind::Vector: {
            const auto &v = static_cast<const VectorExpr &>(e);
            if (v.constant) return *v.constant;
            return evalVector(v, f);
        }
        case ExprKind::Unary: {
            const auto &u = static_cast<const UnaryExpr &>(e);
            Value v = eval(*u.operand, f);
            if (u.op == UnaryOp::Not) return Value::boolean(!v.toBool());
            std::string w;
            Value r = negate(v, w);
            if (!w.empty()) warn(e.loc, w);
            return r;
        }
        case ExprKind::Binary: {
            const auto &b = static_cast<const BinaryExpr &>(e);
            Value l = eval(*b.lhs, f);
            Value r = eval(*b.rhs, f);
            std::string w;
            Value out = applyBinary(b.op, l, r, w);
            if (!w.empty()) warn(e.loc, w);
            return out;
        }
        case ExprKind::And: {
            const auto &b = static_cast<const BinaryExpr &>(e);
            return Value::boolean(eval(*b.lhs, f).toBool() && eval(*b.rhs, f).toBool());
        }
        case ExprKind::Or: {
            const auto &b = static_cast<const BinaryExpr &>(e);
            return Value::boolean(eval(*b.lhs, f).toBool() || eval(*b.rhs, f).toBool());
        }
        case ExprKind::Equal:
        case ExprKind::NotEqual: {
            const auto &b = static_cast<const BinaryExpr &>(e);
            bool eq = eval(*b.lhs, f) == eval(*b.rhs, f);
            return Value::boolean(e.kind == ExprKind::Equal ? eq : !eq);
        }
        case ExprKind::Ternary: {
            const auto &t = static_cast<const TernaryExpr &>(e);
            return eval(*t.cond, f).toBool() ? eval(*t.thenExpr, f) : eval(*t.elseExpr, f);
        }
        case ExprKind::Call:
            return evalCall(static_cast<const CallExpr &>(e), f);
        case ExprKind::Index:
            return evalIndex(static_cast<const IndexExpr &>(e), f);
        case ExprKind::Member:
            return evalMember(static_cast<const MemberExpr &>(e), f);
        case ExprKind::Let:
        case ExprKind::Assert:
        case ExprKind::Echo:
            return evalPrefix(static_cast<const PrefixExpr &>(e), f);
        case ExprKind::FunctionLiteral: {
            auto fv = std::make_shared<FunctionValue>();
            fv->def = &static_cast<const FunctionLiteralExpr &>(e);
            fv->closure = f;
            if (capturedFrames_.empty() || capturedFrames_.back().lock() != f)
                capturedFrames_.push_back(f);
            return Value::function(std::move(fv));
        }
        default: {
            // A comprehension element outside a vector: evaluate it as a one-level list
            std::vector<Value> out;
            evalElement(e, f, out);
            return Value::vector(std::move(out));
        }
    }
}

Value Evaluator::evalRange(const RangeExpr &r, const FramePtr &f) {
    Value b = eval(*r.begin, f);
    Value s = r.step ? eval(*r.step, f) : Value::number(1);
    Value e = eval(*r.end, f);
    if (!b.isNumber() || !s.isNumber() || !e.isNumber()) return Value();
    double begin = b.toNumber(), step = s.toNumber(), end = e.toNumber();
    if (!r.step && end < begin) {
        warn(r.loc,
             "DEPRECATED: Using ranges of the form [begin:end] with begin value greater "
             "than the end value is deprecated");
        std::swap(begin, end);
    } else if (r.step) {
        if (step < 0 && begin < end)
            warn(r.loc, "begin is smaller than the end, but step is negative");
        if (step > 0 && begin > end)
            warn(r.loc, "begin is greater than the end, but step is positive");
    }
    return Value::range(begin, step, end);
}

Value Evaluator::evalVector(const VectorExpr &v, const FramePtr &f) {
    std::vector<Value> out;
    out.reserve(v.elements.size());
    for (const auto &e : v.elements) evalElement(*e, f, out);
    checkElementBudget(out.size(), v.loc);
    return Value::vector(std::move(out));
}

void Evaluator::evalElement(const Expr &e, const FramePtr &f, std::vector<Value> &out) {
    checkStack(e.loc);
    auto push = [&](Value v) {
        if ((out.size() & 1023) == 1023) checkElementBudget(out.size(), e.loc);
        out.push_back(std::move(v));
    };
    switch (e.kind) {
        case ExprKind::LcFor: {
            const auto &lc = static_cast<const LcForExpr &>(e);
            // One frame per loop variable, reused across iterations as OpenSCAD's LcFor does
            // (closures made in the body see the variable's last value).
            auto loop = [&](auto &self, size_t var, const FramePtr &frame) -> void {
                if (var == lc.vars.size()) {
                    evalElement(*lc.body, frame, out);
                    return;
                }
                const Argument &a = lc.vars[var];
                Value seq = eval(*a.expr, frame);
                FramePtr c = makeFrame(frame);
                FrameGuard g(dyn_, c.get());
                auto iterate = [&](Value x) {
                    step(e.loc);
                    c->set(a.name, std::move(x));
                    self(self, var + 1, c);
                };
                forEachElement(*this, seq, kMaxComprehensionRange, a.loc, iterate);
            };
            if (!lc.vars.empty()) loop(loop, 0, f);
            return;
        }
        case ExprKind::LcForC: {
            const auto &lc = static_cast<const LcForCExpr &>(e);
            FramePtr c = makeFrame(f);
            FrameGuard g(dyn_, c.get());
            bindLet(lc.init, c);
            uint64_t count = 0;
            while (eval(*lc.cond, c).toBool()) {
                evalElement(*lc.body, c, out);
                if (++count > kMaxComprehensionRange)
                    throw EvalError(e.loc, "For loop counter exceeded limit");
                step(e.loc);
                // The update binds sequentially in a scratch frame, then replaces the variables
                FramePtr tmp = makeFrame(c);
                {
                    FrameGuard tg(dyn_, tmp.get());
                    bindLet(lc.update, tmp);
                }
                for (const auto &[n, v] : tmp->vars()) c->set(n, v);
            }
            return;
        }
        case ExprKind::LcIf: {
            const auto &lc = static_cast<const LcIfExpr &>(e);
            if (eval(*lc.cond, f).toBool())
                evalElement(*lc.thenExpr, f, out);
            else if (lc.elseExpr)
                evalElement(*lc.elseExpr, f, out);
            return;
        }
        case ExprKind::LcLet: {
            const auto &lc = static_cast<const LcLetExpr &>(e);
            FramePtr c = makeFrame(f);
            FrameGuard g(dyn_, c.get());
            bindLet(lc.args, c);
            evalElement(*lc.body, c, out);
            return;
        }
        case ExprKind::LcEach: {
            const auto &lc = static_cast<const LcEachExpr &>(e);
            std::vector<Value> items;
            if (lc.body->isListComprehension())
                evalElement(*lc.body, f, items);
            else
                items.push_back(eval(*lc.body, f));
            for (const auto &v : items)
                forEachElement(*this, v, kMaxComprehensionRange, e.loc, push);
            return;
        }
        default:
            push(eval(e, f));
            return;
    }
}

Value Evaluator::evalIndex(const IndexExpr &e, const FramePtr &f) {
    Value obj = eval(*e.object, f);
    Value idx = eval(*e.index, f);
    if (!idx.isNumber()) return Value();
    double d = idx.toNumber();
    if (!(d >= 0)) return Value();
    double t = std::trunc(d);
    if (obj.isVector()) {
        const auto &v = obj.toVector();
        return t < static_cast<double>(v.size()) ? v[static_cast<size_t>(t)] : Value();
    }
    if (obj.isString()) {
        auto chars = utf8Chars(obj.toStr());
        return t < static_cast<double>(chars.size()) ? Value::string(chars[static_cast<size_t>(t)])
                                                     : Value();
    }
    if (obj.isRange()) {
        const auto &r = obj.toRange();
        if (t == 0) return Value::number(r.begin);
        if (t == 1) return Value::number(r.step);
        if (t == 2) return Value::number(r.end);
    }
    return Value();
}

Value Evaluator::evalMember(const MemberExpr &e, const FramePtr &f) {
    Value obj = eval(*e.object, f);
    const std::string &m = e.member.str();
    if (obj.isVector()) {
        const auto &v = obj.toVector();
        size_t i = m == "x" ? 0 : m == "y" ? 1 : m == "z" ? 2 : 3;
        return i < v.size() && m.size() == 1 ? v[i] : Value();
    }
    if (obj.isRange()) {
        const auto &r = obj.toRange();
        if (m == "begin") return Value::number(r.begin);
        if (m == "step") return Value::number(r.step);
        if (m == "end") return Value::number(r.end);
    }
    return Value();
}

void Evaluator::bindLet(const ArgumentList &args, const FramePtr &c) {
    // Sequential: each binding sees the ones before it
    for (const auto &a : args) c->set(a.name, eval(*a.expr, c));
}

Value Evaluator::evalPrefix(const PrefixExpr &p, const FramePtr &f) {
    switch (p.kind) {
        case ExprKind::Let: {
            FramePtr c = makeFrame(f);
            FrameGuard g(dyn_, c.get());
            bindLet(p.args, c);
            return eval(*p.body, c);
        }
        case ExprKind::Assert:
            evalAssert(p.args, f, p.loc);
            break;
        default:
            evalEcho(p.args, f, p.loc);
            break;
    }
    return p.body ? eval(*p.body, f) : Value();
}

void Evaluator::evalEcho(const ArgumentList &args, const FramePtr &f, const SourceLoc &loc) {
    // Every argument is evaluated; only the text is capped
    const size_t limit = kMaxEchoBytes + std::string_view("ECHO: ").size();
    std::string msg = "ECHO: ";
    for (size_t i = 0; i < args.size(); ++i) {
        Value v = eval(*args[i].expr, f);
        if (msg.size() > limit) continue;
        if (i) msg += ", ";
        if (!args[i].name.empty()) msg += args[i].name.str() + " = ";
        v.appendEchoString(msg, limit + 1);
    }
    if (msg.size() <= limit) {
        diag_.note(loc, msg);
        return;
    }
    // Cut at a character boundary, not inside a UTF-8 sequence
    size_t cut = limit;
    while (cut > 0 && (static_cast<unsigned char>(msg[cut]) & 0xC0) == 0x80) --cut;
    msg.resize(cut);
    diag_.note(loc, msg + " ...");
    warn(loc, "echo output cut after " + std::to_string(kMaxEchoBytes >> 10) + " KiB");
}

void Evaluator::evalAssert(const ArgumentList &args, const FramePtr &f, const SourceLoc &loc) {
    // assert(condition, message), positional or named
    const Argument *cond = nullptr, *message = nullptr;
    size_t pos = 0;
    for (const auto &a : args) {
        const std::string &n = a.name.str();
        if (n == "condition" || (n.empty() && pos == 0 && !cond))
            cond = &a;
        else if (n == "message" || (n.empty() && pos == 1 && !message))
            message = &a;
        if (n.empty()) ++pos;
    }
    Value c = cond ? eval(*cond->expr, f) : Value();
    if (c.toBool()) return;
    std::string msg =
        "Assertion '" + (cond ? exprToString(*cond->expr) : std::string("undef")) + "' failed";
    if (message) msg += ": " + eval(*message->expr, f).toEchoString();
    throw EvalError(loc, msg);
}

// ---------------------------------------------------------------------------------------------
// Function calls

std::optional<Evaluator::CallTarget> Evaluator::resolveFunction(const Expr &callee,
                                                                const FramePtr &f,
                                                                Value *calleeValue) {
    auto fromValue = [](const Value &v) {
        CallTarget t;
        const FunctionValue &fv = v.toFunction();
        t.params = &fv.def->params;
        t.body = fv.def->body.get();
        t.parent = fv.closure;
        return t;
    };
    if (callee.kind != ExprKind::Identifier) {
        *calleeValue = eval(callee, f);
        if (calleeValue->isFunction()) return fromValue(*calleeValue);
        return std::nullopt;
    }
    Symbol name = static_cast<const IdentifierExpr &>(callee).name;
    // A variable holding a function shadows a function definition (Context::lookup_function)
    if (name.isDollar()) {
        if (const Value *v = dyn_.lookup(name); v && v->isFunction()) {
            CallTarget t = fromValue(*v);
            t.name = name;
            return t;
        }
    } else {
        for (const Frame *p = f.get(); p; p = p->parent.get())
            if (const Value *v = p->findLocal(name); v && v->isFunction()) {
                CallTarget t = fromValue(*v);
                t.name = name;
                return t;
            }
    }
    for (const Frame *p = f.get(); p; p = p->parent.get()) {
        if (p->defs) {
            auto it = p->defs->functions.find(name);
            if (it != p->defs->functions.end()) {
                CallTarget t;
                t.params = &it->second->params;
                t.body = it->second->body.get();
                t.parent = std::const_pointer_cast<Frame>(p->shared_from_this());
                t.name = name;
                return t;
            }
        }
        if (p->file) {
            for (LoadedFile *lib : p->file->uses) {
                auto it = lib->src->top.functions.find(name);
                if (it == lib->src->top.functions.end()) continue;
                CallTarget t;
                t.params = &it->second->params;
                t.body = it->second->body.get();
                t.parent = libraryFrame(*lib);
                t.library = lib;
                t.name = name;
                return t;
            }
        }
    }
    return std::nullopt;
}

Value Evaluator::evalCall(const CallExpr &c, const FramePtr &f) {
    Value calleeValue;
    if (auto target = resolveFunction(*c.callee, f, &calleeValue))
        return callUser(std::move(*target), c.args, f, c.loc);
    if (c.callee->kind == ExprKind::Identifier) {
        Symbol name = static_cast<const IdentifierExpr &>(*c.callee).name;
        if (const BuiltinFunctionEntry *fn = builtins_.findFunction(name))
            return fn->raw ? fn->raw(*this, c.args, f, c.loc)
                           : callBuiltinFunction(fn->function, c.args, f, c.loc);
        throw EvalError(c.loc, "unknown function '" + name.str() + "'");
    }
    warn(c.loc,
         std::string("can't call a value of type ") + calleeValue.typeName() + " as a function");
    return Value();
}

Value Evaluator::callBuiltinFunction(BuiltinFunction fn, const ArgumentList &args,
                                     const FramePtr &f, const SourceLoc &loc) {
    // OpenSCAD's builtin functions read their arguments by position only
    std::vector<Value> values;
    values.reserve(args.size());
    for (const auto &a : args) values.push_back(eval(*a.expr, f));
    step(loc);
    return fn(*this, values, loc);
}

void Evaluator::bindParameters(const ParameterList &params, const ArgumentList &args,
                               const FramePtr &argFrame, Frame &into, const FramePtr &defaultsFrame,
                               const SourceLoc &callLoc) {
    // EvalContext::resolveArguments: positional arguments fill the parameters in order, named
    // ones by name; unknown names warn but are still bound, `$` names silently.
    std::vector<bool> given(params.size(), false);
    size_t pos = 0;
    for (const auto &a : args) {
        if (!a.name.empty()) {
            size_t idx = params.size();
            for (size_t i = 0; i < params.size(); ++i)
                if (params[i].name == a.name) idx = i;
            if (idx < params.size()) {
                if (given[idx])
                    warn(a.loc, "argument " + a.name.str() + " supplied more than once");
                given[idx] = true;
            } else if (!a.name.isDollar() && a.name.str()[0] != '$') {
                warn(a.loc, "variable " + a.name.str() + " not specified as parameter");
            }
            into.set(a.name, eval(*a.expr, argFrame));
        } else if (pos < params.size()) {
            given[pos] = true;
            into.set(params[pos++].name, eval(*a.expr, argFrame));
        } else {
            warn(a.loc, "Too many unnamed arguments supplied");
        }
    }
    (void)callLoc;
    // Defaults are evaluated in the defining scope and cannot see the other parameters
    for (size_t i = 0; i < params.size(); ++i)
        if (!given[i])
            into.set(params[i].name,
                     params[i].defaultExpr ? eval(*params[i].defaultExpr, defaultsFrame) : Value());
}

Value Evaluator::callUser(CallTarget target, const ArgumentList &args, const FramePtr &argFrame,
                          const SourceLoc &loc) {
    if (callDepth_ >= limits_.maxCallDepth)
        throw EvalError(loc, "recursion too deep calling function '" + target.name.str() +
                                 "' (more than " + std::to_string(limits_.maxCallDepth) +
                                 " nested calls)");
    checkStack(loc);
    ++callDepth_;
    // The frames of the current iteration stay alive until they are off the dynamic stack
    std::vector<FramePtr> live;
    struct Restore {
        Evaluator &ev;
        size_t base;
        ~Restore() {
            while (ev.dyn_.depth() > base) ev.dyn_.pop();
            --ev.callDepth_;
        }
    } restore{*this, dyn_.depth()};

    const ArgumentList *callArgs = &args;
    FramePtr callerFrame = argFrame;
    SourceLoc callLoc = loc;
    for (;;) {
        step(callLoc);
        // Bind the arguments with the previous iteration's frames still visible, then
        // replace those frames with the new one
        FramePtr frame = makeFrame(target.parent);
        bindParameters(*target.params, *callArgs, callerFrame, *frame, target.parent, callLoc);
        while (dyn_.depth() > restore.base) dyn_.pop();
        live.clear();
        if (target.library) dyn_.push(libraryFrame(*target.library).get());
        dyn_.push(frame.get());
        live.push_back(frame);

        // Walk the tail positions of the body: ?: branches, let, assert and echo prefixes
        const Expr *body = target.body;
        FramePtr cur = frame;
        for (;;) {
            if (body->kind == ExprKind::Ternary) {
                const auto &t = static_cast<const TernaryExpr &>(*body);
                body = eval(*t.cond, cur).toBool() ? t.thenExpr.get() : t.elseExpr.get();
            } else if (body->kind == ExprKind::Let) {
                const auto &p = static_cast<const PrefixExpr &>(*body);
                FramePtr c = makeFrame(cur);
                dyn_.push(c.get());
                live.push_back(c);
                bindLet(p.args, c);
                cur = c;
                body = p.body.get();
            } else if (body->kind == ExprKind::Assert || body->kind == ExprKind::Echo) {
                const auto &p = static_cast<const PrefixExpr &>(*body);
                if (body->kind == ExprKind::Assert)
                    evalAssert(p.args, cur, p.loc);
                else
                    evalEcho(p.args, cur, p.loc);
                if (!p.body) return Value();
                body = p.body.get();
            } else {
                break;
            }
        }
        if (body->kind == ExprKind::Call) {
            // A call in tail position reuses this loop instead of the C++ stack
            const auto &call = static_cast<const CallExpr &>(*body);
            Value calleeValue;
            if (auto next = resolveFunction(*call.callee, cur, &calleeValue)) {
                target = std::move(*next);
                callArgs = &call.args;
                callerFrame = cur;
                callLoc = call.loc;
                continue;
            }
            if (call.callee->kind != ExprKind::Identifier) {
                warn(call.loc, std::string("can't call a value of type ") + calleeValue.typeName() +
                                   " as a function");
                return Value();
            }
        }
        return eval(*body, cur);
    }
}

// ---------------------------------------------------------------------------------------------
// Scopes and instantiation

void Evaluator::applyAssignments(const std::vector<Assignment> &as, const FramePtr &f) {
    for (const auto &a : as) f->set(a.name, eval(*a.expr, f));
}

void Evaluator::instantiateScope(const Scope &s, const FramePtr &f, std::vector<ir::NodePtr> &out) {
    for (const auto &inst : s.instantiations)
        if (ir::NodePtr n = instantiate(*inst, f)) out.push_back(std::move(n));
}

void Evaluator::instantiateChildren(const ModuleInstantiation &inst, const FramePtr &caller,
                                    std::vector<ir::NodePtr> &out, const Scope *scope) {
    if (!scope) scope = &inst.children;
    if (scope->assignments.empty()) {
        // A frame without variables is invisible to every lookup: skip it
        instantiateScope(*scope, caller, out);
        return;
    }
    FramePtr c = makeFrame(caller);
    FrameGuard g(dyn_, c.get());
    applyAssignments(scope->assignments, c);
    instantiateScope(*scope, c, out);
}

ir::NodePtr Evaluator::instantiate(const ModuleInstantiation &inst, const FramePtr &f) {
    const Modifiers &m = inst.modifiers;
    if (m.disabled) {
        ++scene_.stats.disabledParts;
        return nullptr;
    }
    if (m.background) {
        // Evaluated (echo, assert and errors still happen) but left out, as OpenSCAD's renders do
        ++state_.backgroundDepth;
        instantiateUnmodified(inst, f);
        --state_.backgroundDepth;
        ++scene_.stats.backgroundParts;
        return nullptr;
    }
    if (m.root) {
        if (rootSeen_) {
            warn(inst.loc, "More than one Root Modifier (!)");
        } else {
            // The first `!` in tree order becomes the scene root, without the transforms and
            // colours around it
            rootSeen_ = true;
            Mat4 savedWorld = state_.worldFromLocal;
            auto savedColor = state_.color;
            auto savedMaterials = std::move(state_.materials);
            state_.worldFromLocal = Mat4();
            state_.color.reset();
            state_.materials.clear();
            state_.currentMaterial = -1;
            ir::NodePtr n = instantiateUnmodified(inst, f);
            state_.worldFromLocal = savedWorld;
            state_.color = savedColor;
            state_.materials = std::move(savedMaterials);
            state_.currentMaterial = -1;
            if (n && m.highlight) n->highlight = true;
            rootNode_ = n ? std::move(n) : newNode(ir::NodeKind::Group, inst.loc);
            return nullptr;
        }
    }
    ir::NodePtr n = instantiateUnmodified(inst, f);
    if (n && m.highlight) n->highlight = true;
    return n;
}

std::optional<Evaluator::ModuleLookup> Evaluator::findModule(Symbol name, const Frame *f) {
    for (const Frame *p = f; p; p = p->parent.get()) {
        if (p->defs) {
            auto it = p->defs->modules.find(name);
            if (it != p->defs->modules.end())
                return ModuleLookup{it->second.get(),
                                    std::const_pointer_cast<Frame>(p->shared_from_this()), nullptr};
        }
        if (p->file) {
            for (LoadedFile *lib : p->file->uses) {
                auto it = lib->src->top.modules.find(name);
                if (it != lib->src->top.modules.end())
                    return ModuleLookup{it->second.get(), libraryFrame(*lib), lib};
            }
        }
    }
    return std::nullopt;
}

ir::NodePtr Evaluator::instantiateUnmodified(const ModuleInstantiation &inst, const FramePtr &f) {
    try {
        return instantiateUnchecked(inst, f);
    } catch (const ValueLimitError &err) {
        throw EvalError(inst.loc, err.what());
    }
}

ir::NodePtr Evaluator::instantiateUnchecked(const ModuleInstantiation &inst, const FramePtr &f) {
    checkStack(inst.loc);
    step(inst.loc);
    if (inst.isIf) return moduleIf(inst, f);
    const BuiltinModuleEntry *builtin = builtins_.findModule(inst.name);
    if (auto user = findModule(inst.name, f.get())) {
        if (builtin && builtin->scadrayLibraryStub && isScadrayLibrary(user->def->loc))
            return builtin->module(*this, inst, f);
        return instantiateUser(*user, inst, f);
    }
    const auto &control = controlModules();
    auto it = control.find(inst.name);
    if (it != control.end()) return (this->*(it->second))(inst, f);
    if (builtin) {
        if (builtin->scadrayLibraryStub)
            warn(inst.loc, "`" + inst.name.str() +
                               "` is a scadray metadata module but scadray.scad is not used: "
                               "OpenSCAD will ignore it and drop its children; add `use "
                               "<scadray.scad>`");
        return builtin->module(*this, inst, f);
    }
    throw EvalError(inst.loc, "unknown module '" + inst.name.str() + "'");
}

ir::NodePtr Evaluator::instantiateUser(const ModuleLookup &m, const ModuleInstantiation &inst,
                                       const FramePtr &caller) {
    if (callDepth_ >= limits_.maxCallDepth)
        throw EvalError(inst.loc, "recursion too deep calling module '" + inst.name.str() +
                                      "' (more than " + std::to_string(limits_.maxCallDepth) +
                                      " nested calls)");
    ++callDepth_;
    struct Restore {
        Evaluator &ev;
        ~Restore() { --ev.callDepth_; }
    } restore{*this};

    // The child block's assignments go into the call's frame before the module body runs;
    // the arguments are evaluated there too (UserModule::instantiate, scope.apply(evalctx)).
    FramePtr childFrame = makeFrame(caller);
    FrameGuard childGuard(dyn_, childFrame.get());
    applyAssignments(inst.children.assignments, childFrame);

    std::optional<FrameGuard> libGuard;
    if (m.library) libGuard.emplace(dyn_, m.parent.get());
    ModuleCallInfo info{&inst, childFrame};
    FramePtr body = makeFrame(m.parent);
    body->defs = &m.def->body;
    body->call = &info;
    FrameGuard bodyGuard(dyn_, body.get());
    static const Symbol kChildren = sym("$children"), kParentModules = sym("$parent_modules");
    body->set(kChildren, Value::number(static_cast<double>(inst.children.instantiations.size())));
    moduleStack_.push_back(inst.name);
    body->set(kParentModules, Value::number(static_cast<double>(moduleStack_.size())));
    bindParameters(m.def->params, inst.args, childFrame, *body, m.parent, inst.loc);
    // Body assignments share the parameters' frame, so they can override them
    applyAssignments(m.def->body.assignments, body);

    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    node->label = "module " + inst.name.str();
    instantiateScope(m.def->body, body, node->children);
    moduleStack_.pop_back();
    return node;
}

BoundArgs Evaluator::bindBuiltin(const ModuleInstantiation &inst,
                                 std::initializer_list<std::string_view> params,
                                 const FramePtr &argFrame, Frame *dollarFrame, size_t positional) {
    BoundArgs b;
    size_t n = params.size();
    b.names.assign(params.begin(), params.end());
    b.values.resize(n);
    b.locs.resize(n);
    b.given.assign(n, false);
    b.callLoc = inst.loc;
    size_t pos = 0;
    for (const auto &a : inst.args) {
        size_t idx = n;
        if (!a.name.empty()) {
            size_t i = 0;
            for (auto p : params) {
                if (p == a.name.str()) idx = i;
                ++i;
            }
            if (idx == n) {
                Value v = eval(*a.expr, argFrame);
                if (a.name.str()[0] == '$') {
                    if (dollarFrame) dollarFrame->set(a.name, std::move(v));
                } else {
                    warn(a.loc, "variable " + a.name.str() + " not specified as parameter");
                }
                continue;
            }
            if (b.given[idx]) warn(a.loc, "argument " + a.name.str() + " supplied more than once");
        } else if (pos < std::min(n, positional)) {
            idx = pos++;
        } else {
            eval(*a.expr, argFrame);
            warn(a.loc, "Too many unnamed arguments supplied");
            continue;
        }
        b.values[idx] = eval(*a.expr, argFrame);
        b.locs[idx] = a.loc;
        b.given[idx] = true;
    }
    return b;
}

// ---------------------------------------------------------------------------------------------
// Control modules

ir::NodePtr Evaluator::moduleIf(const ModuleInstantiation &inst, const FramePtr &f) {
    bool cond = !inst.args.empty() && eval(*inst.args[0].expr, f).toBool();
    // `if (false)` without else produces nothing at all (null, not an empty group)
    if (!cond && !inst.hasElse) return nullptr;
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, f, node->children, cond ? &inst.children : &inst.elseChildren);
    return node;
}

void Evaluator::forLoop(const ModuleInstantiation &inst, size_t var, const FramePtr &f,
                        std::vector<ir::NodePtr> &out, bool groupPerIteration) {
    if (var == inst.args.size()) {
        if (!groupPerIteration) {
            instantiateChildren(inst, f, out);
            return;
        }
        std::vector<ir::NodePtr> kids;
        instantiateChildren(inst, f, kids);
        out.push_back(groupOf(ir::NodeKind::Group, inst.loc, std::move(kids)));
        return;
    }
    const Argument &a = inst.args[var];
    Value seq = eval(*a.expr, f);
    FramePtr c = makeFrame(f);
    FrameGuard g(dyn_, c.get());
    auto iterate = [&](Value x) {
        step(inst.loc);
        c->set(a.name, std::move(x));
        forLoop(inst, var + 1, c, out, groupPerIteration);
    };
    forEachElement(*this, seq, kMaxModuleForRange, a.loc, iterate);
}

ir::NodePtr Evaluator::moduleFor(const ModuleInstantiation &inst, const FramePtr &f) {
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    if (!inst.args.empty()) forLoop(inst, 0, f, node->children, false);
    return node;
}

ir::NodePtr Evaluator::moduleIntersectionFor(const ModuleInstantiation &inst, const FramePtr &f) {
    ir::NodePtr node = newNode(ir::NodeKind::Intersection, inst.loc);
    if (!inst.args.empty()) forLoop(inst, 0, f, node->children, true);
    return node;
}

ir::NodePtr Evaluator::moduleLet(const ModuleInstantiation &inst, const FramePtr &f) {
    FramePtr c = makeFrame(f);
    FrameGuard g(dyn_, c.get());
    bindLet(inst.args, c);
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, c, node->children);
    return node;
}

/// echo() and assert() with children act as a group; without children they produce nothing
/// (null, not empty: a difference() skips them when choosing its minuend).
ir::NodePtr Evaluator::childrenGroupOrNull(const ModuleInstantiation &inst, const FramePtr &f) {
    if (inst.children.empty()) return nullptr;
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, f, node->children);
    return node;
}

ir::NodePtr Evaluator::moduleEcho(const ModuleInstantiation &inst, const FramePtr &f) {
    evalEcho(inst.args, f, inst.loc);
    return childrenGroupOrNull(inst, f);
}

ir::NodePtr Evaluator::moduleAssert(const ModuleInstantiation &inst, const FramePtr &f) {
    evalAssert(inst.args, f, inst.loc);
    return childrenGroupOrNull(inst, f);
}

void Evaluator::deprecated(const SourceLoc &loc, const std::string &what, bool oncePerRun) {
    // OpenSCAD prints each deprecation message once: 2021.01's assign() message names its
    // file and line, so it comes once per line; child()'s does not, so it comes once per run.
    std::string key = oncePerRun ? what : loc.fileName() + ":" + std::to_string(loc.line) + what;
    if (deprecationsShown_.insert(key).second) warn(loc, "DEPRECATED: " + what);
}

ir::NodePtr Evaluator::moduleAssign(const ModuleInstantiation &inst, const FramePtr &f) {
    deprecated(inst.loc,
               "The assign() module will be removed in future releases. Use a regular "
               "assignment instead.",
               false);
    // Parallel, unlike let(): every named value is evaluated in the caller's scope before any
    // is bound (control.cc ASSIGN); unnamed arguments are ignored, unevaluated
    std::vector<std::pair<Symbol, Value>> bindings;
    for (const auto &a : inst.args)
        if (!a.name.empty()) bindings.emplace_back(a.name, eval(*a.expr, f));
    FramePtr c = makeFrame(f);
    FrameGuard g(dyn_, c.get());
    for (auto &[name, value] : bindings) c->set(name, std::move(value));
    ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
    instantiateChildren(inst, c, node->children);
    return node;
}

ir::NodePtr Evaluator::moduleChild(const ModuleInstantiation &inst, const FramePtr &f) {
    deprecated(inst.loc, "child() will be removed in future releases. Use children() instead.",
               true);
    // The first argument, whatever its name, picks one child when it is a number; anything
    // else means child 0 (control.cc CHILD)
    double index = 0;
    if (!inst.args.empty()) {
        Value v = eval(*inst.args[0].expr, f);
        if (v.isNumber()) index = std::trunc(v.toNumber());
    }
    if (index < 0) {
        warn(inst.loc, "Negative child index (" + formatNumber(index) + ") not allowed");
        return nullptr;
    }
    const ModuleCallInfo *call = enclosingCall(f);
    if (!call) return nullptr;
    const auto &kids = call->inst->children.instantiations;
    if (!(index < static_cast<double>(kids.size()))) {
        warn(inst.loc, "Child index (" + formatNumber(index) + ") out of bounds (" +
                           std::to_string(kids.size()) + " children)");
        return nullptr;
    }
    return instantiate(*kids[static_cast<size_t>(index)], call->childFrame);
}

const std::unordered_map<Symbol, Evaluator::ModuleHandler, SymbolHash>
    &Evaluator::controlModules() {
    static const std::unordered_map<Symbol, ModuleHandler, SymbolHash> kTable = {
        {sym("for"), &Evaluator::moduleFor},
        {sym("intersection_for"), &Evaluator::moduleIntersectionFor},
        {sym("let"), &Evaluator::moduleLet},
        {sym("echo"), &Evaluator::moduleEcho},
        {sym("assert"), &Evaluator::moduleAssert},
        {sym("children"), &Evaluator::moduleChildren},
        {sym("child"), &Evaluator::moduleChild},
        {sym("assign"), &Evaluator::moduleAssign},
    };
    return kTable;
}

ir::NodePtr Evaluator::moduleChildren(const ModuleInstantiation &inst, const FramePtr &f) {
    const ModuleCallInfo *call = enclosingCall(f);
    if (!call) return nullptr;
    const auto &kids = call->inst->children.instantiations;
    auto child = [&](const Value &v) -> ir::NodePtr {
        if (!v.isNumber()) {
            warn(inst.loc, "Bad parameter type (" + v.toEchoString() +
                               ") for children, only accept: empty, number, vector, range.");
            return nullptr;
        }
        double d = std::trunc(v.toNumber());
        if (d < 0) {
            warn(inst.loc, "Negative children index (" + formatNumber(d) + ") not allowed");
            return nullptr;
        }
        if (!(d < static_cast<double>(kids.size()))) {
            warn(inst.loc, "Children index (" + formatNumber(d) + ") out of bounds (" +
                               std::to_string(kids.size()) + " children)");
            return nullptr;
        }
        return instantiate(*kids[static_cast<size_t>(d)], call->childFrame);
    };
    if (inst.args.empty()) {
        ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
        for (const auto &k : kids)
            if (ir::NodePtr n = instantiate(*k, call->childFrame))
                node->children.push_back(std::move(n));
        return node;
    }
    Value sel = eval(*inst.args[0].expr, f);
    if (sel.isNumber()) return child(sel);
    if (sel.isVector()) {
        ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
        for (const auto &v : sel.toVector())
            if (ir::NodePtr n = child(v)) node->children.push_back(std::move(n));
        return node;
    }
    if (sel.isRange()) {
        uint64_t n = sel.toRange().numValues();
        if (n >= kMaxModuleForRange) {
            warn(inst.loc,
                 "Bad range parameter for children: too many elements (" + std::to_string(n) + ")");
            return nullptr;
        }
        ir::NodePtr node = newNode(ir::NodeKind::Group, inst.loc);
        for (uint64_t i = 0; i < n; ++i)
            if (ir::NodePtr c = child(Value::number(sel.toRange().at(i))))
                node->children.push_back(std::move(c));
        return node;
    }
    warn(inst.loc, "Bad parameter type (" + sel.toEchoString() +
                       ") for children, only accept: empty, number, vector, range.");
    return nullptr;
}

}  // namespace rt::scad
