#include "cavity/core/delaunay/conflict_counter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "cavity/predicates/orient3d.h"

namespace cavity::core {

namespace {

constexpr double kUnit = std::numeric_limits<double>::epsilon() / 2;
// Inside these magnitudes no square or product of three lengths below overflows or loses its
// relative accuracy to underflow; outside them the counter tests every point exactly instead.
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

/// A ball certain to hold every point in conflict with a solid tetrahedron, or `bounded` false
/// when no such ball can be certified in floating point; and, for unweighted points, a concentric
/// ball certain to hold only conflicts (`inner`, negative when none is certified). A point
/// strictly inside the circumsphere conflicts whatever the perturbation, and no inserted point
/// can be (the tetrahedron is Delaunay when created), so every point of a box inside the inner
/// ball is an uninserted conflict: such boxes are counted whole.
struct Reach {
    bool bounded = false;
    Point3 centre{};
    double radius = 0;
    double inner = -1;
    // The two radii squared, rounded toward the safe side by far more than the few roundings
    // of a squared distance (relative error below 6 units): points are tested without a root.
    double radius_squared = std::numeric_limits<double>::infinity();
    double inner_squared = -1;

    void square_radii() {
        radius_squared = bounded ? radius * radius * (1 + 4 * kDistanceSlack)
                                 : std::numeric_limits<double>::infinity();
        inner_squared = inner > 0 ? inner * inner * (1 - 4 * kDistanceSlack) : -1;
    }

    /// True when every point of a box with these corners has a squared distance the tests can
    /// trust (no coordinate beyond kLargest).
    static bool moderate(const Box3& b) {
        return std::max(max_abs(b.lo), max_abs(b.hi)) <= kLargest;
    }

    bool includes_squared(double computed) const {
        return std::isfinite(computed) && computed < inner_squared;
    }

    bool excludes_squared(double computed) const {
        return std::isfinite(computed) && computed > radius_squared;
    }

    /// The computed squared distance from the centre, or NaN (which every test above declines)
    /// where the coordinates are too large for the error bounds.
    double squared_distance(const Point3& q) const {
        if (max_abs(q) > kLargest) {
            return std::numeric_limits<double>::quiet_NaN();
        }
        const double dx = q.x - centre.x;
        const double dy = q.y - centre.y;
        const double dz = q.z - centre.z;
        return dx * dx + dy * dy + dz * dz;
    }

    bool includes(const Box3& b) const {
        if (inner <= 0 || std::max(max_abs(b.lo), max_abs(b.hi)) > kLargest) {
            return false;
        }
        // The farthest corner, per axis.
        const double dx = std::max(std::fabs(centre.x - b.lo.x), std::fabs(centre.x - b.hi.x));
        const double dy = std::max(std::fabs(centre.y - b.lo.y), std::fabs(centre.y - b.hi.y));
        const double dz = std::max(std::fabs(centre.z - b.lo.z), std::fabs(centre.z - b.hi.z));
        return includes_squared(dx * dx + dy * dy + dz * dz);
    }

