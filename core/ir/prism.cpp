// SPDX-License-Identifier: MIT
// Planar faces and points of a PrismPrim.
#include "core/ir/prism.h"

#include <algorithm>

namespace rt::ir {

namespace {

/// Appends the ring of the outline scaled by k at height z (one apex point where k is 0) to
/// `vertices` and returns its indices, one per outline point.
std::vector<int> appendRing(const PrismPrim &p, double k, double z, std::vector<Vec3> &vertices) {
    size_t n = p.outline.size();
    std::vector<int> idx;
    if (k == 0) {
        idx.assign(n, static_cast<int>(vertices.size()));
        vertices.push_back(Vec3(0, 0, z));
        return idx;
    }
    for (const Point2 &v : p.outline) {
        idx.push_back(static_cast<int>(vertices.size()));
        vertices.push_back(Vec3(k * v.x, k * v.y, z));
    }
    return idx;
}

}  // namespace

std::vector<Vec3> prismPoints(const PrismPrim &p) {
    std::vector<Vec3> points;
    appendRing(p, p.k0, p.z0, points);
    appendRing(p, p.k1, p.z1, points);
    return points;
}

PolytopePrim prismPolytope(const PrismPrim &p) {
    PolytopePrim poly;
    size_t n = p.outline.size();
    std::vector<int> bottom = appendRing(p, p.k0, p.z0, poly.vertices);
    std::vector<int> top = appendRing(p, p.k1, p.z1, poly.vertices);
    if (p.k0 != 0) poly.faces.push_back(std::vector<int>(bottom.rbegin(), bottom.rend()));
    if (p.k1 != 0) poly.faces.push_back(top);
    for (size_t i = 0; i < n; ++i) {
        size_t j = (i + 1) % n;
        std::vector<int> f{bottom[i], bottom[j], top[j], top[i]};
        // The apex joins both top (or bottom) corners: a triangle
        f.erase(std::unique(f.begin(), f.end()), f.end());
        poly.faces.push_back(f);
    }
    return poly;
}

}  // namespace rt::ir
