// SPDX-License-Identifier: MIT
#include "importers/scad/evaluator.h"

namespace rt::scad {

ir::NodePtr Evaluator::moduleSurface(const ModuleInstantiation &inst, const FramePtr &f) {
    return moduleUnsupported(inst, f);
}

}  // namespace rt::scad
