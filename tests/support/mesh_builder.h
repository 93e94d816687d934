// SPDX-License-Identifier: MIT
// Meshes built in code for tests: a cube and a subdivided icosahedron, both closed and
// oriented outward.
#pragma once

#include <cmath>
#include <map>
#include <memory>

#include "core/ir/mesh.h"

namespace rt::test {

inline std::shared_ptr<ir::Mesh> cubeMesh(const Vec3 &lo, const Vec3 &hi) {
    auto m = std::make_shared<ir::Mesh>();
    for (int i = 0; i < 8; ++i)
        m->positions.push_back(Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z));
    // Two counter-clockwise (seen from outside) triangles per face
    m->triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    m->name = "cube";
    return m;
}

/// Icosahedron subdivided `levels` times, vertices on the sphere of radius r, with vertex
/// normals (smooth) when `normals`.
inline std::shared_ptr<ir::Mesh> icosphere(int levels, double r, bool normals = false) {
    auto m = std::make_shared<ir::Mesh>();
    double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto &p : v) p = normalize(p);
    std::vector<std::array<uint32_t, 3>> f = {
        {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto middle = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(normalize(v[a] + v[b]));
            return mid[key] = static_cast<uint32_t>(v.size() - 1);
        };
        std::vector<std::array<uint32_t, 3>> g;
        for (const auto &tri : f) {
            uint32_t a = middle(tri[0], tri[1]), b = middle(tri[1], tri[2]),
                     c = middle(tri[2], tri[0]);
            g.push_back({tri[0], a, c});
            g.push_back({tri[1], b, a});
            g.push_back({tri[2], c, b});
            g.push_back({a, b, c});
        }
        f = std::move(g);
    }
    for (const Vec3 &p : v) {
        m->positions.push_back(p * r);
        if (normals) m->normals.push_back(p);
    }
    m->triangles = f;
    m->name = "icosphere";
    return m;
}

/// m with every position rounded to a float, as STL and glTF give them (a TriangleMesh of it
/// keeps float leaves). Through a volatile: GCC 12.2's SLP vectorizer at -O2 drops the rounding
/// of x and y from a plain loop of p[a] = float(p[a]) (and from p = {float(p.x), ...}).
inline std::shared_ptr<ir::Mesh> inFloats(std::shared_ptr<ir::Mesh> m) {
    for (auto &p : m->positions)
        for (int a = 0; a < 3; ++a) {
            volatile float f = static_cast<float>(p[a]);
            p[a] = f;
        }
    return m;
}

}  // namespace rt::test
