// SPDX-License-Identifier: MIT
// Fuzz target: the STL (ASCII and binary) reader, or, built with SCADRAY_FUZZ_OFF, the OFF
// reader, on arbitrary bytes.
#include <cstdint>

#include "importers/mesh/mesh_reader.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
#ifdef SCADRAY_FUZZ_OFF
    std::string path = rt::fuzz::writeInput(data, size, "in.off");
#else
    std::string path = rt::fuzz::writeInput(data, size, "in.stl");
#endif
    rt::fuzz::expectCleanFailure([&] {
        rt::DiagnosticSink diag;
#ifdef SCADRAY_FUZZ_OFF
        rt::ir::Mesh mesh = rt::meshio::readOff(path, diag);
#else
        rt::ir::Mesh mesh = rt::meshio::readStl(path, diag);
#endif
        // What the readers promise: every index names a position
        for (const auto &t : mesh.triangles)
            for (uint32_t i : t)
                if (i >= mesh.positions.size()) rt::fuzz::fail("triangle index out of range");
    });
    return 0;
}
