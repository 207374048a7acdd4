#include "split_point.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <variant>

#include "cavity/core/base/assert.h"
#include "cavity/core/cdt/edge_protection.h"
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

double distance(const Point3& u, const Point3& v) {
    const Point3 d = minus(u, v);
    return std::sqrt(dot(d, d));
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

/// The finest dyadic parameters tried first for a double point with short coordinates, and how
/// near the aim they must be: 2^-11 of the piece, which the grid at j = 10 always meets, since
/// moving the split off the encroacher's projection leaves it encroaching a piece.
constexpr int kShortestBits = 10;
constexpr double kShortWindow = 0x1p-11;

}  // namespace

double split_target(const Point3& p, const Point3& q, const std::optional<SplitAim>& aim) {
    if (!aim) {
        return 0.5;
    }
    double t = 0.5;
    if (aim->shell_centre) {
        // The sphere about the shared input vertex c through the reference: the piece's ends are
        // at distances dp and dq from c along the segment.
        const Point3& c = *aim->shell_centre;
        const double dp = distance(p, c);
        const double dq = distance(q, c);
        t = (distance(aim->reference, c) - dp) / (dq - dp);
    } else {
        const Point3 d = minus(q, p);
        t = dot(minus(aim->reference, p), d) / dot(d, d);
    }
    // Written so that NaN (a degenerate piece in doubles) takes the midpoint too.
    if (!(t >= kLowestAim && t <= 1 - kLowestAim)) {
        return 0.5;
    }
    return t;
}

std::optional<GenericPoint3> split_point(const GenericPoint3& p,
                                         const GenericPoint3& q,
                                         double target) {
    const auto* pp = std::get_if<Point3>(&p);
    const auto* pq = std::get_if<Point3>(&q);
    if (pp != nullptr && pq != nullptr) {
        // The coarsest dyadic parameter k / 2^j near the aim whose point is a double: its
        // coordinates stay short (the midpoint when the aim is the middle), as a rounding-free
        // output wants; else the nearest double point that the exact search finds.
        for (int j = 1; j <= kShortestBits; ++j) {
            const double steps = std::ldexp(1.0, j);
            const double k = std::nearbyint(target * steps);
            if (k <= 0 || k >= steps || std::abs(k / steps - target) > kShortWindow) {
                continue;
            }
            const auto s = predicates::segment_parameter_point(*pp, *pq, k, steps);
            if (s && exact_point(rounded_point(*s)) == exact_point(GenericPoint3(*s))) {
                return GenericPoint3(rounded_point(*s));
            }
        }
        if (const auto d = protection_point(
                *pp, *pq, target, target - kDoubleWindow, target + kDoubleWindow)) {
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
    while (std::abs(hi - lo) < kGridSteps && 2 * d <= kMaxDenominator) {
        d *= 2;
        lo *= 2;
        hi *= 2;
    }
    if (std::abs(hi - lo) < 2) {
        return std::nullopt;
    }
    const double first = std::min(lo, hi) + 1;
    const double last = std::max(lo, hi) - 1;
    double n = std::clamp(std::nearbyint(lo + target * (hi - lo)), first, last);
    // Lowest terms keep the denominators of later splits small.
    while (d > 1 && std::fmod(n, 2.0) == 0) {
        n /= 2;
        d /= 2;
    }
    return GenericPoint3(SegmentParameterPoint{a, b, n, d});
}

}  // namespace cavity::core
