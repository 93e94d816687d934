// SPDX-License-Identifier: MIT
// The default studio environment.
#include "core/ir/environment.h"

namespace rt::ir {

Environment studioEnvironment() {
    Environment e;
    e.kind = EnvironmentKind::Gradient;
    e.gradient = {{-1, Rgb(0.10, 0.10, 0.10)},
                  {0, Rgb(0.50, 0.50, 0.50)},
                  {0.5, Rgb(0.80, 0.82, 0.85)},
                  {1, Rgb(1.00, 1.00, 1.00)}};
    return e;
}

}  // namespace rt::ir
