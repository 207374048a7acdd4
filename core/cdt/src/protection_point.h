#pragma once

#include <optional>

#include "cavity/predicates/point.h"

namespace cavity::core {

using predicates::Point3;

/// protection_point (edge_protection.h) without the sieve in front of it (double_point_sieve.h):
/// the search by GMP rationals alone, the tests' oracle for the sieve.
std::optional<Point3> rational_protection_point(
    const Point3& a, const Point3& b, double target, double lo, double hi);

}  // namespace cavity::core
