// SPDX-License-Identifier: MIT
// `scadray compare`: statistical comparison of two images; exit 0 pass, 1 different, 2 bad input.
#include <CLI/CLI.hpp>
#include <iostream>
#include <limits>

#include "core/image/image_compare.h"
#include "core/image/image_io.h"
#include "core/render/renderer.h"
#include "core/system/input_file.h"
#include "tools/cli_common.h"
#include "tools/commands.h"

namespace rt::cli {

namespace {

struct CompareArgs {
    std::string test, reference, heatMap;
    CompareOptions opts;
};

int runCompare(const CompareArgs &a) {
    if (!a.heatMap.empty()) requireOutputFile(a.heatMap, "--heat-map");
    ImageEstimate test, ref;
    try {
        // Before anything opens them: a FIFO would block, /dev/zero never end
        requireRegularFile(a.test);
        requireRegularFile(a.reference);
        // Refused before any work: the heat map may not replace an input
        if (!a.heatMap.empty()) refuseOverwritingInput(a.heatMap);
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
    constexpr double kAny = std::numeric_limits<double>::max();
    addNumber(cmd, "--tile", o.tileSize, "Tile size in pixels", 1, kMaxImageSide);
    addNumber(cmd, "--alpha", o.alpha, "False-alarm rate, controlled across tiles and channels",
              0.0, 1.0, true);
    addNumber(cmd, "--margin", o.marginAbs, "Absolute equivalence margin", 0.0, kAny);
    addNumber(cmd, "--margin-rel", o.marginRel, "Relative equivalence margin", 0.0, kAny);
    addNumber(cmd, "--edge-spread", o.edgeSpread,
              "Sub-sample spread that masks a reference pixel as an edge", 0.0, kAny);
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
