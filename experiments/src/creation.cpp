#include "cavity/experiments/creation.h"

#include <algorithm>
#include <limits>

#include "cavity/core/delaunay/conflict_reach.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/experiments/life_cycle.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::experiments {

CreationAudit audit_creation(const core::PointSet& points,
                             std::span<const std::uint32_t> sequence) {
    LifeCycleObserver observer;
    // Proposition 5.2's identity holds for an exchangeable order: the bootstrap must be the
    // sequence's own first four, not the widest of 64 candidates, which biases Σj upwards.
    core::TriangulateOptions options;
    options.bootstrap = core::BootstrapRule::kFirst;
    core::triangulate_observed(points, sequence, options, observer);
    CreationAudit audit;
    const auto& p = points.points;
    const auto n = static_cast<std::uint32_t>(p.size());
    for (const TetLife& life : observer.lives()) {
        if (life.ghost) {
            continue;
        }
        std::array<std::uint32_t, 4> t = life.vertices;
        if (predicates::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) == predicates::Sign::kNeg) {
            std::swap(t[0], t[1]);
        }
        std::uint32_t last_trigger = 0;
        for (std::uint32_t v : t) {
            last_trigger = std::max(last_trigger, observer.rank_of_input(v));
        }
        // A squared distance to a certified circumcentre decides all but the points near the
        // sphere; those get the exact perturbed insphere test.
        const core::ConflictReach reach =
            core::conflict_reach({p[t[0]], p[t[1]], p[t[2]], p[t[3]]});
        std::uint64_t j = 0;
        std::uint32_t first_stopper = std::numeric_limits<std::uint32_t>::max();
        for (std::uint32_t y = 0; y < n; ++y) {
            const double d = reach.squared_distance(p[y]);
            if (reach.excludes_squared(d) || y == t[0] || y == t[1] || y == t[2] || y == t[3]) {
                continue;
            }
            if (reach.includes_squared(d) ||
                perturbation::insphere_sos(
                    p[t[0]], p[t[1]], p[t[2]], p[t[3]], p[y], {t[0], t[1], t[2], t[3], y}) ==
                    predicates::Sign::kPos) {
                ++j;
                first_stopper = std::min(first_stopper, observer.rank_of_input(y));
            }
        }
        ++audit.created_by_j[j];
        const std::uint64_t expected_created = last_trigger == 3 ? 0 : last_trigger;
        const std::uint64_t expected_deleted =
            j == 0 ? kNeverDeleted : static_cast<std::uint64_t>(first_stopper);
        if (last_trigger >= first_stopper || life.created != expected_created ||
            life.deleted != expected_deleted) {
            ++audit.violations;
        }
    }
    return audit;
}

}  // namespace cavity::experiments
