#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "cavity/predicates/detail/insphere_filter.h"
#include "cavity/predicates/point.h"

namespace cavity::predicates {

/// A static filter for insphere (as in Shewchuk's, TetGen's and HXT's static filters): one error
/// bound for every query whose five points lie in a given axis-aligned box, fixed when the box is,
/// so that a query costs the plain determinant and one comparison. It answers only when certain
/// and otherwise defers (0) to the exact insphere, whose semi-static filter is tighter for small
/// local spacing.
///
/// Why the bound holds. Let the box have extents X = fl(xmax - xmin), Y, Z and M = max(X, Y, Z).
/// For points in the box |a.x - e.x| <= xmax - xmin exactly, and rounding to nearest is monotone,
/// so every rounded difference has |fl(a.x - e.x)| <= X (likewise Y, Z). The semi-static filter's
/// derivation (detail/insphere_filter.h) bounds the rounding error of insphere_determinant, the
/// same evaluation, by 1152u (1 + 22u) maxx maxy maxz m^2 with the per-query column maxima; that
/// bound grows with each maximum, so 1152u (1 + 22u) X Y Z M^2 bounds it for every query in the
/// box. The derivation assumes no underflow, which the semi-static filter enforces per query; here
/// a query's own maxima may be tiny, so underflow is accounted for instead: each of the 40
/// products may lose at most 2^-1075 absolutely (subtractions and sums of subnormals are exact),
/// and what follows a product multiplies that loss by at most 7 (M^3 + 1) (a 2x2 minor enters
/// two 3x3 minors times z and a lift: 2 * Z * 3M^2; a 3x3 minor product is multiplied by a lift;
/// a squared coordinate by a 3x3 minor, at most 6 X Y Z). With each extent in
/// [2^-190, 2^190], 40 * 7 (M^3 + 1) 2^-1075 is below 2^-70 of 1152u X Y Z M^2, and the lifts
/// stay below 3 * 2^380 and the determinant below 2^960 (no overflow). The constant 1224u,
/// evaluated below with five roundings, covers 1152u (1 + 22u) + 2^-70 with room to spare, as in
/// the semi-static filter. Outside the guards the filter never answers (the bound is +inf).
class InsphereStaticFilter {
public:
    /// Never answers: for an empty or unbounded set of points.
    InsphereStaticFilter() = default;

    /// For points in the box [lo, hi] (lo <= hi coordinatewise, both finite).
    InsphereStaticFilter(const Point3& lo, const Point3& hi) {
        const double x = hi.x - lo.x;
        const double y = hi.y - lo.y;
        const double z = hi.z - lo.z;
        const double smallest = std::min(std::min(x, y), z);
        const double largest = std::max(std::max(x, y), z);
        if (smallest >= detail::kInsphereMinMax && largest <= detail::kInsphereMaxMax) {
            bound_ = detail::kInsphereErrorBound * x * y * z * (largest * largest);
        }
    }

    /// For points where the plain determinant is exact (integer points of an exact lattice box,
    /// lattice.h): the bound is 0, so only an exact zero is left undecided.
    static InsphereStaticFilter exact() {
        InsphereStaticFilter filter;
        filter.bound_ = 0.0;
        return filter;
    }

    /// +1 or -1 when the sign of det[p-e, |p-e|^2] (p = a..d) is certified, 0 when undecided.
    /// Every point must lie in the box the filter was made for.
    [[gnu::always_inline]] int sign(
        const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) const {
        const double det = detail::insphere_determinant(a, b, c, d, e);
        // One well-predicted branch; the sign itself is computed without branching on it.
        if (!(std::abs(det) > bound_)) {
            return 0;
        }
        return det > 0.0 ? 1 : -1;
    }

private:
    double bound_ = std::numeric_limits<double>::infinity();
};

}  // namespace cavity::predicates
