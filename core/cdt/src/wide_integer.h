#pragma once

#include <cmath>
#include <cstdint>

#include "cavity/predicates/dyadic.h"

/// The 128-bit integers of the exact double-point arithmetic of edge protection (dyadic_point.cpp,
/// double_point_sieve.cpp): coordinates of segment ends scaled to one spacing, where GMP's
/// allocation per operation would cost more than the work.
namespace cavity::core {

__extension__ using Int128 = __int128;
__extension__ using Uint128 = unsigned __int128;

/// x = mantissa * 2^exponent with |mantissa| < 2^53, exponent the spacing exponent of x's binade
/// (x == 0: mantissa 0, exponent 0).
struct SplitDouble {
    std::int64_t mantissa;
    int exponent;
};

inline SplitDouble split_double(double x) {
    if (x == 0.0) {
        return {0, 0};
    }
    const int e = predicates::spacing_exponent(x);
    return {static_cast<std::int64_t>(std::ldexp(x, -e)), e};
}

inline Uint128 magnitude(Int128 x) {
    return x < 0 ? -static_cast<Uint128>(x) : static_cast<Uint128>(x);
}

}  // namespace cavity::core
