#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <tuple>

#include "cavity/predicates/detail/insphere_filter.h"
#include "cavity/predicates/detail/orient3d_filter.h"
#include "cavity/predicates/detail/translated_rows.h"
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
///  (2) the evaluation: along the shared expansions (orient3d_rows_determinant and
///      insphere_rows_determinant, the ones every other floating-point stage uses) every monomial
///      of P(v) passes through at most j roundings (orient3d j = 5: the 2x2 product and
///      difference, the product by the z column, the sum of three; insphere j = 11: the lift's
///      square and two sums, the 3x3 minor's five, their product, the final sum of four), so by
///      the standard lemma (Higham, Accuracy and Stability of Numerical Algorithms, 3.1 and 3.3)
///      |fl(P(v)) - P(v)| <= gamma_j N m^k with gamma_j = j u / (1 - j u) when nothing underflows.
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

/// Point g translated by -o, in doubles, with a bound on their distance to the exact translated
/// point in every coordinate, computed without intervals: the generic predicates' first stage,
/// several times cheaper than their interval rows. nullopt for a LinePlanePoint (its rounding
/// divides two degree-4 expressions) and for a SegmentParameterPoint whose parameter underflows.
std::optional<RoundedPoint> translated_rounded(const GenericPoint3& g, const Point3& o);

namespace detail {

inline constexpr double kUnitRoundoff = 0x1p-53;
inline constexpr double kRoundedMin = 0x1p-150;  // the range of m the bound is proven for
inline constexpr double kRoundedMax = 0x1p150;

inline bool in_rounded_range(double m) {
    return m >= kRoundedMin && m <= kRoundedMax;  // false on NaN
}

/// A query of rounded points translated to its last one, `origin`: the rows v_i = fl(r_i -
/// r_origin), m = max |v_i| over every coordinate, eta and M = m + eta, as in the bound above.
template <std::size_t N>
struct RoundedRows {
    std::array<Point3, N> v;
    double m;
    double eta;
    double big_m;
};

template <class... Rounded>
inline RoundedRows<sizeof...(Rounded)> rounded_rows(const RoundedPoint& origin,
                                                    const Rounded&... points) {
    RoundedRows<sizeof...(Rounded)> rows{{translated(points.p, origin.p)...}, 0.0, 0.0, 0.0};
    rows.m = std::apply([](const auto&... v) { return max_magnitude(v...); }, rows.v);
    rows.eta = (std::max({points.error...}) + origin.error) + kUnitRoundoff * rows.m;
    rows.big_m = rows.m + rows.eta;
    return rows;
}

/// The sign of det when |det| exceeds the bound, else 0 (also when either is NaN).
inline int rounded_sign(double det, double bound) {
    if (det > bound) {
        return 1;
    }
    if (-det > bound) {
        return -1;
    }
    return 0;
}

}  // namespace detail

/// A determinant evaluated on rounded points and a bound on its distance to the exact points'.
struct RoundedValue {
    double value;
    double bound;
};

/// orient3d's determinant (orient3d.h's convention) on the rounded points, within `bound` of its
/// value on the exact points; nullopt outside the range the bound is proven for. For a caller
/// that needs the magnitude as well as the sign (a crossing point's parameter, the ratio of two
/// such determinants).
inline std::optional<RoundedValue> orient3d_rounded_value(const RoundedPoint& a,
                                                          const RoundedPoint& b,
                                                          const RoundedPoint& c,
                                                          const RoundedPoint& d) {
    const auto q = detail::rounded_rows(d, a, b, c);
    if (!detail::in_rounded_range(q.m)) {
        return std::nullopt;
    }
    return RoundedValue{
        detail::orient3d_rows_determinant(q.v[0], q.v[1], q.v[2]),
        19.0 * q.eta * (q.big_m * q.big_m) + 31.0 * detail::kUnitRoundoff * (q.m * q.m * q.m)};
}

/// The sign of orient3d (orient3d.h's convention) on the exact points, or 0 when undecided.
inline int orient3d_rounded(const RoundedPoint& a,
                            const RoundedPoint& b,
                            const RoundedPoint& c,
                            const RoundedPoint& d) {
    const auto r = orient3d_rounded_value(a, b, c, d);
    return r ? detail::rounded_sign(r->value, r->bound) : 0;
}

/// The sign of insphere (insphere.h's convention) on the exact points, or 0 when undecided.
inline int insphere_rounded(const RoundedPoint& a,
                            const RoundedPoint& b,
                            const RoundedPoint& c,
                            const RoundedPoint& d,
                            const RoundedPoint& e) {
    const auto q = detail::rounded_rows(e, a, b, c, d);
    if (!detail::in_rounded_range(q.m)) {
        return 0;
    }
    const double det = detail::insphere_rows_determinant(q.v[0], q.v[1], q.v[2], q.v[3]);
    const double big_m2 = q.big_m * q.big_m;
    const double m2 = q.m * q.m;
    const double bound =
        361.0 * q.eta * (big_m2 * big_m2) + 793.0 * detail::kUnitRoundoff * (m2 * m2 * q.m);
    return detail::rounded_sign(det, bound);
}

}  // namespace cavity::predicates
