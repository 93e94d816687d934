// SPDX-License-Identifier: MIT
// Fuzz target: the SVG reader behind import(), on arbitrary bytes (libxml2 parses them from
// memory, with no network and no external DTD).
#include <cmath>
#include <cstdint>
#include <string>

#include "importers/scad/formats/svg.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string bytes(reinterpret_cast<const char *>(data), size);
    rt::fuzz::expectCleanFailure([&] {
        rt::scad::svg::Options opts;
        rt::scad::svg::Drawing drawing;
        std::string error;
        if (!rt::scad::svg::read(bytes, "in.svg", opts, drawing, error)) {
            if (error.empty()) rt::fuzz::fail("svg::read failed without a message");
            return;
        }
        size_t points = 0;
        for (const auto &shape : drawing.shapes)
            for (const auto &outline : shape) points += outline.size();
        if (points > rt::scad::svg::kMaxPoints) rt::fuzz::fail("more points than kMaxPoints");
    });
    return 0;
}
