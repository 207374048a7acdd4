// The stages the counting engine records: the static filter is the first, counted stage of the
// engine's tests. Checked against an independent tally, the staged predicates called directly
// (what the counting engine ran before the static stage existed): the same signs, every test
// counted once, and the static filter takes its decisions only from the semi-static filter's
// share, so the adaptive and exact counts and the tie-breaks are unchanged.

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/gen/generate.h"
#include "cavity/core/geometry/counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/perturbation/sos.h"
#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/stage.h"

namespace cavity::core {
namespace {

using predicates::Stage;

constexpr auto kInsphere = static_cast<std::size_t>(PredicateKind::kInsphere);
constexpr auto kOrient3d = static_cast<std::size_t>(PredicateKind::kOrient3d);

std::uint64_t at(const std::array<std::uint64_t, predicates::kStageCount>& calls, Stage s) {
    return calls[static_cast<std::size_t>(s)];
}

std::uint64_t total(const std::array<std::uint64_t, predicates::kStageCount>& calls) {
    return std::accumulate(calls.begin(), calls.end(), std::uint64_t{0});
}

Geometry unweighted(const std::vector<Point3>& points) {
    std::vector<std::uint32_t> keys(points.size());
    std::iota(keys.begin(), keys.end(), 0u);
    return Geometry(points, std::move(keys), {});
}

/// The side^3 grid points offset + (x, y, z) for integers 0 <= x, y, z < side.
std::vector<Point3> grid(int side, const Point3& offset) {
    std::vector<Point3> points;
    for (int x = 0; x < side; ++x) {
        for (int y = 0; y < side; ++y) {
            for (int z = 0; z < side; ++z) {
                points.push_back({offset.x + x, offset.y + y, offset.z + z});
            }
        }
    }
    return points;
}

/// Five distinct vertices, the first four a positively oriented tetrahedron (as the engine's
/// solid tetrahedra are); false when the four drawn are coplanar.
bool draw_query(const Geometry& g, std::mt19937_64& rng, TetVertices& t, VertexId& u) {
    std::uniform_int_distribution<VertexId> pick(0, static_cast<VertexId>(g.size() - 1));
    std::array<VertexId, 5> v{};
    for (std::size_t i = 0; i < v.size(); ++i) {
        do {
            v[i] = pick(rng);
        } while (std::find(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(i), v[i]) !=
                 v.begin() + static_cast<std::ptrdiff_t>(i));
    }
    const Sign s = g.orient3d(v[0], v[1], v[2], v[3]);
    if (s == Sign::kZero) {
        return false;
    }
    t = s == Sign::kPos ? TetVertices{v[0], v[1], v[2], v[3]} : TetVertices{v[1], v[0], v[2], v[3]};
    u = v[4];
    return true;
}

/// Runs `queries` in-sphere tests on g counted, uncounted and by the staged predicates called
/// directly, and checks the counts against that independent tally. Returns the counts.
Counters check_insphere_stages(const Geometry& g, int queries) {
    std::mt19937_64 rng(7);
    Counters counted;
    Counters direct;  // the staged predicates' own stages: no static filter
    int asked = 0;
    while (asked < queries) {
        TetVertices t{};
        VertexId u = 0;
        if (!draw_query(g, rng, t, u)) {
            continue;
        }
        ++asked;
        const bool with_count = g.conflicts_solid(t, u, counted);
        const perturbation::Keys5 keys{
            g.key(t[0]), g.key(t[1]), g.key(t[2]), g.key(t[3]), g.key(u)};
        const auto v = perturbation::insphere_sos_staged(
            g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3]), g.point(u), keys);
        direct.count_predicate(PredicateKind::kInsphere, v.stage);
        direct.perturbations += v.cofactors > 0 ? 1 : 0;
        direct.perturbation_cofactors += v.cofactors;
        EXPECT_EQ(with_count, g.conflicts_solid(t, u));
        EXPECT_EQ(with_count, v.sign == Sign::kPos);
    }
    const auto& mine = counted.stage_calls[kInsphere];
    const auto& theirs = direct.stage_calls[kInsphere];
    EXPECT_EQ(total(mine), static_cast<std::uint64_t>(queries));
    EXPECT_EQ(at(theirs, Stage::kStatic), 0u);
    if (g.lattice()) {
        // On an exact lattice the static filter's bound is 0: it decides every test, ties too.
        EXPECT_EQ(at(mine, Stage::kStatic), static_cast<std::uint64_t>(queries));
    } else {
        EXPECT_EQ(at(mine, Stage::kStatic) + at(mine, Stage::kFilter), at(theirs, Stage::kFilter));
        EXPECT_EQ(at(mine, Stage::kAdaptive), at(theirs, Stage::kAdaptive));
        EXPECT_EQ(at(mine, Stage::kExact), at(theirs, Stage::kExact));
    }
    EXPECT_EQ(counted.perturbations, direct.perturbations);
    EXPECT_EQ(counted.perturbation_cofactors, direct.perturbation_cofactors);
    return counted;
}