    bool excludes(const Box3& b) const {
        if (std::max(max_abs(b.lo), max_abs(b.hi)) > kLargest) {
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
};

/// The circumcentre (weighted: the orthocentre) c = a + x solves 2 (v_i - a) . x = |v_i - a|^2 -
/// w_i + w_a for the three other vertices. Cramer's rule in floating point has a forward error
/// bounded through the permanents (absolute-value determinants) of the systems, as in Shewchuk's
/// filters: each determinant is off by at most 16 units of its permanent here (7 for its
/// evaluation, the rest for the rounded differences and squares it is built from; 32 for the
/// right-hand side's column). A point q conflicts when |q - c|^2 < |x|^2 - w_a + w_q, so no point
/// farther from the computed centre than the bound below can.
Reach conflict_reach(const Geometry& g, const TetVertices& t, double max_weight) {
    Reach reach;
    const Point3& a = g.point(t[0]);
    if (max_abs(a) > kLargest) {
        return reach;
    }
    const double wa = g.weighted() ? g.weighted_point(t[0]).w : 0.0;
    double p[3][3];
    double rhs[3];
    double rhs_abs[3];
    for (int i = 0; i < 3; ++i) {
        const Point3& v = g.point(t[static_cast<std::size_t>(i) + 1]);
        if (max_abs(v) > kLargest) {
            return reach;
        }
        p[i][0] = v.x - a.x;
        p[i][1] = v.y - a.y;
        p[i][2] = v.z - a.z;
        const double square = p[i][0] * p[i][0] + p[i][1] * p[i][1] + p[i][2] * p[i][2];
        const double wv =
            g.weighted() ? g.weighted_point(t[static_cast<std::size_t>(i) + 1]).w : 0.0;
        rhs[i] = (square - (wv - wa)) / 2;
        rhs_abs[i] = (square + std::fabs(wv) + std::fabs(wa)) / 2;
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
    if (g.weighted()) {
        reach_squared = reach_squared - wa + max_weight;
        reach_squared +=
            kDistanceSlack * (std::fabs(reach_squared) + std::fabs(wa) + std::fabs(max_weight));
    }
    reach.radius =
        (reach_squared > 0 ? std::sqrt(reach_squared) : 0.0) * (1 + kDistanceSlack) + centre_error;
    reach.bounded = std::isfinite(reach.radius) && max_abs(reach.centre) <= kLargest &&
                    reach.radius <= kLargest;
    if (reach.bounded && !g.weighted()) {
        // The true radius is at least |x| - x_error (|x| computed with a relative error under
        // the slack), and the true centre within centre_error of the computed one.
        const double x_norm_low = x_norm * (1 - 2 * kDistanceSlack);
        reach.inner = (x_norm_low - x_error) * (1 - kDistanceSlack) - centre_error;
    }
    reach.square_radii();
    return reach;
}

}  // namespace

void ConflictCountingObserver::on_start(const Geometry& geometry) {
    geometry_ = &geometry;
    std::vector<Point3> points(geometry.size());
    Point3 hi{};
    for (VertexId v = 0; v < geometry.size(); ++v) {
        points[v] = geometry.point(v);
        const Point3& p = points[v];
        lo_ = v == 0 ? p : Point3{std::min(lo_.x, p.x), std::min(lo_.y, p.y), std::min(lo_.z, p.z)};
        hi = v == 0 ? p : Point3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    // Half the extent per coordinate first: the difference of two huge coordinates may overflow.
    const double extent =
        std::max({hi.x / 2 - lo_.x / 2, hi.y / 2 - lo_.y / 2, hi.z / 2 - lo_.z / 2});
    scale_ = extent > 0 && std::isfinite(extent) ? 0.5 * double((1u << 21) - 1) / extent : 0.0;
    tree_ = std::make_unique<PointKdTree>(points);
    max_weight_ = 0;
    if (geometry.weighted() && geometry.size() > 0) {
        max_weight_ = geometry.weighted_point(0).w;
        for (VertexId v = 1; v < geometry.size(); ++v) {
            max_weight_ = std::max(max_weight_, geometry.weighted_point(v).w);
        }
    }
    histogram_.assign(kHistogramBins, 0);
    pending_.reserve(batch_);
}

std::uint64_t ConflictCountingObserver::count_solid(const TetVertices& v) {
    const Reach reach = conflict_reach(*geometry_, v, max_weight_);
    std::uint64_t j = 0;
    std::uint64_t tests = 0;
    const auto test_exactly = [&](std::uint32_t id, const Point3& q) {
        if (id == v[0] || id == v[1] || id == v[2] || id == v[3]) {
            return;
        }
        const double d = reach.squared_distance(q);
        if (reach.bounded && reach.excludes_squared(d)) {
            return;
        }
        if (reach.includes_squared(d)) {
            ++j;  // strictly inside: a conflict without the exact test
            return;
        }
        ++tests;
        j += geometry_->conflicts_solid(v, id, nullptr) ? 1 : 0;
    };
    j += tree_->count_leaves(
        [&](const Box3& box) { return !reach.bounded || !reach.excludes(box); },
        [&](const Box3& box) { return reach.includes(box); },
        [&](const Box3& box, std::span<const std::uint32_t> ids, std::span<const Point3> points) {
            if (!Reach::moderate(box)) {
                for (std::size_t k = 0; k < ids.size(); ++k) {
                    test_exactly(ids[k], points[k]);
                }
                return;
            }
            // One sweep without a branch per point: points certainly inside are counted, and
            // only a leaf with a point in the uncertain shell between the two radii (a vertex
            // of the tetrahedron is always there) is swept again point by point.
            std::uint64_t inside = 0;
            bool shell = false;
            for (const Point3& q : points) {
                const double dx = q.x - reach.centre.x;
                const double dy = q.y - reach.centre.y;
                const double dz = q.z - reach.centre.z;
                const double d = dx * dx + dy * dy + dz * dz;
                inside += d < reach.inner_squared ? 1 : 0;
                shell |= !(d < reach.inner_squared) && !(d > reach.radius_squared);
            }
            if (!shell) {
                j += inside;
                return;
            }
            for (std::size_t k = 0; k < ids.size(); ++k) {
                test_exactly(ids[k], points[k]);
            }
        });
    totals.conflict_tests += tests;
    return j;
}

std::uint64_t ConflictCountingObserver::count_ghost(const TetVertices& v) {
    const Point3& a = geometry_->point(v[0]);
    const Point3& b = geometry_->point(v[1]);
    const Point3& c = geometry_->point(v[2]);
    // The engine's ghost conflict is "in front of the hull triangle", or on its plane and inside
    // the perturbed circumdisk: a box whose eight corners are strictly behind the plane holds
    // none (the halfspace is convex), decided exactly.
    // Likewise a box whose corners are all strictly in front holds only conflicts, none of them
    // a vertex of the triangle (those are on the plane): early in a run the front of a hull
    // triangle holds a large part of the points, and counting them box by box, not point by
    // point, is what keeps the first insertions of a 10^7-point run cheap.
    const auto all_corners = [&](const Box3& box, Sign side) {
        for (int k = 0; k < 8; ++k) {
            const Point3 corner{(k & 1) ? box.hi.x : box.lo.x,
                                (k & 2) ? box.hi.y : box.lo.y,
                                (k & 4) ? box.hi.z : box.lo.z};
            if (predicates::orient3d(a, b, c, corner) != side) {
                return false;
            }
        }
        return true;
    };
    // The bootstrap four (vertex ids 0-3) are inside every hull: the engine's own reference.
    static constexpr std::array<VertexId, 4> kBootstrap{0, 1, 2, 3};
    std::uint64_t j = 0;
    std::uint64_t tests = 0;
    j += tree_->count([&](const Box3& box) { return !all_corners(box, Sign::kNeg); },
                      [&](const Box3& box) { return all_corners(box, Sign::kPos); },
                      [&](std::uint32_t id, const Point3& q) {
                          if (id == v[0] || id == v[1] || id == v[2]) {
                              return;
                          }
                          ++tests;
                          // The engine's own first test, inline here: only a point on the
                          // plane needs the rest of it.
                          const Sign front = predicates::orient3d(a, b, c, q);
                          if (front != Sign::kZero) {
                              j += front == Sign::kPos ? 1 : 0;
                              return;
                          }
                          j += geometry_->conflicts_ghost(v, id, kBootstrap, nullptr) ? 1 : 0;
                      });
    totals.conflict_tests += tests;
    return j;
}

std::uint64_t ConflictCountingObserver::curve_key(const TetVertices& v) const {
    // The Morton code of the centroid of the finite vertices, 21 bits per axis: near tetrahedra
    // get near keys, which is all the batch order needs (any order gives the same counts).
    double c[3] = {0, 0, 0};
    int finite = 0;
    for (VertexId u : v) {
        if (u != kGhostVertex) {
            const Point3& p = geometry_->point(u);
            c[0] += (p.x / 2 - lo_.x / 2) * scale_;
            c[1] += (p.y / 2 - lo_.y / 2) * scale_;
            c[2] += (p.z / 2 - lo_.z / 2) * scale_;
            ++finite;
        }
    }
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double q = std::clamp(c[axis] / finite, 0.0, double((1u << 21) - 1));
        const auto bits = static_cast<std::uint64_t>(q);
        for (int b = 0; b < 21; ++b) {
            key |= ((bits >> b) & 1u) << (3 * b + axis);
        }
    }
    return key;
}

void ConflictCountingObserver::add_at(std::vector<std::uint64_t>& per_step,
                                      std::uint64_t step,
                                      std::uint64_t j) {
    if (per_step.size() <= step) {
        per_step.resize(std::max<std::size_t>(step + 1, 2 * per_step.size()), 0);
    }
    per_step[step] += j;
}

void ConflictCountingObserver::count_batch() {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(pending_.size());
    for (std::size_t i = 0; i < pending_.size(); ++i) {
        order[i] = {curve_key(pending_[i].v), static_cast<std::uint32_t>(i)};
    }
    std::sort(order.begin(), order.end());
    for (const auto& [key, i] : order) {
        const Pending& p = pending_[i];
        const bool ghost = is_ghost(p.v);
        const std::uint64_t j = ghost ? count_ghost(p.v) : count_solid(p.v);
        if (ghost) {
            totals.ghost_conflicts_created += j;
        } else {
            totals.conflicts_created += j;
            ++histogram_[std::min<std::uint64_t>(j, kHistogramBins - 1)];
        }
        add_at(created_at_, p.created_step, j);
        if (p.deleted_step != kAlive) {
            (ghost ? totals.ghost_conflicts_deleted : totals.conflicts_deleted) += j;
            add_at(deleted_at_, p.deleted_step, j);
            continue;
        }
        // Still alive: its deletion, if it comes, finds its count by slot.
        pending_of_[p.slot] = 0;
        j_of_[p.slot] = static_cast<std::uint32_t>(j);
        ghost_of_[p.slot] = ghost ? 1 : 0;
    }
    pending_.clear();
}

void ConflictCountingObserver::on_tet_created(TetId t, const TetVertices& v, std::uint64_t step) {
    if (j_of_.size() <= t) {
        j_of_.resize(std::max<std::size_t>(t + 1, 2 * j_of_.size()), 0);
        ghost_of_.resize(j_of_.size(), 0);
        pending_of_.resize(j_of_.size(), 0);
    }
    pending_.push_back({v, t, static_cast<std::uint32_t>(step), kAlive});
    pending_of_[t] = static_cast<std::uint32_t>(pending_.size());
    if (pending_.size() == batch_) {
        count_batch();
    }
}

void ConflictCountingObserver::on_tet_deleted(TetId t, std::uint64_t step) {
    if (pending_of_[t] != 0) {
        pending_[pending_of_[t] - 1].deleted_step = static_cast<std::uint32_t>(step);
        pending_of_[t] = 0;  // the slot may be reused before the batch is counted
        return;
    }
    const std::uint64_t j = j_of_[t];
    (ghost_of_[t] != 0 ? totals.ghost_conflicts_deleted : totals.conflicts_deleted) += j;
    add_at(deleted_at_, step, j);
}

void ConflictCountingObserver::on_insertion(const InsertionRecord&) {
    ++insertions_;
}

void ConflictCountingObserver::on_finish() {
    count_batch();
    // The driver numbers the bootstrap step 0 and the insertion of vertex u step u, from u = 4;
    // each insertion's entry holds everything up to its step (the bootstrap goes to the first).
    std::uint64_t live = 0;
    std::size_t step = 0;
    const auto at = [](const std::vector<std::uint64_t>& per_step, std::size_t s) {
        return s < per_step.size() ? per_step[s] : 0;
    };
    steps_.clear();
    for (std::uint64_t k = 0; k < insertions_; ++k) {
        ConflictStep entry;
        for (; step <= k + 4; ++step) {
            entry.created += at(created_at_, step);
            entry.deleted += at(deleted_at_, step);
        }
        live = live + entry.created - entry.deleted;
        entry.live = live;
        totals.live_conflicts_max = std::max(totals.live_conflicts_max, live);
        if (keep_steps_) {
            steps_.push_back(entry);
        }
    }
}

}  // namespace cavity::core
