#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// Semi-static filter for orient3d (Meyer and Pion's FPG scheme, as in CGAL's Orientation_3).
//
// Error bound. With u = 2^-53 and exact differences adx = a.x - d.x etc., the determinant
//   det = adz (bdx cdy - bdy cdx) + bdz (cdx ady - cdy adx) + cdz (adx bdy - ady bdx)
// has 6 monomials. Along any monomial's path through the evaluation the number of roundings is
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

/// The orient3d determinant in plain double arithmetic, from the rounded differences to d (the
/// order above), shared by the semi-static filter below and the static one
/// (orient3d_static_filter.h) so that both bounds describe the same evaluation.
[[gnu::always_inline]] inline double orient3d_determinant(double adx,
                                                          double ady,
                                                          double adz,
                                                          double bdx,
                                                          double bdy,
                                                          double bdz,
                                                          double cdx,
                                                          double cdy,
                                                          double cdz) {
    return adz * (bdx * cdy - bdy * cdx) + bdz * (cdx * ady - cdy * adx) +
           cdz * (adx * bdy - ady * bdx);
}

/// orient3d_determinant of the rounded differences of a, b, c to d: the evaluation of the static
/// filter and of the lattice test (lattice.h), which take the differences for nothing else.
[[gnu::always_inline]] inline double orient3d_determinant(const Point3& a,
                                                          const Point3& b,
                                                          const Point3& c,
                                                          const Point3& d) {
    return orient3d_determinant(a.x - d.x,
                                a.y - d.y,
                                a.z - d.z,
                                b.x - d.x,
                                b.y - d.y,
                                b.z - d.z,
                                c.x - d.x,
                                c.y - d.y,
                                c.z - d.z);
}

/// +1 or -1 when the sign of det[a-d; b-d; c-d] is certified, 0 when the filter cannot decide.
inline int orient3d_filter(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    const double adx = a.x - d.x;
    const double ady = a.y - d.y;
    const double adz = a.z - d.z;
    const double bdx = b.x - d.x;
    const double bdy = b.y - d.y;
    const double bdz = b.z - d.z;
    const double cdx = c.x - d.x;
    const double cdy = c.y - d.y;
    const double cdz = c.z - d.z;

    const double det = orient3d_determinant(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz);

    const double maxx = std::max(std::max(std::abs(adx), std::abs(bdx)), std::abs(cdx));
    const double maxy = std::max(std::max(std::abs(ady), std::abs(bdy)), std::abs(cdy));
    const double maxz = std::max(std::max(std::abs(adz), std::abs(bdz)), std::abs(cdz));
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
