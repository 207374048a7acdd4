#pragma once

#include "cavity/predicates/detail/orient4d_filter.h"
#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

namespace detail {

/// The stages after the filter, out of line: kept out of the callers' inlined fast path.
Verdict orient4d_slow(const WeightedPoint3& a,
                      const WeightedPoint3& b,
                      const WeightedPoint3& c,
                      const WeightedPoint3& d,
                      const WeightedPoint3& e);

}  // namespace detail

/// orient4d, also reporting the stage that decided.
inline Verdict orient4d_staged(const WeightedPoint3& a,
                               const WeightedPoint3& b,
                               const WeightedPoint3& c,
                               const WeightedPoint3& d,
                               const WeightedPoint3& e) {
    if (const int s = detail::orient4d_filter(a, b, c, d, e)) {
        return {static_cast<Sign>(s), Stage::kFilter};
    }
    return detail::orient4d_slow(a, b, c, d, e);
}

/// The power test. Sign of det[p-e, h_p-h_e] over the rows p = a, b, c, d, with the lifted height
/// h_p = |p|^2 - w_p computed exactly inside the predicate. kPos when the lifted e lies below the
/// witness plane of the lifted a, b, c, d if they are positively oriented: e is in conflict with
/// (encroaches upon) the weighted tetrahedron abcd. Equals insphere when every weight is zero.
/// Exact for every finite double input.
inline Sign orient4d(const WeightedPoint3& a,
                     const WeightedPoint3& b,
                     const WeightedPoint3& c,
                     const WeightedPoint3& d,
                     const WeightedPoint3& e) {
    return orient4d_staged(a, b, c, d, e).sign;
}

}  // namespace cavity::predicates
