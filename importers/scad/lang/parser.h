// SPDX-License-Identifier: MIT
// Recursive-descent parser for OpenSCAD 2021.01 with include<> splicing and use<> loading.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/ir/diagnostics.h"
#include "importers/scad/lang/ast.h"
#include "importers/scad/lang/token.h"

namespace rt::scad {

/// Largest source file read (main file, include<> or use<>): 256 MiB.
constexpr uint64_t kMaxSourceBytes = uint64_t{256} << 20;
/// Largest font file `use <font.ttf>` registers (the largest CJK collections are ~100 MiB).
constexpr uint64_t kMaxFontBytes = uint64_t{256} << 20;

/// True when `path` ends in .scad (any case); other files are not quoted in diagnostics.
bool isScadFile(const std::string &path);

/// Finds, reads and caches source files for include<> and use<>.
class SourceLoader {
  public:
    /// `libraryPaths` are searched after the including file's folder, in order.
    SourceLoader(std::vector<std::string> libraryPaths, DiagnosticSink &diag);

    /// Resolves `name` as written in include<>/use<> against `fromDir`, then the library
    /// paths; empty when no readable file exists.
    std::string resolve(const std::string &name, const std::string &fromDir) const;
    /// Reads a whole regular file of at most kMaxSourceBytes; throws ParseError at `loc` when it
    /// cannot be read. A file not named .scad is marked unquotable (markUnquotable).
    std::string read(const std::string &path, const SourceLoc &loc) const;

    /// Parses a used library once (by path) and returns it; cycles return the file being parsed.
    std::shared_ptr<SourceFile> loadUsed(const std::string &path, const SourceLoc &loc);
    const std::map<std::string, std::shared_ptr<SourceFile>> &usedFiles() const { return used_; }

    /// use<x.ttf>/use<x.otf>: records the font file for text(), resolved like a library;
    /// a missing or unreadable font is a warning at `loc`, as OpenSCAD goes on without it.
    void registerFont(const std::string &name, const std::string &fromDir, const SourceLoc &loc);
    /// Registered font files, in order of first use<>.
    const std::vector<std::string> &fontFiles() const { return fontFiles_; }

    const std::vector<std::string> &libraryPaths() const { return libraryPaths_; }
    DiagnosticSink &diag() { return diag_; }

  private:
    std::vector<std::string> libraryPaths_;
    DiagnosticSink &diag_;
    std::map<std::string, std::shared_ptr<SourceFile>> used_;
    std::vector<std::string> fontFiles_;
};

/// Search path of include<>/use<> after the including file's folder: the options' folders,
/// then $OPENSCADPATH (colon-separated), then scadray's library folder, then OpenSCAD's.
std::vector<std::string> defaultLibraryPaths(const std::vector<std::string> &extra);

/// Parses a whole file's text. `file` is its path as shown in diagnostics and the anchor of
/// relative include<>/use<> lookups.
std::shared_ptr<SourceFile> parseSource(const std::string &text, const std::string &file,
                                        SourceLoader &loader);

/// Parses one expression (for -D overrides); throws ParseError on trailing text.
ExprPtr parseExpressionText(const std::string &text, const std::string &file, SourceLoader &loader);

/// Adds `name = expr` to a scope with OpenSCAD's one-slot-per-name rule; warns when an
/// assignment of the same file is overwritten unless `quiet`.
void addAssignment(Scope &scope, Symbol name, ExprPtr expr, const SourceLoc &loc,
                   DiagnosticSink *diag, bool quiet = false);

}  // namespace rt::scad
