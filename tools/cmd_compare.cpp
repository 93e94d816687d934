// SPDX-License-Identifier: MIT
// `scadray compare`: statistical comparison of two images; exit 0 pass, 1 different, 2 bad input.
#include <CLI/CLI.hpp>
#include <iostream>

#include "core/image/image_compare.h"
#include "core/image/image_io.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

struct CompareArgs {
    std::string test, reference, heatMap;
    CompareOptions opts;
};

int runCompare(const CompareArgs &a) {
    ImageEstimate test, ref;
    try {
        test = readEstimate(a.test);
        ref = readEstimate(a.reference);
    } catch (const std::runtime_error &e) {
        throw std::invalid_argument(e.what());  // unreadable input is bad usage: exit 2
    }
    CompareResult r = compareImages(test, ref, a.opts);
    if (!a.heatMap.empty()) writeImage(r.heatMap, a.heatMap);
    std::cout << (r.pass ? "PASS" : "DIFFERENT") << ": " << a.test << " vs " << a.reference << "\n"
              << r.summary(a.opts);
    return r.pass ? kExitOk : kExitInputError;
}

}  // namespace

void addCompareOptions(CLI::App &cmd, CompareOptions &o) {
    cmd.add_option("--tile", o.tileSize, "Tile size in pixels")->capture_default_str();
    cmd.add_option("--alpha", o.alpha, "False-alarm rate, controlled across tiles and channels")
        ->capture_default_str();
    cmd.add_option("--margin", o.marginAbs, "Absolute equivalence margin")->capture_default_str();
    cmd.add_option("--margin-rel", o.marginRel, "Relative equivalence margin")->capture_default_str();
    cmd.add_option("--edge-spread", o.edgeSpread,
                   "Sub-sample spread that masks a reference pixel as an edge")
        ->capture_default_str();
}

void addCompareCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<CompareArgs>();
    CLI::App *cmd = app.add_subcommand(
        "compare",
        "Compare an image with a reference statistically (exit 0 pass, 1 different, 2 bad input)");
    cmd->add_option("test", args->test, "Image under test (.exr from scadray keeps its variance)")
        ->required();
    cmd->add_option("reference", args->reference, "Reference image")->required();
    cmd->add_option("--heat-map", args->heatMap, "Write the difference heat map here");
    addCompareOptions(*cmd, args->opts);
    cmd->callback([args, &action]() { action = [args]() { return runCompare(*args); }; });
}

}  // namespace rt::cli
