#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

// The cheap exact case of the expansion stage: integer inputs with small differences, the usual
// exactly degenerate input (grids, integer spheres, integer weights). Their determinant is
// evaluated without any rounding, in doubles for the low-degree minors and in 128-bit integers
// for the last products, an order of magnitude faster than general expansions.
namespace cavity::predicates::detail {

__extension__ using Int128 = __int128;

/// True when v is an integer below 2^50 in magnitude: differences of such values are exact.
inline bool is_small_integer(double v) {
    // For |v| < 2^51, adding 1.5 * 2^52 rounds v to an integer (the sum lies in [2^52, 2^53),
    // where the spacing is 1), so the round trip returns v exactly when v is an integer.
    constexpr double kRoundToInteger = 0x1.8p52;
    return (std::abs(v) < 0x1p50) & ((v + kRoundToInteger) - kRoundToInteger == v);
}

inline bool is_small_integer(const Point3& p) {
    return is_small_integer(p.x) & is_small_integer(p.y) & is_small_integer(p.z);
}

inline bool is_small_integer(const WeightedPoint3& p) {
    return is_small_integer(p.x) & is_small_integer(p.y) & is_small_integer(p.z) &
           is_small_integer(p.w);
}

inline Sign sign_of(Int128 v) {
    return static_cast<Sign>((v > 0) - (v < 0));
}

}  // namespace cavity::predicates::detail
