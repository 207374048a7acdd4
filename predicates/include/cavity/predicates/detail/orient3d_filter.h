#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/detail/translated_rows.h"
#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// Semi-static filter for orient3d (Meyer and Pion's FPG scheme, as in CGAL's Orientation_3).
//
// Error bound. With u = 2^-53 and exact differences adx = a.x - d.x etc., the determinant
//   det = adz (bdx cdy - bdy cdx) + bdz (cdx ady - cdy adx) + cdz (adx bdy - ady bdx)
// (evaluated as written by orient3d_rows_determinant, translated_rows.h) has 6 monomials. Along
// any monomial's path through the evaluation the number of roundings is
//   3 (the three differences) + 1 (the product bdx*cdy) + 1 (the 2x2 minor's subtraction)
//   + 1 (the product with adz) + 2 (the sum of three terms) = 8,
// so |computed - det| <= gamma_8 * sum|monomials| (Higham, Accuracy and Stability, §3.1), with
// gamma_8 = 8u / (1 - 8u). Each monomial is at most maxx*maxy*maxz times (1 + u)^3 (the maxima
// are taken over the rounded differences, |exact| <= (1 + u) |rounded|), so the error is at most
// 48u (1 + 12u) maxx*maxy*maxz. eps itself is computed with three roundings (down by at most
// (1 - u)^3), and the range guards make underflow errors (at most 2^-1075 per product, scaled by
// the remaining factors) smaller than 2^-600 relative to eps. 50u covers all of it.
//
// Range guards: every column maximum lies in [2^-300, 2^330]. Then no product overflows (the
// determinant is below 6 * 2^990), eps >= 50u * 2^-900 is a normal number, and a maximum that is
// 0 (a degenerate column) or inf (an overflowed difference) fails the guard.
inline constexpr double kOrient3dErrorBound = 50.0 * 0x1p-53;
inline constexpr double kOrient3dMinMax = 0x1p-300;
inline constexpr double kOrient3dMaxMax = 0x1p330;

/// orient3d_rows_determinant of the rounded differences of a, b, c to d: the evaluation of the
/// static filter and of the lattice test (lattice.h), which take the differences for nothing else.
[[gnu::always_inline]] inline double orient3d_determinant(const Point3& a,
                                                          const Point3& b,
                                                          const Point3& c,
                                                          const Point3& d) {
    return orient3d_rows_determinant(translated(a, d), translated(b, d), translated(c, d));
}

/// +1 or -1 when the sign of det[a-d; b-d; c-d] is certified, 0 when the filter cannot decide.
inline int orient3d_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const Point3 ad = translated(a, d);
    const Point3 bd = translated(b, d);
    const Point3 cd = translated(c, d);

    const double det = orient3d_rows_determinant(ad, bd, cd);

    const double maxx = std::max(std::max(std::abs(ad.x), std::abs(bd.x)), std::abs(cd.x));
    const double maxy = std::max(std::max(std::abs(ad.y), std::abs(bd.y)), std::abs(cd.y));
    const double maxz = std::max(std::max(std::abs(ad.z), std::abs(bd.z)), std::abs(cd.z));
    const double lo = std::min(std::min(maxx, maxy), maxz);
    const double hi = std::max(std::max(maxx, maxy), maxz);
    const double eps = kOrient3dErrorBound * maxx * maxy * maxz;
    // One well-predicted branch: the guards and the bound are combined without short-circuit
    // (eps may be inf or 0 when a guard fails; the guard then decides), and the sign is computed
    // without branching on the random sign of det.
    const bool certified =
        (lo >= kOrient3dMinMax) & (hi <= kOrient3dMaxMax) & (std::abs(det) > eps);
    if (!certified) {
        return 0;
    }
    return det > 0.0 ? 1 : -1;
}

}  // namespace cavity::predicates::detail
