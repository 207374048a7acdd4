#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "cavity/core/base/assert.h"

namespace cavity::core {

/// A hash map from 32-bit ids (vertex or tetrahedron numbers) to small values, for the sets and
/// memos that live as long as one search or one polygon: open addressing with linear probing in
/// two flat arrays, at most half full. The std::unordered_ containers it replaces made and freed a
/// node per entry (1.65 million on one CDT of cheese.off, where the entries are a few dozen per
/// polygon). Every id but kEmpty (0xFFFFFFFF, which is kNoTet and no vertex) can be a key; entries
/// are never erased. Growing moves the values: a pointer from try_emplace() lasts until the next
/// insertion.
template <class Value>
class IdHashMap {
public:
    static constexpr std::uint32_t kEmpty = 0xFFFF'FFFFu;

    /// The value of `id`, value-initialised and inserted when absent, and whether it was.
    std::pair<Value*, bool> try_emplace(std::uint32_t id) {
        CAVITY_ASSERT(id != kEmpty, "an id other than kEmpty");
        if (2 * (size_ + 1) > keys_.size()) {
            grow();
        }
        std::size_t k = slot(id);
        while (keys_[k] != id) {
            if (keys_[k] == kEmpty) {
                keys_[k] = id;
                values_[k] = Value{};
                ++size_;
                return {&values_[k], true};
            }
            k = (k + 1) & (keys_.size() - 1);
        }
        return {&values_[k], false};
    }

    bool contains(std::uint32_t id) const {
        if (size_ == 0) {
            return false;
        }
        for (std::size_t k = slot(id); keys_[k] != kEmpty; k = (k + 1) & (keys_.size() - 1)) {
            if (keys_[k] == id) {
                return true;
            }
        }
        return false;
    }

    std::size_t size() const { return size_; }

private:
    /// Fibonacci hashing: the top bits of id times 2^64 / phi. Consecutive ids (a walk through
    /// tetrahedra created together) land far apart.
    std::size_t slot(std::uint32_t id) const {
        return static_cast<std::size_t>((id * 0x9E37'79B9'7F4A'7C15ull) >> shift_);
    }

    void grow() {
        const std::size_t capacity = keys_.empty() ? 32 : 2 * keys_.size();
        std::vector<std::uint32_t> keys(capacity, kEmpty);
        std::vector<Value> values(capacity);
        keys.swap(keys_);
        values.swap(values_);
        shift_ = 64 - std::countr_zero(capacity);
        for (std::size_t k = 0; k < keys.size(); ++k) {
            if (keys[k] != kEmpty) {
                std::size_t j = slot(keys[k]);
                while (keys_[j] != kEmpty) {
                    j = (j + 1) & (keys_.size() - 1);
                }
                keys_[j] = keys[k];
                values_[j] = std::move(values[k]);
            }
        }
    }

    std::vector<std::uint32_t> keys_;
    std::vector<Value> values_;
    std::size_t size_ = 0;
    int shift_ = 64;
};

/// A set of 32-bit ids on IdHashMap.
class IdHashSet {
public:
    /// True when `id` was not in the set.
    bool insert(std::uint32_t id) { return map_.try_emplace(id).second; }

    bool contains(std::uint32_t id) const { return map_.contains(id); }

    std::size_t size() const { return map_.size(); }

private:
    struct Nothing {};

    IdHashMap<Nothing> map_;
};

}  // namespace cavity::core
