// SPDX-License-Identifier: MIT
// OpenSCAD parser: grammar and precedence of 2021.01 parser.y, as recursive descent.
#include "importers/scad/lang/parser.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/ir/diagnostics.h"
#include "core/system/input_file.h"
#include "importers/scad/lang/lexer.h"

#ifndef SCADRAY_LIBRARY_DIR
#define SCADRAY_LIBRARY_DIR ""
#endif

namespace rt::scad {

namespace fs = std::filesystem;

namespace {

/// Deepest nesting of expressions/statements accepted; beyond it the input is rejected
/// instead of exhausting the parser's stack. The links of a left-associative or postfix chain
/// (`1+1+...`, `f(1)(1)...`, `a[0][0]...`, `a.x.x...`) count as nesting too: the tree such a
/// chain builds is as deep as the chain, and evaluating or freeing it recurses that deep. So
/// no syntax tree is deeper than a small multiple of this.
constexpr int kMaxNesting = 10000;
/// include<> chains deeper than this are taken to be recursive.
constexpr int kMaxIncludeDepth = 64;
constexpr const char *kOpenScadLibraryDir = "/usr/share/openscad/libraries";

std::string dirOf(const std::string &path) {
    fs::path p(path);
    return p.has_parent_path() ? p.parent_path().string() : std::string(".");
}

/// use<> of a TrueType/OpenType file registers a font instead of reading source
/// (2021.01 SourceFile::registerUse compares the extension without case).
bool isFontFile(const std::string &name) {
    std::string ext = fs::path(name).extension().string();
    for (auto &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".ttf" || ext == ".otf";
}

/// The first bytes of a font file: TrueType (00 01 00 00 or "true"), OpenType with CFF
/// outlines ("OTTO") or a TrueType collection ("ttcf").
bool hasFontSignature(const std::string &path) {
    char magic[4] = {};
    std::ifstream in(path, std::ios::binary);
    if (!in.read(magic, sizeof magic)) return false;
    std::string m(magic, sizeof magic);
    return m == std::string("\0\1\0\0", 4) || m == "true" || m == "OTTO" || m == "ttcf";
}

/// Runs `parse` on the text of `path`. A syntax error in a file that is not named .scad says
/// only "syntax error", as OpenSCAD does: the usual message would quote the file's text.
template <typename F>
void parseQuietly(const std::string &path, F &&parse) {
    try {
        parse();
    } catch (const ParseError &e) {
        if (isScadFile(path) || e.loc().fileName() != path) throw;
        throw ParseError(e.loc(), "syntax error (in a file not named .scad, not quoted)");
    }
}

class Parser {
  public:
    Parser(std::vector<Token> tokens, SourceLoader &loader, SourceFile &root, int includeDepth)
        : toks_(std::move(tokens)), loader_(loader), root_(root), includeDepth_(includeDepth) {}

    void parseStatements(Scope &scope);
    ExprPtr parseWholeExpression();

  private:
    [[noreturn]] static void tooDeep(const SourceLoc &loc) {
        throw ParseError(loc, "expression or statement nesting too deep (more than " +
                                  std::to_string(kMaxNesting) +
                                  " nested or chained brackets, operators, calls or statements)");
    }
    struct NestingGuard {
        explicit NestingGuard(Parser &p) : p_(p) {
            if (++p_.nesting_ > kMaxNesting) tooDeep(p_.cur().loc);
        }
        ~NestingGuard() { --p_.nesting_; }
        Parser &p_;
    };
    /// Counts each link of a chain as one level of nesting until the chain ends.
    struct ChainGuard {
        explicit ChainGuard(Parser &p) : p_(p), base_(p.nesting_) {}
        void link(const SourceLoc &loc) {
            if (++p_.nesting_ > kMaxNesting) tooDeep(loc);
        }
        ~ChainGuard() { p_.nesting_ = base_; }
        Parser &p_;
        int base_;
    };

    const Token &cur() const { return toks_[pos_]; }
    const Token &peekTok(size_t n = 1) const { return toks_[std::min(pos_ + n, toks_.size() - 1)]; }
    bool at(TokenKind k) const { return cur().kind == k; }
    bool accept(TokenKind k) {
        if (!at(k)) return false;
        ++pos_;
        return true;
    }
    Token expect(TokenKind k, const char *context);
    /// Skips a run of commas (parser.y `optional_commas`); true when there was one.
    bool skipCommas() {
        bool any = false;
        while (accept(TokenKind::Comma)) any = true;
        return any;
    }
    [[noreturn]] void unexpected(const char *context) const;

    void parseStatement(Scope &scope);
    void parseInclude(Scope &scope);
    void parseUse();
    void parseModuleDef(Scope &scope);
    void parseFunctionDef(Scope &scope);
    void parseAssignment(Scope &scope);
    std::unique_ptr<ModuleInstantiation> parseInstantiation();
    void parseChildStatement(Scope &scope);
    ParameterList parseParameters();
    ArgumentList parseArguments(TokenKind close);

    ExprPtr parseExpr();
    ExprPtr parseTernary();
    ExprPtr parseOr();
    ExprPtr parseAnd();
    ExprPtr parseEquality();
    ExprPtr parseComparison();
    ExprPtr parseAddition();
    ExprPtr parseMultiplication();
    ExprPtr parseUnary();
    ExprPtr parseExponent();
    ExprPtr parsePostfix();
    ExprPtr parsePrimary();
    ExprPtr parseBracket();
    ExprPtr parseElement();
    ExprPtr parsePrefix(ExprKind kind);

    std::vector<Token> toks_;
    size_t pos_ = 0;
    SourceLoader &loader_;
    SourceFile &root_;
    int includeDepth_;
    int nesting_ = 0;
};

Token Parser::expect(TokenKind k, const char *context) {
    if (!at(k)) {
        throw ParseError(cur().loc, std::string("syntax error: expected ") + tokenKindName(k) +
                                        " " + context + ", found " + describeToken(cur()));
    }
    return toks_[pos_++];
}

void Parser::unexpected(const char *context) const {
    throw ParseError(cur().loc, "syntax error: unexpected " + describeToken(cur()) + " " + context);
}

void Parser::parseStatements(Scope &scope) {
    while (!at(TokenKind::End)) parseStatement(scope);
}

void Parser::parseStatement(Scope &scope) {
    NestingGuard guard(*this);
    switch (cur().kind) {
        case TokenKind::Semicolon:
            ++pos_;
            return;
        case TokenKind::LBrace: {
            // A bare block is not a scope: its statements belong to the enclosing one
            ++pos_;
            while (!at(TokenKind::RBrace)) {
                if (at(TokenKind::End)) expect(TokenKind::RBrace, "to close the block");
                parseStatement(scope);
            }
            ++pos_;
            return;
        }
        case TokenKind::Include:
            parseInclude(scope);
            return;
        case TokenKind::Use:
            parseUse();
            return;
        case TokenKind::KwModule:
            parseModuleDef(scope);
            return;
        case TokenKind::KwFunction:
            parseFunctionDef(scope);
            return;
        case TokenKind::Identifier:
            if (peekTok().kind == TokenKind::Assign) {
                parseAssignment(scope);
                return;
            }
            break;
        case TokenKind::RBrace:
            unexpected("(no block to close)");
        default:
            break;
    }
    scope.instantiations.push_back(parseInstantiation());
}

void Parser::parseInclude(Scope &scope) {
    Token tok = toks_[pos_++];
    std::string path = loader_.resolve(tok.text, dirOf(*tok.loc.file));
    if (path.empty()) throw ParseError(tok.loc, "can't find include file '" + tok.text + "'");
    if (includeDepth_ >= kMaxIncludeDepth)
        throw ParseError(tok.loc, "include<> nested more than " + std::to_string(kMaxIncludeDepth) +
                                      " deep (recursive include?)");
    std::string text = loader_.read(path, tok.loc);
    auto file = std::make_shared<const std::string>(path);
    parseQuietly(path, [&] {
        Lexer lexer(std::move(text), file, &loader_.diag());
        // Textual inclusion: the included statements join the current scope
        Parser sub(lexer.tokenize(), loader_, root_, includeDepth_ + 1);
        sub.parseStatements(scope);
    });
}

void Parser::parseUse() {
    Token tok = toks_[pos_++];
    if (isFontFile(tok.text)) {
        loader_.registerFont(tok.text, dirOf(*tok.loc.file), tok.loc);
        return;
    }
    std::string path = loader_.resolve(tok.text, dirOf(*tok.loc.file));
    if (path.empty()) throw ParseError(tok.loc, "can't find used file '" + tok.text + "'");
    for (const auto &u : root_.uses)
        if (u.path == path) return;
    root_.uses.push_back({path, tok.loc});
    loader_.loadUsed(path, tok.loc);
}

ParameterList Parser::parseParameters() {
    ParameterList params;
    expect(TokenKind::LParen, "to open the parameter list");
    // parser.y `parameters optional_commas`: empty elements are skipped anywhere, even before
    // the first parameter and after the last (`m(,a,,b,)`, `f(,)`)
    skipCommas();
    while (!at(TokenKind::RParen)) {
        Token name = expect(TokenKind::Identifier, "as parameter name");
        Parameter p;
        p.name = Symbol::intern(name.text);
        p.loc = name.loc;
        if (accept(TokenKind::Assign)) p.defaultExpr = parseExpr();
        params.push_back(std::move(p));
        if (!skipCommas()) break;
    }
    expect(TokenKind::RParen, "to close the parameter list");
    return params;
}

ArgumentList Parser::parseArguments(TokenKind close) {
    // parser.y `arguments`: empty, or arguments joined by one or more commas, which may also
    // stand before the first one (`f(,,1)`); but every comma needs an argument after it, so
    // `f(1,)` and `f(,)` are errors in 2021.01. An empty list also ends at ';' (the empty
    // init of a C-style `for (; cond; next)`).
    ArgumentList args;
    if (at(close) || at(TokenKind::Semicolon)) return args;
    for (;;) {
        if (skipCommas() && at(close))
            throw ParseError(cur().loc, "syntax error: unexpected " + describeToken(cur()) +
                                            " after ',' (an argument list has no trailing comma)");
        Argument a;
        a.loc = cur().loc;
        if (at(TokenKind::Identifier) && peekTok().kind == TokenKind::Assign) {
            a.name = Symbol::intern(cur().text);
            pos_ += 2;
        }
        a.expr = parseExpr();
        args.push_back(std::move(a));
        if (!at(TokenKind::Comma)) return args;
    }
}

void Parser::parseModuleDef(Scope &scope) {
    SourceLoc loc = cur().loc;
    ++pos_;
    Token name = expect(TokenKind::Identifier, "as module name");
    auto def = std::make_shared<ModuleDef>();
    def->name = Symbol::intern(name.text);
    def->loc = loc;
    def->params = parseParameters();
    parseStatement(def->body);
    scope.modules[def->name] = std::move(def);
}

void Parser::parseFunctionDef(Scope &scope) {
    SourceLoc loc = cur().loc;
    ++pos_;
    Token name = expect(TokenKind::Identifier, "as function name");
    auto def = std::make_shared<FunctionDef>();
    def->name = Symbol::intern(name.text);
    def->loc = loc;
    def->params = parseParameters();
    expect(TokenKind::Assign, "after the function's parameter list");
    def->body = parseExpr();
    expect(TokenKind::Semicolon, "after the function definition");
    scope.functions[def->name] = std::move(def);
}

void Parser::parseAssignment(Scope &scope) {
    Token name = toks_[pos_];
    pos_ += 2;
    ExprPtr e = parseExpr();
    expect(TokenKind::Semicolon, "after the assignment");
    addAssignment(scope, Symbol::intern(name.text), std::move(e), name.loc, &loader_.diag());
}

std::unique_ptr<ModuleInstantiation> Parser::parseInstantiation() {
    NestingGuard guard(*this);
    auto inst = std::make_unique<ModuleInstantiation>();
    inst->loc = cur().loc;
    for (;;) {
        if (accept(TokenKind::Bang))
            inst->modifiers.root = true;
        else if (accept(TokenKind::Hash))
            inst->modifiers.highlight = true;
        else if (accept(TokenKind::Percent))
            inst->modifiers.background = true;
        else if (accept(TokenKind::Star))
            inst->modifiers.disabled = true;
        else
            break;
    }
    if (at(TokenKind::KwIf)) {
        inst->loc = cur().loc;
        ++pos_;
        inst->isIf = true;
        inst->name = Symbol::intern("if");
        expect(TokenKind::LParen, "after 'if'");
        Argument cond;
        cond.loc = cur().loc;
        cond.expr = parseExpr();
        inst->args.push_back(std::move(cond));
        expect(TokenKind::RParen, "to close the if condition");
        parseChildStatement(inst->children);
        if (accept(TokenKind::KwElse)) {
            inst->hasElse = true;
            parseChildStatement(inst->elseChildren);
        }
        return inst;
    }
    switch (cur().kind) {
        case TokenKind::Identifier:
        case TokenKind::KwFor:
        case TokenKind::KwLet:
        case TokenKind::KwAssert:
        case TokenKind::KwEcho:
            break;
        default:
            unexpected("where a statement was expected");
    }
    inst->loc = cur().loc;
    inst->name = Symbol::intern(cur().text);
    ++pos_;
    expect(TokenKind::LParen, "after the module name");
    inst->args = parseArguments(TokenKind::RParen);
    expect(TokenKind::RParen, "to close the argument list");
    parseChildStatement(inst->children);
    return inst;
}

void Parser::parseChildStatement(Scope &scope) {
    NestingGuard guard(*this);
    if (accept(TokenKind::Semicolon)) return;
    if (accept(TokenKind::LBrace)) {
        while (!accept(TokenKind::RBrace)) {
            switch (cur().kind) {
                case TokenKind::End:
                    expect(TokenKind::RBrace, "to close the child block");
                    break;
                case TokenKind::LBrace:
                case TokenKind::Semicolon:
                    parseChildStatement(scope);
                    break;
                case TokenKind::Include:
                    parseInclude(scope);
                    break;
                case TokenKind::Use:
                    parseUse();
                    break;
                case TokenKind::KwModule:
                case TokenKind::KwFunction:
                    unexpected("(definitions are not allowed inside a module's child block)");
                case TokenKind::Identifier:
                    if (peekTok().kind == TokenKind::Assign) {
                        parseAssignment(scope);
                        break;
                    }
                    [[fallthrough]];
                default:
                    scope.instantiations.push_back(parseInstantiation());
            }
        }
        return;
    }
    scope.instantiations.push_back(parseInstantiation());
}

ExprPtr Parser::parseWholeExpression() {
    ExprPtr e = parseExpr();
    if (!at(TokenKind::End)) unexpected("after the expression");
    return e;
}

ExprPtr Parser::parsePrefix(ExprKind kind) {
    auto e = std::make_unique<PrefixExpr>(kind, cur().loc);
    ++pos_;
    expect(TokenKind::LParen, "after the keyword");
    e->args = parseArguments(TokenKind::RParen);
    expect(TokenKind::RParen, "to close the argument list");
    return e;
}

ExprPtr Parser::parseExpr() {
    NestingGuard guard(*this);
    switch (cur().kind) {
        case TokenKind::KwFunction: {
            auto f = std::make_unique<FunctionLiteralExpr>(cur().loc);
            ++pos_;
            f->params = parseParameters();
            f->body = parseExpr();
            return f;
        }
        case TokenKind::KwLet: {
            ExprPtr e = parsePrefix(ExprKind::Let);
            static_cast<PrefixExpr &>(*e).body = parseExpr();
            return e;
        }
        case TokenKind::KwAssert:
        case TokenKind::KwEcho: {
            ExprPtr e = parsePrefix(at(TokenKind::KwAssert) ? ExprKind::Assert : ExprKind::Echo);
            // The body is optional (expr_or_empty)
            switch (cur().kind) {
                case TokenKind::Semicolon:
                case TokenKind::RParen:
                case TokenKind::RBracket:
                case TokenKind::Comma:
                case TokenKind::Colon:
                case TokenKind::RBrace:
                case TokenKind::End:
                    break;
                default:
                    static_cast<PrefixExpr &>(*e).body = parseExpr();
            }
            return e;
        }
        default:
            return parseTernary();
    }
}

ExprPtr Parser::parseTernary() {
    ExprPtr c = parseOr();
    if (!at(TokenKind::Question)) return c;
    auto t = std::make_unique<TernaryExpr>(cur().loc);
    ++pos_;
    t->cond = std::move(c);
    t->thenExpr = parseExpr();
    expect(TokenKind::Colon, "in the conditional expression");
    t->elseExpr = parseExpr();
    return t;
}

ExprPtr Parser::parseOr() {
    ChainGuard chain(*this);
    ExprPtr e = parseAnd();
    while (at(TokenKind::OrOr)) {
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(ExprKind::Or, BinaryOp::Add, std::move(e), parseAnd(),
                                         loc);
    }
    return e;
}

ExprPtr Parser::parseAnd() {
    ChainGuard chain(*this);
    ExprPtr e = parseEquality();
    while (at(TokenKind::AndAnd)) {
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(ExprKind::And, BinaryOp::Add, std::move(e),
                                         parseEquality(), loc);
    }
    return e;
}

ExprPtr Parser::parseEquality() {
    ChainGuard chain(*this);
    ExprPtr e = parseComparison();
    while (at(TokenKind::EqualEqual) || at(TokenKind::NotEqual)) {
        ExprKind k = at(TokenKind::EqualEqual) ? ExprKind::Equal : ExprKind::NotEqual;
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(k, BinaryOp::Add, std::move(e), parseComparison(), loc);
    }
    return e;
}

ExprPtr Parser::parseComparison() {
    ChainGuard chain(*this);
    ExprPtr e = parseAddition();
    for (;;) {
        BinaryOp op;
        switch (cur().kind) {
            case TokenKind::Less:
                op = BinaryOp::Less;
                break;
            case TokenKind::LessEqual:
                op = BinaryOp::LessEqual;
                break;
            case TokenKind::Greater:
                op = BinaryOp::Greater;
                break;
            case TokenKind::GreaterEqual:
                op = BinaryOp::GreaterEqual;
                break;
            default:
                return e;
        }
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(ExprKind::Binary, op, std::move(e), parseAddition(), loc);
    }
}

ExprPtr Parser::parseAddition() {
    ChainGuard chain(*this);
    ExprPtr e = parseMultiplication();
    while (at(TokenKind::Plus) || at(TokenKind::Minus)) {
        BinaryOp op = at(TokenKind::Plus) ? BinaryOp::Add : BinaryOp::Sub;
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(ExprKind::Binary, op, std::move(e), parseMultiplication(),
                                         loc);
    }
    return e;
}

ExprPtr Parser::parseMultiplication() {
    ChainGuard chain(*this);
    ExprPtr e = parseUnary();
    for (;;) {
        BinaryOp op;
        switch (cur().kind) {
            case TokenKind::Star:
                op = BinaryOp::Mul;
                break;
            case TokenKind::Slash:
                op = BinaryOp::Div;
                break;
            case TokenKind::Percent:
                op = BinaryOp::Mod;
                break;
            default:
                return e;
        }
        SourceLoc loc = cur().loc;
        ++pos_;
        chain.link(loc);
        e = std::make_unique<BinaryExpr>(ExprKind::Binary, op, std::move(e), parseUnary(), loc);
    }
}

ExprPtr Parser::parseUnary() {
    NestingGuard guard(*this);
    SourceLoc loc = cur().loc;
    if (accept(TokenKind::Minus)) {
        ExprPtr operand = parseUnary();
        // Fold negative number literals so `-1` is a constant
        if (operand->kind == ExprKind::Literal) {
            auto &lit = static_cast<LiteralExpr &>(*operand);
            if (lit.value.isNumber()) {
                lit.value = Value::number(-lit.value.toNumber());
                lit.loc = loc;
                return operand;
            }
        }
        return std::make_unique<UnaryExpr>(UnaryOp::Negate, std::move(operand), loc);
    }
    if (accept(TokenKind::Plus)) return parseUnary();  // parser.y: '+' unary is the operand
    if (accept(TokenKind::Bang))
        return std::make_unique<UnaryExpr>(UnaryOp::Not, parseUnary(), loc);
    return parseExponent();
}

ExprPtr Parser::parseExponent() {
    ExprPtr base = parsePostfix();
    if (!at(TokenKind::Caret)) return base;
    SourceLoc loc = cur().loc;
    ++pos_;
    // Right-associative, and the exponent may carry a sign: call '^' unary
    return std::make_unique<BinaryExpr>(ExprKind::Binary, BinaryOp::Pow, std::move(base),
                                        parseUnary(), loc);
}

ExprPtr Parser::parsePostfix() {
    ChainGuard chain(*this);
    ExprPtr e = parsePrimary();
    for (;;) {
        SourceLoc loc = cur().loc;
        if (at(TokenKind::LParen) || at(TokenKind::LBracket) || at(TokenKind::Dot)) chain.link(loc);
        if (accept(TokenKind::LParen)) {
            auto c = std::make_unique<CallExpr>(e->loc);
            c->callee = std::move(e);
            c->args = parseArguments(TokenKind::RParen);
            expect(TokenKind::RParen, "to close the argument list");
            e = std::move(c);
        } else if (accept(TokenKind::LBracket)) {
            auto i = std::make_unique<IndexExpr>(loc);
            i->object = std::move(e);
            i->index = parseExpr();
            expect(TokenKind::RBracket, "to close the index");
            e = std::move(i);
        } else if (accept(TokenKind::Dot)) {
            auto m = std::make_unique<MemberExpr>(loc);
            m->object = std::move(e);
            m->member = Symbol::intern(expect(TokenKind::Identifier, "after '.'").text);
            e = std::move(m);
        } else {
            return e;
        }
    }
}

ExprPtr Parser::parsePrimary() {
    const Token &t = cur();
    switch (t.kind) {
        case TokenKind::Number:
            ++pos_;
            return std::make_unique<LiteralExpr>(Value::number(t.number), t.loc);
        case TokenKind::String:
            ++pos_;
            return std::make_unique<LiteralExpr>(Value::string(t.text), t.loc);
        case TokenKind::KwTrue:
            ++pos_;
            return std::make_unique<LiteralExpr>(Value::boolean(true), t.loc);
        case TokenKind::KwFalse:
            ++pos_;
            return std::make_unique<LiteralExpr>(Value::boolean(false), t.loc);
        case TokenKind::KwUndef:
            ++pos_;
            return std::make_unique<LiteralExpr>(Value(), t.loc);
        case TokenKind::Identifier:
            ++pos_;
            return std::make_unique<IdentifierExpr>(Symbol::intern(t.text), t.loc);
        case TokenKind::LParen: {
            ++pos_;
            ExprPtr e = parseExpr();
            expect(TokenKind::RParen, "to close the parenthesis");
            return e;
        }
        case TokenKind::LBracket:
            return parseBracket();
        default:
            unexpected("where an expression was expected");
    }
}

ExprPtr Parser::parseElement() {
    NestingGuard guard(*this);
    SourceLoc loc = cur().loc;
    switch (cur().kind) {
        case TokenKind::KwFor: {
            ++pos_;
            expect(TokenKind::LParen, "after 'for'");
            ArgumentList first = parseArguments(TokenKind::RParen);
            if (accept(TokenKind::Semicolon)) {
                auto f = std::make_unique<LcForCExpr>(loc);
                f->init = std::move(first);
                f->cond = parseExpr();
                expect(TokenKind::Semicolon, "after the loop condition");
                f->update = parseArguments(TokenKind::RParen);
                expect(TokenKind::RParen, "to close the for header");
                f->body = parseElement();
                return f;
            }
            expect(TokenKind::RParen, "to close the for header");
            auto f = std::make_unique<LcForExpr>(loc);
            f->vars = std::move(first);
            f->body = parseElement();
            return f;
        }
        case TokenKind::KwEach: {
            ++pos_;
            auto e = std::make_unique<LcEachExpr>(loc);
            e->body = parseElement();
            return e;
        }
        case TokenKind::KwIf: {
            ++pos_;
            auto i = std::make_unique<LcIfExpr>(loc);
            expect(TokenKind::LParen, "after 'if'");
            i->cond = parseExpr();
            expect(TokenKind::RParen, "to close the if condition");
            i->thenExpr = parseElement();
            if (accept(TokenKind::KwElse)) i->elseExpr = parseElement();
            return i;
        }
        case TokenKind::KwLet: {
            // `let(...)` followed by a comprehension element is an LcLet, otherwise a let
            // expression
            ExprPtr e = parsePrefix(ExprKind::Let);
            auto &p = static_cast<PrefixExpr &>(*e);
            ExprPtr body = parseElement();
            if (body->isListComprehension()) {
                auto l = std::make_unique<LcLetExpr>(loc);
                l->args = std::move(p.args);
                l->body = std::move(body);
                return l;
            }
            p.body = std::move(body);
            return e;
        }
        case TokenKind::LParen: {
            TokenKind next = peekTok().kind;
            if (next == TokenKind::KwFor || next == TokenKind::KwEach || next == TokenKind::KwIf) {
                ++pos_;
                ExprPtr e = parseElement();
                expect(TokenKind::RParen, "to close the parenthesis");
                return e;
            }
            return parseExpr();
        }
        default:
            return parseExpr();
    }
}

ExprPtr Parser::parseBracket() {
    auto v = std::make_unique<VectorExpr>(cur().loc);
    ++pos_;
    // parser.y `'[' optional_commas ']'`: commas alone make an empty vector, but no comma may
    // come before a first element
    if (skipCommas() && !at(TokenKind::RBracket))
        throw ParseError(cur().loc, "syntax error: unexpected " + describeToken(cur()) +
                                        " after ',' (a vector's first element has no comma "
                                        "before it)");
    if (accept(TokenKind::RBracket)) {
        v->constant = std::make_unique<Value>(Value::vector(std::vector<Value>()));
        return v;
    }
    ExprPtr first = parseElement();
    if (!first->isListComprehension() && at(TokenKind::Colon)) {
        auto r = std::make_unique<RangeExpr>(v->loc);
        ++pos_;
        r->begin = std::move(first);
        ExprPtr second = parseExpr();
        if (accept(TokenKind::Colon)) {
            r->step = std::move(second);
            r->end = parseExpr();
        } else {
            r->end = std::move(second);
        }
        expect(TokenKind::RBracket, "to close the range");
        return r;
    }
    v->elements.push_back(std::move(first));
    // Repeated and trailing commas are empty elements, skipped
    while (skipCommas() && !at(TokenKind::RBracket)) v->elements.push_back(parseElement());
    expect(TokenKind::RBracket, "to close the vector");
    // Vectors of literals are built once
    bool allConstant = true;
    for (const auto &e : v->elements) {
        bool c = e->kind == ExprKind::Literal ||
                 (e->kind == ExprKind::Vector && static_cast<VectorExpr &>(*e).constant);
        if (!c) allConstant = false;
    }
    if (allConstant) {
        std::vector<Value> items;
        items.reserve(v->elements.size());
        for (const auto &e : v->elements)
            items.push_back(e->kind == ExprKind::Literal ? static_cast<LiteralExpr &>(*e).value
                                                         : *static_cast<VectorExpr &>(*e).constant);
        v->constant = std::make_unique<Value>(Value::vector(std::move(items)));
    }
    return v;
}

}  // namespace

void addAssignment(Scope &scope, Symbol name, ExprPtr expr, const SourceLoc &loc,
                   DiagnosticSink *diag, bool quiet) {
    for (auto &a : scope.assignments) {
        if (a.name != name) continue;
        // One slot per name: keep the first position, take the last expression
        if (!quiet && diag && a.loc.fileName() == loc.fileName())
            diag->warning(loc, name.str() + " was assigned on line " + std::to_string(a.loc.line) +
                                   " but was overwritten");
        a.expr = std::move(expr);
        return;
    }
    scope.assignments.push_back({name, std::move(expr), loc});
}

SourceLoader::SourceLoader(std::vector<std::string> libraryPaths, DiagnosticSink &diag)
    : libraryPaths_(std::move(libraryPaths)), diag_(diag) {}

std::string SourceLoader::resolve(const std::string &name, const std::string &fromDir) const {
    auto usable = [](const fs::path &p) {
        std::error_code ec;
        return fs::is_regular_file(p, ec);
    };
    fs::path n(name);
    if (n.is_absolute()) return usable(n) ? n.lexically_normal().string() : std::string();
    std::vector<std::string> dirs;
    dirs.push_back(fromDir);
    dirs.insert(dirs.end(), libraryPaths_.begin(), libraryPaths_.end());
    for (const auto &d : dirs) {
        if (d.empty()) continue;
        fs::path p = fs::path(d) / n;
        if (usable(p)) return p.lexically_normal().string();
    }
    return {};
}

void SourceLoader::registerFont(const std::string &name, const std::string &fromDir,
                                const SourceLoc &loc) {
    // OpenSCAD goes on without the font in both failure cases (its messages are unlocated)
    std::string path = resolve(name, fromDir);
    if (path.empty()) {
        diag_.warning(
            loc, "Can't open library '" + name + "': can't read font with path '" + name + "'");
        return;
    }
    // Through the input reader's checks: FreeType opens the file itself later, so it must
    // be a regular file (or a link to one) of at most a font's size
    try {
        checkInputFile(path, kMaxFontBytes);
    } catch (const InputFileError &e) {
        diag_.warning(loc, "Can't register font '" + path + "': " + e.what());
        return;
    }
    if (!hasFontSignature(path)) {
        diag_.warning(loc, "Can't register font '" + path + "': not a TrueType/OpenType file");
        return;
    }
    if (std::find(fontFiles_.begin(), fontFiles_.end(), path) == fontFiles_.end())
        fontFiles_.push_back(path);
}

std::string SourceLoader::read(const std::string &path, const SourceLoc &loc) const {
    // A file that is not named .scad may be anything (include </etc/shadow>): diagnostics
    // located in it never quote its lines. A link counts by what it leads to (link.scad ->
    // /etc/shadow).
    std::error_code ec;
    fs::path target = fs::weakly_canonical(path, ec);
    if (!isScadFile(path) || ec || !isScadFile(target.string())) markUnquotable(path);
    return readInputFileAt(path, loc, kMaxSourceBytes);
}

bool isScadFile(const std::string &path) {
    std::string ext = fs::path(path).extension().string();
    for (auto &c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".scad";
}

std::shared_ptr<SourceFile> SourceLoader::loadUsed(const std::string &path, const SourceLoc &loc) {
    auto it = used_.find(path);
    if (it != used_.end()) return it->second;
    auto file = std::make_shared<SourceFile>();
    file->path = path;
    used_[path] = file;
    std::string text = read(path, loc);
    auto name = std::make_shared<const std::string>(path);
    parseQuietly(path, [&] {
        Lexer lexer(std::move(text), name, &diag_);
        Parser parser(lexer.tokenize(), *this, *file, 0);
        parser.parseStatements(file->top);
    });
    return file;
}

std::vector<std::string> defaultLibraryPaths(const std::vector<std::string> &extra) {
    std::vector<std::string> paths = extra;
    if (const char *env = std::getenv("OPENSCADPATH")) {
        std::string s = env;
        size_t start = 0;
        while (start <= s.size()) {
            size_t colon = s.find(':', start);
            if (colon == std::string::npos) colon = s.size();
            if (colon > start) paths.push_back(s.substr(start, colon - start));
            start = colon + 1;
        }
    }
    if (*SCADRAY_LIBRARY_DIR) paths.push_back(SCADRAY_LIBRARY_DIR);
    paths.push_back(kOpenScadLibraryDir);
    return paths;
}

std::shared_ptr<SourceFile> parseSource(const std::string &text, const std::string &file,
                                        SourceLoader &loader) {
    auto root = std::make_shared<SourceFile>();
    root->path = file;
    auto name = std::make_shared<const std::string>(file);
    Lexer lexer(text, name, &loader.diag());
    Parser parser(lexer.tokenize(), loader, *root, 0);
    parser.parseStatements(root->top);
    return root;
}

ExprPtr parseExpressionText(const std::string &text, const std::string &file,
                            SourceLoader &loader) {
    SourceFile scratch;
    auto name = std::make_shared<const std::string>(file);
    Lexer lexer(text, name, &loader.diag());
    Parser parser(lexer.tokenize(), loader, scratch, 0);
    return parser.parseWholeExpression();
}

}  // namespace rt::scad
