#include "rounded_region.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace cavity::core {

namespace {

using predicates::Point3;
using predicates::RoundedPoint;

constexpr double kUnitRoundoff = 0x1p-53;
/// Every error bound below is computed in doubles through fewer than twenty roundings, each off
/// by a relative 2^-53 at most: this factor makes the computed bound no smaller than the exact.
constexpr double kInflate = 1.0 + 0x1p-40;
/// A product that underflows errs by at most 2^-1075 absolutely, beyond the relative bounds;
/// every error below gains this instead.
constexpr double kUnderflow = 0x1p-1000;

std::size_t u_axis(int drop) {
    return drop == 0 ? 1 : 0;
}

std::size_t v_axis(int drop) {
    return drop == 2 ? 1 : 2;
}

double coordinate(const Point3& p, std::size_t k) {
    return k == 0 ? p.x : (k == 1 ? p.y : p.z);
}

/// x - e and x + e rounded outward (nextafter past a result rounded to nearest covers its
/// rounding); x itself when e is 0.
double lower(double x, double e) {
    return e == 0.0 ? x : std::nextafter(x - e, -std::numeric_limits<double>::infinity());
}

double upper(double x, double e) {
    return e == 0.0 ? x : std::nextafter(x + e, std::numeric_limits<double>::infinity());
}

/// A point's two coordinates kept by the projection and their errors, each made by
/// axis(k, value, error), which says whether both are finite; nullopt when either is not.
template <class Axis>
std::optional<RoundedPoint2> projected(int drop, const Axis& axis) {
    RoundedPoint2 x{};
    if (!axis(u_axis(drop), x.u, x.error_u) || !axis(v_axis(drop), x.v, x.error_v)) {
        return std::nullopt;
    }
    return x;
}

/// Whether corner p's exact v is above (true) or below (false) every v in [lo, hi]; nullopt when
/// the intervals meet. Below excludes level: the exact test's "not above" includes it, and so
/// the walk below never meets a level corner.
std::optional<bool> above(const RoundedPoint2& p, double lo, double hi) {
    if (lower(p.v, p.error_v) > hi) {
        return true;
    }
    if (upper(p.v, p.error_v) < lo) {
        return false;
    }
    return std::nullopt;
}

/// The sign of (q - p) x (x - p) at the exact points, or 0 when undecided. With m bounding every
/// coordinate (errors included) and E every error, each of the four differences is within
/// delta = 2E + 2u (2m) of the exact one and at most 2m in magnitude, so each product is within
/// 4m delta + delta^2 of the exact product; the two products and the difference round by at most
/// u (4m^2 + 4m^2 + 8m^2 (1 + u)) < 2^-48 m^2.
int orientation(const RoundedPoint2& p, const RoundedPoint2& q, const RoundedPoint2& x) {
    const double e = std::max({p.error_u, p.error_v, q.error_u, q.error_v, x.error_u, x.error_v});
    const double m = std::max({std::abs(p.u),
                               std::abs(p.v),
                               std::abs(q.u),
                               std::abs(q.v),
                               std::abs(x.u),
                               std::abs(x.v)}) +
                     e;
    if (!(m > 0x1p-400 && m < 0x1p+400)) {  // no overflow, and underflow below the bound
        return 0;
    }
    const double det = (q.u - p.u) * (x.v - p.v) - (q.v - p.v) * (x.u - p.u);
    const double delta = 2.0 * e + 4.0 * kUnitRoundoff * m;
    const double bound = (8.0 * m * delta + 2.0 * delta * delta + 0x1p-48 * m * m) * kInflate;
    if (det > bound) {
        return 1;
    }
    if (det < -bound) {
        return -1;
    }
    return 0;
}

}  // namespace

