// SPDX-License-Identifier: MIT
// `scadray dump`: print the scene IR as canonical text.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/ir/ir_dump.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

struct DumpArgs {
    std::string input;
    std::vector<std::string> defines, libs;
};

int runDump(const DumpArgs &a) {
    LoadOptions lo;
    lo.quiet = true;
    lo.libraryPaths = a.libs;
    for (const auto &d : a.defines) lo.defines.push_back(parseDefine(d));
    DiagnosticSink diag;
    attachPrinter(diag, true);
    ir::Scene scene = loadScene(a.input, diag, lo);
    std::cout << ir::dump(scene);
    return kExitOk;
}

}  // namespace

void addDumpCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<DumpArgs>();
    CLI::App *cmd = app.add_subcommand("dump", "Print the scene IR (after defaults) as text");
    cmd->add_option("scene", args->input, "Scene file (.scad)")->required();
    cmd->add_option("-D,--define", args->defines, "Override a top-level variable: name=value");
    cmd->add_option("-L,--library", args->libs, "Extra folder searched by include<> and use<>");
    cmd->callback([args, &action]() { action = [args]() { return runDump(*args); }; });
}

}  // namespace rt::cli
