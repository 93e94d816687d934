// SPDX-License-Identifier: MIT
// The names the language resolves to builtin modules and functions, and their entry points.
#pragma once

#include <span>
#include <unordered_map>
#include <vector>

#include "core/ir/node.h"
#include "importers/scad/lang/ast.h"
#include "importers/scad/lang/environment.h"

namespace rt::scad {

class Evaluator;

/// A builtin module: the node its instantiation `inst` makes in frame `f` (null for nothing).
using BuiltinModule = ir::NodePtr (*)(Evaluator &ev, const ModuleInstantiation &inst,
                                      const FramePtr &f);
/// A builtin function over its evaluated positional arguments, as OpenSCAD passes them.
using BuiltinFunction = Value (*)(Evaluator &ev, const std::vector<Value> &args,
                                  const SourceLoc &loc);
/// A builtin function that reads its arguments unevaluated (by name, or an identifier as it
/// is written) in the caller's frame `f`.
using BuiltinRawFunction = Value (*)(Evaluator &ev, const ArgumentList &args, const FramePtr &f,
                                     const SourceLoc &loc);
/// A pass of the builtins over the whole evaluated scene (Evaluator::evaluate says when).
using BuiltinScenePass = void (*)(Evaluator &ev, const SourceFile &main);

struct BuiltinModuleEntry {
    const char *name;
    BuiltinModule module;
    /// scadray.scad declares the module as an empty stub for OpenSCAD: the builtin replaces
    /// that stub, and a call without the library warns that OpenSCAD will ignore it.
    bool scadrayLibraryStub = false;
};

struct BuiltinFunctionEntry {
    const char *name;
    BuiltinFunction function = nullptr;  ///< used when `raw` is null
    BuiltinRawFunction raw = nullptr;
};

/// What one family of builtins contributes (builtins/families.h).
struct BuiltinFamily {
    std::span<const BuiltinModuleEntry> modules;
    std::span<const BuiltinFunctionEntry> functions;
};

/// Every builtin by name, composed once from the families.
class BuiltinTable {
  public:
    explicit BuiltinTable(std::span<const BuiltinFamily> families);

    const BuiltinModuleEntry *findModule(Symbol name) const {
        auto it = modules_.find(name);
        return it == modules_.end() ? nullptr : it->second;
    }
    const BuiltinFunctionEntry *findFunction(Symbol name) const {
        auto it = functions_.find(name);
        return it == functions_.end() ? nullptr : it->second;
    }

    /// Run on the instantiated node tree, before its depth is checked.
    std::vector<BuiltinScenePass> treePasses;
    /// Run last, on the finished scene.
    std::vector<BuiltinScenePass> scenePasses;

  private:
    std::unordered_map<Symbol, const BuiltinModuleEntry *, SymbolHash> modules_;
    std::unordered_map<Symbol, const BuiltinFunctionEntry *, SymbolHash> functions_;
};

/// The composed table of all builtins (importers/scad/builtins/builtin_list.cpp): the
/// evaluator finds every builtin name here and names none itself.
const BuiltinTable &builtinTable();

}  // namespace rt::scad
