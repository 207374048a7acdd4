#include <algorithm>
#include <chrono>
#include <cmath>

#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/creation.h"
#include "cavity/experiments/identity_test.h"
#include "cavity/experiments/jtets.h"
#include "cavity/experiments/measure.h"
#include "format.h"

namespace cavity::experiments::measure {

using detail::number;

namespace {

/// Proposition 5.2: under a uniform order a j-tetrahedron is created with probability
/// 1/C(j+4, 4), the chance that its four vertices come before its j stoppers.
double q_uniform(std::size_t j) {
    const auto jj = static_cast<double>(j);
    return 24.0 / ((jj + 1) * (jj + 2) * (jj + 3) * (jj + 4));
}

}  // namespace

std::vector<std::string> creation_columns() {
    // Per order: tetrahedra created and Σj, their standard deviations over the orders, and the
    // exact expectations under a uniform order (Proposition 5.2: Σ_j f_j / C(j+4, 4) and
    // Σ_j j f_j / C(j+4, 4)), so that each identity is tested with its own standard error; and
    // the joint test of every q_j at once (Hotelling's T² over the orders, with its degrees of
    // freedom and the bins that never vary, which are compared exactly).
    return {"points",
            "orders",
            "time_s",
            "created_mean",
            "created_solid_total",
            "rule_violations",
            "sum_j_mean",
            "created_sd",
            "sum_j_sd",
            "created_exact_uniform",
            "sum_j_exact_uniform",
            "identity_bins",
            "identity_t2",
            "identity_fixed_bins"};
}

std::vector<std::string> creation_j_columns() {
    // created_sd: the standard deviation over orders of the number created per order, so that
    // q̂_j's interval accounts for the dependence of the tetrahedra of one order.
    return {"j", "f_j", "created", "created_sd", "q_hat", "q_uniform", "j4_q_hat"};
}

RunOutput creation(const Suite& suite, const TierSettings& tier, const RunSpec& run) {
    const core::PointSet points = core::generate_points(run.dist, run.n, run.seed);
    const auto start = std::chrono::steady_clock::now();
    const JTetCounts counts = count_jtets(points.points);
    std::vector<double> expected(counts.f.size());
    for (std::size_t j = 0; j < counts.f.size(); ++j) {
        expected[j] = static_cast<double>(counts.f[j]) * q_uniform(j);
    }
    IdentityTest identity(expected, tier.orders);
    std::vector<std::uint64_t> created(counts.f.size(), 0);
    std::vector<std::uint64_t> created_squares(counts.f.size(), 0);
    std::uint64_t violations = 0;
    std::uint64_t created_total = 0;
    std::uint64_t sum_j = 0;
    detail::Moments created_per_order;
    detail::Moments sum_j_per_order;
    for (std::uint64_t r = 0; r < tier.orders; ++r) {
        // Order seeds differ per repetition and from the point seed.
        const core::InsertionOrder order = core::make_insertion_order(
            points.points,
            detail::order_options(run.order, suite.brio_ratio, run.seed * 1000003 + r));
        const CreationAudit audit = audit_creation(points, order.sequence);
        violations += audit.violations;
        std::uint64_t created_here = 0;
        std::uint64_t sum_j_here = 0;
        identity.add(audit.created_by_j);
        for (const auto& [j, number_created] : audit.created_by_j) {
            created[j] += number_created;
            created_squares[j] += number_created * number_created;
            created_here += number_created;
            sum_j_here += j * number_created;
        }
        created_total += created_here;
        sum_j += sum_j_here;
        created_per_order.add(static_cast<double>(created_here));
        sum_j_per_order.add(static_cast<double>(sum_j_here));
    }
    const double time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto orders = static_cast<double>(tier.orders);
    double created_exact = 0;
    double sum_j_exact = 0;
    const IdentityTest::Result joint = identity.result();
    RunOutput out;
    for (std::size_t j = 0; j < counts.f.size(); ++j) {
        if (counts.f[j] == 0) {
            continue;
        }
        const double q_hat =
            static_cast<double>(created[j]) / (orders * static_cast<double>(counts.f[j]));
        const double jj = static_cast<double>(j);
        created_exact += expected[j];
        sum_j_exact += jj * expected[j];
        detail::Moments per_order{static_cast<double>(created[j]),
                                  static_cast<double>(created_squares[j])};
        out.j_rows.push_back({number(std::uint64_t{j}),
                              number(counts.f[j]),
                              number(created[j]),
                              number(per_order.sd(orders)),
                              number(q_hat),
                              number(q_uniform(j)),
                              number(q_hat * jj * jj * jj * jj)});
    }
    out.values = {number(std::uint64_t{points.size()}),
                  number(tier.orders),
                  number(time_s),
                  number(static_cast<double>(created_total) / orders),
                  number(created_total),
                  number(violations),
                  number(static_cast<double>(sum_j) / orders),
                  number(created_per_order.sd(orders)),
                  number(sum_j_per_order.sd(orders)),
                  number(created_exact),
                  number(sum_j_exact),
                  number(std::uint64_t{joint.bins}),
                  number(joint.t2),
                  number(std::uint64_t{joint.fixed})};
    return out;
}

}  // namespace cavity::experiments::measure
