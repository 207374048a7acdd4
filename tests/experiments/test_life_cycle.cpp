#include <algorithm>
#include <limits>
#include <map>

#include <gtest/gtest.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/experiments/creation.h"
#include "cavity/experiments/jtets.h"
#include "cavity/experiments/life_cycle.h"
#include "cavity/predicates/insphere.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::experiments {
namespace {

using Tet = std::array<std::uint32_t, 4>;

struct Observed {
    std::vector<TetLife> lives;
    /// The order the engine actually inserted the points in: the bootstrap may move the first
    /// four affinely independent points ahead of the rest.
    std::vector<std::uint32_t> inserted;
};

Observed observe(const core::PointSet& points,
                 std::span<const std::uint32_t> sequence,
                 core::LocateKind locate,
                 core::StorageKind storage,
                 core::BootstrapRule bootstrap = core::BootstrapRule::kWidest) {
    LifeCycleObserver observer;
    core::TriangulateOptions options;
    options.locate = locate;
    options.storage = storage;
    options.bootstrap = bootstrap;
    core::triangulate_observed(points, sequence, options, observer);
    std::vector<std::uint32_t> inserted(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        inserted[observer.rank_of_input(i)] = i;
    }
    return {observer.lives(), inserted};
}

/// The chapter's rule, by enumeration: the 4-subsets whose last vertex (in insertion order)
/// precedes their first stopper, with the steps at which they are created and deleted.
std::vector<TetLife> predicted_lives(const core::PointSet& points,
                                     std::span<const std::uint32_t> sequence) {
    const auto& p = points.points;
    const auto n = static_cast<std::uint32_t>(p.size());
    std::vector<std::uint32_t> rank(n);
    for (std::uint32_t r = 0; r < n; ++r) {
        rank[sequence[r]] = r;
    }
    std::vector<TetLife> lives;
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            for (std::uint32_t c = b + 1; c < n; ++c) {
                for (std::uint32_t d = c + 1; d < n; ++d) {
                    const auto o = predicates::orient3d(p[a], p[b], p[c], p[d]);
                    if (o == predicates::Sign::kZero) {
                        continue;
                    }
                    const std::uint32_t last = std::max({rank[a], rank[b], rank[c], rank[d]});
                    std::uint32_t first_stopper = std::numeric_limits<std::uint32_t>::max();
                    for (std::uint32_t y = 0; y < n; ++y) {
                        const auto s = predicates::insphere(p[a], p[b], p[c], p[d], p[y]);
                        if (s != predicates::Sign::kZero && s == o) {
                            first_stopper = std::min(first_stopper, rank[y]);
                        }
                    }
                    if (last < first_stopper) {
                        lives.push_back({{a, b, c, d},
                                         false,
                                         last == 3 ? 0u : last,
                                         first_stopper == std::numeric_limits<std::uint32_t>::max()
                                             ? kNeverDeleted
                                             : first_stopper});
                    }
                }
            }
        }
    }
    return lives;
}

std::vector<std::tuple<Tet, std::uint64_t, std::uint64_t>> solid(
    const std::vector<TetLife>& lives) {
    std::vector<std::tuple<Tet, std::uint64_t, std::uint64_t>> out;
    for (const TetLife& life : lives) {
        if (!life.ghost) {
            out.emplace_back(life.vertices, life.created, life.deleted);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

TEST(LifeCycle, CreatedTetrahedraAreExactlyThoseWhoseVerticesPrecedeAllStoppers) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const core::PointSet points = core::generate_points(seed % 2 ? "cube" : "ball", 30, seed);
        for (const char* order : {"random", "brio", "hilbert"}) {
            core::OrderOptions options;
            options.kind = core::parse_order_kind(order);
            options.seed = seed + 100;
            const auto sequence = core::make_insertion_order(points.points, options).sequence;
            const Observed r =
                observe(points, sequence, core::LocateKind::kWalk, core::StorageKind::kArray);
            const auto observed = solid(r.lives);
            const auto predicted = solid(predicted_lives(points, r.inserted));
            ASSERT_FALSE(observed.empty());
            EXPECT_EQ(observed, predicted) << "seed " << seed << ", order " << order;
        }
    }
}

TEST(LifeCycle, WalkAndConflictGraphCreateTheSameTetrahedra) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const core::PointSet points = core::generate_points("gaussian", 300, seed);
        core::OrderOptions options;
        options.kind = core::OrderKind::kRandom;
        options.seed = seed;
        const auto sequence = core::make_insertion_order(points.points, options).sequence;
        const Observed walk =
            observe(points, sequence, core::LocateKind::kWalk, core::StorageKind::kArray);
        const Observed graph =
            observe(points, sequence, core::LocateKind::kConflictGraph, core::StorageKind::kHash);
        EXPECT_EQ(walk.inserted, graph.inserted);
        EXPECT_GT(walk.lives.size(), 1000u);
        EXPECT_EQ(solid(walk.lives), solid(graph.lives)) << "seed " << seed;
    }
}

TEST(LifeCycle, AuditFindsNoViolationAndCountsEveryCreatedTetrahedron) {
    const core::PointSet points = core::generate_points("cube", 60, 4);
    core::OrderOptions options;
    options.kind = core::OrderKind::kBrio;
    options.seed = 7;
    const auto sequence = core::make_insertion_order(points.points, options).sequence;
    const CreationAudit audit = audit_creation(points, sequence);
    std::uint64_t created = 0;
    for (const auto& [j, count] : audit.created_by_j) {
        created += count;
    }
    EXPECT_EQ(audit.violations, 0u);
    // The audit takes the sequence's own first four as the bootstrap (an exchangeable order).
    EXPECT_EQ(created,
              solid(observe(points,
                            sequence,
                            core::LocateKind::kWalk,
                            core::StorageKind::kArray,
                            core::BootstrapRule::kFirst)
                        .lives)
                  .size());
}

// The audit decides most points by a squared distance to a certified circumcentre: its j must
// be the exact perturbed count of every created tetrahedron, on cospherical grids too.
TEST(LifeCycle, AuditCountsEqualTheExactCircumballCounts) {
    for (const char* dist : {"cube", "grid", "sphere"}) {
        const core::PointSet points = core::generate_points(dist, 80, 3);
        core::OrderOptions options;
        options.kind = core::OrderKind::kRandom;
        options.seed = 11;
        const auto sequence = core::make_insertion_order(points.points, options).sequence;
        const CreationAudit audit = audit_creation(points, sequence);
        std::map<std::uint64_t, std::uint64_t> expected;
        for (const auto& [tet, created, deleted] : solid(observe(points,
                                                                 sequence,
                                                                 core::LocateKind::kWalk,
                                                                 core::StorageKind::kArray,
                                                                 core::BootstrapRule::kFirst)
                                                             .lives)) {
            ++expected[circumball_count(points.points, tet, true)];
        }
        EXPECT_EQ(audit.created_by_j, expected) << dist;
    }
}

}  // namespace
}  // namespace cavity::experiments
