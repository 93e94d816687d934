// SPDX-License-Identifier: MIT
// Builtin CSG operations and pass-through groups: union, difference, intersection, render, group
// (csgops.cc).
#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <variant>

#include "core/meshing/facets.h"
#include "core/meshing/hull.h"
#include "importers/scad/builtins/colors.h"
#include "importers/scad/builtins/families.h"

namespace rt::scad {

namespace {

ir::NodePtr csgOperation(Evaluator &ev, ir::NodeKind kind, const ModuleInstantiation &inst,
                         const FramePtr &f) {
    // OpenSCAD 2021.01's CSG modules ignore every argument, `$` ones included
    ir::NodePtr node = ev.newNode(kind, inst.loc);
    ev.instantiateChildren(inst, f, node->children);
    return node;
}

ir::NodePtr moduleUnion(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ev, ir::NodeKind::Union, inst, f);
}

ir::NodePtr moduleDifference(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ev, ir::NodeKind::Difference, inst, f);
}

ir::NodePtr moduleIntersection(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    return csgOperation(ev, ir::NodeKind::Intersection, inst, f);
}

ir::NodePtr moduleGroup(Evaluator &ev, const ModuleInstantiation &inst, const FramePtr &f) {
    // render(convexity) and group(): pass-through implicit unions
    FramePtr dollars = makeFrame(nullptr);
    if (inst.name.str() == "render")
        ev.bindBuiltin(inst, {"convexity"}, f, dollars.get());
    else
        ev.bindBuiltin(inst, {}, f, dollars.get());
    FrameGuard g(ev.dynamicScope(), dollars.get());
    ir::NodePtr node = ev.newNode(ir::NodeKind::Group, inst.loc);
    ev.instantiateChildren(inst, f, node->children);
    return node;
}

}  // namespace

BuiltinFamily booleanBuiltins() {
    static constexpr BuiltinModuleEntry kModules[] = {
        {"union", moduleUnion},
        {"difference", moduleDifference},
        {"intersection", moduleIntersection},
        {"render", moduleGroup},
        {"group", moduleGroup},
    };
    return {kModules, {}};
}

}  // namespace rt::scad