std::optional<RoundedPoint2> rounded_crossing(const std::array<Point3, 3>& plane,
                                              int drop,
                                              const RoundedPoint& p,
                                              const RoundedPoint& q) {
    // The heights of p and q over the plane, as orient3d's determinant: the same affine function
    // of the fourth point for both, so the crossing's parameter along pq is
    // T = |H_p| / (|H_p| + |H_q|) with H the exact heights (of opposite signs: p and q lie on
    // opposite sides).
    const RoundedPoint a{plane[0], 0.0};
    const RoundedPoint b{plane[1], 0.0};
    const RoundedPoint c{plane[2], 0.0};
    const auto hp = predicates::orient3d_rounded_value(a, b, c, p);
    const auto hq = predicates::orient3d_rounded_value(a, b, c, q);
    if (!hp || !hq) {
        return std::nullopt;
    }
    const double height_p = std::abs(hp->value);
    const double height_q = std::abs(hq->value);
    // Each rounded height within 2^-10 of its magnitude (false on NaN).
    if (!(height_p > 0x1p10 * hp->bound && height_q > 0x1p10 * hq->bound) ||
        (hp->value > 0) == (hq->value > 0)) {
        return std::nullopt;
    }
    // With |H_p| = height_p (1 + e_p), |e_p| <= alpha, and likewise beta for q, T = 1 / (1 + r)
    // where r = |H_q| / |H_p| is within a relative (alpha + beta) (1 + 2^-9) of height_q /
    // height_p; d/dr 1 / (1 + r) at most t (1 - t) / r (1 - 2^-8)^-2 over that range, so
    // |T - t0| <= 1.01 t0 (alpha + beta), t0 = height_p / (height_p + height_q); the division and
    // the sum put t within 2.01 u t0 of t0, and t <= 1.
    const double alpha = hp->bound / height_p;
    const double beta = hq->bound / height_q;
    const double t = height_p / (height_p + height_q);
    const double dt = (1.02 * t * (alpha + beta) + 4.0 * kUnitRoundoff) * kInflate;
    // X = P + T (Q - P) at the exact points, x = fl(p + fl(t fl(q - p))) at the rounded ones:
    // |X - x| <= |P - p| + T |(Q - P) - d| + |T - t| |d| + (the product's and the sum's
    // roundings) <= 2 e_p + e_q + (2u + dt) |d| + u (1 + u) |x|, d = fl(q - p).
    const auto axis = [&](std::size_t k, double& x, double& error) {
        const double pk = coordinate(p.p, k);
        const double d = coordinate(q.p, k) - pk;
        x = pk + t * d;
        error = (2.0 * p.error + q.error + (2.0 * kUnitRoundoff + dt) * std::abs(d) +
                 1.01 * kUnitRoundoff * std::abs(x)) *
                    kInflate +
                kUnderflow;
        return std::isfinite(x) && std::isfinite(error);
    };
    return projected(drop, axis);
}

std::optional<RoundedPoint2> rounded_centroid(std::span<const RoundedPoint> points, int drop) {
    if (points.empty() || points.size() > 3) {
        return std::nullopt;
    }
    const auto n = static_cast<double>(points.size());
    // The sum of n <= 3 doubles errs by at most (n - 1) u (1 + u) times the sum of their
    // magnitudes, the division by n by u |c|; the exact points add their errors' mean.
    const auto axis = [&](std::size_t k, double& c, double& error) {
        double sum = 0.0;
        double magnitudes = 0.0;
        double errors = 0.0;
        for (const RoundedPoint& r : points) {
            const double x = coordinate(r.p, k);
            sum += x;
            magnitudes += std::abs(x);
            errors += r.error;
        }
        c = sum / n;
        error = ((errors + 2.01 * kUnitRoundoff * magnitudes) / n +
                 1.01 * kUnitRoundoff * std::abs(c)) *
                    kInflate +
                kUnderflow;
        return std::isfinite(c) && std::isfinite(error);
    };
    return projected(drop, axis);
}

std::optional<std::vector<RoundedPoint2>> rounded_loop(const Plc& plc,
                                                       const std::vector<std::uint32_t>& loop,
                                                       int drop) {
    std::vector<RoundedPoint2> out;
    out.reserve(loop.size());
    for (const std::uint32_t c : loop) {
        const Point3& r = plc.points.points[c];
        const double error =
            plc.points.exact.empty() ? 0.0 : predicates::rounding_error(plc.points.exact[c], r);
        if (!std::isfinite(error)) {
            return std::nullopt;
        }
        out.push_back({coordinate(r, u_axis(drop)), coordinate(r, v_axis(drop)), error, error});
    }
    return out;
}

std::optional<bool> inside_loop_rounded(const std::vector<RoundedPoint2>& loop,
                                        const RoundedPoint2& x) {
    const double lo = lower(x.v, x.error_v);
    const double hi = upper(x.v, x.error_v);
    const double u_lo = lower(x.u, x.error_u);
    bool inside = false;
    // position()'s walk (exact_plane.cpp): with every comparison of v strict, no corner is level
    // with x, so a side meets the ray from x along +u only when its ends are on either side of
    // it, and a decided orientation is not zero, so x is on no side.
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const RoundedPoint2& p = loop[i];
        const RoundedPoint2& q = loop[(i + 1) % loop.size()];
        // A side wholly before x along u neither holds x nor meets the ray: the exact walk,
        // whichever way its comparisons of v go, leaves the count as it is. CAD loops have many
        // corners level with one another, and so often with x within its error.
        if (std::max(upper(p.u, p.error_u), upper(q.u, q.error_u)) < u_lo) {
            continue;
        }
        const std::optional<bool> p_above = above(p, lo, hi);
        const std::optional<bool> q_above = above(q, lo, hi);
        if (!p_above || !q_above) {
            return std::nullopt;
        }
        if (*p_above == *q_above) {
            continue;
        }
        const int o = orientation(p, q, x);
        if (o == 0) {
            return std::nullopt;
        }
        if (*q_above == (o > 0)) {
            inside = !inside;
        }
    }
    return inside;
}

}  // namespace cavity::core
