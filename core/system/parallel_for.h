// SPDX-License-Identifier: MIT
// Splits [begin, end) into `parts` equal chunks and runs f(part, chunkBegin, chunkEnd) for each,
// the first on the calling thread and the others on threads of their own; returns when all are
// done. For one-off parallel passes over large arrays (BVH builds), not for the render loop.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace rt {

template <typename F>
void parallelFor(size_t begin, size_t end, size_t parts, F &&f) {
    if (parts <= 1) return f(size_t{0}, begin, end);
    std::vector<std::thread> workers;
    size_t chunk = (end - begin + parts - 1) / parts;
    auto run = [&](size_t i) {
        f(i, std::min(end, begin + i * chunk), std::min(end, begin + (i + 1) * chunk));
    };
    for (size_t i = 1; i < parts; ++i) workers.emplace_back(run, i);
    run(0);
    for (auto &w : workers) w.join();
}

}  // namespace rt
