// SPDX-License-Identifier: MIT
// Per-thread counters of rays by kind and of numerical events, summed after a render.
#pragma once

#include <cstdint>

namespace rt {

struct RayStats {
    int64_t camera = 0;
    int64_t shadow = 0;  ///< shadow-ray segments (one per surface crossed towards a light)
    int64_t reflection = 0;
    int64_t refraction = 0;    ///< rays bent by a change of ior
    int64_t transmission = 0;  ///< rays continuing straight through a transparent surface
    int64_t internalReflection = 0;
    int64_t distributed = 0;     ///< glossy and frosted rays spread about a principal direction
    int64_t spanOps = 0;         ///< CSG span-list merges
    int64_t prunedSubtrees = 0;  ///< CSG subtrees skipped by bounds or pruning rules
    int64_t nonFinite = 0;       ///< NaN or Inf radiance values replaced by black
    int64_t interiorOverflow = 0;

    int64_t totalRays() const {
        return camera + shadow + reflection + refraction + transmission + internalReflection +
               distributed;
    }
    RayStats &operator+=(const RayStats &o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        transmission += o.transmission;
        internalReflection += o.internalReflection;
        distributed += o.distributed;
        spanOps += o.spanOps;
        prunedSubtrees += o.prunedSubtrees;
        nonFinite += o.nonFinite;
        interiorOverflow += o.interiorOverflow;
        return *this;
    }
};

}  // namespace rt
