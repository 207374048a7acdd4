#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// Semi-static filter for insphere (FPG scheme, as in CGAL's Side_of_oriented_sphere_3).
//
// Evaluation (Shewchuk's order): with differences to e, the 2x2 minors ab = aex*bey - bex*aey
// etc., the 3x3 minors abc = aez*bc - bez*ac + cez*ab etc. and the lifts alift = aex^2 + aey^2 +
// aez^2,  det = (dlift*abc - clift*dab) + (blift*cda - alift*bcd).
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

/// The insphere determinant det[p-e, |p-e|^2] in plain double arithmetic, from the rounded
/// differences p-e (Shewchuk's order, above), shared by the semi-static filter below and the
/// static one (insphere_static_filter.h) so that both bounds describe the same evaluation.
[[gnu::always_inline]] inline double insphere_determinant(double aex,
                                                          double aey,
                                                          double aez,
                                                          double bex,
                                                          double bey,
                                                          double bez,
                                                          double cex,
                                                          double cey,
                                                          double cez,
                                                          double dex,
                                                          double dey,
                                                          double dez) {
    const double ab = aex * bey - bex * aey;
    const double bc = bex * cey - cex * bey;
    const double cd = cex * dey - dex * cey;
    const double da = dex * aey - aex * dey;
    const double ac = aex * cey - cex * aey;
    const double bd = bex * dey - dex * bey;

    const double abc = aez * bc - bez * ac + cez * ab;
    const double bcd = bez * cd - cez * bd + dez * bc;
    const double cda = cez * da + dez * ac + aez * cd;
    const double dab = dez * ab + aez * bd + bez * da;

    const double alift = aex * aex + aey * aey + aez * aez;
    const double blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez;
    const double dlift = dex * dex + dey * dey + dez * dez;

    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

/// insphere_determinant of the rounded differences of a..d to e: the evaluation of the static
/// filter and of the lattice test (lattice.h), which take the differences for nothing else.
[[gnu::always_inline]] inline double insphere_determinant(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    return insphere_determinant(a.x - e.x,
                                a.y - e.y,
                                a.z - e.z,
                                b.x - e.x,
                                b.y - e.y,
                                b.z - e.z,
                                c.x - e.x,
                                c.y - e.y,
                                c.z - e.z,
                                d.x - e.x,
                                d.y - e.y,
                                d.z - e.z);
}

/// +1 or -1 when the sign of det[p-e, |p-e|^2] (p = a..d) is certified, 0 when undecided.
[[gnu::always_inline]] inline int insphere_filter(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const double aex = a.x - e.x;
    const double aey = a.y - e.y;
    const double aez = a.z - e.z;
    const double bex = b.x - e.x;
    const double bey = b.y - e.y;
    const double bez = b.z - e.z;
    const double cex = c.x - e.x;
    const double cey = c.y - e.y;
    const double cez = c.z - e.z;
    const double dex = d.x - e.x;
    const double dey = d.y - e.y;
    const double dez = d.z - e.z;

    const double det =
        insphere_determinant(aex, aey, aez, bex, bey, bez, cex, cey, cez, dex, dey, dez);

    const double maxx =
        std::max(std::max(std::abs(aex), std::abs(bex)), std::max(std::abs(cex), std::abs(dex)));
    const double maxy =
        std::max(std::max(std::abs(aey), std::abs(bey)), std::max(std::abs(cey), std::abs(dey)));
    const double maxz =
        std::max(std::max(std::abs(aez), std::abs(bez)), std::max(std::abs(cez), std::abs(dez)));
    const double lo = std::min(std::min(maxx, maxy), maxz);
    const double m = std::max(std::max(maxx, maxy), maxz);
    const double eps = kInsphereErrorBound * maxx * maxy * maxz * (m * m);
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
