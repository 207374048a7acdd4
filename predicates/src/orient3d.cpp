#include "cavity/predicates/orient3d.h"

#include "exact_integer.h"

namespace cavity::predicates::detail {

Verdict orient3d_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return {orient3d_exact(a, b, c, d), Stage::kExact};
}

}  // namespace cavity::predicates::detail