TEST(Stages, StaticIsCountedFirstOnUniformPointsAndTheLaterStagesKeepTheirCounts) {
    const Geometry g = unweighted(generate_points("cube", 2000, 3).points);
    const Counters c = check_insphere_stages(g, 20000);
    // Not vacuous: well-spread points leave almost everything to the static filter.
    EXPECT_GT(at(c.stage_calls[kInsphere], Stage::kStatic), 19000u);
}

TEST(Stages, OnAGridTheTiesStillReachTheExactStagesAndTheTieBreak) {
    // Half-integer grid points are cospherical in many ways but no lattice (the lattice path
    // needs integers): their ties reach the staged predicates' exact stages.
    const Geometry g = unweighted(grid(6, {0.5, 0.25, 0.125}));
    ASSERT_FALSE(g.lattice());
    const Counters c = check_insphere_stages(g, 20000);
    const auto& calls = c.stage_calls[kInsphere];
    EXPECT_GT(at(calls, Stage::kStatic), 0u);
    EXPECT_GT(at(calls, Stage::kAdaptive) + at(calls, Stage::kExact), 0u);
    EXPECT_GT(c.perturbations, 0u);
}

TEST(Stages, OnALatticeTheStaticFilterDecidesEveryTestAndTiesGoToTheTieBreak) {
    const Geometry g = unweighted(grid(6, {0, 0, 0}));
    ASSERT_TRUE(g.lattice());
    const Counters c = check_insphere_stages(g, 20000);
    EXPECT_GT(c.perturbations, 0u);
}

TEST(Stages, WalkOrientationsCountTheStaticStage) {
    const Geometry g = unweighted(generate_points("cube", 500, 5).points);
    std::mt19937_64 rng(9);
    std::uniform_int_distribution<VertexId> pick(0, static_cast<VertexId>(g.size() - 1));
    Counters counted;
    Counters direct;
    constexpr int kQueries = 10000;
    for (int i = 0; i < kQueries; ++i) {
        const Point3& a = g.point(pick(rng));
        const Point3& b = g.point(pick(rng));
        const Point3& c = g.point(pick(rng));
        const Point3& d = g.point(pick(rng));
        ASSERT_TRUE(g.in_box(a) && g.in_box(b) && g.in_box(c) && g.in_box(d));
        const Sign s = g.orient3d_in_box(a, b, c, d, counted);
        const auto v = predicates::orient3d_staged(a, b, c, d);
        direct.count_predicate(PredicateKind::kOrient3d, v.stage);
        EXPECT_EQ(s, v.sign);
        Uncounted none;
        EXPECT_EQ(s, g.orient3d_in_box(a, b, c, d, none));
    }
    const auto& mine = counted.stage_calls[kOrient3d];
    const auto& theirs = direct.stage_calls[kOrient3d];
    EXPECT_EQ(total(mine), static_cast<std::uint64_t>(kQueries));
    EXPECT_EQ(at(mine, Stage::kStatic) + at(mine, Stage::kFilter), at(theirs, Stage::kFilter));
    EXPECT_EQ(at(mine, Stage::kAdaptive), at(theirs, Stage::kAdaptive));
    EXPECT_EQ(at(mine, Stage::kExact), at(theirs, Stage::kExact));
    EXPECT_GT(at(mine, Stage::kStatic), 0u);
    // Repeated vertices make exact zeros, which no filter decides.
    EXPECT_GT(at(mine, Stage::kExact) + at(mine, Stage::kAdaptive), 0u);
}

