#pragma once

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

// The last stage: exact integer arithmetic (GMP mpz) on the whole query scaled by a power of two.
// Correct for every finite input, whatever the exponent spread; costs microseconds.
namespace cavity::predicates::detail {

Sign orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

Sign insphere_exact(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e);

Sign orient4d_exact(const WeightedPoint3& a,
                    const WeightedPoint3& b,
                    const WeightedPoint3& c,
                    const WeightedPoint3& d,
                    const WeightedPoint3& e);

}  // namespace cavity::predicates::detail
