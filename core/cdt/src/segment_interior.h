#pragma once

// Whether an implicit point on a segment lies strictly between the segment's ends. Such a point
// inherits exact signs from the ends: a predicate affine in it (orient3d in one point, a side of a
// plane or of a line) has, strictly inside the segment, the ends' sign when they agree or one of
// them is zero, which spares the exact stage an implicit point's zero always costs.

#include "cavity/predicates/generic_point.h"

namespace cavity::core {

/// 0 < numerator / denominator < 1, exactly (the parameter's two doubles compared as given).
inline bool strictly_inside(const predicates::SegmentParameterPoint& s) {
    const double n = s.numerator;
    const double d = s.denominator;
    return (d > 0 && n > 0 && n < d) || (d < 0 && n < 0 && n > d);
}

}  // namespace cavity::core