// On a lattice the counted orientations derive orient3d_staged's stage instead of running it
// (lattice.h's orient3d_staged_on_lattice): the same counts as the staged predicate, for the tests
// of vertices and the walks' tests in the box, where a query point off the lattice (a straight
// walk's source) takes the staged predicate.
TEST(Stages, OnALatticeOrientationsCountTheStagedPredicatesStages) {
    const Geometry g = unweighted(grid(5, {0, 0, 0}));
    ASSERT_TRUE(g.lattice());
    std::mt19937_64 rng(19);
    std::uniform_int_distribution<VertexId> pick(0, static_cast<VertexId>(g.size() - 1));
    Counters by_vertex;
    Counters in_box;
    Counters direct;      // orient3d_staged's stages, for the tests of vertices
    Counters direct_box;  // the same for the tests in the box (no static stage)
    constexpr int kQueries = 20000;
    for (int i = 0; i < kQueries; ++i) {
        const VertexId a = pick(rng), b = pick(rng), c = pick(rng), d = pick(rng);
        const auto v = predicates::orient3d_staged(g.point(a), g.point(b), g.point(c), g.point(d));
        direct.count_predicate(PredicateKind::kOrient3d, v.stage);
        EXPECT_EQ(g.orient3d(a, b, c, d, by_vertex), v.sign);
        // Every fourth query point off the lattice, still in the box.
        const Point3 q =
            i % 4 == 0 ? Point3{g.point(d).x * 0.75 + 0.5, g.point(d).y, g.point(d).z} : g.point(d);
        ASSERT_TRUE(g.in_box(q));
        const auto w = predicates::orient3d_staged(g.point(a), g.point(b), g.point(c), q);
        const Sign s = g.orient3d_in_box(g.point(a), g.point(b), g.point(c), q, in_box);
        EXPECT_EQ(s, w.sign);
        Uncounted none;
        EXPECT_EQ(s, g.orient3d_in_box(g.point(a), g.point(b), g.point(c), q, none));
        direct_box.count_predicate(PredicateKind::kOrient3d, w.stage);
    }
    EXPECT_EQ(by_vertex.stage_calls[kOrient3d], direct.stage_calls[kOrient3d]);
    // In the box the static filter decides first, and only what the semi-static filter would.
    const auto& mine = in_box.stage_calls[kOrient3d];
    const auto& theirs = direct_box.stage_calls[kOrient3d];
    EXPECT_EQ(at(mine, Stage::kStatic) + at(mine, Stage::kFilter), at(theirs, Stage::kFilter));
    EXPECT_EQ(at(mine, Stage::kAdaptive), at(theirs, Stage::kAdaptive));
    EXPECT_EQ(at(mine, Stage::kExact), at(theirs, Stage::kExact));
    // Not vacuous: the filter, and the exact zeros after it, are reached in both forms.
    EXPECT_GT(at(by_vertex.stage_calls[kOrient3d], Stage::kFilter), 0u);
    EXPECT_GT(at(by_vertex.stage_calls[kOrient3d], Stage::kAdaptive), 0u);
    EXPECT_GT(at(in_box.stage_calls[kOrient3d], Stage::kAdaptive), 0u);
}

