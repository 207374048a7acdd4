#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/point.h"

/// A floating-point stage for orient3d and insphere on generic points (generic_point.h), to run
/// before generic_predicates.h's interval filter: each point is given by doubles p and a bound on
/// how far its exact coordinates lie from them (computed once per point by rounding_error), and
/// the determinant of the p is taken in doubles under an error bound that covers both that
/// distance and the evaluation's rounding. It answers the sign or 0 (undecided: ask the staged
/// predicates). Explicit points have error 0.
///
/// The bound. Write u = 2^-53 (unit roundoff), r_i for the doubles of point i, x_i for its exact
/// coordinates, |x_i - r_i| <= err_i per coordinate. Both predicates translate the query to its
/// last point (d for orient3d, e for insphere): v_i = fl(r_i - r_last) is the computed
/// difference and x_i - x_last the exact one. A difference of doubles is exact when subnormal and
/// has relative error at most u otherwise (|fl(s) - s| <= u |fl(s)| under round-to-nearest), so
/// with m = max |v_i| over every coordinate,
///   |(x_i - x_last) - v_i| <= err_i + err_last + u m  <=  eta := max_i err_i + err_last + u m.
/// Each determinant is a homogeneous polynomial P of degree k in the differences with N monomials
/// of coefficient +-1 (orient3d: k = 3, N = 6; insphere, after the lift |v|^2 = x^2 + y^2 + z^2:
/// k = 5, N = 72). Two errors separate the computed value from P at the exact differences:
///  (1) the inputs: for one monomial, |prod x - prod v| <= prod(|v| + eta) - prod |v|
///      <= (m + eta)^k - m^k <= k eta (m + eta)^(k-1) (telescoping, then the mean value theorem),
///      so |P(x) - P(v)| <= N k eta M^(k-1) with M = m + eta;
///  (2) the evaluation: along the formulas below every monomial of P(v) passes through at most
///      j roundings (orient3d j = 5: the 2x2 product and difference, the product by the third
///      row, the sum of three; insphere j = 11: the lift's square and two sums, the 3x3 minor's
///      five, their product, the final sum of four), so by the standard lemma (Higham, Accuracy and
///      Stability of Numerical Algorithms, 3.1 and 3.3) |fl(P(v)) - P(v)| <= gamma_j N m^k with
///      gamma_j = j u / (1 - j u) when nothing underflows.
/// orient3d: 18 eta M^2 + 6 gamma_5 m^3 <= 18 eta M^2 + 30.001 u m^3;
/// insphere: 360 eta M^4 + 72 gamma_11 m^5 <= 360 eta M^4 + 792.01 u m^5.
/// The code uses 19 and 31 u, 361 and 793 u. The extra is what makes the bound computed in
/// doubles sound: (i) the bound's own evaluation (each term, eta and M included, is at most 1 +
/// 2^-47 below its exact value: fewer than thirty roundings) is covered by the extra factor
/// 1 + 10^-3 on each term; (ii) underflow (a sum that
/// lands below 2^-1022 is exact): a product that underflows errs by at most 2^-1075 absolutely,
/// there are fewer than a hundred products, and each is multiplied afterwards by factors no larger
/// than 8 max(1, m)^3 in magnitude, so underflow adds at most 2^-1065 max(1, m)^3; the extra
/// eta M^(k-1) >= u m^k covers that for m in [2^-150, 2^150], the only range the stage decides
/// in (outside it, or on a non-finite value, it answers 0); there the bound's terms stay above
/// 2^-810, so they do not underflow themselves. Within that range nothing overflows (|P(v)| <= 72
/// m^5 <= 2^757; an infinite eta or M makes the bound infinite and the stage undecided).
namespace cavity::predicates {

/// Doubles p within `error` of an exact point in every coordinate.
struct RoundedPoint {
    Point3 p;
    double error;
};

/// An upper bound on max |g - r| over the three coordinates (0 when g is the explicit point r),
/// +inf when it cannot be bounded (r not finite, or the filter cannot tell g's W from zero).
double rounding_error(const GenericPoint3& g, const Point3& r);

namespace detail {

inline constexpr double kUnitRoundoff = 0x1p-53;
inline constexpr double kRoundedMin = 0x1p-150;  // the range of m the bound is proven for
inline constexpr double kRoundedMax = 0x1p150;

inline bool in_rounded_range(double m) {
    return m >= kRoundedMin && m <= kRoundedMax;  // false on NaN
}

}  // namespace detail

/// The sign of orient3d (orient3d.h's convention) on the exact points, or 0 when undecided.
inline int orient3d_rounded(const RoundedPoint& a,
                            const RoundedPoint& b,
                            const RoundedPoint& c,
                            const RoundedPoint& d) {
    const double adx = a.p.x - d.p.x, ady = a.p.y - d.p.y, adz = a.p.z - d.p.z;
    const double bdx = b.p.x - d.p.x, bdy = b.p.y - d.p.y, bdz = b.p.z - d.p.z;
    const double cdx = c.p.x - d.p.x, cdy = c.p.y - d.p.y, cdz = c.p.z - d.p.z;
    const double m = std::max({std::abs(adx),
                               std::abs(ady),
                               std::abs(adz),
                               std::abs(bdx),
                               std::abs(bdy),
                               std::abs(bdz),
                               std::abs(cdx),
                               std::abs(cdy),
                               std::abs(cdz)});
    if (!detail::in_rounded_range(m)) {
        return 0;
    }
    const double det = adx * (bdy * cdz - bdz * cdy) + ady * (bdz * cdx - bdx * cdz) +
                       adz * (bdx * cdy - bdy * cdx);
    const double eta =
        (std::max({a.error, b.error, c.error}) + d.error) + detail::kUnitRoundoff * m;
    const double big_m = m + eta;
    const double bound = 19.0 * eta * (big_m * big_m) + 31.0 * detail::kUnitRoundoff * (m * m * m);
    if (det > bound) {
        return 1;
    }
    if (-det > bound) {
        return -1;
    }
    return 0;
}

/// The sign of insphere (insphere.h's convention) on the exact points, or 0 when undecided.
inline int insphere_rounded(const RoundedPoint& a,
                            const RoundedPoint& b,
                            const RoundedPoint& c,
                            const RoundedPoint& d,
                            const RoundedPoint& e) {
    const double aex = a.p.x - e.p.x, aey = a.p.y - e.p.y, aez = a.p.z - e.p.z;
    const double bex = b.p.x - e.p.x, bey = b.p.y - e.p.y, bez = b.p.z - e.p.z;
    const double cex = c.p.x - e.p.x, cey = c.p.y - e.p.y, cez = c.p.z - e.p.z;
    const double dex = d.p.x - e.p.x, dey = d.p.y - e.p.y, dez = d.p.z - e.p.z;
    const double m = std::max({std::abs(aex),
                               std::abs(aey),
                               std::abs(aez),
                               std::abs(bex),
                               std::abs(bey),
                               std::abs(bez),
                               std::abs(cex),
                               std::abs(cey),
                               std::abs(cez),
                               std::abs(dex),
                               std::abs(dey),
                               std::abs(dez)});
    if (!detail::in_rounded_range(m)) {
        return 0;
    }
    // det of the rows (v, |v|^2) by cofactors of the lift column: four 3x3 minors sharing six
    // 2x2 ones.
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
    const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    const double eta =
        (std::max({a.error, b.error, c.error, d.error}) + e.error) + detail::kUnitRoundoff * m;
    const double big_m = m + eta;
    const double big_m2 = big_m * big_m;
    const double m2 = m * m;
    const double bound =
        361.0 * eta * (big_m2 * big_m2) + 793.0 * detail::kUnitRoundoff * (m2 * m2 * m);
    if (det > bound) {
        return 1;
    }
    if (-det > bound) {
        return -1;
    }
    return 0;
}

}  // namespace cavity::predicates
