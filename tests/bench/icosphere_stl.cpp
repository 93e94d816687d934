// SPDX-License-Identifier: MIT
// Writes a subdivided icosahedron of 20 * 4^levels triangles as a binary STL, for the mesh
// benchmark script (scripts/bench_mesh.sh). Usage: icosphere_stl OUT.stl LEVELS
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "support/mesh_builder.h"

int main(int argc, char **argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: icosphere_stl OUT.stl LEVELS\n");
        return 2;
    }
    auto mesh = rt::test::icosphere(std::atoi(argv[2]), 10);
    std::ofstream out(argv[1], std::ios::binary);
    char header[80] = "scadray benchmark icosphere";
    out.write(header, 80);
    uint32_t n = static_cast<uint32_t>(mesh->triangles.size());
    out.write(reinterpret_cast<const char *>(&n), 4);
    for (const auto &t : mesh->triangles) {
        float data[12] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const rt::Vec3 &p = mesh->positions[t[k]];
            data[3 + 3 * k] = static_cast<float>(p.x);
            data[4 + 3 * k] = static_cast<float>(p.y);
            data[5 + 3 * k] = static_cast<float>(p.z);
        }
        out.write(reinterpret_cast<const char *>(data), sizeof data);
        uint16_t attr = 0;
        out.write(reinterpret_cast<const char *>(&attr), 2);
    }
    std::printf("%u triangles\n", n);
    return out ? 0 : 1;
}
