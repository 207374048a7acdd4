#include "cavity/predicates/generic_predicates.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <variant>

#include "cavity/predicates/dyadic.h"
#include "cavity/predicates/generic_filter.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"
#include "coplanarity_certificate.h"
#include "homogeneous.h"
#include "homogeneous_exact.h"
#include "interval.h"
#include "scaled_integers.h"

// Filter, then exact, on the homogeneous coordinates (homogeneous.h).
//
// orient3d. det[a-d; b-d; c-d] = det[p 1] over p = a..d (oracle.cpp states why), and multiplying
// row p by W_p turns (x, y, z, 1) into (X, Y, Z, W), so det[X Y Z W] = W_a W_b W_c W_d orient3d:
// the sign is that of the homogeneous determinant times the signs of the four W (the same as
// normalising each W to be positive first). W may be negative: a LinePlanePoint's W = n.(b - a)
// has either sign, and so may a SegmentParameterPoint's denominator.
//
// insphere. det[p-e, |p-e|^2] over p = a..d = det[p |p|^2 1] over p = a..e (oracle.cpp), and
// multiplying row p by W_p^2 > 0 turns (x, y, z, |p|^2, 1) into (XW, YW, ZW, X^2+Y^2+Z^2, W^2):
// the same sign, whatever the signs of the W.
//
// The filter works on the query translated to one of its defining points, so that its errors
// grow with the query's extent, not with its distance from the origin. It first rounds each point
// so translated directly in doubles, with a bound on the distance to the exact one
// (translated_rounded), and tries the floating-point stage of generic_filter.h: a 4x4 or 3x3
// determinant in doubles. That decides nearly every query of a CDT (all but 630 of turbine's
// 130000 insphere tests that reach it), and is several times cheaper than what follows. Else it
// computes the homogeneous coordinates in interval arithmetic (interval.h, sound for every finite
// input, overflow and underflow included); for a query with a LinePlanePoint, which has no direct
// rounding, it takes the rounded points and their bounds from those intervals and tries the
// floating-point stage then. It answers when the homogeneous determinant's interval and those of
// the W exclude zero. What the filter leaves is mostly
// exactly coplanar (flat hull faces, the validator's checks); coplanarity_certificate.h proves
// those zeros from exact orient3d on the defining doubles, some twenty times cheaper than the
// integers. The exact stage evaluates the same formulas over GMP integers, in place
// (homogeneous_exact.h), after scaling the
// defining doubles to integers (homogeneous.h says why that keeps the signs). Before both, an
// insphere query of input points and edge protection's dyadic split points, whose exact
// coordinates are integers of at most 124 bits at one scale, is evaluated in fixed-width integers
// (scaled_integers.h): on cheese.off's CDT 9.8 k instructions per query, where the GMP rows and
// determinant took 55 k.
namespace cavity::predicates {

namespace {

using Integer = detail::ExactInteger;
using detail::Homogeneous;
using detail::Interval;
using detail::Matrix;

int sign_of(const Interval& x) {
    return x.sign();
}

Interval identity_interval(double x) {
    return Interval(x);
}

/// x * 2^-scale, an integer when x == 0 or scale <= spacing_exponent(x).
Integer scaled(double x, int scale) {
    return scaled_to_integer<Integer>(x, scale);
}

/// Calls f on every coordinate of every point defining g.
template <class F>
void for_each_defining_point(const GenericPoint3& g, F f) {
    if (const auto* p = std::get_if<Point3>(&g)) {
        f(*p);
    } else if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
        f(s->a);
        f(s->b);
    } else {
        const auto& l = std::get<LinePlanePoint>(g);
        for (const Point3* x : {&l.a, &l.b, &l.p, &l.q, &l.r}) {
            f(*x);
        }
    }
}

/// The least spacing exponent of the nonzero doubles in `values` (0 when all are zero).
int common_scale(std::initializer_list<double> values, int scale) {
    for (const double v : values) {
        if (v != 0.0) {
            scale = std::min(scale, spacing_exponent(v));
        }
    }
    return scale;
}

/// A defining point of the query, to translate the query to: the filter's intervals then grow
/// with the query's extent, not with its distance from the origin.
template <std::size_t N>
Point3 query_origin(const std::array<const GenericPoint3*, N>& g) {
    Point3 origin{};
    for_each_defining_point(*g[0], [&](const Point3& p) { origin = p; });
    return origin;
}

template <std::size_t N>
std::array<Homogeneous<Interval>, N> interval_rows(const std::array<const GenericPoint3*, N>& g,
                                                   const Point3& o) {
    const auto lift = [&](const Point3& p) {
        return std::array<Interval, 3>{Interval(p.x) - Interval(o.x),
                                       Interval(p.y) - Interval(o.y),
                                       Interval(p.z) - Interval(o.z)};
    };
    std::array<Homogeneous<Interval>, N> rows;
    for (std::size_t i = 0; i < N; ++i) {
        rows[i] = detail::homogeneous<Interval>(*g[i], lift, identity_interval);
    }
    return rows;
}

/// Exact homogeneous coordinates of the whole query, every coordinate scaled by one power of two
/// and each parameter by its own.
template <std::size_t N>
std::array<Homogeneous<Integer>, N> exact_rows(const std::array<const GenericPoint3*, N>& g) {
    int scale = INT_MAX;
    for (const GenericPoint3* p : g) {
        for_each_defining_point(*p, [&](const Point3& q) {
            scale = common_scale({q.x, q.y, q.z}, scale);
        });
    }
    if (scale == INT_MAX) {
        scale = 0;
    }
    std::array<Homogeneous<Integer>, N> rows;
    for (std::size_t i = 0; i < N; ++i) {
        if (const auto* s = std::get_if<SegmentParameterPoint>(g[i])) {
            rows[i] = detail::segment_row(
                *s, scale, common_scale({s->numerator, s->denominator}, INT_MAX));
            continue;
        }
        rows[i] = detail::homogeneous<Integer>(
            *g[i],
            [&](const Point3& p) {
                return std::array<Integer, 3>{
                    scaled(p.x, scale), scaled(p.y, scale), scaled(p.z, scale)};
            },
            // Only a SegmentParameterPoint has a parameter, and it was made above.
            [](double x) { return scaled(x, 0); });
    }
    return rows;
}

/// The sign of orient3d from homogeneous rows; 0 also when undecided (a W of unknown sign).
template <class T>
int orient3d_sign(const std::array<Homogeneous<T>, 4>& rows) {
    int w_signs = 1;
    Matrix<T, 4> m;
    for (std::size_t i = 0; i < 4; ++i) {
        w_signs *= sign_of(rows[i].w);
        m[i] = {rows[i].x, rows[i].y, rows[i].z, rows[i].w};
    }
    if (w_signs == 0) {
        return 0;
    }
    return w_signs * sign_of(detail::determinant<T, 4>(m));
}

template <class T>
int insphere_sign(const std::array<Homogeneous<T>, 5>& rows) {
    Matrix<T, 5> m;
    for (std::size_t i = 0; i < 5; ++i) {
        const Homogeneous<T>& h = rows[i];
        m[i] = {T(h.x * h.w),
                T(h.y * h.w),
                T(h.z * h.w),
                T(h.x * h.x + h.y * h.y + h.z * h.z),
                T(h.w * h.w)};
    }
    return sign_of(detail::determinant<T, 5>(m));
}

/// True when every point is an input point: the Point3 predicates (filter, adaptive stages,
/// exact) then decide, some thirty times faster than the intervals here.
template <std::size_t N>
bool all_explicit(const std::array<const GenericPoint3*, N>& g) {
    for (const GenericPoint3* p : g) {
        if (!std::holds_alternative<Point3>(*p)) {
            return false;
        }
    }
    return true;
}

bool is_finite(const Point3& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// An upper bound on max |x - r| over the coordinates of the point x whose homogeneous
/// coordinates h encloses, +inf when r is not finite or h's W interval holds zero.
double distance_bound(const Homogeneous<Interval>& h, const Point3& r) {
    constexpr double kUnknown = std::numeric_limits<double>::infinity();
    if (!is_finite(r)) {
        return kUnknown;
    }
    // x - r = (X - r W) / W: bound |X - r W| from above and |W| from below.
    double w_min = 0.0;
    if (h.w.lo() > 0.0) {
        w_min = h.w.lo();
    } else if (h.w.hi() < 0.0) {
        w_min = -h.w.hi();
    } else {
        return kUnknown;
    }
    double numerator = 0.0;
    for (const auto& [coordinate, rounded] :
         {std::pair{h.x, r.x}, std::pair{h.y, r.y}, std::pair{h.z, r.z}}) {
        const Interval distance = coordinate - Interval(rounded) * h.w;
        numerator = std::max({numerator, -distance.lo(), distance.hi()});
    }
    // q = fl(numerator / w_min) is within a spacing of the true quotient, so q plus interval.h's
    // widening of q, rounded to nearest, is at least the next double up, hence above it; both
    // ends are bounds already (an endpoint's magnitude), so the result bounds max |x - r|.
    const double q = numerator / w_min;
    return q + (q * 0x1p-52 + 0x1p-1074);
}

double midpoint(const Interval& x) {
    return 0.5 * x.lo() + 0.5 * x.hi();
}

/// The floating-point stage's view of the filter's rows (translated like them, which keeps the
/// signs): each point at the ratio of its intervals' midpoints, with the bound on its distance.
template <std::size_t N>
std::array<RoundedPoint, N> rounded_rows(const std::array<Homogeneous<Interval>, N>& rows) {
    std::array<RoundedPoint, N> rounded;
    for (std::size_t i = 0; i < N; ++i) {
        const Homogeneous<Interval>& h = rows[i];
        const double w = midpoint(h.w);
        const Point3 r{midpoint(h.x) / w, midpoint(h.y) / w, midpoint(h.z) / w};
        rounded[i] = {r, distance_bound(h, r)};
    }
    return rounded;
}

/// translated_rounded of every point of the query, or nullopt when one has none.
template <std::size_t N>
std::optional<std::array<RoundedPoint, N>> translated_rounded_rows(
    const std::array<const GenericPoint3*, N>& g, const Point3& o) {
    std::array<RoundedPoint, N> rows;
    for (std::size_t i = 0; i < N; ++i) {
        const std::optional<RoundedPoint> r = translated_rounded(*g[i], o);
        if (!r) {
            return std::nullopt;
        }
        rows[i] = *r;
    }
    return rows;
}

}  // namespace

Verdict orient3d_staged(const GenericPoint3& a,
                        const GenericPoint3& b,
                        const GenericPoint3& c,
                        const GenericPoint3& d) {
    const std::array<const GenericPoint3*, 4> g{&a, &b, &c, &d};
    if (all_explicit(g)) {
        return orient3d_staged(
            std::get<Point3>(a), std::get<Point3>(b), std::get<Point3>(c), std::get<Point3>(d));
    }
    const Point3 o = query_origin(g);
    const auto direct = translated_rounded_rows(g, o);
    if (direct) {
        const auto& r = *direct;
        if (const int s = orient3d_rounded(r[0], r[1], r[2], r[3])) {
            return {static_cast<Sign>(s), Stage::kFilter};
        }
    }
    const auto rows = interval_rows(g, o);
    if (!direct) {
        const auto r = rounded_rows(rows);
        if (const int s = orient3d_rounded(r[0], r[1], r[2], r[3])) {
            return {static_cast<Sign>(s), Stage::kFilter};
        }
    }
    if (const int s = orient3d_sign(rows)) {
        return {static_cast<Sign>(s), Stage::kFilter};
    }
    if (detail::certified_coplanar(g)) {
        return {Sign::kZero, Stage::kExact};
    }
    return {static_cast<Sign>(detail::homogeneous_orient3d_sign(exact_rows(g))), Stage::kExact};
}

Verdict insphere_staged(const GenericPoint3& a,
                        const GenericPoint3& b,
                        const GenericPoint3& c,
                        const GenericPoint3& d,
                        const GenericPoint3& e) {
    const std::array<const GenericPoint3*, 5> g{&a, &b, &c, &d, &e};
    if (all_explicit(g)) {
        return insphere_staged(std::get<Point3>(a),
                               std::get<Point3>(b),
                               std::get<Point3>(c),
                               std::get<Point3>(d),
                               std::get<Point3>(e));
    }
    const Point3 o = query_origin(g);
    const auto direct = translated_rounded_rows(g, o);
    if (direct) {
        const auto& r = *direct;
        if (const int s = insphere_rounded(r[0], r[1], r[2], r[3], r[4])) {
            return {static_cast<Sign>(s), Stage::kFilter};
        }
    }
    const auto rows = interval_rows(g, o);
    if (!direct) {
        const auto r = rounded_rows(rows);
        if (const int s = insphere_rounded(r[0], r[1], r[2], r[3], r[4])) {
            return {static_cast<Sign>(s), Stage::kFilter};
        }
    }
    if (const int s = insphere_sign(rows)) {
        return {static_cast<Sign>(s), Stage::kFilter};
    }
    // Edge protection's dyadic split points and input points, the usual exact query of a CDT:
    // a fifth of the cost of the GMP determinant below (see the top).
    if (const std::optional<Sign> s = detail::insphere_scaled_integers(g)) {
        return {*s, Stage::kExact};
    }
    if (detail::certified_coplanar(g)) {
        return {Sign::kZero, Stage::kExact};
    }
    return {static_cast<Sign>(detail::homogeneous_insphere_sign(exact_rows(g))), Stage::kExact};
}

double rounding_error(const GenericPoint3& g, const Point3& r) {
    if (const auto* p = std::get_if<Point3>(&g);
        p != nullptr && p->x == r.x && p->y == r.y && p->z == r.z) {
        return 0.0;
    }
    // Untranslated intervals: r is in absolute coordinates.
    const auto lift = [](const Point3& p) {
        return std::array<Interval, 3>{Interval(p.x), Interval(p.y), Interval(p.z)};
    };
    return distance_bound(detail::homogeneous<Interval>(g, lift, identity_interval), r);
}

// translated_rounded's bound. With u = 2^-53 and every operation rounded to nearest, an explicit
// point p gives r = fl(p - o) with |r - (p - o)| <= u |r| (exact when subnormal). A
// SegmentParameterPoint (a, b, n / d) gives t = fl(n / d), da = fl(a - o), db = fl(b - a), q = fl(t
// db), r = fl(da + q), and with T = n / d exactly,
//   |r - (a - o + T (b - a))| <= |da - (a - o)| + |T| |db - (b - a)| + |T - t| |b - a|
//                                + |q - t db| + |r - (da + q)|
// where each term is at most u times |da|, |q|, |q|, |q| and |r| up to factors 1 + O(u) (|t db| is
// |q| up to one rounding, |b - a| is |db| up to another, |T - t| <= u |t| when t is normal), and
// products that underflow add at most 2^-1074 each (t is 0 only when n is: then exactly). So
// 2u (|da| + 3 |q| + |r|) + 2^-1070 bounds it, the factor 2 covering every 1 + O(u) and the
// bound's own roundings.
std::optional<RoundedPoint> translated_rounded(const GenericPoint3& g, const Point3& o) {
    constexpr double kTwiceUnit = 0x1p-52;
    constexpr double kUnderflow = 0x1p-1070;
    if (const auto* p = std::get_if<Point3>(&g)) {
        const Point3 r = detail::translated(*p, o);
        return RoundedPoint{r, kTwiceUnit * detail::max_magnitude(r) + kUnderflow};
    }
    const auto* s = std::get_if<SegmentParameterPoint>(&g);
    if (s == nullptr) {
        return std::nullopt;
    }
    const double t = s->numerator / s->denominator;
    if (s->numerator != 0 && !(std::abs(t) >= 0x1p-1000)) {
        return std::nullopt;  // underflow: |T - t| is not relative any more (or NaN)
    }
    const Point3 da = detail::translated(s->a, o);
    const Point3 db = detail::translated(s->b, s->a);
    const Point3 q{t * db.x, t * db.y, t * db.z};
    const Point3 r{da.x + q.x, da.y + q.y, da.z + q.z};
    const double error = kTwiceUnit * (detail::max_magnitude(da) + 3 * detail::max_magnitude(q) +
                                       detail::max_magnitude(r)) +
                         kUnderflow;
    return RoundedPoint{r, error};
}

std::optional<LinePlanePoint> line_plane_point(
    const Point3& a, const Point3& b, const Point3& p, const Point3& q, const Point3& r) {
    for (const Point3* x : {&a, &b, &p, &q, &r}) {
        if (!is_finite(*x)) {
            return std::nullopt;
        }
    }
    const GenericPoint3 point = LinePlanePoint{a, b, p, q, r};
    if (exact_rows(std::array<const GenericPoint3*, 1>{&point})[0].w == 0) {
        return std::nullopt;
    }
    return std::get<LinePlanePoint>(point);
}

std::optional<SegmentParameterPoint> segment_parameter_point(const Point3& a,
                                                             const Point3& b,
                                                             double numerator,
                                                             double denominator) {
    if (!is_finite(a) || !is_finite(b) || !std::isfinite(numerator) ||
        !std::isfinite(denominator) || denominator == 0.0) {
        return std::nullopt;
    }
    return SegmentParameterPoint{a, b, numerator, denominator};
}

}  // namespace cavity::predicates
