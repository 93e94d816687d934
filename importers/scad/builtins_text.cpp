// SPDX-License-Identifier: MIT
#include "importers/scad/evaluator.h"

namespace rt::scad {

ir::NodePtr Evaluator::moduleText(const ModuleInstantiation &inst, const FramePtr &f) {
    return moduleUnsupported(inst, f);
}

}  // namespace rt::scad
