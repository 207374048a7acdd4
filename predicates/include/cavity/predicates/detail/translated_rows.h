#pragma once

#include <algorithm>
#include <cmath>

#include "cavity/predicates/point.h"

namespace cavity::predicates::detail {

// The floating-point stages of orient3d, insphere and orient4d (static, semi-static, rounded and
// small-integer) all translate a query to its last point and evaluate one determinant of the
// translated rows. Their error bounds (orient3d_filter.h, insphere_filter.h, orient4d_filter.h,
// the static filters and generic_filter.h) count the roundings along that evaluation, so every
// stage takes the rows and the cofactor expansions from here: an operation changed here changes
// them all, and each bound must then be derived again.

/// fl(p - q) in each coordinate: the row of p in a determinant translated to q.
[[gnu::always_inline]] inline Point3 translated(const Point3& p, const Point3& q) {
    return {p.x - q.x, p.y - q.y, p.z - q.z};
}

/// The same for the coordinates of weighted points (the weights are translated apart).
[[gnu::always_inline]] inline Point3 translated(const WeightedPoint3& p, const WeightedPoint3& q) {
    return {p.x - q.x, p.y - q.y, p.z - q.z};
}

/// max |coordinate| over the rows, folded left to right with std::max as std::max of the whole
/// list would (so a NaN is returned only when it is the first coordinate).
template <class... Rows>
[[gnu::always_inline]] inline double max_magnitude(const Point3& first, const Rows&... rest) {
    double m = std::max({std::abs(first.x), std::abs(first.y), std::abs(first.z)});
    ((m = std::max({m, std::abs(rest.x), std::abs(rest.y), std::abs(rest.z)})), ...);
    return m;
}

/// The largest |x|, |y| and |z| over four rows, each taken as max(max(a, b), max(c, d)): the
/// column maxima of the semi-static filters' bounds.
[[gnu::always_inline]] inline Point3 column_maxima(const Point3& a,
                                                   const Point3& b,
                                                   const Point3& c,
                                                   const Point3& d) {
    const auto column = [](double p, double q, double r, double s) {
        return std::max(std::max(std::abs(p), std::abs(q)), std::max(std::abs(r), std::abs(s)));
    };
    return {column(a.x, b.x, c.x, d.x), column(a.y, b.y, c.y, d.y), column(a.z, b.z, c.z, d.z)};
}

/// det[ad; bd; cd] of translated rows, in doubles, by cofactors of the z column:
/// ad.z (bd.x cd.y - bd.y cd.x) + bd.z (cd.x ad.y - cd.y ad.x) + cd.z (ad.x bd.y - ad.y bd.x).
/// Along any monomial's path: 2 roundings in the 2x2 minor, 1 for the product by z, 2 for the sum.
[[gnu::always_inline]] inline double orient3d_rows_determinant(const Point3& ad,
                                                               const Point3& bd,
                                                               const Point3& cd) {
    return ad.z * (bd.x * cd.y - bd.y * cd.x) + bd.z * (cd.x * ad.y - cd.y * ad.x) +
           cd.z * (ad.x * bd.y - ad.y * bd.x);
}

/// |v|^2 summed as (x^2 + y^2) + z^2: the lift of a translated row.
[[gnu::always_inline]] inline double squared_norm(const Point3& v) {
    return v.x * v.x + v.y * v.y + v.z * v.z;
}

/// det[a, alift; b, blift; c, clift; d, dlift] of translated rows, in doubles, by cofactors of the
/// lift column in Shewchuk's order: six 2x2 minors of x and y (ab = a.x b.y - b.x a.y, ...), four
/// 3x3 minors sharing them (abc = a.z bc - b.z ac + c.z ab, ...), then
/// (dlift abc - clift dab) + (blift cda - alift bcd). Along any monomial's path that is 2
/// roundings in the 2x2 minor, 3 in the 3x3 one, 1 for the lift's product and 2 for the final sum,
/// plus the lift's own.
[[gnu::always_inline]] inline double lifted_determinant(const Point3& a,
                                                        const Point3& b,
                                                        const Point3& c,
                                                        const Point3& d,
                                                        double alift,
                                                        double blift,
                                                        double clift,
                                                        double dlift) {
    const double ab = a.x * b.y - b.x * a.y;
    const double bc = b.x * c.y - c.x * b.y;
    const double cd = c.x * d.y - d.x * c.y;
    const double da = d.x * a.y - a.x * d.y;
    const double ac = a.x * c.y - c.x * a.y;
    const double bd = b.x * d.y - d.x * b.y;

    const double abc = a.z * bc - b.z * ac + c.z * ab;
    const double bcd = b.z * cd - c.z * bd + d.z * bc;
    const double cda = c.z * da + d.z * ac + a.z * cd;
    const double dab = d.z * ab + a.z * bd + b.z * da;

    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

}  // namespace cavity::predicates::detail
