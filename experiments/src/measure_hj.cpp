#include <algorithm>
#include <chrono>
#include <cmath>

#include "cavity/core/conflict_counter.h"
#include "cavity/core/generate.h"
#include "cavity/core/insertion_order.h"
#include "cavity/core/triangulate_observed.h"
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
    std::vector<double> h_sum(bins, 0);
    std::vector<double> h_squares(bins, 0);
    double created = 0;
    double created_squares = 0;
    double sum_j = 0;
    double sum_j_squares = 0;
    double ghost = 0;
    double live_max = 0;
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
        const std::vector<std::uint64_t>& h = observer.histogram();
        for (std::size_t j = 0; j < bins; ++j) {
            const auto x = static_cast<double>(h[j]);
            h_sum[j] += x;
            h_squares[j] += x * x;
        }
        const core::Counters& c = result.counters;
        const auto made = static_cast<double>(c.tets_created);
        const auto conflicts = static_cast<double>(c.conflicts_created);
        created += made;
        created_squares += made * made;
        sum_j += conflicts;
        sum_j_squares += conflicts * conflicts;
        ghost += static_cast<double>(c.ghost_conflicts_created);
        live_max += static_cast<double>(c.live_conflicts_max);
    }
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto orders = static_cast<double>(tier.orders);
    const auto sd = [orders](double total, double squares) {
        if (orders < 2) {
            return 0.0;
        }
        const double mean = total / orders;
        return std::sqrt(std::max(0.0, (squares - orders * mean * mean) / (orders - 1)));
    };
    RunOutput out;
    for (std::size_t j = 0; j < bins; ++j) {
        if (h_sum[j] == 0) {
            continue;
        }
        const auto jj = static_cast<double>(j);
        const double q_uniform = 24.0 / ((jj + 1) * (jj + 2) * (jj + 3) * (jj + 4));
        out.j_rows.push_back({number(std::uint64_t{j}),
                              number(h_sum[j] / orders),
                              number(sd(h_sum[j], h_squares[j])),
                              number(q_uniform)});
    }
    out.values = {number(std::uint64_t{points.size()}),
                  number(tier.orders),
                  run.order.rfind("brio", 0) == 0 ? number(ratio) : std::string("-"),
                  number(time_s),
                  number(created / orders),
                  number(sd(created, created_squares)),
                  number(sum_j / orders),
                  number(sd(sum_j, sum_j_squares)),
                  number(ghost / orders),
                  number(live_max / orders)};
    return out;
}

}  // namespace cavity::experiments::measure
