#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/bucket_sort.h"
#include "cavity/core/base/random.h"

namespace cavity::core {
namespace {

// The same sequence as std::sort, on the shapes the callers sort: edges led by their lower end,
// (edge, facet) pairs with repeated edges, and 64-bit side keys led by their high word; with
// empty and one-item inputs, repeated items and leads with gaps.
TEST(BucketSort, SameSequenceAsStdSort) {
    Random random(7);
    for (int trial = 0; trial < 300; ++trial) {
        const std::size_t n = random.below(trial < 10 ? 3 : 400);
        const std::uint64_t range = 1 + random.below(trial % 2 == 0 ? 8 : 5000);
        std::vector<std::pair<std::array<std::uint32_t, 2>, std::size_t>> sides;
        std::vector<std::pair<std::uint64_t, std::uint32_t>> keys;
        for (std::size_t i = 0; i < n; ++i) {
            const auto a = static_cast<std::uint32_t>(random.below(range));
            const auto b = static_cast<std::uint32_t>(random.below(range));
            const auto f = static_cast<std::uint32_t>(random.below(4));
            sides.push_back({{std::min(a, b), std::max(a, b)}, f});
            keys.push_back({(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b), f});
        }
        auto expected_sides = sides;
        std::sort(expected_sides.begin(), expected_sides.end());
        bucket_sort(sides, [](const auto& s) { return std::size_t{s.first[0]}; });
        EXPECT_EQ(sides, expected_sides) << "trial " << trial;
        auto expected_keys = keys;
        std::sort(expected_keys.begin(), expected_keys.end());
        bucket_sort(keys, [](const auto& k) { return std::size_t{k.first >> 32}; });
        EXPECT_EQ(keys, expected_keys) << "trial " << trial;
    }
}

}  // namespace
}  // namespace cavity::core
