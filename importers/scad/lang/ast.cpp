// SPDX-License-Identifier: MIT
// Printing expressions the way OpenSCAD 2021.01 does in assertion messages and echo output.
#include "importers/scad/lang/ast.h"

namespace rt::scad {

namespace {

std::string argsToString(const ArgumentList &args) {
    std::string s;
    for (size_t i = 0; i < args.size(); ++i) {
        if (i) s += ", ";
        if (!args[i].name.empty()) s += args[i].name.str() + " = ";
        if (args[i].expr) s += exprToString(*args[i].expr);
    }
    return s;
}

std::string paramsToString(const ParameterList &params) {
    std::string s;
    for (size_t i = 0; i < params.size(); ++i) {
        if (i) s += ", ";
        s += params[i].name.str();
        if (params[i].defaultExpr) s += " = " + exprToString(*params[i].defaultExpr);
    }
    return s;
}

const char *binarySpelling(const BinaryExpr &b) {
    switch (b.kind) {
        case ExprKind::And:
            return "&&";
        case ExprKind::Or:
            return "||";
        case ExprKind::Equal:
            return "==";
        case ExprKind::NotEqual:
            return "!=";
        default:
            return binaryOpSpelling(b.op);
    }
}

}  // namespace

std::string functionLiteralToString(const FunctionLiteralExpr &f) {
    return "function(" + paramsToString(f.params) + ") " + exprToString(*f.body);
}

std::string exprToString(const Expr &e) {
    switch (e.kind) {
        case ExprKind::Literal:
            return static_cast<const LiteralExpr &>(e).value.toEchoString();
        case ExprKind::Identifier:
            return static_cast<const IdentifierExpr &>(e).name.str();
        case ExprKind::Range: {
            const auto &r = static_cast<const RangeExpr &>(e);
            std::string s = "[" + exprToString(*r.begin) + " : ";
            if (r.step) s += exprToString(*r.step) + " : ";
            return s + exprToString(*r.end) + "]";
        }
        case ExprKind::Vector: {
            const auto &v = static_cast<const VectorExpr &>(e);
            std::string s = "[";
            for (size_t i = 0; i < v.elements.size(); ++i) {
                if (i) s += ", ";
                s += exprToString(*v.elements[i]);
            }
            return s + "]";
        }
        case ExprKind::Unary: {
            const auto &u = static_cast<const UnaryExpr &>(e);
            return (u.op == UnaryOp::Negate ? "-" : "!") + exprToString(*u.operand);
        }
        case ExprKind::Binary:
        case ExprKind::And:
        case ExprKind::Or:
        case ExprKind::Equal:
        case ExprKind::NotEqual: {
            const auto &b = static_cast<const BinaryExpr &>(e);
            return "(" + exprToString(*b.lhs) + " " + binarySpelling(b) + " " +
                   exprToString(*b.rhs) + ")";
        }
        case ExprKind::Ternary: {
            const auto &t = static_cast<const TernaryExpr &>(e);
            return "(" + exprToString(*t.cond) + " ? " + exprToString(*t.thenExpr) + " : " +
                   exprToString(*t.elseExpr) + ")";
        }
        case ExprKind::Call: {
            const auto &c = static_cast<const CallExpr &>(e);
            return exprToString(*c.callee) + "(" + argsToString(c.args) + ")";
        }
        case ExprKind::Index: {
            const auto &i = static_cast<const IndexExpr &>(e);
            return exprToString(*i.object) + "[" + exprToString(*i.index) + "]";
        }
        case ExprKind::Member: {
            const auto &m = static_cast<const MemberExpr &>(e);
            return exprToString(*m.object) + "." + m.member.str();
        }
        case ExprKind::Let:
        case ExprKind::Assert:
        case ExprKind::Echo: {
            const auto &p = static_cast<const PrefixExpr &>(e);
            const char *kw = e.kind == ExprKind::Let      ? "let"
                             : e.kind == ExprKind::Assert ? "assert"
                                                          : "echo";
            std::string s = std::string(kw) + "(" + argsToString(p.args) + ")";
            if (p.body) s += " " + exprToString(*p.body);
            return s;
        }
        case ExprKind::FunctionLiteral:
            return functionLiteralToString(static_cast<const FunctionLiteralExpr &>(e));
        case ExprKind::LcFor: {
            const auto &f = static_cast<const LcForExpr &>(e);
            return "for(" + argsToString(f.vars) + ") " + exprToString(*f.body);
        }
        case ExprKind::LcForC: {
            const auto &f = static_cast<const LcForCExpr &>(e);
            return "for(" + argsToString(f.init) + "; " + exprToString(*f.cond) + "; " +
                   argsToString(f.update) + ") " + exprToString(*f.body);
        }
        case ExprKind::LcIf: {
            const auto &i = static_cast<const LcIfExpr &>(e);
            std::string s = "if(" + exprToString(*i.cond) + ") " + exprToString(*i.thenExpr);
            if (i.elseExpr) s += " else " + exprToString(*i.elseExpr);
            return s;
        }
        case ExprKind::LcLet: {
            const auto &l = static_cast<const LcLetExpr &>(e);
            return "let(" + argsToString(l.args) + ") " + exprToString(*l.body);
        }
        case ExprKind::LcEach:
            return "each " + exprToString(*static_cast<const LcEachExpr &>(e).body);
    }
    return "?";
}

}  // namespace rt::scad
