#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/detail/translated_rows.h"
#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// Semi-static filter for insphere (FPG scheme, as in CGAL's Side_of_oriented_sphere_3).
//
// Evaluation (Shewchuk's order): with differences to e, the 2x2 minors ab = aex*bey - bex*aey
// etc., the 3x3 minors abc = aez*bc - bez*ac + cez*ab etc. and the lifts alift = aex^2 + aey^2 +
// aez^2,  det = (dlift*abc - clift*dab) + (blift*cda - alift*bcd) (lifted_determinant and
// squared_norm, translated_rows.h).
//
// Error bound (u = 2^-53). Expanded, det has 4 * 3 * 6 = 72 monomials x*y*z*t^2 (three from the
// lift times six from the 3x3 minor, for each of the four rows), each at most
// maxx*maxy*maxz*m^2 with m = max(maxx, maxy, maxz), times (1 + u)^5 for the rounded maxima.
// Roundings along any monomial's path:
//   5 (differences: x, y, z, and the squared coordinate twice)
//   + 3 (lift: the square, two additions) + 5 (3x3 minor: product, subtraction, product with z,
//   two additions) + 1 (lift times minor) + 2 (final two-level sum) = 16,
// so the error is at most gamma_16 * 72 (1 + u)^5 maxx*maxy*maxz*m^2 = 1152u (1 + 22u) * (...).
// Rounding of eps and underflow (below 2^-120 relative to eps under the guards) are covered by
// rounding the constant up generously to 1224u.
//
// Range guards: every column maximum lies in [2^-190, 2^190]: the lifts stay below 3 * 2^380, the
// determinant below 2^960, eps above 2^-1000, and 0 or inf maxima fail the guard.
inline constexpr double kInsphereErrorBound = 1224.0 * 0x1p-53;
inline constexpr double kInsphereMinMax = 0x1p-190;
inline constexpr double kInsphereMaxMax = 0x1p190;

/// The insphere determinant det[p-e, |p-e|^2] in plain double arithmetic, from the rows p-e
/// already translated (Shewchuk's order, above: lifted_determinant with the lifts squared_norm),
/// shared by the semi-static filter below, the static one (insphere_static_filter.h) and the
/// rounded stage (generic_filter.h) so that every bound describes the same evaluation.
[[gnu::always_inline]] inline double insphere_rows_determinant(const Point3& ae,
                                                               const Point3& be,
                                                               const Point3& ce,
                                                               const Point3& de) {
    return lifted_determinant(
        ae, be, ce, de, squared_norm(ae), squared_norm(be), squared_norm(ce), squared_norm(de));
}

/// insphere_rows_determinant of the rounded differences of a..d to e: the evaluation of the static
/// filter and of the lattice test (lattice.h), which take the differences for nothing else.
[[gnu::always_inline]] inline double insphere_determinant(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    return insphere_rows_determinant(
        translated(a, e), translated(b, e), translated(c, e), translated(d, e));
}

/// +1 or -1 when the sign of det[p-e, |p-e|^2] (p = a..d) is certified, 0 when undecided.
[[gnu::always_inline]] inline int insphere_filter(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const Point3 ae = translated(a, e);
    const Point3 be = translated(b, e);
    const Point3 ce = translated(c, e);
    const Point3 de = translated(d, e);

    const double det = insphere_rows_determinant(ae, be, ce, de);

    const Point3 cmax = column_maxima(ae, be, ce, de);
    const double lo = std::min(std::min(cmax.x, cmax.y), cmax.z);
    const double m = std::max(std::max(cmax.x, cmax.y), cmax.z);
    const double eps = kInsphereErrorBound * cmax.x * cmax.y * cmax.z * (m * m);
    // One well-predicted branch: the guards and the bound are combined without short-circuit
    // (eps may be inf or 0 when a guard fails; the guard then decides), and the sign is computed
    // without branching on the random sign of det.
    const bool certified = (lo >= kInsphereMinMax) & (m <= kInsphereMaxMax) & (std::abs(det) > eps);
    if (!certified) {
        return 0;
    }
    return det > 0.0 ? 1 : -1;
}

}  // namespace cavity::predicates::detail
