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

// The tests are taken into locals and combined with `&`, not `&&`: one branch on the combined
// answer (and no bitwise operator between calls, which clang warns about).
inline bool is_small_integer(const Point3& p) {
    const bool x = is_small_integer(p.x);
    const bool y = is_small_integer(p.y);
    const bool z = is_small_integer(p.z);
    return x & y & z;
}

inline bool is_small_integer(const WeightedPoint3& p) {
    const bool x = is_small_integer(p.x);
    const bool y = is_small_integer(p.y);
    const bool z = is_small_integer(p.z);
    const bool w = is_small_integer(p.w);
    return x & y & z & w;
}

/// True when every point is a small integer point, tested without a branch between them (the
/// fold is over unsigned values: `&` between bool calls draws clang's warning).
template <class... Points>
inline bool all_small_integers(const Points&... points) {
    return ((static_cast<unsigned>(is_small_integer(points))) & ...) != 0u;
}

inline Sign sign_of(Int128 v) {
    return static_cast<Sign>((v > 0) - (v < 0));
}

}  // namespace cavity::predicates::detail
