// SPDX-License-Identifier: MIT
// `scadray merge`: the tiles of `render --tile K/N` -> the picture, bit for bit the one a
// single `render` writes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "core/image/image_io.h"
#include "tools/cli_common.h"
#include "tools/commands.h"
#include "tools/tiles.h"

namespace rt::cli {

namespace {

struct MergeArgs {
    std::vector<std::string> tiles;
    std::string output;
    int bits = 8;
    bool linear = false, quiet = false;
};

int runMerge(const MergeArgs &a) {
    requireOutputFile(a.output, "-o");
    for (const std::string &t : a.tiles) requireRegularFile(t);
    int64_t samples = 0;
    Image picture = mergeTiles(a.tiles, &samples);
    WriteOptions wo;
    wo.pngDepth = a.bits == 16 ? PngDepth::Bits16 : PngDepth::Bits8;
    wo.linearPng = a.linear;
    writeImage(picture, a.output, wo);
    if (!a.quiet)
        std::fprintf(stderr, "scadray: %s: %dx%d from %zu tiles, %.2f samples per pixel\n",
                     a.output.c_str(), picture.width(), picture.height(), a.tiles.size(),
                     double(samples) / (double(picture.width()) * picture.height()));
    return kExitOk;
}

}  // namespace

void addMergeCommand(CLI::App &app, std::function<int()> &action) {
    auto args = std::make_shared<MergeArgs>();
    CLI::App *cmd = app.add_subcommand("merge",
                                       "Assemble the tiles of `render --tile K/N` into the picture "
                                       "(the same, bit for bit, as one render)");
    cmd->add_option("tiles", args->tiles,
                    "Tile files (.exr), every tile of one render once, in any order")
        ->required();
    cmd->add_option("-o,--output", args->output, "Output image; .png (sRGB) or .exr (linear float)")
        ->required();
    cmd->add_option("--bits", args->bits, "PNG bits per channel")
        ->check(CLI::IsMember({8, 16}))
        ->capture_default_str();
    cmd->add_flag("--linear", args->linear, "Write PNG values linear instead of sRGB");
    cmd->add_flag("-q,--quiet", args->quiet, "Only warnings and errors");
    cmd->callback([args, &action]() { action = [args]() { return runMerge(*args); }; });
}

}  // namespace rt::cli
