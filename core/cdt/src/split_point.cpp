#include "split_point.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <variant>

#include "cavity/core/base/assert.h"
#include "cavity/core/cdt/edge_protection.h"
#include "dyadic_point.h"
#include "exact_plane.h"

namespace cavity::core {

namespace {

using predicates::SegmentParameterPoint;

double dot(const Point3& u, const Point3& v) {
    return u.x * v.x + u.y * v.y + u.z * v.z;
}

Point3 minus(const Point3& u, const Point3& v) {
    return {u.x - v.x, u.y - v.y, u.z - v.z};
}

bool same(const Point3& p, const Point3& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z;
}

/// Beyond this the numerators of the dyadic parameters stop being exact doubles.
constexpr double kMaxDenominator = 0x1p53;

/// How much finer than the piece the grid of split parameters is.
constexpr double kGridSteps = 1024;

/// TetGen keeps its splits in the middle 60% of the piece: a split nearer an end would make a
/// short piece that the same vertex still encroaches upon.
constexpr double kLowestAim = 0.2;

/// The window around the aim searched for a point with double coordinates (protection_point).
constexpr double kDoubleWindow = 0.05;

/// How much of the way from the reference's projection to the edge of the interval that frees
/// the piece of it a split may go: a margin for the doubles the interval is computed in, and so
/// that the reference stays clearly outside both pieces' diametral balls.
constexpr double kFreeingShare = 0.9;

/// The finest dyadic parameters tried first for a double point with short coordinates, and how
/// near the aim they must be: 2^-11 of the piece, which the grid at j = 10 always meets.
constexpr int kShortestBits = 10;
constexpr double kShortWindow = 0x1p-11;

/// How far from its sphere, relative to the radius, a split on a concentric shell may stand.
constexpr double kShellTolerance = 0x1p-30;

SplitTarget around(double t) {
    return {t, t - kDoubleWindow, t + kDoubleWindow};
}

}  // namespace

ProjectionOnPiece projection_on_piece(const Point3& p, const Point3& q, const Point3& w) {
    const Point3 d = minus(q, p);
    const Point3 v = minus(w, p);
    const double length2 = dot(d, d);
    const double s = dot(v, d) / length2;
    return {s, std::max(0.0, dot(v, v) / length2 - s * s)};
}

SplitTarget split_target(const Point3& p, const Point3& q, const std::optional<Point3>& reference) {
    if (!reference) {
        return around(0.5);
    }
    // In units of |pq|, the reference w projects at s with squared height h2. A split at m leaves
    // w outside the closed diametral balls of both pieces, (w - p).(w - m) > 0 and
    // (w - m).(w - q) > 0, exactly when m is in (s - h2 / (1 - s), s + h2 / s): the projection is
    // one such point but puts the new vertex nearest w, a feature of size h that later splits
    // around w must resolve; the point of the interval nearest the midpoint keeps the pieces even
    // and the new vertex as far from w as freeing the piece allows.
    const auto [s, h2] = projection_on_piece(p, q, *reference);
    if (!(s > 0 && s < 1)) {
        return around(0.5);
    }
    const double lo = s - kFreeingShare * h2 / (1 - s);
    const double hi = s + kFreeingShare * h2 / s;
    const double t = std::clamp(0.5, lo, hi);
    if (!(t >= kLowestAim && t <= 1 - kLowestAim)) {
        return around(0.5);
    }
    // A double point off the interval would leave w encroaching a piece: the search keeps to it.
    return {t, std::max(lo, t - kDoubleWindow), std::min(hi, t + kDoubleWindow)};
}

SplitTarget shell_target(const Point3& p, const Point3& q, bool about_p) {
    const Point3 d = minus(q, p);
    const double length = std::sqrt(dot(d, d));
    const double radius = std::ldexp(1.0, std::ilogb(length * 2 / 3));
    const double from_centre = radius / length;
    const double margin = from_centre * kShellTolerance;
    const double t = about_p ? from_centre : 1 - from_centre;
    return {t, t - margin, t + margin};
}

std::optional<GenericPoint3> split_point(const GenericPoint3& p,
                                         const GenericPoint3& q,
                                         const SplitTarget& aim) {
    const double target = aim.target;
    const auto* pp = std::get_if<Point3>(&p);
    const auto* pq = std::get_if<Point3>(&q);
    if (pp != nullptr && pq != nullptr) {
        // The coarsest dyadic parameter k / 2^j near the aim whose point is a double: its
        // coordinates stay short (the midpoint when the aim is the middle), as a rounding-free
        // output wants; else the nearest double point that the exact search finds.
        for (int j = 1; j <= kShortestBits; ++j) {
            const double steps = std::ldexp(1.0, j);
            const double k = std::nearbyint(target * steps);
            if (k <= 0 || k >= steps || std::abs(k / steps - target) > kShortWindow ||
                k / steps < aim.lo || k / steps > aim.hi) {
                continue;
            }
            const DyadicPoint fast = dyadic_point(*pp, *pq, static_cast<std::int64_t>(k), j);
            if (fast.decided) {
                if (fast.is_double) {
                    return GenericPoint3(fast.point);
                }
                continue;
            }
            const auto s = predicates::segment_parameter_point(*pp, *pq, k, steps);
            if (s && exact_point(rounded_point(*s)) == exact_point(GenericPoint3(*s))) {
                return GenericPoint3(rounded_point(*s));
            }
        }
        if (const auto d = protection_point(*pp, *pq, target, aim.lo, aim.hi)) {
            return GenericPoint3(*d);
        }
    }
    // The base edge: the piece itself when both ends are doubles, else the edge between doubles
    // that the implicit end was made on (the pieces of a base edge end only at its ends and at
    // points made on it).
    const auto* implicit_end = std::get_if<SegmentParameterPoint>(&p);
    if (implicit_end == nullptr) {
        implicit_end = std::get_if<SegmentParameterPoint>(&q);
    }
    const Point3 a = implicit_end != nullptr ? implicit_end->a : *pp;
    const Point3 b = implicit_end != nullptr ? implicit_end->b : *pq;
    // A point's base parameter as numerator and denominator (a power of two).
    const auto parameter = [&](const GenericPoint3& g) -> std::pair<double, double> {
        if (const auto* s = std::get_if<SegmentParameterPoint>(&g)) {
            CAVITY_ASSERT(same(s->a, a) && same(s->b, b),
                          "the pieces of a protected edge share its base");
            return {s->numerator, s->denominator};
        }
        const Point3& x = std::get<Point3>(g);
        CAVITY_ASSERT(same(x, a) || same(x, b), "a piece of a protected edge ends on its base");
        return {same(x, a) ? 0.0 : 1.0, 1.0};
    };
    const auto [np, dp] = parameter(p);
    const auto [nq, dq] = parameter(q);
    // Over the common denominator d every numerator is an integer below d <= 2^53: exact.
    double d = std::max(dp, dq);
    double lo = np * (d / dp);
    double hi = nq * (d / dq);
    // Fine enough that the window holds two grid points, so that the split stays where it frees
    // the piece of its reference.
    const double window = aim.hi - aim.lo;
    while ((std::abs(hi - lo) < kGridSteps || std::abs(hi - lo) * window < 2) &&
           2 * d <= kMaxDenominator) {
        d *= 2;
        lo *= 2;
        hi *= 2;
    }
    if (std::abs(hi - lo) < 2) {
        return std::nullopt;
    }
    const double first = std::min(lo, hi) + 1;
    const double last = std::max(lo, hi) - 1;
    double n = std::nearbyint(lo + target * (hi - lo));
    const double w0 = lo + aim.lo * (hi - lo);
    const double w1 = lo + aim.hi * (hi - lo);
    const double inside_lo = std::ceil(std::min(w0, w1));
    const double inside_hi = std::floor(std::max(w0, w1));
    if (inside_lo <= inside_hi) {
        n = std::clamp(n, inside_lo, inside_hi);
    }
    n = std::clamp(n, first, last);
    // Lowest terms keep the denominators of later splits small.
    while (d > 1 && std::fmod(n, 2.0) == 0) {
        n /= 2;
        d /= 2;
    }
    return GenericPoint3(SegmentParameterPoint{a, b, n, d});
}

}  // namespace cavity::core
