// SPDX-License-Identifier: MIT
// scadray command line: the only place that catches errors and maps them to exit codes.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/ir/diagnostics.h"
#include "core/system/input_file.h"
#include "core/system/large_stack.h"
#include "core/system/temp_file.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

int main(int argc, char **argv) {
    using namespace rt;
    // An interrupt removes the temporary of a write in progress (and still ends the program)
    installInterruptCleanup();
    CLI::App app{"scadray: ray-trace OpenSCAD scenes and convert them for POV-Ray"};
    std::function<int()> action;
    cli::addCommands(app, action);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError &e) {
        int rc = app.exit(e);
        return rc == 0 ? cli::kExitOk : cli::kExitUsage;
    }
    if (!action) return cli::kExitUsage;
    try {
        // On a large stack: the walks over a scene tree recurse once per level (ir::kMaxTreeDepth)
        int rc = cli::kExitUsage;
        runWithStack(kLargeStackBytes, [&] { rc = action(); });
        return rc;
    } catch (const LocatedError &e) {
        std::cerr << formatDiagnostic(e.diagnostic()) << "\n";
        return cli::kExitInputError;
    } catch (const std::invalid_argument &e) {
        // Messages quote names and file content: printable() keeps escapes off the terminal
        std::cerr << "scadray: error: " << printable(e.what(), true) << "\n";
        return cli::kExitUsage;
    } catch (const std::bad_alloc &) {
        std::cerr << "scadray: error: out of memory\n";
        return cli::kExitInputError;
    } catch (const std::exception &e) {
        std::cerr << "scadray: error: " << printable(e.what(), true) << "\n";
        return cli::kExitInputError;
    }
}
