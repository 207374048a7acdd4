// The conflict counter (Σj of Theorem 5.4) against brute force: every created tetrahedron's
// conflicts recounted over all points, for solid tetrahedra with the perturbed insphere called
// directly (not through the engine's Geometry), on random, degenerate and weighted sets.

#include <algorithm>
#include <memory>
#include <numeric>

#include <gtest/gtest.h>

#include "cavity/core/delaunay/conflict_counter.h"
#include "cavity/core/delaunay/point_kd_tree.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/perturbation/sos.h"

namespace cavity::core {
namespace {

/// The counter, logging every tetrahedron it saw created, and a copy of the engine's points (the
/// engine's own do not outlive the run).
struct LoggingCounter : ConflictCountingObserver {
    using ConflictCountingObserver::ConflictCountingObserver;

    void on_start(const Geometry& g) {
        ConflictCountingObserver::on_start(g);
        geometry = std::make_unique<Geometry>(g);
    }

    void on_tet_created(TetId t, const TetVertices& v, std::uint64_t step) {
        ConflictCountingObserver::on_tet_created(t, v, step);
        created.push_back(v);
    }

    std::unique_ptr<Geometry> geometry;
    std::vector<TetVertices> created;
};

struct BruteForce {
    std::uint64_t solid = 0;
    std::uint64_t ghost = 0;
    std::vector<std::uint64_t> histogram =
        std::vector<std::uint64_t>(ConflictCountingObserver::kHistogramBins, 0);
};

BruteForce brute_force(const LoggingCounter& log) {
    const Geometry& g = *log.geometry;
    BruteForce out;
    for (const TetVertices& v : log.created) {
        std::uint64_t j = 0;
        for (VertexId y = 0; y < g.size(); ++y) {
            if (std::find(v.begin(), v.end(), y) != v.end()) {
                continue;
            }
            if (is_ghost(v)) {
                j += g.conflicts_ghost(v, y, {0, 1, 2, 3}) ? 1 : 0;
            } else if (!g.weighted()) {
                const perturbation::Keys5 keys{
                    g.key(v[0]), g.key(v[1]), g.key(v[2]), g.key(v[3]), g.key(y)};
                j += perturbation::insphere_sos(g.point(v[0]),
                                                g.point(v[1]),
                                                g.point(v[2]),
                                                g.point(v[3]),
                                                g.point(y),
                                                keys) == Sign::kPos;
            } else {
                j += g.conflicts_solid(v, y) ? 1 : 0;
            }
        }
        if (is_ghost(v)) {
            out.ghost += j;
        } else {
            out.solid += j;
            ++out.histogram[std::min<std::uint64_t>(j, out.histogram.size() - 1)];
        }
    }
    return out;
}

Counters count(const PointSet& points, OrderKind kind, LocateKind locate, BruteForce* brute) {
    OrderOptions order;
    order.kind = kind;
    order.seed = 11;
    const InsertionOrder sequence = make_insertion_order(points.points, order);
    TriangulateOptions options;
    options.locate = locate;
    // Batches of 97 created tetrahedra: counts cross many batch boundaries, and tetrahedra are
    // deleted both before and after their batch is counted.
    LoggingCounter observer(true, 97);
    const Triangulation tri = triangulate_observed(points, sequence.sequence, options, observer);
    if (brute != nullptr) {
        *brute = brute_force(observer);
        EXPECT_EQ(observer.histogram(), brute->histogram);
    }
    // Every conflict created is deleted by the end (each point is a vertex, a repeat or
    // redundant), and the steps add up to the totals.
    const Counters& c = tri.counters;
    EXPECT_EQ(c.conflicts_created + c.ghost_conflicts_created,
              c.conflicts_deleted + c.ghost_conflicts_deleted);
    std::uint64_t created = 0;
    std::uint64_t live_max = 0;
    for (const ConflictStep& s : observer.steps()) {
        created += s.created;
        live_max = std::max(live_max, s.live);
    }
    EXPECT_EQ(created, c.conflicts_created + c.ghost_conflicts_created);
    EXPECT_EQ(live_max, c.live_conflicts_max);
    EXPECT_EQ(observer.steps().back().live, 0u);
    return c;
}

TEST(ConflictCounter, EqualsBruteForceOnRandomAndDegenerateSets) {
    const std::vector<std::pair<const char*, std::size_t>> sets = {{"cube", 400},
                                                                   {"ball", 300},
                                                                   {"grid", 216},
                                                                   {"cospherical", 120},
                                                                   {"skew-lines", 80},
                                                                   {"paraboloid", 100}};
    for (const auto& [name, n] : sets) {
        SCOPED_TRACE(name);
        const PointSet points = generate_points(name, n, 7);
        for (const OrderKind kind : {OrderKind::kRandom, OrderKind::kBrio}) {
            BruteForce brute;
            const Counters c = count(points, kind, LocateKind::kWalk, &brute);
            EXPECT_EQ(c.conflicts_created, brute.solid);
            EXPECT_EQ(c.ghost_conflicts_created, brute.ghost);
            EXPECT_GT(c.conflicts_created, 0u);
        }
    }
}

TEST(ConflictCounter, EqualsBruteForceOnWeightedSets) {
    WeightSpec weights;
    weights.kind = WeightSpec::Kind::kUniform;
    weights.a = 0;
    weights.b = 0.01;
    const PointSet points = generate_points("cube", 300, 3, weights);
    BruteForce brute;
    const Counters c = count(points, OrderKind::kRandom, LocateKind::kWalk, &brute);
    EXPECT_EQ(c.conflicts_created, brute.solid);
    EXPECT_EQ(c.ghost_conflicts_created, brute.ghost);
}

// Far from the origin and tiny: the floating-point circumcentre is poor, and pruning must stay
// safe (or step aside).
TEST(ConflictCounter, EqualsBruteForceAtExtremeScales) {
    for (const double scale : {1e-150, 1e-30, 1e30, 1e120}) {
        SCOPED_TRACE(scale);
        PointSet points = generate_points("cube", 150, 5);
        for (Point3& p : points.points) {
            p = {p.x * scale + 1e3 * scale, p.y * scale, p.z * scale};
        }
        BruteForce brute;
        const Counters c = count(points, OrderKind::kRandom, LocateKind::kWalk, &brute);
        EXPECT_EQ(c.conflicts_created, brute.solid);
        EXPECT_EQ(c.ghost_conflicts_created, brute.ghost);
    }
}

// Σj depends on the order only: the locator and the storage change how the cavity is found, not
// which tetrahedra are created.
TEST(ConflictCounter, TheSameForEveryLocatorAndStorage) {
    const PointSet points = generate_points("cube", 3000, 2);
    const Counters walk = count(points, OrderKind::kBrio, LocateKind::kWalk, nullptr);
    const Counters graph = count(points, OrderKind::kBrio, LocateKind::kConflictGraph, nullptr);
    EXPECT_EQ(walk.conflicts_created, graph.conflicts_created);
    EXPECT_EQ(walk.ghost_conflicts_created, graph.ghost_conflicts_created);
    EXPECT_EQ(walk.live_conflicts_max, graph.live_conflicts_max);

    OrderOptions order;
    order.seed = 11;
    const InsertionOrder sequence = make_insertion_order(points.points, order);
    TriangulateOptions options;
    options.count_conflicts = true;
    options.storage = StorageKind::kHash;
    const Triangulation hashed = triangulate(points, sequence.sequence, options);
    EXPECT_EQ(hashed.counters.conflicts_created, walk.conflicts_created);
}

// A prefix run inserts the first k points and counts their conflicts against all n: its steps are
// exactly the first k - 4 steps of the whole run (the bootstrap's conflicts go to the first), for
// the walk and the conflict graph, which still holds the points it never inserts.
TEST(ConflictCounter, APrefixRunIsTheStartOfTheWholeRun) {
    const PointSet points = generate_points("ball", 2500, 4);
    OrderOptions order;
    order.seed = 5;
    const InsertionOrder sequence = make_insertion_order(points.points, order);
    TriangulateOptions options;
    options.bootstrap = BootstrapRule::kFirst;
    ConflictCountingObserver whole(true, 97);
    const Triangulation all = triangulate_observed(points, sequence.sequence, options, whole);
    for (const LocateKind locate : {LocateKind::kWalk, LocateKind::kConflictGraph}) {
        for (const std::size_t k : {4u, 5u, 300u, 2499u, 2500u}) {
            SCOPED_TRACE(k);
            options.locate = locate;
            options.prefix = k;
            ConflictCountingObserver prefix(true, 97);
            const Triangulation part =
                triangulate_observed(points, sequence.sequence, options, prefix);
            ASSERT_EQ(prefix.steps().size(), k - 4);
            std::uint64_t created = 0;
            for (std::size_t s = 0; s < k - 4; ++s) {
                EXPECT_EQ(prefix.steps()[s].created, whole.steps()[s].created) << s;
                EXPECT_EQ(prefix.steps()[s].deleted, whole.steps()[s].deleted) << s;
                EXPECT_EQ(prefix.steps()[s].live, whole.steps()[s].live) << s;
                created += prefix.steps()[s].created;
            }
            const Counters& c = part.counters;
            if (k > 4) {
                EXPECT_EQ(c.conflicts_created + c.ghost_conflicts_created, created);
            }
            EXPECT_LE(c.tets_created, all.counters.tets_created);
            if (k == points.size()) {
                EXPECT_EQ(c.conflicts_created, all.counters.conflicts_created);
                const auto as_set = [](std::vector<std::array<std::uint32_t, 4>> tets) {
                    for (auto& t : tets) {
                        std::sort(t.begin(), t.end());
                    }
                    std::sort(tets.begin(), tets.end());
                    return tets;
                };
                EXPECT_EQ(as_set(part.tets), as_set(all.tets));
            }
        }
    }
}

// The two independent counts: the full conflict graph's lists and the kd-tree counter agree to the
// unit (run together, the engine checks it and throws otherwise), on random, degenerate and
// weighted sets, for every order.
TEST(ConflictCounter, TheFullConflictGraphCountsTheSame) {
    WeightSpec weights;
    weights.kind = WeightSpec::Kind::kUniform;
    weights.b = 0.02;
    const std::vector<PointSet> sets = {generate_points("cube", 2000, 1),
                                        generate_points("grid", 343, 2),
                                        generate_points("cospherical", 200, 3),
                                        generate_points("skew-lines", 120, 4),
                                        generate_points("ball", 800, 5, weights)};
    for (const PointSet& points : sets) {
        for (const OrderKind kind : {OrderKind::kRandom, OrderKind::kBrio, OrderKind::kHilbert}) {
            OrderOptions order;
            order.kind = kind;
            order.seed = 9;
            const InsertionOrder sequence = make_insertion_order(points.points, order);
            TriangulateOptions options;
            options.locate = LocateKind::kFullConflictGraph;
            options.count = true;
            const Counters graph = triangulate(points, sequence.sequence, options).counters;
            options.locate = LocateKind::kWalk;
            options.count_conflicts = true;
            const Counters counted = triangulate(points, sequence.sequence, options).counters;
            EXPECT_EQ(graph.conflicts_created, counted.conflicts_created);
            EXPECT_EQ(graph.ghost_conflicts_created, counted.ghost_conflicts_created);
            EXPECT_EQ(graph.conflicts_deleted, counted.conflicts_deleted);
            EXPECT_EQ(graph.live_conflicts_max, counted.live_conflicts_max);
            EXPECT_GT(graph.conflicts_created, 0u);
            options.locate = LocateKind::kFullConflictGraph;
            EXPECT_NO_THROW(triangulate(points, sequence.sequence, options));
        }
    }
}

}  // namespace
}  // namespace cavity::core