TEST(Stages, WeightedGeometryHasNoStaticStage) {
    const PointSet set = generate_points(
        "cube", 1000, 4, WeightSpec{.kind = WeightSpec::Kind::kUniform, .a = 0.0, .b = 0.01});
    std::vector<std::uint32_t> keys(set.size());
    std::iota(keys.begin(), keys.end(), 0u);
    const Geometry g(set.points, keys, set.weights);
    ASSERT_TRUE(g.weighted());
    std::mt19937_64 rng(11);
    Counters c;
    int asked = 0;
    while (asked < 5000) {
        TetVertices t{};
        VertexId u = 0;
        if (draw_query(g, rng, t, u)) {
            ++asked;
            EXPECT_EQ(g.conflicts_solid(t, u, c), g.conflicts_solid(t, u));
        }
    }
    const auto& orient4d = c.stage_calls[static_cast<std::size_t>(PredicateKind::kOrient4d)];
    EXPECT_EQ(total(orient4d), 5000u);
    EXPECT_EQ(at(orient4d, Stage::kStatic), 0u);
    EXPECT_EQ(total(c.stage_calls[kInsphere]), 0u);
}

TEST(Stages, ImplicitPointsHaveNoStaticStage) {
    // Points of a cube's edges as exact fractions: implicit, so the static filter (sound only
    // for the rounded points in its box) must not decide their tests.
    std::vector<Point3> points;
    std::vector<GenericPoint3> exact;
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const Point3 a{unit(rng), unit(rng), unit(rng)};
        const Point3 b{unit(rng), unit(rng), unit(rng)};
        const auto p = predicates::segment_parameter_point(a, b, 1.0, 3.0);
        ASSERT_TRUE(p.has_value());
        exact.emplace_back(*p);
        points.push_back({a.x + (b.x - a.x) / 3, a.y + (b.y - a.y) / 3, a.z + (b.z - a.z) / 3});
    }
    std::vector<std::uint32_t> keys(points.size());
    std::iota(keys.begin(), keys.end(), 0u);
    const Geometry g(points, keys, {}, exact);
    ASSERT_TRUE(g.has_implicit());
    std::mt19937_64 draw(17);
    Counters c;
    int asked = 0;
    while (asked < 3000) {
        TetVertices t{};
        VertexId u = 0;
        if (draw_query(g, draw, t, u)) {
            ++asked;
            EXPECT_EQ(g.conflicts_solid(t, u, c), g.conflicts_solid(t, u));
        }
    }
    const auto& insphere = c.stage_calls[kInsphere];
    EXPECT_EQ(total(insphere), 3000u);
    EXPECT_EQ(at(insphere, Stage::kStatic), 0u);
}

TEST(Stages, TheCountingEngineBuildsThePlainEnginesTetrahedraAndCountsTheStaticStage) {
    for (const char* dist : {"cube", "grid"}) {
        const PointSet set = generate_points(dist, 3000, 21);
        std::vector<std::uint32_t> sequence(set.size());
        std::iota(sequence.begin(), sequence.end(), 0u);
        TriangulateOptions options;
        const auto plain = triangulate(set, sequence, options);
        options.count = true;
        const auto counted = triangulate(set, sequence, options);
        EXPECT_EQ(plain.tets, counted.tets) << dist;
        const Counters& c = counted.counters;
        // The conflict tests (DigCavity3D's, and the search for the first conflict) and the walk's
        // orientations are all counted, most of them decided by the static filter.
        const std::uint64_t insphere = total(c.stage_calls[kInsphere]);
        EXPECT_GT(insphere, 0u) << dist;
        EXPECT_GT(at(c.stage_calls[kInsphere], Stage::kStatic), insphere / 2) << dist;
        EXPECT_GE(total(c.stage_calls[kOrient3d]), c.walk_orient_calls) << dist;
        EXPECT_GT(at(c.stage_calls[kOrient3d], Stage::kStatic), c.walk_orient_calls / 2) << dist;
    }
}

}  // namespace
}  // namespace cavity::core
