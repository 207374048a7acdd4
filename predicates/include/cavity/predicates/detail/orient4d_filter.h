#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/detail/translated_rows.h"
#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// Semi-static filter for the power test orient4d (FPG scheme, as in CGAL's
// Power_side_of_oriented_power_sphere_3). Translating by e and subtracting 2e.(p - e) times the
// coordinate columns turns det[p - e, h_p - h_e] into det[p - e, |p - e|^2 - (w_p - w_e)]: the
// insphere determinant with lifts t_p = |p - e|^2 - dw_p, dw_p = w_p - w_e. So the lift is exact
// up to the roundings counted below, never a rounded |p|^2 - w.
//
// Error bound (u = 2^-53). Expanded, det has 72 monomials x*y*z*s^2 (s a coordinate difference),
// each at most maxx*maxy*maxz*m^2, and 4 * 6 = 24 monomials x*y*z*dw, each at most
// maxx*maxy*maxz*maxw (m = max(maxx, maxy, maxz), maxw = max |dw|), all times (1 + u)^5 for the
// rounded maxima. Roundings along a path: for the squares 5 (differences) + 4 (lift: square, two
// additions, the subtraction of dw) + 5 (3x3 minor) + 1 (lift times minor) + 2 (final sum) = 17;
// for the weights 3 + 1 (dw) + 1 + 5 + 1 + 2 = 13. Hence the error is at most
// gamma_17 (72 m^2 + 24 maxw) (1 + u)^5 maxx*maxy*maxz <= 1632u (1 + 23u) maxx*maxy*maxz *
// max(m^2, maxw); rounding eps and underflow are covered by rounding up to 1728u.
//
// Range guards: coordinate maxima in [2^-190, 2^190] as for insphere, maxw <= 2^380 (the square
// of the upper guard, so lifts stay below 2^382 and the determinant below 2^960). maxw may be 0
// (all weights equal): the bound then rests on m^2 >= 2^-380.
inline constexpr double kOrient4dErrorBound = 1728.0 * 0x1p-53;
inline constexpr double kOrient4dMinMax = 0x1p-190;
inline constexpr double kOrient4dMaxMax = 0x1p190;
inline constexpr double kOrient4dMaxWeight = 0x1p380;

/// +1 or -1 when the sign of det[p-e, |p-e|^2 - (w_p - w_e)] (p = a..d) is certified, 0 when
/// undecided.
inline int orient4d_filter(const WeightedPoint3& a,
                           const WeightedPoint3& b,
                           const WeightedPoint3& c,
                           const WeightedPoint3& d,
                           const WeightedPoint3& e) {
    // The rows and weights translated to e; the rows are those of insphere_rows_determinant.
    const Point3 ae = translated(a, e);
    const Point3 be = translated(b, e);
    const Point3 ce = translated(c, e);
    const Point3 de = translated(d, e);
    const double aew = a.w - e.w;
    const double bew = b.w - e.w;
    const double cew = c.w - e.w;
    const double dew = d.w - e.w;

    const double det = lifted_determinant(ae,
                                          be,
                                          ce,
                                          de,
                                          squared_norm(ae) - aew,
                                          squared_norm(be) - bew,
                                          squared_norm(ce) - cew,
                                          squared_norm(de) - dew);

    const Point3 cmax = column_maxima(ae, be, ce, de);
    const double maxw =
        std::max(std::max(std::abs(aew), std::abs(bew)), std::max(std::abs(cew), std::abs(dew)));
    const double lo = std::min(std::min(cmax.x, cmax.y), cmax.z);
    const double m = std::max(std::max(cmax.x, cmax.y), cmax.z);
    const double eps = kOrient4dErrorBound * cmax.x * cmax.y * cmax.z * std::max(m * m, maxw);
    // One well-predicted branch: the guards and the bound are combined without short-circuit
    // (eps may be inf or 0 when a guard fails; the guard then decides), and the sign is computed
    // without branching on the random sign of det.
    const bool certified = (lo >= kOrient4dMinMax) & (m <= kOrient4dMaxMax) &
                           (maxw <= kOrient4dMaxWeight) & (std::abs(det) > eps);
    if (!certified) {
        return 0;
    }
    return det > 0.0 ? 1 : -1;
}

}  // namespace cavity::predicates::detail
