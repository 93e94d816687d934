// SPDX-License-Identifier: MIT
// Fuzz target: surface()'s height-map reader (DAT text, or PNG by its signature) and the mesh
// built of a map, on arbitrary bytes.
#include <cstdint>
#include <string>

#include "importers/scad/formats/surface.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string path = rt::fuzz::writeInput(data, size, "in.dat");
    rt::fuzz::expectCleanFailure([&] {
        rt::scad::surface::HeightMap map;
        auto r =
            rt::scad::surface::readHeightMap(path, size % 2 == 1, map, [](const std::string &) {});
        if (r != rt::scad::surface::ReadResult::Ok) return;
        size_t cells = static_cast<size_t>(map.lines) * static_cast<size_t>(map.columns);
        if (cells > rt::scad::surface::kMaxCells || map.values.size() != cells)
            rt::fuzz::fail("height map larger than kMaxCells or inconsistent");
        // The mesh of a small map (a large one is the evaluator's to refuse, and slow here)
        if (cells <= 65536) rt::scad::surface::surfaceMesh(map, true);
    });
    return 0;
}
