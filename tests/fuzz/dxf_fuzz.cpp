// SPDX-License-Identifier: MIT
// Fuzz target: the DXF reader behind import(), dxf_dim() and dxf_cross(), on arbitrary bytes.
#include <cstdint>
#include <string>

#include "importers/scad/formats/dxf.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    std::string bytes(reinterpret_cast<const char *>(data), size);
    rt::fuzz::expectCleanFailure([&] {
        rt::scad::dxf::ReadOptions opts;
        opts.fragments = rt::ir::Fragments{36, 0, 0};
        rt::scad::dxf::Data d;
        rt::scad::dxf::read(bytes, "in.dxf", opts, d, [](const std::string &) {});
        for (const auto &path : d.paths)
            for (auto i : path.indices)
                if (i < 0 || static_cast<size_t>(i) >= d.points.size())
                    rt::fuzz::fail("path index out of range");
        std::vector<rt::scad::Outline> outlines = rt::scad::dxf::outlines(d);
        double value = 0, x = 0, y = 0;
        bool unsupported = false;
        rt::scad::dxf::dimension(d, "", value, unsupported);
        rt::scad::dxf::cross(d, x, y);
    });
    return 0;
}
