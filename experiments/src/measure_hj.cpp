#include <algorithm>
#include <chrono>
#include <cmath>

#include "cavity/core/delaunay/conflict_counter.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

using detail::number;

std::vector<std::string> hj_columns() {
    return {"points",
            "orders",
            "brio_ratio",
            "time_s",
            "created_mean",
            "created_sd",
            "sum_j_mean",
            "sum_j_sd",
            "ghost_conflicts_mean",
            "live_conflicts_max_mean"};
}

std::vector<std::string> hj_j_columns() {
    return {"j", "h_mean", "h_sd", "q_uniform"};
}

RunOutput hj(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const auto start = std::chrono::steady_clock::now();
    const std::size_t bins = core::ConflictCountingObserver::kHistogramBins - 1;  // exact bins
    std::vector<detail::Moments> h(bins);
    detail::Moments created;
    detail::Moments sum_j;
    detail::Moments ghost;
    detail::Moments live_max;
    double ratio = suite.brio_ratio;
    for (std::uint64_t r = 0; r < tier.orders; ++r) {
        // The same order seeds as the creation suite; the bootstrap is the order's own first
        // four points, so that a uniform order stays a uniform permutation.
        const core::OrderOptions options =
            detail::order_options(run.order, suite.brio_ratio, run.seed * 1000003 + r);
        ratio = options.brio_ratio;
        const core::InsertionOrder order = core::make_insertion_order(points.points, options);
        core::TriangulateOptions triangulate;
        triangulate.bootstrap = core::BootstrapRule::kFirst;
        core::ConflictCountingObserver observer;
        const core::Triangulation result =
            core::triangulate_observed(points, order.sequence, triangulate, observer);
        for (std::size_t j = 0; j < bins; ++j) {
            h[j].add(static_cast<double>(observer.histogram()[j]));
        }
        const core::Counters& c = result.counters;
        created.add(static_cast<double>(c.tets_created));
        sum_j.add(static_cast<double>(c.conflicts_created));
        ghost.add(static_cast<double>(c.ghost_conflicts_created));
        live_max.add(static_cast<double>(c.live_conflicts_max));
    }
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto orders = static_cast<double>(tier.orders);
    RunOutput out;
    for (std::size_t j = 0; j < bins; ++j) {
        if (h[j].sum == 0) {
            continue;
        }
        const auto jj = static_cast<double>(j);
        const double q_uniform = 24.0 / ((jj + 1) * (jj + 2) * (jj + 3) * (jj + 4));
        out.j_rows.push_back({number(std::uint64_t{j}),
                              number(h[j].mean(orders)),
                              number(h[j].sd(orders)),
                              number(q_uniform)});
    }
    out.values = {number(std::uint64_t{points.size()}),
                  number(tier.orders),
                  run.order.rfind("brio", 0) == 0 ? number(ratio) : std::string("-"),
                  number(time_s),
                  number(created.mean(orders)),
                  number(created.sd(orders)),
                  number(sum_j.mean(orders)),
                  number(sum_j.sd(orders)),
                  number(ghost.mean(orders)),
                  number(live_max.mean(orders))};
    return out;
}

}  // namespace cavity::experiments::measure
