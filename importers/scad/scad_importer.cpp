// SPDX-License-Identifier: MIT
// importScad: parse and evaluate on a thread with a large stack (kLargeStackBytes), so deep
// recursion ends in a located EvalError rather than a stack overflow.
#include "importers/scad/scad_importer.h"

#include <exception>
#include <functional>

#include "core/ir/diagnostics.h"
#include "core/system/large_stack.h"
#include "importers/scad/lang/evaluator.h"
#include "importers/scad/lang/lexer.h"
#include "importers/scad/lang/parser.h"

namespace rt::scad {

namespace {

bool isIdentifier(const std::string &s) {
    if (s.empty()) return false;
    size_t i = s[0] == '$' ? 1 : 0;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i)
        if (!std::isalnum(static_cast<unsigned char>(s[i])) && s[i] != '_') return false;
    return true;
}

}  // namespace

ir::Scene importScadSource(const std::string &source, const std::string &virtualPath,
                           DiagnosticSink &diag, const ImportOptions &opts) {
    ir::Scene scene;
    runWithStack(kLargeStackBytes, [&] {
        SourceLoader loader(defaultLibraryPaths(opts.libraryPaths), diag);
        std::shared_ptr<SourceFile> file = parseSource(source, virtualPath, loader);
        // -D name=expr: appended to the main file's top-level assignments, replacing the
        // expression of an existing one in place without a warning (OpenSCAD's -D)
        auto defineFile = std::make_shared<const std::string>("<-D>");
        for (const auto &[name, expr] : opts.defines) {
            SourceLoc loc(defineFile, 1, 1);
            if (!isIdentifier(name))
                throw ParseError(loc, "-D: '" + name + "' is not a variable name");
            ExprPtr e = parseExpressionText(expr, "<-D " + name + ">", loader);
            addAssignment(file->top, Symbol::intern(name), std::move(e), loc, &diag, true);
        }
        EvalLimits limits;
        limits.maxSteps = opts.maxSteps;
        limits.maxLiveElements = opts.maxElements;
        limits.maxGeometryWork = opts.maxGeometry;
        Evaluator evaluator(diag, limits);
        evaluator.setProgress(opts.progress);
        evaluator.setTime(opts.time);
        scene = evaluator.evaluate(*file, loader);
    });
    return scene;
}

ir::Scene importScad(const std::string &path, DiagnosticSink &diag, const ImportOptions &opts) {
    SourceLoc loc(std::make_shared<const std::string>(path), 0, 0);
    return importScadSource(readInputFileAt(path, loc, kMaxSourceBytes), path, diag, opts);
}

}  // namespace rt::scad
