#pragma once

// Every finite double is an integer times a power of two. Scaled by a common power, the doubles
// that define a point or a query become integers, and exact arithmetic on them needs no
// fractions: the exact stage of the generic predicates and the CDT's rational coordinates of
// implicit points both build on these two functions.

#include <algorithm>
#include <cmath>

#include <gmp.h>

namespace cavity::predicates {

/// The exponent k of the spacing of x's binade: x is an integer multiple of 2^k (x finite).
inline int spacing_exponent(double x) {
    return std::max(std::ilogb(x), -1022) - 52;
}

/// x * 2^-scale as an Integer (a Boost.Multiprecision integer over GMP, gmp_int), exact when
/// x == 0 or scale <= spacing_exponent(x).
template <class Integer>
Integer scaled_to_integer(double x, int scale) {
    if (x == 0.0) {
        return Integer(0);
    }
    const int k = spacing_exponent(x);
    // Shifted in place: `mantissa << shift` made a second integer, and copying and freeing it
    // was a fifth of this function's cost in the exact stage of a protected CDT. Room for the
    // shifted value first (the shift wants a limb to spare): setting the mantissa and then
    // shifting allocated twice, a third of the cost again.
    const auto shift = static_cast<mp_bitcnt_t>(k - scale);
    Integer result;
    mpz_ptr z = result.backend().data();
    mpz_realloc2(z, 53 + shift + GMP_NUMB_BITS);
    mpz_set_si(z, static_cast<long>(std::ldexp(x, -k)));  // |mantissa| < 2^53
    mpz_mul_2exp(z, z, shift);
    return result;
}

}  // namespace cavity::predicates
