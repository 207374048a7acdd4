#pragma once

#include <array>

#include <boost/multiprecision/gmp.hpp>

#include "homogeneous.h"

// The exact stage's two determinants of homogeneous rows (homogeneous.h), evaluated in place in
// GMP. determinant<Integer> with value-semantics integers makes a fresh integer for every product
// and every partial sum (some two hundred allocations and as many reallocations as they grow):
// that churn, not the arithmetic, was most of the exact stage of a protected CDT (cheese: 36 000
// exact insphere tests at 125 000 instructions each). Here every entry and minor is allocated
// once, at its final size, and products accumulate with mpz_addmul / mpz_submul. The formulas
// and the expansion are those of generic_predicates.cpp and homogeneous.h; integer arithmetic
// is exact, so the order of the operations cannot change a sign.
namespace cavity::predicates::detail {

using ExactInteger =
    boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

/// The homogeneous coordinates of s (homogeneous.h) with every coordinate of a and b scaled by
/// 2^-scale and the numerator and denominator by 2^-parameter_scale, each an integer then: the
/// row that homogeneous<ExactInteger> makes of them, without its temporaries.
Homogeneous<ExactInteger> segment_row(const SegmentParameterPoint& s,
                                      int scale,
                                      int parameter_scale);

/// The sign of det[X Y Z W] over the four rows.
int homogeneous_orient3d_sign(const std::array<Homogeneous<ExactInteger>, 4>& rows);

/// The sign of det[XW YW ZW X^2+Y^2+Z^2 W^2] over the five rows.
int homogeneous_insphere_sign(const std::array<Homogeneous<ExactInteger>, 5>& rows);

}  // namespace cavity::predicates::detail
