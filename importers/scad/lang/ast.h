// SPDX-License-Identifier: MIT
// Abstract syntax tree of OpenSCAD 2021.01 programs; every node carries its SourceLoc.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/ir/source_loc.h"
#include "importers/scad/lang/symbol.h"
#include "importers/scad/lang/value.h"

namespace rt::scad {

enum class ExprKind {
    Literal,
    Identifier,
    Range,
    Vector,
    Unary,
    Binary,
    And,
    Or,
    Equal,
    NotEqual,
    Ternary,
    Call,
    Index,
    Member,
    Let,
    Assert,
    Echo,
    FunctionLiteral,
    // List-comprehension elements; they appear only as elements of a Vector
    LcFor,
    LcForC,
    LcIf,
    LcLet,
    LcEach,
};

struct Expr {
    ExprKind kind;
    SourceLoc loc;
    Expr(ExprKind k, SourceLoc l) : kind(k), loc(std::move(l)) {}
    virtual ~Expr() = default;
    bool isListComprehension() const { return kind >= ExprKind::LcFor; }
};
using ExprPtr = std::unique_ptr<Expr>;

/// `name = expr` or a positional `expr` in a call, or a binding in let/for.
struct Argument {
    Symbol name;  ///< empty for positional arguments
    ExprPtr expr;
    SourceLoc loc;
};
using ArgumentList = std::vector<Argument>;

/// A formal parameter with its optional default.
struct Parameter {
    Symbol name;
    ExprPtr defaultExpr;  ///< null when the parameter has no default
    SourceLoc loc;
};
using ParameterList = std::vector<Parameter>;

struct LiteralExpr : Expr {
    Value value;
    LiteralExpr(Value v, SourceLoc l)
        : Expr(ExprKind::Literal, std::move(l)), value(std::move(v)) {}
};

struct IdentifierExpr : Expr {
    Symbol name;
    IdentifierExpr(Symbol n, SourceLoc l) : Expr(ExprKind::Identifier, std::move(l)), name(n) {}
};

struct RangeExpr : Expr {
    ExprPtr begin, step, end;  ///< step is null for `[b:e]`
    explicit RangeExpr(SourceLoc l) : Expr(ExprKind::Range, std::move(l)) {}
};

struct VectorExpr : Expr {
    std::vector<ExprPtr> elements;
    /// Set when every element is a literal: the vector is built once at parse time.
    std::unique_ptr<Value> constant;
    explicit VectorExpr(SourceLoc l) : Expr(ExprKind::Vector, std::move(l)) {}
};

enum class UnaryOp { Negate, Not };

struct UnaryExpr : Expr {
    UnaryOp op;
    ExprPtr operand;
    UnaryExpr(UnaryOp o, ExprPtr e, SourceLoc l)
        : Expr(ExprKind::Unary, std::move(l)), op(o), operand(std::move(e)) {}
};

/// Arithmetic and ordering operators (kind Binary), and `&&`, `||`, `==`, `!=` (their own kinds).
struct BinaryExpr : Expr {
    BinaryOp op = BinaryOp::Add;  ///< only for kind Binary
    ExprPtr lhs, rhs;
    BinaryExpr(ExprKind k, BinaryOp o, ExprPtr a, ExprPtr b, SourceLoc l)
        : Expr(k, std::move(l)), op(o), lhs(std::move(a)), rhs(std::move(b)) {}
};

struct TernaryExpr : Expr {
    ExprPtr cond, thenExpr, elseExpr;
    explicit TernaryExpr(SourceLoc l) : Expr(ExprKind::Ternary, std::move(l)) {}
};

struct CallExpr : Expr {
    ExprPtr callee;  ///< an IdentifierExpr for named calls
    ArgumentList args;
    explicit CallExpr(SourceLoc l) : Expr(ExprKind::Call, std::move(l)) {}
};

struct IndexExpr : Expr {
    ExprPtr object, index;
    explicit IndexExpr(SourceLoc l) : Expr(ExprKind::Index, std::move(l)) {}
};

struct MemberExpr : Expr {
    ExprPtr object;
    Symbol member;
    explicit MemberExpr(SourceLoc l) : Expr(ExprKind::Member, std::move(l)) {}
};

/// `let(...) e`, `assert(...) e`, `echo(...) e`; the body may be null for assert/echo.
struct PrefixExpr : Expr {
    ArgumentList args;
    ExprPtr body;
    PrefixExpr(ExprKind k, SourceLoc l) : Expr(k, std::move(l)) {}
};

struct FunctionLiteralExpr : Expr {
    ParameterList params;
    ExprPtr body;
    explicit FunctionLiteralExpr(SourceLoc l) : Expr(ExprKind::FunctionLiteral, std::move(l)) {}
};

/// `for (a = ..., b = ...) body` in a list comprehension.
struct LcForExpr : Expr {
    ArgumentList vars;
    ExprPtr body;
    explicit LcForExpr(SourceLoc l) : Expr(ExprKind::LcFor, std::move(l)) {}
};

/// C-style `for (init; cond; update) body`.
struct LcForCExpr : Expr {
    ArgumentList init, update;
    ExprPtr cond, body;
    explicit LcForCExpr(SourceLoc l) : Expr(ExprKind::LcForC, std::move(l)) {}
};

struct LcIfExpr : Expr {
    ExprPtr cond, thenExpr, elseExpr;  ///< elseExpr may be null
    explicit LcIfExpr(SourceLoc l) : Expr(ExprKind::LcIf, std::move(l)) {}
};

struct LcLetExpr : Expr {
    ArgumentList args;
    ExprPtr body;
    explicit LcLetExpr(SourceLoc l) : Expr(ExprKind::LcLet, std::move(l)) {}
};

struct LcEachExpr : Expr {
    ExprPtr body;
    explicit LcEachExpr(SourceLoc l) : Expr(ExprKind::LcEach, std::move(l)) {}
};

struct ModuleInstantiation;
struct ModuleDef;
struct FunctionDef;

/// `name = expr;` in a scope. Within one scope a name has one slot: the first assignment's
/// position with the last assignment's expression (parser.y handle_assignment).
struct Assignment {
    Symbol name;
    ExprPtr expr;
    SourceLoc loc;  ///< of the first assignment (where it is evaluated)
};

/// A block's assignments, module instantiations and (hoisted) definitions.
struct Scope {
    std::vector<Assignment> assignments;
    std::vector<std::unique_ptr<ModuleInstantiation>> instantiations;
    std::unordered_map<Symbol, std::shared_ptr<const FunctionDef>, SymbolHash> functions;
    std::unordered_map<Symbol, std::shared_ptr<const ModuleDef>, SymbolHash> modules;

