#pragma once

#include <cstdint>

namespace cavity::predicates {

/// The exact sign of a predicate's determinant.
enum class Sign : std::int8_t { kNeg = -1, kZero = 0, kPos = 1 };

constexpr int to_int(Sign s) {
    return static_cast<int>(s);
}

constexpr Sign negate(Sign s) {
    return static_cast<Sign>(-static_cast<int>(s));
}

}  // namespace cavity::predicates
