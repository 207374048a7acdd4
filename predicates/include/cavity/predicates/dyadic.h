#pragma once

// Every finite double is an integer times a power of two. Scaled by a common power, the doubles
// that define a point or a query become integers, and exact arithmetic on them needs no
// fractions: the exact stage of the generic predicates and the CDT's rational coordinates of
// implicit points both build on these functions.

#include <algorithm>
#include <cmath>

#include <gmp.h>

namespace cavity::predicates {

/// The exponent k of the spacing of x's binade: x is an integer multiple of 2^k (x finite).
inline int spacing_exponent(double x) {
    return std::max(std::ilogb(x), -1022) - 52;
}

/// The integer m = x * 2^-k for k = spacing_exponent(x); |m| < 2^53.
inline long spacing_mantissa(double x, int k) {
    return static_cast<long>(std::ldexp(x, -k));
}

/// z = x * 2^-scale, exact when x == 0 or scale <= spacing_exponent(x). In place: an integer
/// that already has the room allocates nothing.
inline void set_scaled(mpz_ptr z, double x, int scale) {
    if (x == 0.0) {
        mpz_set_ui(z, 0);
        return;
    }
    const int k = spacing_exponent(x);
    mpz_set_si(z, spacing_mantissa(x, k));
    mpz_mul_2exp(z, z, static_cast<mp_bitcnt_t>(k - scale));
}

/// z = factor * x * 2^-scale under set_scaled's condition: one product by x's mantissa and one
/// shift, in place (z may be factor).
inline void set_scaled_product(mpz_ptr z, mpz_srcptr factor, double x, int scale) {
    if (x == 0.0) {
        mpz_set_ui(z, 0);
        return;
    }
    const int k = spacing_exponent(x);
    mpz_mul_si(z, factor, spacing_mantissa(x, k));
    mpz_mul_2exp(z, z, static_cast<mp_bitcnt_t>(k - scale));
}

/// x * 2^-scale as a new Integer (a Boost.Multiprecision integer over GMP, gmp_int), exact under
/// set_scaled's condition.
template <class Integer>
Integer scaled_to_integer(double x, int scale) {
    Integer result;
    mpz_ptr z = result.backend().data();
    if (x != 0.0) {
        // Room for the shifted value first (the shift wants a limb to spare): setting the
        // mantissa and then shifting allocated twice, a third of this function's cost in the
        // exact stage of a protected CDT.
        mpz_realloc2(z, 53 + static_cast<mp_bitcnt_t>(spacing_exponent(x) - scale) + GMP_NUMB_BITS);
    }
    set_scaled(z, x, scale);
    return result;
}

}  // namespace cavity::predicates
