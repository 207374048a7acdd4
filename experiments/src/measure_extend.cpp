#include <algorithm>
#include <chrono>
#include <numeric>

#include "cavity/core/base/random.h"
#include "cavity/core/delaunay/conflict_counter.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

namespace {

using detail::Moments;
using detail::number;

/// The conflict counter, which also keeps each insertion's input index and tetrahedra created
/// and deleted, so that the work can be split where S ends and T begins.
class PhaseObserver : public core::ConflictCountingObserver {
public:
    PhaseObserver() : core::ConflictCountingObserver(/*keep_steps=*/true) {}

    void on_insertion(const core::InsertionRecord& record) {
        core::ConflictCountingObserver::on_insertion(record);
        records.push_back(record);
    }

    std::vector<core::InsertionRecord> records;
};

/// T: t points uniform in the bounding box of S, so that they fall among S's tetrahedra.
std::vector<core::Point3> points_in_box(const std::vector<core::Point3>& s,
                                        std::uint64_t t,
                                        std::uint64_t seed) {
    core::Point3 lo = s.front(), hi = s.front();
    for (const core::Point3& p : s) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    core::Random random(seed);
    std::vector<core::Point3> out(t);
    for (core::Point3& p : out) {
        p = {random.uniform(lo.x, hi.x), random.uniform(lo.y, hi.y), random.uniform(lo.z, hi.z)};
    }
    return out;
}

/// A uniform permutation of [first, last), appended to `out` (Fisher-Yates).
void append_shuffled(std::vector<std::uint32_t>& out,
                     std::uint32_t first,
                     std::uint32_t last,
                     core::Random& random) {
    const std::size_t start = out.size();
    for (std::uint32_t i = first; i < last; ++i) {
        out.push_back(i);
    }
    for (std::size_t i = out.size(); i > start + 1; --i) {  // an empty range draws nothing
        std::swap(out[i - 1], out[start + random.below(i - start)]);
    }
}

/// The work of inserting T into Del S, one order: Theorem 5.4's charge split at the phase change.
struct Phase {
    double created = 0;    ///< tetrahedra created during T's insertions, ghosts included
    double deleted = 0;    ///< and deleted
    double conflicts = 0;  ///< conflicts created during T's insertions, solid and ghost
    /// Live conflicts after S: the conflict graph Exercise 2 builds by brute force.
    double initial_conflicts = 0;
    double first_deleted = 0;  ///< the first point of T's cavity
    double max_cavity = 0;
};

Phase extend_once(const core::PointSet& points, std::uint32_t s, std::uint64_t seed) {
    const auto n = static_cast<std::uint32_t>(points.size());
    core::Random random(seed);
    std::vector<std::uint32_t> sequence;
    append_shuffled(sequence, 0, s, random);
    append_shuffled(sequence, s, n, random);
    core::TriangulateOptions options;
    options.bootstrap = core::BootstrapRule::kFirst;  // S is 3D: its first four stay in S
    options.locate = core::LocateKind::kConflictGraph;
    PhaseObserver observer;
    (void)core::triangulate_observed(points, sequence, options, observer);
    Phase phase;
    const std::vector<core::ConflictStep>& steps = observer.steps();
    bool first = true;
    for (std::size_t k = 0; k < observer.records.size(); ++k) {
        const core::InsertionRecord& r = observer.records[k];
        if (r.vertex < s) {
            phase.initial_conflicts = static_cast<double>(steps[k].live);
            continue;
        }
        phase.created += r.created;
        phase.deleted += r.deleted;
        phase.conflicts += static_cast<double>(steps[k].created);
        phase.max_cavity = std::max(phase.max_cavity, static_cast<double>(r.deleted));
        if (first) {
            phase.first_deleted = r.deleted;
            first = false;
        }
    }
    return phase;
}

/// The same points from scratch in a uniform order of S ∪ T: tetrahedra created and conflicts
/// created over the whole construction, ghosts included in both as in extend_once.
std::pair<double, double> scratch_once(const core::PointSet& points, std::uint64_t seed) {
    core::Random random(seed);
    std::vector<std::uint32_t> sequence;
    append_shuffled(sequence, 0, static_cast<std::uint32_t>(points.size()), random);
    core::TriangulateOptions options;
    options.bootstrap = core::BootstrapRule::kFirst;
    options.locate = core::LocateKind::kConflictGraph;
    core::ConflictCountingObserver observer;
    const core::Counters c =
        core::triangulate_observed(points, sequence, options, observer).counters;
    return {static_cast<double>(c.tets_created + c.ghosts_created),
            static_cast<double>(c.conflicts_created + c.ghost_conflicts_created)};
}

}  // namespace

