#include "cavity/predicates/orient4d.h"

#include <array>
#include <cmath>
#include <optional>

#include "cavity/predicates/detail/expansion.h"
#include "exact_integer.h"
#include "lifted_adaptive.h"
#include "small_integers.h"
#include "staged_pipeline.h"

namespace cavity::predicates::detail {
namespace {

std::optional<Verdict> orient4d_adaptive(const std::array<WeightedPoint3, 5>& p) {
    LiftedRows rows{};
    double tails = 0.0;
    for (int i = 0; i < 4; ++i) {
        two_diff(p[i].x, p[4].x, rows.x[i], rows.xt[i]);
        two_diff(p[i].y, p[4].y, rows.y[i], rows.yt[i]);
        two_diff(p[i].z, p[4].z, rows.z[i], rows.zt[i]);
        two_diff(p[i].w, p[4].w, rows.w[i], rows.wt[i]);
        // Tails are nonzero multiples of 2^-332 or zero, and far below overflow here, so this
        // sum of magnitudes is 0 exactly when every tail is.
        tails += std::abs(rows.xt[i]) + std::abs(rows.yt[i]) + std::abs(rows.zt[i]) +
                 std::abs(rows.wt[i]);
    }
    rows.differences_exact = tails == 0.0;
    return lifted_adaptive(rows, lifted_permanent(rows));
}

}  // namespace

Verdict orient4d_slow(const WeightedPoint3& a,
                      const WeightedPoint3& b,
                      const WeightedPoint3& c,
                      const WeightedPoint3& d,
                      const WeightedPoint3& e) {
    const std::array<WeightedPoint3, 5> query = {a, b, c, d, e};
    // The first point alone before the others: most queries here have fractional coordinates.
    if (is_small_integer(a) && all_small_integers(b, c, d, e)) {
        LiftedRows rows{};
        for (int i = 0; i < 4; ++i) {
            rows.x[i] = query[i].x - query[4].x;
            rows.y[i] = query[i].y - query[4].y;
            rows.z[i] = query[i].z - query[4].z;
            rows.w[i] = query[i].w - query[4].w;
        }
        rows.differences_exact = true;
        if (const std::optional<Sign> s = lifted_small_integers(rows)) {
            return {*s, Stage::kAdaptive};
        }
    }
    return run_after_filter(
        query,
        kLiftedAdaptiveWindow,
        [](const auto& p) { return orient4d_filter(p[0], p[1], p[2], p[3], p[4]); },
        orient4d_adaptive,
        [](const auto& p) { return orient4d_exact(p[0], p[1], p[2], p[3], p[4]); });
}

}  // namespace cavity::predicates::detail
