#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include <gtest/gtest.h>

#include "cavity/core/base/id_hash_map.h"
#include "cavity/core/base/random.h"

namespace cavity::core {
namespace {

// The same answers as std::unordered_map through growth from empty to thousands of entries: ids
// from narrow ranges (many repeats, long probe runs among consecutive ids) and from the whole
// 32-bit range below kEmpty, with kGhostVertex (0xFFFFFFFE, kEmpty - 1), a valid key, among them.
TEST(IdHashMap, AgreesWithUnorderedMap) {
    Random random(11);
    for (int trial = 0; trial < 60; ++trial) {
        const std::uint64_t range =
            trial % 3 == 0 ? 0xFFFF'FFFFull : 1 + random.below(trial < 30 ? 64 : 20000);
        IdHashMap<int> map;
        std::unordered_map<std::uint32_t, int> oracle;
        EXPECT_FALSE(map.contains(5));
        const std::size_t n = random.below(5000);
        for (std::size_t i = 0; i < n; ++i) {
            const auto id =
                static_cast<std::uint32_t>(i % 97 == 0 ? 0xFFFF'FFFEu : random.below(range));
            const auto [value, inserted] = map.try_emplace(id);
            const auto [it, oracle_inserted] = oracle.try_emplace(id, 0);
            ASSERT_EQ(inserted, oracle_inserted) << "id " << id;
            ASSERT_EQ(*value, it->second) << "id " << id;
            *value += 1;
            it->second += 1;
            const auto probe = static_cast<std::uint32_t>(random.below(range));
            ASSERT_EQ(map.contains(probe), oracle.contains(probe)) << "id " << probe;
        }
        ASSERT_EQ(map.size(), oracle.size());
        for (const auto& [id, count] : oracle) {
            ASSERT_TRUE(map.contains(id)) << "id " << id;
            const auto [value, inserted] = map.try_emplace(id);
            EXPECT_FALSE(inserted) << "id " << id;
            EXPECT_EQ(*value, count) << "id " << id;
        }
    }
}

TEST(IdHashSet, InsertsEachIdOnce) {
    Random random(12);
    IdHashSet set;
    std::unordered_set<std::uint32_t> oracle;
    for (int i = 0; i < 20000; ++i) {
        const auto id = static_cast<std::uint32_t>(random.below(3000));
        ASSERT_EQ(set.insert(id), oracle.insert(id).second) << "id " << id;
    }
    EXPECT_EQ(set.size(), oracle.size());
    for (std::uint32_t id = 0; id < 3100; ++id) {
        EXPECT_EQ(set.contains(id), oracle.contains(id)) << "id " << id;
    }
}

}  // namespace
}  // namespace cavity::core
