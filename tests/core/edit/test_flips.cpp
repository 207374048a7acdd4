// Bistellar flips on hand-built configurations and on random Delaunay triangulations: every flip
// keeps the complex valid (check_complex), refuses configurations where the new tetrahedra would
// be inverted, and the inverse flip restores the original tetrahedra.
#include <algorithm>
#include <numeric>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/random.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/flips.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/mesh/star.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {
namespace {

using Tets = std::vector<std::array<std::uint32_t, 4>>;

using test::canonical;

/// Orders each tetrahedron with positive right-hand volume, as complex_from_tets takes them.
Tets oriented(const PointSet& ps, Tets tets) {
    for (auto& t : tets) {
        const auto& p = ps.points;
        if (predicates::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]) == predicates::Sign::kPos) {
            std::swap(t[0], t[1]);
        }
    }
    return tets;
}

PointSet points(std::vector<Point3> p) {
    PointSet ps;
    ps.points = std::move(p);
    return ps;
}

/// A live tet holding all of `vs`, and the slots of vs[0], vs[1].
std::tuple<TetId, int, int> find_edge(const ArrayStorage& s, VertexId a, VertexId b) {
    for (TetId t = 0; t < s.capacity(); ++t) {
        if (s.alive(t) && slot_of(s.vertices(t), a) >= 0 && slot_of(s.vertices(t), b) >= 0) {
            return {t, slot_of(s.vertices(t), a), slot_of(s.vertices(t), b)};
        }
    }
    return {kNoTet, -1, -1};
}

HalfFacet find_facet(const ArrayStorage& s, std::array<VertexId, 3> tri) {
    std::sort(tri.begin(), tri.end());
    for (TetId t = 0; t < s.capacity(); ++t) {
        if (!s.alive(t)) {
            continue;
        }
        for (int f = 0; f < 4; ++f) {
            auto k = facet_vertices(s.vertices(t), f);
            std::sort(k.begin(), k.end());
            if (k == tri) {
                return half_facet(t, f);
            }
        }
    }
    return kNoHalfFacet;
}

void expect_valid(const ArrayStorage& s, const Geometry& g) {
    const auto problems = check_complex(s, g);
    EXPECT_TRUE(problems.empty()) << problems.front();
}

// p q r in the plane z = 0; d above and e below, on a line through the triangle's interior.
PointSet bipyramid() {
    return points({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {1, 1, 3}, {1, 1, -2}});
}

TEST(Flips, TwoThreeAndBack) {
    const PointSet ps = bipyramid();
    const Geometry g = geometry_by_index(ps);
    const Tets before = oriented(ps, {{0, 1, 2, 3}, {0, 1, 2, 4}});
    ArrayStorage s = complex_from_tets(before);
    expect_valid(s, g);
    RetriangulationCounters counters;
    const auto created = flip23(s, g, find_facet(s, {0, 1, 2}), counters);
    ASSERT_EQ(created.size(), 3u);
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical({{0, 1, 3, 4}, {1, 2, 3, 4}, {0, 2, 3, 4}}));
    const auto [t, i, j] = find_edge(s, 3, 4);
    ASSERT_EQ(flip32(s, g, t, i, j, counters).size(), 2u);
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical(before));
    EXPECT_EQ(counters.flip_count(FlipKind::k23), 1u);
    EXPECT_EQ(counters.flip_count(FlipKind::k32), 1u);
    EXPECT_EQ(counters.flips_refused, 0u);
}

TEST(Flips, ThreeTwoRefusedUnlessDegreeThree) {
    const PointSet ps = bipyramid();
    const Geometry g = geometry_by_index(ps);
    ArrayStorage s = complex_from_tets(oriented(ps, {{0, 1, 2, 3}, {0, 1, 2, 4}}));
    const auto [t, i, j] = find_edge(s, 0, 1);  // a hull edge with two solid and two ghost tets
    RetriangulationCounters counters;
    EXPECT_TRUE(flip32(s, g, t, i, j, counters).empty());
    EXPECT_EQ(counters.flips_refused, 1u);
    expect_valid(s, g);
}

