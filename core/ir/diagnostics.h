// SPDX-License-Identifier: MIT
// Located diagnostics: the sink collecting warnings, and the exceptions importers throw for fatal
// errors.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/ir/source_loc.h"

namespace rt {

enum class Severity { Note, Warning, Error };

struct Diagnostic {
    Severity severity = Severity::Warning;
    SourceLoc loc;
    std::string message;
};

/// "file:line:col: warning: message", followed by the source line and a caret under the column
/// when the file is a readable regular file. The excerpt costs O(1) per call however long the
/// line: the line starts of the last file excerpted are indexed once and only a window around
/// the column is read.
std::string formatDiagnostic(const Diagnostic &d, bool withExcerpt = true);

/// Warnings of one kind (the same message once its digits are ignored) beyond this many are
/// only counted: neither kept nor passed to the listener. DiagnosticSink::summary() names them.
constexpr int kWarningsShownPerKind = 5;
/// At most this many diagnostics are kept (all()); later ones are only counted.
constexpr size_t kMaxKeptDiagnostics = 1000;
/// At most this many kinds of warning are told apart; further kinds share one count.
constexpr size_t kMaxWarningKinds = 1000;
/// Marks a file whose lines formatDiagnostic never quotes: one a program only named (an
/// include<> target that is not a .scad file), which may hold anything. Its locations are
/// still printed. Thread-safe.
void markUnquotable(const std::string &path);

/// Collects non-fatal diagnostics; an optional listener sees each one as it is reported
/// (the CLI prints them immediately). Memory is bounded whatever a hostile input reports:
/// repeated warnings of one kind are counted after the first kWarningsShownPerKind. Notes
/// (echo() output) all reach the listener; like every diagnostic, only the first
/// kMaxKeptDiagnostics are kept.
class DiagnosticSink {
  public:
    using Listener = std::function<void(const Diagnostic &)>;

    void setListener(Listener l) { listener_ = std::move(l); }
    void report(Severity s, const SourceLoc &loc, std::string message);
    void warning(const SourceLoc &loc, std::string message) {
        report(Severity::Warning, loc, std::move(message));
    }
    void note(const SourceLoc &loc, std::string message) {
        report(Severity::Note, loc, std::move(message));
    }
    /// The diagnostics kept: those the listener saw, up to kMaxKeptDiagnostics.
    const std::vector<Diagnostic> &all() const { return diags_; }
    /// Every diagnostic of this severity reported, kept or only counted.
    int count(Severity s) const;
    /// Number of diagnostics whose message contains the given text (tests): the kept ones,
    /// plus the warnings not kept of each kind whose first message contains it.
    int countContaining(const std::string &text) const;
    /// Warnings reported but not passed to the listener.
    int64_t suppressed() const { return suppressed_; }
    /// One line per kind with counted repeats, in order of first appearance:
    /// "N more warnings like: file:line:col: message" (empty when nothing was held back).
    std::vector<std::string> summary() const;
    /// The kind of a warning: its message with every run of digits read as one '#'.
    static std::string kindOf(const std::string &message);

  private:
    struct Kind {
        std::string key;
        Diagnostic first;
        int64_t count = 0;
        int64_t kept = 0;  ///< of them in diags_
    };
    Kind &kindFor(const std::string &message);

    std::vector<Diagnostic> diags_;
    std::vector<Kind> kinds_;  ///< in order of first appearance
    std::unordered_map<std::string, size_t> kindIndex_;
    Kind overflowKind_;  ///< every kind past kMaxWarningKinds
    int64_t counts_[3] = {0, 0, 0};
    int64_t suppressed_ = 0;
    Listener listener_;
};

/// A fatal, located problem in an input file. The CLI prints it and exits non-zero.
class LocatedError : public std::runtime_error {
  public:
    LocatedError(SourceLoc loc, const std::string &message)
        : std::runtime_error(message), loc_(std::move(loc)) {}
    const SourceLoc &loc() const { return loc_; }
    Diagnostic diagnostic() const { return {Severity::Error, loc_, what()}; }

  private:
    SourceLoc loc_;
};

class ParseError : public LocatedError {
    using LocatedError::LocatedError;
};
class EvalError : public LocatedError {
    using LocatedError::LocatedError;
};
/// A scene that is well-formed but cannot be rendered or exported (e.g. a singular transform).
class SceneError : public LocatedError {
    using LocatedError::LocatedError;
};

/// readInputFile (core/system/input_file.h) with its refusal as a ParseError at `loc`: the
/// reader of every file an importer opens on behalf of its input.
std::string readInputFileAt(const std::string &path, const SourceLoc &loc, uint64_t maxBytes);

}  // namespace rt
