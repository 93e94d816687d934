// SPDX-License-Identifier: MIT
// The interior list copies only its entries in use: copies and assignments must still give
// equal, independent lists, at every size up to the capacity.
#include <gtest/gtest.h>

#include <array>

#include "core/render/interior_stack.h"

namespace rt {
namespace {

// Distinct addresses to stand for solids (never dereferenced)
std::array<char, InteriorStack::kCapacity + 1> solids;
const Shape *solid(int i) { return reinterpret_cast<const Shape *>(&solids[i]); }

void expectHolds(const InteriorStack &s, int first, int count) {
    ASSERT_EQ(s.size(), count);
    EXPECT_EQ(s.empty(), count == 0);
    for (int i = 0; i <= InteriorStack::kCapacity; ++i)
        EXPECT_EQ(s.contains(solid(i)), i >= first && i < first + count) << i;
    EXPECT_EQ(s.top(), count ? solid(first + count - 1) : nullptr);
}

TEST(InteriorStack, CopiesAndAssignmentsAreEqualAndIndependent) {
    for (int n = 0; n <= InteriorStack::kCapacity; ++n) {
        InteriorStack a;
        for (int i = 0; i < n; ++i) ASSERT_TRUE(a.push(solid(i)));
        InteriorStack copy = a;
        expectHolds(copy, 0, n);
        // Assigned over a fuller list: its extra entries must not show through
        InteriorStack assigned;
        for (int i = 0; i < InteriorStack::kCapacity; ++i)
            assigned.push(solid(InteriorStack::kCapacity - i));
        assigned = a;
        expectHolds(assigned, 0, n);
        const InteriorStack &alias = assigned;
        assigned = alias;  // self-assignment
        expectHolds(assigned, 0, n);
        // Changing a copy leaves the original alone
        if (n > 0) {
            EXPECT_TRUE(copy.remove(solid(0)));
            expectHolds(copy, 1, n - 1);
            expectHolds(a, 0, n);
        }
        bool room = copy.size() < InteriorStack::kCapacity;
        EXPECT_EQ(copy.push(solid(InteriorStack::kCapacity)), room);
        expectHolds(a, 0, n);
    }
}

}  // namespace
}  // namespace rt