TEST(Flips, OneFourAndBack) {
    const PointSet ps = points({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1, 1, 1}});
    const Geometry g = geometry_by_index(ps);
    const Tets before = oriented(ps, {{0, 1, 2, 3}});
    ArrayStorage s = complex_from_tets(before);
    RetriangulationCounters counters;
    const auto [t, i, j] = find_edge(s, 0, 3);
    (void)i;
    (void)j;
    ASSERT_FALSE(is_ghost(s.vertices(t)));
    ASSERT_EQ(flip14(s, g, t, 4, counters).size(), 4u);
    expect_valid(s, g);
    EXPECT_EQ(solid_tets(s).size(), 4u);
    ASSERT_EQ(flip41(s, g, 4, counters).size(), 1u);
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical(before));
    EXPECT_EQ(counters.flip_count(FlipKind::k14), 1u);
    EXPECT_EQ(counters.flip_count(FlipKind::k41), 1u);
}

TEST(Flips, OneFourRefusedOutsideTheTetrahedron) {
    const PointSet ps = points({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {5, 5, 5}});
    const Geometry g = geometry_by_index(ps);
    ArrayStorage s = complex_from_tets(oriented(ps, {{0, 1, 2, 3}}));
    const auto [t, i, j] = find_edge(s, 0, 3);
    (void)i;
    (void)j;
    RetriangulationCounters counters;
    EXPECT_TRUE(flip14(s, g, t, 4, counters).empty());
    EXPECT_EQ(counters.flips_refused, 1u);
    expect_valid(s, g);
}

TEST(Flips, OneFourIntoAGhostGrowsTheHullAndFourOneShrinksIt) {
    // Point 4 lies just beyond the face 1 2 3 (x + y + z = 4), and behind the other three faces'
    // planes, so it sees only that hull triangle.
    const PointSet ps = points({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {1.5, 1.5, 1.5}});
    const Geometry g = geometry_by_index(ps);
    const Tets before = oriented(ps, {{0, 1, 2, 3}});
    ArrayStorage s = complex_from_tets(before);
    const TetId ghost = tet_of(find_facet(s, {1, 2, kGhostVertex}));
    // The ghost over 1 2 3 is the one whose hull triangle lacks vertex 0.
    TetId over = kNoTet;
    for (TetId t = 0; t < s.capacity(); ++t) {
        if (s.alive(t) && is_ghost(s.vertices(t)) && slot_of(s.vertices(t), 0) < 0) {
            over = t;
        }
    }
    (void)ghost;
    ASSERT_NE(over, kNoTet);
    RetriangulationCounters counters;
    ASSERT_EQ(flip14(s, g, over, 4, counters).size(), 4u);
    expect_valid(s, g);
    EXPECT_EQ(solid_tets(s).size(), 2u);
    ASSERT_EQ(flip41(s, g, 4, counters).size(), 1u);
    EXPECT_EQ(counters.flip_count(FlipKind::k14), 1u);
    EXPECT_EQ(counters.flip_count(FlipKind::k41), 1u);
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical(before));
}

TEST(Flips, OneFourIntoAGhostRefusedWhenThePointSeesMoreOfTheHull) {
    // Point 4 is beyond face 1 2 3 and also beyond face 0 1 2 (z < 0).
    const PointSet ps = points({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {3, 3, -1}});
    const Geometry g = geometry_by_index(ps);
    ArrayStorage s = complex_from_tets(oriented(ps, {{0, 1, 2, 3}}));
    TetId over = kNoTet;
    for (TetId t = 0; t < s.capacity(); ++t) {
        if (s.alive(t) && is_ghost(s.vertices(t)) && slot_of(s.vertices(t), 0) < 0) {
            over = t;
        }
    }
    RetriangulationCounters counters;
    EXPECT_TRUE(flip14(s, g, over, 4, counters).empty());
    EXPECT_EQ(counters.flips_refused, 1u);
    expect_valid(s, g);
}

TEST(Flips, TwoTwoOnAFlatHullQuadrilateralAndBack) {
    // Square 0 1 2 3 in z = 0 with apex 4 above: diagonal 0 2 becomes 1 3 and back.
    const PointSet ps = points({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.3, 0.4, 1}});
    const Geometry g = geometry_by_index(ps);
    const Tets before = oriented(ps, {{0, 1, 2, 4}, {0, 2, 3, 4}});
    ArrayStorage s = complex_from_tets(before);
    RetriangulationCounters counters;
    {
        const auto [t, i, j] = find_edge(s, 0, 2);
        ASSERT_EQ(flip22(s, g, t, i, j, counters).size(), 4u);
    }
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical({{0, 1, 3, 4}, {1, 2, 3, 4}}));
    {
        const auto [t, i, j] = find_edge(s, 1, 3);
        ASSERT_EQ(flip22(s, g, t, i, j, counters).size(), 4u);
    }
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical(before));
    EXPECT_EQ(counters.flip_count(FlipKind::k22), 2u);
    // Edge 0 4 is not a diagonal of a flat quadrilateral.
    const auto [t, i, j] = find_edge(s, 0, 4);
    EXPECT_TRUE(flip22(s, g, t, i, j, counters).empty());
}

