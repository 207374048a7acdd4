#pragma once

#include "cavity/predicates/detail/orient3d_filter.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

namespace detail {

/// The stages after the filter, out of line: kept out of the callers' inlined fast path.
Verdict orient3d_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace detail

/// orient3d, also reporting the stage that decided. Costs the same as orient3d on the fast path;
/// instrumentation is chosen at compile time by calling this overload instead of orient3d.
inline Verdict orient3d_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    if (const int s = detail::orient3d_filter(a, b, c, d)) {
        return {static_cast<Sign>(s), Stage::kFilter};
    }
    return detail::orient3d_slow(a, b, c, d);
}

/// Sign of det[a-d; b-d; c-d]: kPos when a, b, c, d are positively oriented, i.e. d lies below the
/// plane of a, b, c seen with a, b, c counter-clockwise from above (Shewchuk's convention; CGAL's
/// orientation() is the opposite). Exact for every finite double input.
inline Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return orient3d_staged(a, b, c, d).sign;
}

}  // namespace cavity::predicates
