// SPDX-License-Identifier: MIT
// Shared pieces of the libFuzzer targets: a private scratch folder for the readers
// that take a path, and the one rule every target checks: bad input ends in a located error
// (rt::LocatedError) or a documented std::exception, never a crash, a hang or an unlocated
// surprise.
#pragma once

#include <unistd.h>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "core/ir/diagnostics.h"

namespace rt::fuzz {

/// A folder of this process's own under /dev/shm (or the temporary folder), made on first use:
/// inputs are written there, so relative names in an input (a glTF buffer, a .scad import)
/// find nothing. (Not the working directory: libFuzzer's corpus and artifact paths are
/// relative to that.)
inline const std::filesystem::path &scratchDir() {
    static const std::filesystem::path dir = [] {
        std::string base = std::filesystem::exists("/dev/shm") ? "/dev/shm" : "/tmp";
        std::string tmpl = base + "/scadray-fuzz-XXXXXX";
        if (!mkdtemp(tmpl.data())) {
            std::perror("mkdtemp");
            std::abort();
        }
        std::atexit([] { std::filesystem::remove_all(scratchDir()); });
        return std::filesystem::path(tmpl);
    }();
    return dir;
}

/// Writes the input to `name` in the scratch folder and returns its path.
inline std::string writeInput(const uint8_t *data, size_t size, const std::string &name) {
    std::string path = (scratchDir() / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
        std::perror(path.c_str());
        std::abort();
    }
    return path;
}

/// A bug the sanitizers cannot see: stop here so libFuzzer saves the input.
[[noreturn]] inline void fail(const std::string &what) {
    std::fprintf(stderr, "scadray fuzz: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

/// Runs `fn`; located errors are the expected outcome of bad input. `allowed` says whether a
/// plain std::exception is a documented outcome of this reader (the image reader throws
/// std::runtime_error by contract); anything else aborts.
template <class Fn>
void expectCleanFailure(Fn &&fn, bool plainExceptionsAllowed = false) {
    try {
        fn();
    } catch (const LocatedError &e) {
        if (e.diagnostic().message.empty()) fail("located error without a message");
    } catch (const std::bad_alloc &) {
        fail("std::bad_alloc: an input reached an allocation larger than the limits allow");
    } catch (const std::exception &e) {
        if (!plainExceptionsAllowed) fail(std::string("unlocated exception: ") + e.what());
    }
}

}  // namespace rt::fuzz
