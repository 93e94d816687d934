// SPDX-License-Identifier: MIT
// The command line as one list of subcommands.
#include "tools/commands.h"

#include <CLI/CLI.hpp>

namespace rt::cli {

void addCommands(CLI::App &app, std::function<int()> &action) {
    app.require_subcommand(1);
    app.set_version_flag("--version", "scadray " SCADRAY_VERSION);
    addRenderCommand(app, action);
    addDumpCommand(app, action);
    addExportCommand(app, action);
    addCompareCommand(app, action);
    addCheckCommand(app, action);
    addConvergeCommand(app, action);
    addMergeCommand(app, action);
    addReportCommand(app, action);
}

}  // namespace rt::cli
