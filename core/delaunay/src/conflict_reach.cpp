#include "cavity/core/delaunay/conflict_reach.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavity::core {

namespace {

constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;
// Inside these magnitudes no square or product of three lengths below overflows or loses its
// relative accuracy to underflow; outside them the caller tests every point exactly instead.
constexpr double kLargest = 1e100;
constexpr double kSmallestVolume = 1e-200;
// Generous allowance for the few roundings of a distance (each a relative error below 4 units).
constexpr double kDistanceSlack = 1e-14;

double det3(const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

double permanent3(const double m[3][3]) {
    const auto a = [&](int i, int j) { return std::fabs(m[i][j]); };
    return a(0, 0) * (a(1, 1) * a(2, 2) + a(1, 2) * a(2, 1)) +
           a(0, 1) * (a(1, 0) * a(2, 2) + a(1, 2) * a(2, 0)) +
           a(0, 2) * (a(1, 0) * a(2, 1) + a(1, 1) * a(2, 0));
}

double max_abs(const Point3& p) {
    return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
}

void square_radii(ConflictReach& reach) {
    reach.radius_squared = reach.bounded ? reach.radius * reach.radius * (1 + 4 * kDistanceSlack)
                                         : std::numeric_limits<double>::infinity();
    reach.inner_squared =
        reach.inner > 0 ? reach.inner * reach.inner * (1 - 4 * kDistanceSlack) : -1;
}

/// The circumcentre (weighted: the orthocentre) c = a + x solves 2 (v_i - a) . x = |v_i - a|^2 -
/// w_i + w_a for the three other vertices. Cramer's rule in floating point has a forward error
/// bounded through the permanents (absolute-value determinants) of the systems, as in Shewchuk's
/// filters: each determinant is off by at most 16 units of its permanent here (7 for its
/// evaluation, the rest for the rounded differences and squares it is built from; 32 for the
/// right-hand side's column). A point q conflicts when |q - c|^2 < |x|^2 - w_a + w_q, so no point
/// farther from the computed centre than the bound below can.
ConflictReach reach_of(const std::array<Point3, 4>& v,
                       const std::array<double, 4>& w,
                       bool weighted,
                       double max_weight) {
    ConflictReach reach;
    const Point3& a = v[0];
    if (max_abs(a) > kLargest) {
        return reach;
    }
    const double wa = w[0];
    double p[3][3];
    double rhs[3];
    double rhs_abs[3];
    for (int i = 0; i < 3; ++i) {
        const Point3& u = v[static_cast<std::size_t>(i) + 1];
        if (max_abs(u) > kLargest) {
            return reach;
        }
        p[i][0] = u.x - a.x;
        p[i][1] = u.y - a.y;
        p[i][2] = u.z - a.z;
        const double square = p[i][0] * p[i][0] + p[i][1] * p[i][1] + p[i][2] * p[i][2];
        const double wu = w[static_cast<std::size_t>(i) + 1];
        rhs[i] = (square - (wu - wa)) / 2;
        rhs_abs[i] = (square + std::fabs(wu) + std::fabs(wa)) / 2;
    }
    const double d = det3(p);
    const double d_error = 16 * kUnit * permanent3(p);
    if (!std::isfinite(d) || !(std::fabs(d) > 4 * d_error) || std::fabs(d) < kSmallestVolume) {
        return reach;
    }
    double x[3];
    double x_error_squared = 0;
    for (int k = 0; k < 3; ++k) {
        double m[3][3];
        double m_abs[3][3];
        for (int i = 0; i < 3; ++i) {
            for (int c = 0; c < 3; ++c) {
                m[i][c] = c == k ? rhs[i] : p[i][c];
                m_abs[i][c] = c == k ? rhs_abs[i] : p[i][c];
            }
        }
        const double n = det3(m);
        x[k] = n / d;
        const double e = (32 * kUnit * permanent3(m_abs) + std::fabs(x[k]) * d_error) /
                             (std::fabs(d) - d_error) +
                         2 * kUnit * std::fabs(x[k]);
        x_error_squared += e * e;
    }
    const double x_error = std::sqrt(x_error_squared) * (1 + kDistanceSlack);
    const double x_norm = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) * (1 + kDistanceSlack);
    reach.centre = {a.x + x[0], a.y + x[1], a.z + x[2]};
    // The centre's own rounding: one addition per coordinate.
    const double centre_error = x_error + 2 * kUnit * (max_abs(a) + max_abs(reach.centre));
    double reach_squared = (x_norm + x_error) * (x_norm + x_error);
    if (weighted) {
        reach_squared = reach_squared - wa + max_weight;
        reach_squared +=
            kDistanceSlack * (std::fabs(reach_squared) + std::fabs(wa) + std::fabs(max_weight));
    }
    reach.radius =
        (reach_squared > 0 ? std::sqrt(reach_squared) : 0.0) * (1 + kDistanceSlack) + centre_error;
    reach.bounded = std::isfinite(reach.radius) && max_abs(reach.centre) <= kLargest &&
                    reach.radius <= kLargest;
    if (reach.bounded && !weighted) {
        // The true radius is at least |x| - x_error (|x| computed with a relative error under
        // the slack), and the true centre within centre_error of the computed one.
        const double x_norm_low = x_norm * (1 - 2 * kDistanceSlack);
        reach.inner = (x_norm_low - x_error) * (1 - kDistanceSlack) - centre_error;
    }
    square_radii(reach);
    return reach;
}

}  // namespace

bool ConflictReach::moderate(const Box3& b) {
    return std::max(max_abs(b.lo), max_abs(b.hi)) <= kLargest;
}

double ConflictReach::squared_distance(const Point3& q) const {
    if (max_abs(q) > kLargest) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const double dx = q.x - centre.x;
    const double dy = q.y - centre.y;
    const double dz = q.z - centre.z;
    return dx * dx + dy * dy + dz * dz;
}

bool ConflictReach::includes(const Box3& b) const {
    if (inner <= 0 || !moderate(b)) {
        return false;
    }
    // The farthest corner, per axis.
    const double dx = std::max(std::fabs(centre.x - b.lo.x), std::fabs(centre.x - b.hi.x));
    const double dy = std::max(std::fabs(centre.y - b.lo.y), std::fabs(centre.y - b.hi.y));
    const double dz = std::max(std::fabs(centre.z - b.lo.z), std::fabs(centre.z - b.hi.z));
    return includes_squared(dx * dx + dy * dy + dz * dz);
}

bool ConflictReach::excludes(const Box3& b) const {
    if (!moderate(b)) {
        return false;
    }
    const auto gap = [](double c, double lo, double hi) {
        return c < lo ? lo - c : c > hi ? c - hi : 0.0;
    };
    const double dx = gap(centre.x, b.lo.x, b.hi.x);
    const double dy = gap(centre.y, b.lo.y, b.hi.y);
    const double dz = gap(centre.z, b.lo.z, b.hi.z);
    return excludes_squared(dx * dx + dy * dy + dz * dz);
}

ConflictReach conflict_reach(const std::array<Point3, 4>& v) {
    return reach_of(v, {0, 0, 0, 0}, false, 0);
}

ConflictReach conflict_reach(const std::array<Point3, 4>& v,
                             const std::array<double, 4>& w,
                             double max_weight) {
    return reach_of(v, w, true, max_weight);
}

}  // namespace cavity::core
