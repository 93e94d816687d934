// SPDX-License-Identifier: MIT
// `scadray dump`: print the scene IR as canonical text.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/ir/ir_dump.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

int runDump(const SceneArgs &a) {
    DiagnosticSink diag;
    DiagnosticPrinter printer(diag, true);
    ir::Scene scene = loadScene(a.input, diag, a.loadOptions(false));
    std::cout << ir::dump(scene);
    return kExitOk;
}

}  // namespace

void addDumpCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<SceneArgs>();
    CLI::App *cmd = app.add_subcommand("dump", "Print the scene IR (after defaults) as text");
    args->addTo(*cmd);
    cmd->callback([args, &action]() { action = [args]() { return runDump(*args); }; });
}

}  // namespace rt::cli
