#include "cavity/core/delaunay/conflict_counter.h"

#include <algorithm>
#include <cmath>

#include "cavity/core/delaunay/conflict_reach.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {

namespace {

ConflictReach reach_of_tet(const Geometry& g, const TetVertices& t, double max_weight) {
    const std::array<Point3, 4> v{g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3])};
    if (!g.weighted()) {
        return conflict_reach(v);
    }
    std::array<double, 4> w{};
    for (std::size_t i = 0; i < 4; ++i) {
        w[i] = g.weighted_point(t[i]).w;
    }
    return conflict_reach(v, w, max_weight);
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
    const ConflictReach reach = reach_of_tet(*geometry_, v, max_weight_);
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
        j += geometry_->conflicts_solid(v, id) ? 1 : 0;
    };
    j += tree_->count_leaves(
        [&](const Box3& box) { return !reach.bounded || !reach.excludes(box); },
        [&](const Box3& box) { return reach.includes(box); },
        [&](const Box3& box, std::span<const std::uint32_t> ids, std::span<const Point3> points) {
            if (!ConflictReach::moderate(box)) {
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
                          j += geometry_->conflicts_ghost(v, id, kBootstrap) ? 1 : 0;
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
