// SPDX-License-Identifier: MIT
// Diagnostic formatting with a source excerpt, and the collecting sink.
#include "core/ir/diagnostics.h"

#include <algorithm>
#include <fstream>
#include <mutex>
#include <set>

namespace rt {

const std::string &SourceLoc::fileName() const {
    static const std::string kUnknown = "<unknown>";
    return file ? *file : kUnknown;
}

std::string SourceLoc::toString() const {
    if (!file) return "<unknown>";
    std::string s = *file;
    if (line > 0) {
        s += ":" + std::to_string(line);
        if (col > 0) s += ":" + std::to_string(col);
    }
    return s;
}

namespace {

const char *severityName(Severity s) {
    switch (s) {
        case Severity::Note: return "note";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "error";
}

/// Reads line `line` (1-based) of `path`; empty when unreadable.
std::string readSourceLine(const std::string &path, int line) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::string text;
    for (int i = 1; std::getline(in, text); ++i)
        if (i == line) {
            if (!text.empty() && text.back() == '\r') text.pop_back();
            return text;
        }
    return {};
}

std::mutex unquotableMutex;
std::set<std::string> &unquotable() {
    static std::set<std::string> paths;
    return paths;
}

bool isUnquotable(const std::string &path) {
    std::lock_guard<std::mutex> lock(unquotableMutex);
    return unquotable().count(path) > 0;
}

}  // namespace

void markUnquotable(const std::string &path) {
    std::lock_guard<std::mutex> lock(unquotableMutex);
    unquotable().insert(path);
}

std::string formatDiagnostic(const Diagnostic &d, bool withExcerpt) {
    // A diagnostic about the scene as a whole has no location to print
    std::string out = (d.loc.file ? d.loc.toString() + ": " : std::string()) +
                      severityName(d.severity) + ": " + d.message;
    if (!withExcerpt || !d.loc.isValid() || isUnquotable(*d.loc.file)) return out;
    std::string src = readSourceLine(*d.loc.file, d.loc.line);
    if (src.empty()) return out;
    // Long lines (minified JSON) are shown as a window around the column
    constexpr int kContext = 60;
    int col = std::max(d.loc.col, 1);
    int first = std::max(1, col - kContext);
    int last = std::min(static_cast<int>(src.size()), col + kContext);
    std::string lead = first > 1 ? "..." : "";
    std::string tail = last < static_cast<int>(src.size()) ? "..." : "";
    std::string window = src.substr(static_cast<size_t>(first - 1),
                                    static_cast<size_t>(std::max(0, last - first + 1)));
    out += "\n    " + lead + window + tail + "\n    " + std::string(lead.size(), ' ');
    // Keep tabs so the caret lines up under the offending text
    for (int i = first; i < col && i - 1 < static_cast<int>(src.size()); ++i)
        out += src[static_cast<size_t>(i - 1)] == '\t' ? '\t' : ' ';
    out += "^";
    return out;
}

void DiagnosticSink::report(Severity s, const SourceLoc &loc, std::string message) {
    diags_.push_back({s, loc, std::move(message)});
    if (listener_) listener_(diags_.back());
}

int DiagnosticSink::count(Severity s) const {
    int n = 0;
    for (const auto &d : diags_) n += d.severity == s;
    return n;
}

int DiagnosticSink::countContaining(const std::string &text) const {
    int n = 0;
    for (const auto &d : diags_) n += d.message.find(text) != std::string::npos;
    return n;
}

}  // namespace rt
