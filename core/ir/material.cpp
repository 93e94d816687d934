// SPDX-License-Identifier: MIT
// TexelMaterial compares, orders and hashes the glTF material it holds by value, so equal
// materials from different files or nodes dedupe to one.
#include "core/ir/material.h"

#include <functional>
#include <tuple>

#include "core/ir/pbr_material.h"

namespace rt::ir {

bool TexelMaterial::operator==(const TexelMaterial &o) const {
    if (pbr == o.pbr) return true;
    if (!pbr || !o.pbr) return false;
    return *pbr == *o.pbr;
}

bool TexelMaterial::operator<(const TexelMaterial &o) const {
    if (!pbr || !o.pbr) return !pbr && o.pbr;
    return pbr->key() < o.pbr->key();
}

bool TexelMaterial::seeThrough() const { return pbr->mayBeSeeThrough(); }

size_t TexelMaterial::hash() const {
    if (!pbr) return 0;
    size_t h = 1;
    std::apply([&h](auto... v) { ((h = h * 1000003 ^ std::hash<decltype(v)>()(v)), ...); },
               pbr->key());
    return h;
}

}  // namespace rt::ir
