#include "cavity/predicates/insphere.h"

#include "exact_integer.h"

namespace cavity::predicates::detail {

Verdict insphere_slow(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    return {insphere_exact(a, b, c, d, e), Stage::kExact};
}

}  // namespace cavity::predicates::detail
