#include "cavity/predicates/insphere.h"

#include <array>
#include <cmath>
#include <optional>

#include "cavity/predicates/detail/expansion.h"
#include "exact_integer.h"
#include "insphere_permanent.h"
#include "lifted_adaptive.h"
#include "small_integers.h"
#include "staged_pipeline.h"

namespace cavity::predicates::detail {
namespace {

std::optional<Verdict> insphere_adaptive(const std::array<Point3, 5>& p) {
    const LiftedRows rows = insphere_rows(p);
    // One permanent for every stage: on a rounded sphere most queries pass through stage A to
    // the double-double stage, which needs it again.
    const double permanent = insphere_row_permanent(rows);
    if (const std::optional<Sign> s = insphere_permanent(rows, permanent)) {
        return Verdict{*s, Stage::kAdaptive};
    }
    return lifted_adaptive(rows, permanent, p);
}

}  // namespace

Verdict insphere_slow(
    const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
    const std::array<Point3, 5> query = {a, b, c, d, e};
    // The first point alone before the others: most queries here have fractional coordinates.
    if (is_small_integer(a) && all_small_integers(b, c, d, e)) {
        LiftedRows rows{};
        for (int i = 0; i < 4; ++i) {
            rows.x[i] = query[i].x - query[4].x;
            rows.y[i] = query[i].y - query[4].y;
            rows.z[i] = query[i].z - query[4].z;
        }
        rows.differences_exact = true;
        if (const std::optional<Sign> s = lifted_small_integers(rows)) {
            return {*s, Stage::kAdaptive};
        }
    }
    return run_after_filter(
        query,
        kLiftedAdaptiveWindow,
        [](const auto& p) { return insphere_filter(p[0], p[1], p[2], p[3], p[4]); },
        insphere_adaptive,
        [](const auto& p) { return insphere_exact(p[0], p[1], p[2], p[3], p[4]); });
}

}  // namespace cavity::predicates::detail
