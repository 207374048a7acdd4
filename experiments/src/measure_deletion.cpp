#include <algorithm>
#include <chrono>
#include <cstdio>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/vertex_deletion.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/mesh/star.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

namespace {

using detail::number;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The star of v before its deletion: the link's vertex count (the vertex degree), the
/// tetrahedra around v and whether v is on the hull (a ghost tetrahedron in its star).
struct Star {
    std::uint64_t degree = 0;
    std::uint64_t tets = 0;
    bool hull = false;
};

Star star_of(const core::ArrayStorage& storage, core::VertexId v) {
    Star star;
    std::vector<core::VertexId> link;
    for (core::TetId t : core::vertex_star(storage, v)) {
        ++star.tets;
        for (core::VertexId w : storage.vertices(t)) {
            if (w == core::kGhostVertex) {
                star.hull = true;
            } else if (w != v) {
                link.push_back(w);
            }
        }
    }
    std::sort(link.begin(), link.end());
    star.degree = static_cast<std::uint64_t>(std::unique(link.begin(), link.end()) - link.begin());
    return star;
}

/// Bowyer-Watson on the points not deleted, in the original indices: removing points keeps the
/// relative order of the others' perturbation keys, so it is the triangulation deletion must give.
detail::TetList rebuilt_without(const core::PointSet& points,
                                const std::vector<bool>& gone,
                                const core::OrderOptions& order) {
    core::PointSet kept;
    std::vector<std::uint32_t> original;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (!gone[i]) {
            original.push_back(i);
            kept.points.push_back(points.points[i]);
        }
    }
    const core::InsertionOrder sequence = core::make_insertion_order(kept.points, order);
    detail::TetList tets = core::triangulate(kept, sequence.sequence, {}).tets;
    for (auto& t : tets) {
        for (auto& v : t) {
            v = original[v];
        }
    }
    return tets;
}

}  // namespace

std::vector<std::string> deletion_columns() {
    return {"points",
            "tets_before",
            "tets_after",
            "deletions",
            "hull_deletions",
            "delete_s",
            "us_per_deletion",
            "rebuild_s",
            "mean_degree",
            "max_degree",
            "mean_star_tets",
            "tets_created",
            "tets_deleted",
            "facets_wrapped",
            "apex_orient_tests",
            "insphere_calls",
            "created_per_deletion",
            "insphere_per_deletion",
            "apex_per_deletion",
            "apex_per_degree_sq",
            "equal_rebuild",
            "hash"};
}

std::vector<std::string> deletion_j_columns() {
    return {"deletion",
            "vertex",
            "hull",
            "degree",
            "star_tets",
            "created",
            "facets_wrapped",
            "apex_orient_tests",
            "insphere_calls"};
}

RunOutput deletion(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const core::OrderOptions order = detail::order_options("brio", suite.brio_ratio, run.seed);
    const core::Triangulation full =
        core::triangulate(points, core::make_insertion_order(points.points, order).sequence, {});
    // Exact duplicates (and the points they repeat) are not deletable one by one; leave them.
    std::vector<bool> deletable(points.size(), true);
    for (const auto& d : full.duplicates) {
        deletable[d[0]] = deletable[d[1]] = false;
    }
    std::vector<std::uint32_t> pool;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        if (deletable[i]) {
            pool.push_back(i);
        }
    }
    // Keep at least half of the points (and a 3D triangulation) whatever the suite asks.
    const std::uint64_t count = std::min<std::uint64_t>(tier.deletions, pool.size() / 2);
    core::ArrayStorage storage = core::complex_from_tets(full.tets);
    const core::Geometry geometry = core::geometry_by_index(points);
    core::Random random(run.seed + 2000);
    std::vector<bool> gone(points.size(), false);
    core::RetriangulationCounters total;
    RunOutput out;
    std::uint64_t hull_deletions = 0, degree_sum = 0, degree_max = 0, star_sum = 0;
    double degree_sq_sum = 0;
    double delete_s = 0;
    for (std::uint64_t k = 0; k < count; ++k) {
        const std::size_t pick = random.below(pool.size());
        const core::VertexId v = pool[pick];
        pool[pick] = pool.back();
        pool.pop_back();
        const Star star = star_of(storage, v);
        core::RetriangulationCounters one;
        const auto start = Clock::now();
        core::delete_vertex(storage, geometry, v, {}, one);
        delete_s += seconds_since(start);
        gone[v] = true;
        hull_deletions += star.hull ? 1 : 0;
        degree_sum += star.degree;
        degree_sq_sum += static_cast<double>(star.degree) * static_cast<double>(star.degree);
        degree_max = std::max(degree_max, star.degree);
        star_sum += star.tets;
        total.tets_created += one.tets_created;
        total.tets_deleted += one.tets_deleted;
        total.facets_wrapped += one.facets_wrapped;
        total.apex_orient_tests += one.apex_orient_tests;
        total.insphere_calls += one.insphere_calls;
        out.j_rows.push_back({number(k),
                              number(std::uint64_t{v}),
                              star.hull ? "1" : "0",
                              number(star.degree),
                              number(star.tets),
                              number(one.tets_created),
                              number(one.facets_wrapped),
                              number(one.apex_orient_tests),
                              number(one.insphere_calls)});
    }
    const detail::TetList after = core::solid_tets(storage);
    const auto start = Clock::now();
    const detail::TetList expected = rebuilt_without(points, gone, order);
    const double rebuild_s = seconds_since(start);
    const bool equal = detail::canonical(after) == detail::canonical(expected);
    const auto per = [count](double x) { return count > 0 ? x / static_cast<double>(count) : 0.0; };
    char hash[20];
    std::snprintf(hash,
                  sizeof hash,
                  "%016llx",
                  static_cast<unsigned long long>(detail::canonical_hash(after)));
    out.values = {
        number(std::uint64_t{points.size()}),
        number(std::uint64_t{full.tets.size()}),
        number(std::uint64_t{after.size()}),
        number(count),
        number(hull_deletions),
        number(delete_s),
        number(per(delete_s * 1e6)),
        number(rebuild_s),
        number(per(static_cast<double>(degree_sum))),
        number(degree_max),
        number(per(static_cast<double>(star_sum))),
        number(total.tets_created),
        number(total.tets_deleted),
        number(total.facets_wrapped),
        number(total.apex_orient_tests),
        number(total.insphere_calls),
        number(per(static_cast<double>(total.tets_created))),
        number(per(static_cast<double>(total.insphere_calls))),
        number(per(static_cast<double>(total.apex_orient_tests))),
        number(degree_sq_sum > 0 ? static_cast<double>(total.apex_orient_tests) / degree_sq_sum
                                 : 0.0),
        equal ? "1" : "0",
        hash};
    return out;
}

}  // namespace cavity::experiments::measure