    bool empty() const { return assignments.empty() && instantiations.empty(); }
};

struct Modifiers {
    bool root = false;        ///< `!`
    bool highlight = false;   ///< `#`
    bool background = false;  ///< `%`
    bool disabled = false;    ///< `*`
};

/// A module call `name(args) child` (also `if`, `for`, `let`, `echo`, `assert`).
struct ModuleInstantiation {
    Symbol name;
    ArgumentList args;
    SourceLoc loc;
    Modifiers modifiers;
    Scope children;
    bool isIf = false;
    bool hasElse = false;
    Scope elseChildren;  ///< `if` only
};

struct FunctionDef {
    Symbol name;
    ParameterList params;
    ExprPtr body;
    SourceLoc loc;
};

struct ModuleDef {
    Symbol name;
    ParameterList params;
    Scope body;
    SourceLoc loc;
};

/// A `use <file>` statement, resolved at parse time.
struct UseDecl {
    std::string path;  ///< resolved path of the used file
    SourceLoc loc;
};

/// A parsed file: its top-level scope (with included files spliced in) and its `use` list.
struct SourceFile {
    std::string path;
    Scope top;
    std::vector<UseDecl> uses;
};

/// OpenSCAD's printed form of an expression (as in `Assertion '(x > 1)' failed`).
std::string exprToString(const Expr &e);
std::string functionLiteralToString(const FunctionLiteralExpr &f);

}  // namespace rt::scad
