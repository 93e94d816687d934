// SPDX-License-Identifier: MIT
// Registration of the scadray subcommands; each sets `action` when it is chosen.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace rt::cli {

void addRenderCommand(CLI::App &app, std::function<int()> &action);
void addDumpCommand(CLI::App &app, std::function<int()> &action);

}  // namespace rt::cli
