#pragma once

#include <array>
#include <cstdint>

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"

/// A brute-force symbolic oracle for the perturbed predicates, sharing no code with them: each
/// determinant is expanded from its definition over polynomials in eps with exact rational
/// coefficients (GMP), the heights lowered by eps^(key + 1), and the sign is that of the
/// lowest-order nonzero coefficient. Keys must be small (the polynomials are dense in eps).
namespace cavity::perturbation::test {

using predicates::Point3;
using predicates::Sign;
using predicates::WeightedPoint3;

/// Sign of the 5x5 determinant with rows (x, y, z, |p|^2 - w - eps^(key + 1), 1) in argument order.
Sign symbolic_lifted(const std::array<WeightedPoint3, 5>& p,
                     const std::array<std::uint32_t, 5>& keys);

/// Sign of the 4x4 determinant with rows (x, y, z, 1): Shewchuk's orient3d.
Sign symbolic_orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

/// The perturbed outer halfspace of triangle vwx: kPos when u is strictly on the other side of the
/// plane of vwx than y, kNeg on y's side; for u in the plane, the perturbed 2D (power) in-circle
/// test of u against v, w, x, computed in a coordinate plane onto which vwx projects without
/// degenerating.
Sign symbolic_outer_halfspace(const WeightedPoint3& v,
                              const WeightedPoint3& w,
                              const WeightedPoint3& x,
                              const WeightedPoint3& y,
                              const WeightedPoint3& u,
                              const std::array<std::uint32_t, 4>& keys);

}  // namespace cavity::perturbation::test
