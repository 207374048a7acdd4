#pragma once

#include "cavity/predicates/detail/insphere_filter.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

namespace detail {

/// The stages after the filter, out of line: kept out of the callers' inlined fast path.
Verdict insphere_slow(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e);

}  // namespace detail

/// insphere, also reporting the stage that decided.
[[gnu::always_inline]] inline Verdict insphere_staged(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    if (const int s = detail::insphere_filter(a, b, c, d, e)) {
        return {static_cast<Sign>(s), Stage::kFilter};
    }
    return detail::insphere_slow(a, b, c, d, e);
}

/// Sign of det[p-e, |p-e|^2] over the rows p = a, b, c, d: kPos when e lies inside the circumball
/// of a, b, c, d if they are positively oriented (the sign flips when they are negatively
/// oriented). Exact for every finite double input.
[[gnu::always_inline]] inline Sign insphere(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    return insphere_staged(a, b, c, d, e).sign;
}

}  // namespace cavity::predicates