TEST(Flips, FourFourInAnOctahedronAndBack) {
    // Octahedron: poles 0 and 1, equator 2 3 4 5; the axis 0 1 is replaced by 2 4, then back.
    const PointSet ps =
        points({{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}});
    const Geometry g = geometry_by_index(ps);
    const Tets before = oriented(ps, {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 2}});
    ArrayStorage s = complex_from_tets(before);
    RetriangulationCounters counters;
    {
        const auto [t, i, j] = find_edge(s, 0, 1);
        const EdgeRing ring = edge_ring(s, t, i, j);
        ASSERT_EQ(ring.ring.size(), 4u);
        const int diagonal = (ring.ring[0] == 2 || ring.ring[0] == 4) ? 0 : 1;
        ASSERT_EQ(flip44(s, g, t, i, j, diagonal, counters).size(), 4u);
    }
    expect_valid(s, g);
    EXPECT_TRUE(find_facet(s, {2, 4, 0}) != kNoHalfFacet);
    {
        const auto [t, i, j] = find_edge(s, 2, 4);
        const EdgeRing ring = edge_ring(s, t, i, j);
        const int diagonal = (ring.ring[0] == 0 || ring.ring[0] == 1) ? 0 : 1;
        ASSERT_EQ(flip44(s, g, t, i, j, diagonal, counters).size(), 4u);
    }
    expect_valid(s, g);
    EXPECT_EQ(canonical(solid_tets(s)), canonical(before));
    EXPECT_EQ(counters.flip_count(FlipKind::k44), 2u);
}

// Random sequences of flips on a Delaunay triangulation: every performed flip leaves a valid
// complex, and undoing a 2-3 flip by the 3-2 flip of its new edge restores the tetrahedra.
TEST(Flips, RandomTwoThreeFlipsAreUndoneByThreeTwo) {
    const PointSet ps = generate_points("ball", 200, 7);
    std::vector<std::uint32_t> seq(ps.size());
    std::iota(seq.begin(), seq.end(), 0u);
    const Triangulation tri = triangulate(ps, seq, {});
    const Geometry g = geometry_by_index(ps);
    ArrayStorage s = complex_from_tets(tri.tets);
    Random random(11);
    RetriangulationCounters counters;
    int performed = 0;
    int refused = 0;
    int kept = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const auto t = static_cast<TetId>(random.below(s.capacity()));
        if (!s.alive(t)) {
            continue;
        }
        const int f = static_cast<int>(random.below(4));
        const Tets before = canonical(solid_tets(s));
        const HalfFacet across = s.adjacent(t, f);
        const VertexId d = s.vertices(t)[static_cast<std::size_t>(f)];
        const VertexId e = s.vertices(tet_of(across))[static_cast<std::size_t>(facet_of(across))];
        const auto triangle = facet_vertices(s.vertices(t), f);
        if (flip23(s, g, half_facet(t, f), counters).empty()) {
            // A reflex pair (the edge d e misses the triangle): nothing may have changed.
            ++refused;
            EXPECT_EQ(canonical(solid_tets(s)), before);
            continue;
        }
        ++performed;
        expect_valid(s, g);
        const auto [u, i, j] = find_edge(s, d, e);
        ASSERT_EQ(flip32(s, g, u, i, j, counters).size(), 2u);
        EXPECT_EQ(canonical(solid_tets(s)), before);
        // Keep every third flip, so later flips act on a non-Delaunay complex.
        if (trial % 3 == 0) {
            ++kept;
            ASSERT_FALSE(flip23(s, g, find_facet(s, triangle), counters).empty());
        }
    }
    expect_valid(s, g);
    EXPECT_GT(performed, 50);
    EXPECT_GT(refused, 20);
    EXPECT_EQ(counters.flips_refused, static_cast<std::uint64_t>(refused));
    EXPECT_EQ(counters.flip_count(FlipKind::k32), static_cast<std::uint64_t>(performed));
    EXPECT_EQ(counters.flip_count(FlipKind::k23), static_cast<std::uint64_t>(performed + kept));
}

}  // namespace
}  // namespace cavity::core
