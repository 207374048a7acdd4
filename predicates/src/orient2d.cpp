#include "cavity/predicates/orient2d.h"

#include <cmath>
#include <optional>

#include "cavity/predicates/detail/expansion.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::predicates {

namespace {

/// Shewchuk's ccwerrboundA, (3 + 16u)u with u = 2^-53: the error of the determinant of rounded
/// differences and rounded products, relative to |left| + |right|, without underflow.
constexpr double kFilterBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

/// Differences of magnitude in [2^-450, 2^450] (or zero) keep every product of two of them, and
/// its rounding error, a normal double: the filter's bound holds and two_product is exact.
bool in_safe_range(double d) {
    const double m = std::abs(d);
    return m == 0.0 || (m >= 0x1p-450 && m <= 0x1p450);
}

/// The sign when the filter or the exact product difference decides; nullopt otherwise (a
/// difference out of the safe range, or inexact when the filter fails).
std::optional<Sign> orient2d_fast(
    double ax, double ay, double bx, double by, double cx, double cy) {
    double d[4];
    double tail[4];
    detail::two_diff(ax, cx, d[0], tail[0]);
    detail::two_diff(by, cy, d[1], tail[1]);
    detail::two_diff(ay, cy, d[2], tail[2]);
    detail::two_diff(bx, cx, d[3], tail[3]);
    for (const double x : d) {
        if (!in_safe_range(x)) {  // NaN and infinity fail too
            return std::nullopt;
        }
    }
    const double left = d[0] * d[1];
    const double right = d[2] * d[3];
    const double det = left - right;
    const double bound = kFilterBound * (std::abs(left) + std::abs(right));
    if (det > bound) {
        return Sign::kPos;
    }
    if (-det > bound) {
        return Sign::kNeg;
    }
    if (tail[0] != 0.0 || tail[1] != 0.0 || tail[2] != 0.0 || tail[3] != 0.0) {
        return std::nullopt;
    }
    double h[4];
    const int n = detail::product_difference(d[0], d[1], d[2], d[3], h);
    return static_cast<Sign>(detail::expansion_sign(n, h));
}

}  // namespace

Sign orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    if (const std::optional<Sign> s = orient2d_fast(ax, ay, bx, by, cx, cy)) {
        return *s;
    }
    // (0, 0, 1) is above the plane z = 0, where orient3d is negative for a counter-clockwise
    // a, b, c.
    return negate(orient3d({ax, ay, 0.0}, {bx, by, 0.0}, {cx, cy, 0.0}, {0.0, 0.0, 1.0}));
}

}  // namespace cavity::predicates
