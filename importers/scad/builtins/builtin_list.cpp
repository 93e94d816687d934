// SPDX-License-Identifier: MIT
// The one list of builtin families the evaluator's table is composed from.
#include "importers/scad/builtins/families.h"

namespace rt::scad {

BuiltinTable::BuiltinTable(std::span<const BuiltinFamily> families) {
    for (const BuiltinFamily &family : families) {
        for (const BuiltinModuleEntry &m : family.modules) modules_[Symbol::intern(m.name)] = &m;
        for (const BuiltinFunctionEntry &f : family.functions)
            functions_[Symbol::intern(f.name)] = &f;
    }
}

const BuiltinTable &builtinTable() {
    // An explicit list rather than self-registration from each family file: which families
    // exist, and in what order, is visible in one place; the table is built on first use, with
    // no dependence on the order of static initialisation; and the linker cannot drop a family
    // whose file nothing else refers to.
    static const BuiltinTable kTable = [] {
        const BuiltinFamily families[] = {
            primitives3dBuiltins(), transformBuiltins(),      booleanBuiltins(),
            shape2dBuiltins(),      extrusionBuiltins(),      hullMinkowskiBuiltins(),
            textBuiltins(),         importBuiltins(),         metadataBuiltins(),
            mathFunctionBuiltins(), stringFunctionBuiltins(), listFunctionBuiltins(),
            typeFunctionBuiltins(),
        };
        BuiltinTable t(families);
        // Before the tree's depth is checked: the plates become part of the tree
        t.treePasses = {finish2dPass};
        // Last: a camera() call, evaluated with the tree, wins over the $vp* variables
        t.scenePasses = {viewportCameraPass};
        return t;
    }();
    return kTable;
}

}  // namespace rt::scad
