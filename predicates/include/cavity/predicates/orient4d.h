#pragma once

#include "cavity/predicates/point.h"
#include "cavity/predicates/sign.h"
#include "cavity/predicates/stage.h"

namespace cavity::predicates {

/// The power test. Sign of det[p-e, h_p-h_e] over the rows p = a, b, c, d, with the lifted height
/// h_p = |p|^2 - w_p computed exactly inside the predicate. kPos when the lifted e lies below the
/// witness plane of the lifted a, b, c, d if they are positively oriented: e is in conflict with
/// (encroaches upon) the weighted tetrahedron abcd. Equals insphere when every weight is zero.
/// Exact for every finite double input.
Sign orient4d(const WeightedPoint3& a,
              const WeightedPoint3& b,
              const WeightedPoint3& c,
              const WeightedPoint3& d,
              const WeightedPoint3& e);

/// orient4d, also reporting the stage that decided.
Verdict orient4d_staged(const WeightedPoint3& a,
                        const WeightedPoint3& b,
                        const WeightedPoint3& c,
                        const WeightedPoint3& d,
                        const WeightedPoint3& e);

}  // namespace cavity::predicates