std::vector<std::string> extend_columns() {
    return {"points", "del_s_tets", "del_s_hull_triangles", "time_s"};
}

std::vector<std::string> extend_j_columns() {
    return {"t",
            "orders",
            "created_mean",
            "created_sd",
            "deleted_mean",
            "conflicts_mean",
            "conflicts_sd",
            "initial_conflicts_mean",
            "first_deleted_mean",
            "max_cavity_mean",
            "scratch_created_mean",
            "scratch_conflicts_mean",
            "scratch_conflicts_sd"};
}

core::PointSet extend_points(const core::PointSet& s_points, std::uint64_t t, std::uint64_t seed) {
    core::PointSet points = s_points;
    const std::vector<core::Point3> t_points =
        points_in_box(s_points.points, t, seed * 1000003 + t);
    points.points.insert(points.points.end(), t_points.begin(), t_points.end());
    return points;
}

RunOutput extend(const Suite&, const TierSettings& tier, const RunSpec& run) {
    const auto start = std::chrono::steady_clock::now();
    const core::PointSet s_points = core::generate_points(run.dist, run.n, run.seed);
    const auto s = static_cast<std::uint32_t>(s_points.size());
    std::vector<std::uint32_t> input_order(s);
    std::iota(input_order.begin(), input_order.end(), 0u);
    const core::Triangulation del_s = core::triangulate(s_points, input_order, {});
    if (!del_s.duplicates.empty()) {
        throw core::Error("extend: S (" + run.dist +
                          ") repeats points; Exercise 2 assumes S ∪ T generic");
    }
    RunOutput out;
    for (std::uint64_t t : tier.added) {
        const core::PointSet points = extend_points(s_points, t, run.seed);
        Moments created, deleted, conflicts, initial, first, cavity, scratch_created,
            scratch_conflicts;
        for (std::uint64_t r = 0; r < tier.orders; ++r) {
            const std::uint64_t seed = (run.seed * 1000003 + t) * 1000003 + r;
            const Phase phase = extend_once(points, s, seed);
            created.add(phase.created);
            deleted.add(phase.deleted);
            conflicts.add(phase.conflicts);
            initial.add(phase.initial_conflicts);
            first.add(phase.first_deleted);
            cavity.add(phase.max_cavity);
            const auto [sc_created, sc_conflicts] = scratch_once(points, seed + 1);
            scratch_created.add(sc_created);
            scratch_conflicts.add(sc_conflicts);
        }
        const auto orders = static_cast<double>(tier.orders);
        out.j_rows.push_back({number(t),
                              number(tier.orders),
                              number(created.mean(orders)),
                              number(created.sd(orders)),
                              number(deleted.mean(orders)),
                              number(conflicts.mean(orders)),
                              number(conflicts.sd(orders)),
                              number(initial.mean(orders)),
                              number(first.mean(orders)),
                              number(cavity.mean(orders)),
                              number(scratch_created.mean(orders)),
                              number(scratch_conflicts.mean(orders)),
                              number(scratch_conflicts.sd(orders))});
    }
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.values = {number(std::uint64_t{s}),
                  number(std::uint64_t{del_s.tets.size()}),
                  number(del_s.hull_triangles),
                  number(time_s)};
    return out;
}

}  // namespace cavity::experiments::measure
