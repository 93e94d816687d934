// SPDX-License-Identifier: MIT
// Registration of the scadray subcommands; each sets `action` when it is chosen.
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace rt {
struct CompareOptions;
}

namespace rt::cli {

void addRenderCommand(CLI::App &app, std::function<int()> &action);
void addDumpCommand(CLI::App &app, std::function<int()> &action);
void addExportCommand(CLI::App &app, std::function<int()> &action);
void addCompareCommand(CLI::App &app, std::function<int()> &action);
void addCheckCommand(CLI::App &app, std::function<int()> &action);
void addConvergeCommand(CLI::App &app, std::function<int()> &action);
void addMergeCommand(CLI::App &app, std::function<int()> &action);
void addReportCommand(CLI::App &app, std::function<int()> &action);
/// The whole command line: every subcommand above registered on `app` (which must require one),
/// with the version flag. Shared by main() and the option-parsing fuzz target.
void addCommands(CLI::App &app, std::function<int()> &action);

/// The comparison options shared by `compare` and `check`.
void addCompareOptions(CLI::App &cmd, CompareOptions &o);

}  // namespace rt::cli
