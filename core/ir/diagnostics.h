// SPDX-License-Identifier: MIT
// Located diagnostics: the sink collecting warnings, and the exceptions importers throw for fatal errors.
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
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
/// when the file can be read.
std::string formatDiagnostic(const Diagnostic &d, bool withExcerpt = true);

/// Marks a file whose lines formatDiagnostic never quotes: one a program only named (an
/// include<> target that is not a .scad file), which may hold anything. Its locations are
/// still printed. Thread-safe.
void markUnquotable(const std::string &path);

/// Collects non-fatal diagnostics; an optional listener sees each one as it is reported
/// (the CLI prints them immediately).
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
    const std::vector<Diagnostic> &all() const { return diags_; }
    int count(Severity s) const;
    /// Number of diagnostics whose message contains the given text (tests).
    int countContaining(const std::string &text) const;

  private:
    std::vector<Diagnostic> diags_;
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

}  // namespace rt
