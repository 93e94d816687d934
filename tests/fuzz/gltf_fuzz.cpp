// SPDX-License-Identifier: MIT
// Fuzz target: the glTF importer (tinygltf + importers/gltf) on a .gltf (JSON) file, or, built
// with SCADRAY_FUZZ_GLB, on a .glb container (the first four bytes are forced to the "glTF"
// magic so every mutation reaches the binary loader). External buffers and images resolve in
// an empty scratch folder.
#include <cstdint>
#include <cstring>
#include <vector>

#include "importers/gltf/gltf_importer.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
#ifdef SCADRAY_FUZZ_GLB
    if (size < 4) return 0;
    std::vector<uint8_t> bytes(data, data + size);
    std::memcpy(bytes.data(), "glTF", 4);
    std::string path = rt::fuzz::writeInput(bytes.data(), bytes.size(), "in.glb");
#else
    if (size >= 4 && std::memcmp(data, "glTF", 4) == 0) return 0;  // glb_fuzz's input
    std::string path = rt::fuzz::writeInput(data, size, "in.gltf");
#endif
    rt::fuzz::expectCleanFailure([&] {
        rt::DiagnosticSink diag;
        rt::ir::Scene scene = rt::gltf::importGltf(path, diag);
        (void)scene;
    });
    return 0;
}
