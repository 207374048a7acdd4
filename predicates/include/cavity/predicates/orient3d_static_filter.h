#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "cavity/predicates/detail/orient3d_filter.h"
#include "cavity/predicates/point.h"

namespace cavity::predicates {

/// A static filter for orient3d (the orient3d counterpart of InsphereStaticFilter, as in
/// Shewchuk's, TetGen's and HXT's static filters): one error bound for every query whose four
/// points lie in a given axis-aligned box, fixed when the box is, so that a query costs the plain
/// determinant and one comparison. It answers only when certain and otherwise defers (0) to the
/// exact orient3d, whose semi-static filter is tighter for small local spacing.
///
/// Why the bound holds. Let the box have extents X = fl(xmax - xmin), Y, Z and M = max(X, Y, Z).
/// For points in the box |a.x - d.x| <= xmax - xmin exactly, and rounding to nearest is monotone,
/// so every rounded difference has |fl(a.x - d.x)| <= X (likewise Y, Z). The semi-static filter's
/// derivation (detail/orient3d_filter.h) bounds the rounding error of orient3d_determinant, the
/// same evaluation, by 48u (1 + 12u) maxx maxy maxz with the per-query column maxima; that bound
/// grows with each maximum, so 48u (1 + 12u) X Y Z bounds it for every query in the box.
/// That derivation assumes no underflow, which the semi-static filter enforces per query; here a
/// query's own maxima may be tiny, so underflow is accounted for instead. A product whose result is
/// subnormal loses at most 2^-1075 absolutely on top of its relative rounding, and a sum or
/// difference with a subnormal result is exact. Of the 9 products, the 6 inside the 2x2 minors pass
/// their loss on through one subtraction and one multiplication by a z difference (|z| <= Z <= M)
/// and the final two additions, the 3 outer ones through the two additions only, so underflow
/// adds at most 3 (2M + 1) 2^-1075 (1 + u)^4 <= 7 (M + 1) 2^-1075.
///
/// Guards: each extent in [2^-300, 2^330]. Then 1 <= 2^300 M and X Y Z >= 2^-600 M (the two
/// smaller extents are at least 2^-300), so the underflow term is at most
/// 7 (2^300 + 1) M 2^-1075 <= 2^-771 M <= 2^-171 X Y Z, below 2^-120 of 48u X Y Z. Every product
/// stays below 2^990 and the determinant below 6 * 2^990 (no overflow), and the bound, computed as
/// ((50u X) Y) Z, stays between 2^-947 and 2^944: normal, so its three roundings lower it by a
/// factor of at most (1 - u)^3. 50u (1 - u)^3 covers 48u (1 + 12u) plus 2^-120 * 48u with room to
/// spare; it is the semi-static filter's constant. Outside the guards (a flat, tiny, huge or
/// unbounded box) the filter never answers (the bound is +inf).
class Orient3dStaticFilter {
public:
    /// Never answers: for an empty or unbounded set of points.
    Orient3dStaticFilter() = default;

    /// For points in the box [lo, hi] (lo <= hi coordinatewise, both finite).
    Orient3dStaticFilter(const Point3& lo, const Point3& hi) {
        const double x = hi.x - lo.x;
        const double y = hi.y - lo.y;
        const double z = hi.z - lo.z;
        const double smallest = std::min(std::min(x, y), z);
        const double largest = std::max(std::max(x, y), z);
        if (smallest >= detail::kOrient3dMinMax && largest <= detail::kOrient3dMaxMax) {
            bound_ = detail::kOrient3dErrorBound * x * y * z;
        }
    }

    /// +1 or -1 when the sign of det[a-d; b-d; c-d] is certified, 0 when undecided.
    /// Every point must lie in the box the filter was made for.
    [[gnu::always_inline]] int sign(const Point3& a,
                                    const Point3& b,
                                    const Point3& c,
                                    const Point3& d) const {
        const double det = detail::orient3d_determinant(a, b, c, d);
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
