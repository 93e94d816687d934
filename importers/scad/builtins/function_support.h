// SPDX-License-Identifier: MIT
// What the builtin function families share: their argument list and OpenSCAD's undef warning.
#pragma once

#include <string>
#include <vector>

#include "importers/scad/lang/evaluator.h"

namespace rt::scad {

using Args = std::vector<Value>;

/// undef, with OpenSCAD's warning for a wrong number of arguments (`countProblem`) or an
/// argument of the wrong type.
inline Value undefWarn(Evaluator &ev, const SourceLoc &loc, const char *name, bool countProblem) {
    ev.warn(loc, std::string(name) + (countProblem ? "() number of parameters does not match"
                                                   : "() parameter could not be converted"));
    return Value();
}

}  // namespace rt::scad
