#include <chrono>
#include <cstdio>

#include "canonical.h"
#include "cavity/core/edit/gift_wrap.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
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

double ratio(double a, double b) {
    return b > 0 ? a / b : 0.0;
}

}  // namespace

std::vector<std::string> giftwrap_columns() {
    return {"points",
            "tets",
            "hull_triangles",
            "gw_s",
            "bw_s",
            "gw_over_bw_time",
            "facets_wrapped",
            "hull_facets",
            "apex_orient_tests",
            "gw_insphere_calls",
            "seed_steps",
            "apex_per_nh",
            "insphere_per_nh",
            "apex_per_facet_per_n",
            "bw_orient3d",
            "bw_insphere",
            "bw_orient4d",
            "bw_ghost",
            "bw_predicates",
            "bw_predicates_per_point",
            "bw_created",
            "gw_over_bw_predicates",
            "same_tets",
            "same_hull",
            "hash"};
}

RunOutput giftwrap(const Suite& suite, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const core::InsertionOrder order = core::make_insertion_order(
        points.points, detail::order_options(run.order, suite.brio_ratio, run.seed));

    // Bowyer-Watson twice: uninstrumented for its time, then counting for its predicate calls.
    auto start = Clock::now();
    const core::Triangulation timed = core::triangulate(points, order.sequence, {});
    const double bw_s = seconds_since(start);
    core::TriangulateOptions counting;
    counting.count = true;
    counting.seed = run.seed;
    const core::Triangulation bw = core::triangulate(points, order.sequence, counting);

    start = Clock::now();
    const core::GiftWrapResult gw = core::gift_wrap_delaunay(points);
    const double gw_s = seconds_since(start);

    const bool same = detail::canonical(gw.tets) == detail::canonical(bw.tets) &&
                      detail::canonical(timed.tets) == detail::canonical(bw.tets);
    const core::RetriangulationCounters& c = gw.counters;
    const auto n = static_cast<double>(points.size());
    const auto h = static_cast<double>(gw.tets.size());
    std::array<std::uint64_t, core::kPredicateKindCount> bw_calls{};
    std::uint64_t bw_total = 0;
    for (std::size_t kind = 0; kind < bw_calls.size(); ++kind) {
        for (std::uint64_t calls : bw.counters.stage_calls[kind]) {
            bw_calls[kind] += calls;
        }
        bw_total += bw_calls[kind];
    }
    const double gw_total = static_cast<double>(c.apex_orient_tests + c.insphere_calls);
    char hash[20];
    std::snprintf(hash,
                  sizeof hash,
                  "%016llx",
                  static_cast<unsigned long long>(detail::canonical_hash(gw.tets)));
    RunOutput out;
    out.values = {number(std::uint64_t{points.size()}),
                  number(std::uint64_t{gw.tets.size()}),
                  number(std::uint64_t{gw.hull_triangles}),
                  number(gw_s),
                  number(bw_s),
                  number(ratio(gw_s, bw_s)),
                  number(c.facets_wrapped),
                  number(c.hull_facets),
                  number(c.apex_orient_tests),
                  number(c.insphere_calls),
                  number(c.seed_steps),
                  number(ratio(static_cast<double>(c.apex_orient_tests), n * h)),
                  number(ratio(static_cast<double>(c.insphere_calls), n * h)),
                  number(ratio(static_cast<double>(c.apex_orient_tests),
                               static_cast<double>(c.facets_wrapped) * n)),
                  number(bw_calls[static_cast<std::size_t>(core::PredicateKind::kOrient3d)]),
                  number(bw_calls[static_cast<std::size_t>(core::PredicateKind::kInsphere)]),
                  number(bw_calls[static_cast<std::size_t>(core::PredicateKind::kOrient4d)]),
                  number(bw_calls[static_cast<std::size_t>(core::PredicateKind::kGhost)]),
                  number(bw_total),
                  number(ratio(static_cast<double>(bw_total), n)),
                  number(bw.counters.tets_created),
                  number(ratio(gw_total, static_cast<double>(bw_total))),
                  same ? "1" : "0",
                  gw.hull_triangles == bw.hull_triangles ? "1" : "0",
                  hash};
    return out;
}

}  // namespace cavity::experiments::measure