namespace cavity::core {
namespace {

// PointKdTree::count certifies whole boxes: the points it counts whole plus those it visits and
// finds inside must be exactly the points inside, for regions that do and do not cover boxes.
TEST(PointKdTree, CountingWholeBoxesMissesAndRepeatsNothing) {
    const PointSet points = generate_points("cube", 50000, 11);
    const PointKdTree tree(points.points);
    for (const double half : {0.02, 0.1, 0.3, 0.7}) {
        const Box3 region{{0.5 - half, 0.4 - half, 0.6 - half},
                          {0.5 + half, 0.4 + half, 0.6 + half}};
        const auto inside = [&](const Point3& p) {
            return p.x >= region.lo.x && p.x <= region.hi.x && p.y >= region.lo.y &&
                   p.y <= region.hi.y && p.z >= region.lo.z && p.z <= region.hi.z;
        };
        std::uint64_t visited_inside = 0;
        std::uint64_t visits = 0;
        const std::uint64_t whole = tree.count(
            [&](const Box3& b) {
                return b.lo.x <= region.hi.x && b.hi.x >= region.lo.x && b.lo.y <= region.hi.y &&
                       b.hi.y >= region.lo.y && b.lo.z <= region.hi.z && b.hi.z >= region.lo.z;
            },
            [&](const Box3& b) { return inside(b.lo) && inside(b.hi); },
            [&](std::uint32_t, const Point3& p) {
                ++visits;
                visited_inside += inside(p) ? 1 : 0;
            });
        const auto expected = static_cast<std::uint64_t>(
            std::count_if(points.points.begin(), points.points.end(), inside));
        EXPECT_EQ(whole + visited_inside, expected) << "half side " << half;
        if (half >= 0.3) {
            EXPECT_GT(whole, expected / 2) << "large regions are counted mostly by whole boxes";
            EXPECT_LT(visits, points.size() / 2);
        }
    }
}

}  // namespace
}  // namespace cavity::core
