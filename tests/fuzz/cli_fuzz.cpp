// SPDX-License-Identifier: MIT
// Fuzz target: the command line's option parsing, on arbitrary words (the input split at NUL
// bytes into arguments). Parsing must end in CLI11's usage error or a chosen command, never a
// crash; the command itself is not run.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_support.h"
#include "tools/commands.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::vector<std::string> words;
    std::string word;
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word += static_cast<char>(data[i]);
        }
    }
    words.push_back(word);
    if (words.size() > 64) return 0;
    CLI::App app{"scadray"};
    std::function<int()> action;
    rt::cli::addCommands(app, action);
    std::vector<std::string> args = {"scadray"};
    args.insert(args.end(), words.begin(), words.end());
    std::vector<char *> argv;
    for (std::string &a : args) argv.push_back(a.data());
    try {
        app.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError &) {
        // Bad usage, --help and --version: the outcomes main() maps to exit codes
    } catch (const std::exception &e) {
        rt::fuzz::fail(std::string("option parsing threw outside CLI11's errors: ") + e.what());
    }
    return 0;
}
