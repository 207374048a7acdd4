#pragma once

// rational_protection_point (protection_point.h) for a segment along which one coordinate alone
// varies, the usual case of CAD models (cheese.off: 98% of the searches), in double expansions
// instead of GMP rationals: the same search, piece by piece in the same order, with the same
// choice in each, so the same point. There the double points of the segment are the multiples of
// one power of two in the varying coordinate, and every parameter the general search divides by
// the segment's extent becomes a value of that coordinate, exact as an expansion of a few doubles.

#include <optional>

#include "cavity/predicates/point.h"

namespace cavity::core {

/// The answer of the axis search: `handled` false when the segment is not along one axis or its
/// numbers are outside the range the expansions are exact in (then ask rational_protection_point);
/// otherwise `point` is rational_protection_point's answer for the same arguments.
struct AxisSearch {
    bool handled = false;
    std::optional<predicates::Point3> point;
};

AxisSearch axis_protection_point(
    const predicates::Point3& a, const predicates::Point3& b, double target, double lo, double hi);

}  // namespace cavity::core
