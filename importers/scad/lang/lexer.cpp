// SPDX-License-Identifier: MIT
// OpenSCAD lexer: token rules follow 2021.01's lexer.l (longest match, numbers win ties).
#include "importers/scad/lang/lexer.h"

#include <cctype>
#include <cstdlib>

#include "core/system/utf8.h"

namespace rt::scad {

namespace {

bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
int hexValue(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/// A byte of U+00A0 no-break space in UTF-8 (C2 A0) or Latin-1 (A0).
bool isNoBreakSpaceByte(char c) {
    return static_cast<unsigned char>(c) == 0xC2 || static_cast<unsigned char>(c) == 0xA0;
}

/// Length of the run of UTF-8 sequences starting at `s[pos]` as lexer.l's `{UNICODE}+`
/// matches them (lead bytes C2-DF, E0-EF, F0-F4 with their continuation bytes 80-BF).
size_t utf8RunLength(const std::string &s, size_t pos) {
    auto continuation = [&](size_t i) {
        return i < s.size() && (static_cast<unsigned char>(s[i]) & 0xC0) == 0x80;
    };
    size_t p = pos;
    while (p < s.size()) {
        auto lead = static_cast<unsigned char>(s[p]);
        size_t n = lead >= 0xC2 && lead <= 0xDF   ? 2
                   : lead >= 0xE0 && lead <= 0xEF ? 3
                   : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                  : 0;
        if (n == 0) break;
        size_t k = 1;
        while (k < n && continuation(p + k)) ++k;
        if (k < n) break;
        p += n;
    }
    return p - pos;
}

struct Keyword {
    const char *text;
    TokenKind kind;
};
constexpr Keyword kKeywords[] = {
    {"module", TokenKind::KwModule}, {"function", TokenKind::KwFunction},
    {"if", TokenKind::KwIf},         {"else", TokenKind::KwElse},
    {"for", TokenKind::KwFor},       {"let", TokenKind::KwLet},
    {"assert", TokenKind::KwAssert}, {"echo", TokenKind::KwEcho},
    {"each", TokenKind::KwEach},     {"true", TokenKind::KwTrue},
    {"false", TokenKind::KwFalse},   {"undef", TokenKind::KwUndef},
};

}  // namespace

const char *tokenKindName(TokenKind kind) {
    switch (kind) {
        case TokenKind::End:
            return "end of file";
        case TokenKind::Identifier:
            return "identifier";
        case TokenKind::Number:
            return "number";
        case TokenKind::String:
            return "string";
        case TokenKind::Include:
            return "include";
        case TokenKind::Use:
            return "use";
        case TokenKind::KwModule:
            return "'module'";
        case TokenKind::KwFunction:
            return "'function'";
        case TokenKind::KwIf:
            return "'if'";
        case TokenKind::KwElse:
            return "'else'";
        case TokenKind::KwFor:
            return "'for'";
        case TokenKind::KwLet:
            return "'let'";
        case TokenKind::KwAssert:
            return "'assert'";
        case TokenKind::KwEcho:
            return "'echo'";
        case TokenKind::KwEach:
            return "'each'";
        case TokenKind::KwTrue:
            return "'true'";
        case TokenKind::KwFalse:
            return "'false'";
        case TokenKind::KwUndef:
            return "'undef'";
        case TokenKind::LParen:
            return "'('";
        case TokenKind::RParen:
            return "')'";
        case TokenKind::LBracket:
            return "'['";
        case TokenKind::RBracket:
            return "']'";
        case TokenKind::LBrace:
            return "'{'";
        case TokenKind::RBrace:
            return "'}'";
        case TokenKind::Semicolon:
            return "';'";
        case TokenKind::Comma:
            return "','";
        case TokenKind::Dot:
            return "'.'";
        case TokenKind::Colon:
            return "':'";
        case TokenKind::Question:
            return "'?'";
        case TokenKind::Assign:
            return "'='";
        case TokenKind::Plus:
            return "'+'";
        case TokenKind::Minus:
            return "'-'";
        case TokenKind::Star:
            return "'*'";
        case TokenKind::Slash:
            return "'/'";
        case TokenKind::Percent:
            return "'%'";
        case TokenKind::Caret:
            return "'^'";
        case TokenKind::Bang:
            return "'!'";
        case TokenKind::Hash:
            return "'#'";
        case TokenKind::Less:
            return "'<'";
        case TokenKind::LessEqual:
            return "'<='";
        case TokenKind::Greater:
            return "'>'";
        case TokenKind::GreaterEqual:
            return "'>='";
        case TokenKind::EqualEqual:
            return "'=='";
        case TokenKind::NotEqual:
            return "'!='";
        case TokenKind::AndAnd:
            return "'&&'";
        case TokenKind::OrOr:
            return "'||'";
    }
    return "token";
}

std::string describeToken(const Token &tok) {
    switch (tok.kind) {
        case TokenKind::End:
            return "end of file";
        case TokenKind::String:
            return "string \"" + tok.text + "\"";
        case TokenKind::Include:
            return "include <" + tok.text + ">";
        case TokenKind::Use:
            return "use <" + tok.text + ">";
        default:
            return "'" + tok.text + "'";
    }
}

Lexer::Lexer(std::string source, std::shared_ptr<const std::string> file, DiagnosticSink *diag)
    : src_(std::move(source)), file_(std::move(file)), diag_(diag) {}

char Lexer::peek(size_t ahead) const {
    return pos_ + ahead < src_.size() ? src_[pos_ + ahead] : '\0';
}

void Lexer::advance(size_t n) {
    for (size_t i = 0; i < n && pos_ < src_.size(); ++i) {
        if (src_[pos_] == '\n') {
            ++line_;
            col_ = 1;
        } else {
            ++col_;
        }
        ++pos_;
    }
}

void Lexer::skipSpaceAndComments() {
    for (;;) {
        char c = peek();
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
            advance();
        } else if (isNoBreakSpaceByte(c)) {
            // lexer.l `[\xc2\xa0]+`: any run of the bytes C2 and A0 is white space (so UTF-8
            // and Latin-1 no-break spaces both are), unless the longer match of `{UNICODE}+`,
            // an error token, wins; lexOperator then reports the character.
            size_t run = 1;
            while (isNoBreakSpaceByte(peek(run))) ++run;
            if (utf8RunLength(src_, pos_) > run) return;
            advance(run);
        } else if (c == '/' && peek(1) == '/') {
            while (pos_ < src_.size() && peek() != '\n') advance();
        } else if (c == '/' && peek(1) == '*') {
            SourceLoc start = here();
            advance(2);
            while (pos_ < src_.size() && !(peek() == '*' && peek(1) == '/')) advance();
            if (pos_ >= src_.size()) throw ParseError(start, "unterminated comment");
            advance(2);
        } else {
            return;
        }
    }
}

std::vector<Token> Lexer::tokenize() {
    std::vector<Token> out;
    // The UTF-8 byte order mark is not part of the program
    if (src_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;
    for (;;) {
        skipSpaceAndComments();
        if (pos_ >= src_.size()) {
            Token end;
            end.kind = TokenKind::End;
            end.loc = here();
            out.push_back(std::move(end));
            return out;
        }
        char c = peek();
        Token tok;
        if (c == '"') {
            tok = lexString();
        } else if (isIdentChar(c) || c == '$' || (c == '.' && isDigit(peek(1)))) {
            if (!lexIncludeOrUse(tok)) tok = lexNumberOrIdentifier();
        } else {
            tok = lexOperator();
        }
        out.push_back(std::move(tok));
    }
}

bool Lexer::lexIncludeOrUse(Token &tok) {
    // `include` / `use` followed by optional whitespace and `<path>` (lexer.l includes this
    // in one rule, so `include<f>` and `use  <f>` both work).
    TokenKind kind;
    size_t len;
    if (src_.compare(pos_, 7, "include") == 0) {
        kind = TokenKind::Include;
        len = 7;
    } else if (src_.compare(pos_, 3, "use") == 0) {
        kind = TokenKind::Use;
        len = 3;
    } else {
        return false;
    }
    if (isIdentChar(peek(len))) return false;
    size_t p = pos_ + len;
    while (p < src_.size() &&
           (src_[p] == ' ' || src_[p] == '\t' || src_[p] == '\r' || src_[p] == '\n'))
        ++p;
    if (p >= src_.size() || src_[p] != '<') return false;
    tok.kind = kind;
    tok.loc = here();
    advance(p + 1 - pos_);
    std::string path;
    while (pos_ < src_.size() && peek() != '>' && peek() != '\n') {
        path += peek();
        advance();
    }
    if (peek() != '>')
        throw ParseError(tok.loc, std::string("unterminated ") +
                                      (kind == TokenKind::Include ? "include" : "use") +
                                      " path: missing '>'");
    advance();
    tok.text = path;
    return true;
}

Token Lexer::lexNumberOrIdentifier() {
    Token tok;
    tok.loc = here();
    if (peek() == '$') {
        size_t n = 1;
        while (isIdentChar(peek(n))) ++n;
        if (n == 1) throw ParseError(tok.loc, "'$' must be followed by a name");
        tok.kind = TokenKind::Identifier;
        tok.text = src_.substr(pos_, n);
        advance(n);
        return tok;
    }
    // Length of the number rule: D+ E? | D* '.' D+ E? | D+ '.' D* E?
    size_t n = 0;
    while (isDigit(peek(n))) ++n;
    size_t intDigits = n;
    if (peek(n) == '.' && (intDigits > 0 || isDigit(peek(n + 1)))) {
        ++n;
        while (isDigit(peek(n))) ++n;
    }
    if (n > 0 && (peek(n) == 'e' || peek(n) == 'E')) {
        size_t e = n + 1;
        if (peek(e) == '+' || peek(e) == '-') ++e;
        if (isDigit(peek(e))) {
            while (isDigit(peek(e))) ++e;
            n = e;
        }
    }
    // Length of the identifier rule [A-Za-z0-9_]+
    size_t idLen = 0;
    while (isIdentChar(peek(idLen))) ++idLen;
    if (n > 0 && n >= idLen) {
        tok.kind = TokenKind::Number;
        tok.text = src_.substr(pos_, n);
        tok.number = std::strtod(tok.text.c_str(), nullptr);
        advance(n);
        return tok;
    }
    tok.kind = TokenKind::Identifier;
    tok.text = src_.substr(pos_, idLen);
    advance(idLen);
    for (const auto &kw : kKeywords)
        if (tok.text == kw.text) tok.kind = kw.kind;
    return tok;
}

Token Lexer::lexString() {
    Token tok;
    tok.kind = TokenKind::String;
    tok.loc = here();
    advance();  // opening quote
    std::string s;
    for (;;) {
        if (pos_ >= src_.size()) throw ParseError(tok.loc, "unterminated string");
        char c = peek();
        if (c == '"') {
            advance();
            break;
        }
        if (c == '\n') {
            // lexer.l drops raw newlines inside strings
            advance();
            continue;
        }
        if (c != '\\') {
            s += c;
            advance();
            continue;
        }
        SourceLoc escLoc = here();
        char e = peek(1);
        if (e == 'n' || e == 't' || e == 'r' || e == '\\' || e == '"') {
            s += e == 'n' ? '\n' : e == 't' ? '\t' : e == 'r' ? '\r' : e;
            advance(2);
        } else if (e == 'x' && peek(2) >= '0' && peek(2) <= '7' && hexValue(peek(3)) >= 0) {
            s += static_cast<char>((peek(2) - '0') * 16 + hexValue(peek(3)));
            advance(4);
        } else if (e == 'u' || e == 'U') {
            int digits = e == 'u' ? 4 : 6;
            unsigned cp = 0;
            bool ok = true;
            for (int i = 0; i < digits; ++i) {
                int h = hexValue(peek(2 + i));
                if (h < 0) ok = false;
                cp = cp * 16 + static_cast<unsigned>(h < 0 ? 0 : h);
            }
            if (ok && cp <= 0x10FFFF && !(cp >= 0xD800 && cp <= 0xDFFF) && cp != 0) {
                appendUtf8(s, cp);
                advance(2 + digits);
            } else {
                if (diag_) diag_->warning(escLoc, "invalid \\" + std::string(1, e) + " escape");
                advance(1);
            }
        } else {
            // OpenSCAD's lexer drops the backslash of an unknown escape
            if (diag_) diag_->warning(escLoc, std::string("unknown escape sequence '\\") + e + "'");
            advance(1);
        }
    }
    tok.text = std::move(s);
    return tok;
}

Token Lexer::lexOperator() {
    Token tok;
    tok.loc = here();
    char c = peek(), d = peek(1);
    auto two = [&](TokenKind k) {
        tok.kind = k;
        tok.text = src_.substr(pos_, 2);
        advance(2);
        return tok;
    };
    if (c == '<' && d == '=') return two(TokenKind::LessEqual);
    if (c == '>' && d == '=') return two(TokenKind::GreaterEqual);
    if (c == '=' && d == '=') return two(TokenKind::EqualEqual);
    if (c == '!' && d == '=') return two(TokenKind::NotEqual);
    if (c == '&' && d == '&') return two(TokenKind::AndAnd);
    if (c == '|' && d == '|') return two(TokenKind::OrOr);
    TokenKind k;
    switch (c) {
        case '(':
            k = TokenKind::LParen;
            break;
        case ')':
            k = TokenKind::RParen;
            break;
        case '[':
            k = TokenKind::LBracket;
            break;
        case ']':
            k = TokenKind::RBracket;
            break;
        case '{':
            k = TokenKind::LBrace;
            break;
        case '}':
            k = TokenKind::RBrace;
            break;
        case ';':
            k = TokenKind::Semicolon;
            break;
        case ',':
            k = TokenKind::Comma;
            break;
        case '.':
            k = TokenKind::Dot;
            break;
        case ':':
            k = TokenKind::Colon;
            break;
        case '?':
            k = TokenKind::Question;
            break;
        case '=':
            k = TokenKind::Assign;
            break;
        case '+':
            k = TokenKind::Plus;
            break;
        case '-':
            k = TokenKind::Minus;
            break;
        case '*':
            k = TokenKind::Star;
            break;
        case '/':
            k = TokenKind::Slash;
            break;
        case '%':
            k = TokenKind::Percent;
            break;
        case '^':
            k = TokenKind::Caret;
            break;
        case '!':
            k = TokenKind::Bang;
            break;
        case '#':
            k = TokenKind::Hash;
            break;
        case '<':
            k = TokenKind::Less;
            break;
        case '>':
            k = TokenKind::Greater;
            break;
        default: {
            std::string shown;
            unsigned char u = static_cast<unsigned char>(c);
            if (u < 0x20 || u >= 0x7F) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\x%02X", u);
                shown = buf;
            } else {
                shown = std::string(1, c);
            }
            throw ParseError(tok.loc, "unexpected character '" + shown + "'");
        }
    }
    tok.kind = k;
    tok.text = std::string(1, c);
    advance();
    return tok;
}

}  // namespace rt::scad
