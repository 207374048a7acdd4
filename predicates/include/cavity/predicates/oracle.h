#pragma once

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

/// The independent exact oracle: every determinant evaluated from its definition over exact
/// rationals (Boost.Multiprecision on GMP). It shares no code with the staged predicates. Slow
/// (microseconds per call) and certain; used by the tests and by `cavity sign --oracle`.
namespace cavity::predicates::oracle {

Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e);

Sign orient4d(const WeightedPoint3& a,
              const WeightedPoint3& b,
              const WeightedPoint3& c,
              const WeightedPoint3& d,
              const WeightedPoint3& e);

}  // namespace cavity::predicates::oracle
