#include "cavity/predicates/orient4d.h"

#include "exact_integer.h"

namespace cavity::predicates::detail {

Verdict orient4d_slow(const WeightedPoint3& a,
                      const WeightedPoint3& b,
                      const WeightedPoint3& c,
                      const WeightedPoint3& d,
                      const WeightedPoint3& e) {
    return {orient4d_exact(a, b, c, d, e), Stage::kExact};
}

}  // namespace cavity::predicates::detail
