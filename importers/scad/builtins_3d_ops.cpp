// SPDX-License-Identifier: MIT
#include "importers/scad/evaluator.h"

namespace rt::scad {

ir::NodePtr Evaluator::moduleResize(const ModuleInstantiation &inst, const FramePtr &f) {
    return moduleUnsupported(inst, f);
}

ir::NodePtr Evaluator::moduleMinkowski(const ModuleInstantiation &inst, const FramePtr &f) {
    return moduleUnsupported(inst, f);
}

ir::NodePtr Evaluator::moduleProjection(const ModuleInstantiation &inst, const FramePtr &f) {
    return moduleUnsupported(inst, f);
}

}  // namespace rt::scad
