// Geometry's lattice mode (geometry.h): detected exactly for integer points spanning at most
// predicates::kLatticeMaxSpan per axis, kept up to date by the appends, and, when on, its fast
// uncounted tests decide as the counting engine's staged predicates and perturbation do.

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/geometry/counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/predicates/generic_point.h"
#include "cavity/predicates/lattice.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {
namespace {

Geometry geometry_of(std::vector<Point3> points, std::vector<double> weights = {}) {
    std::vector<std::uint32_t> keys(points.size());
    std::iota(keys.begin(), keys.end(), 0u);
    return Geometry(std::move(points), std::move(keys), std::move(weights));
}

// The k^3 integer grid with spacing `step`, shifted by `offset`.
std::vector<Point3> grid(int k, double step, double offset = 0) {
    std::vector<Point3> points;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
            for (int l = 0; l < k; ++l) {
                points.push_back({offset + step * i, offset + step * j, offset + step * l});
            }
        }
    }
    return points;
}

TEST(Lattice, DetectedForIntegerPointsWithinTheSpanOnly) {
    EXPECT_TRUE(geometry_of(grid(3, 1)).lattice());
    EXPECT_TRUE(geometry_of(grid(6, 143)).lattice());      // span 715: the bound
    EXPECT_FALSE(geometry_of(grid(6, 144)).lattice());     // span 720
    EXPECT_TRUE(geometry_of(grid(3, 1, 1e15)).lattice());  // the differences are what count
    EXPECT_FALSE(geometry_of(grid(3, 0.5)).lattice());
    auto points = grid(3, 1);
    points.back().z = 1.5;
    EXPECT_FALSE(geometry_of(points).lattice());
    EXPECT_FALSE(geometry_of(grid(2, 1), std::vector<double>(8, 0.0)).lattice());  // weighted
}

TEST(Lattice, KeptUpToDateByTheAppends) {
    Geometry empty = geometry_of({});
    for (const Point3& p : grid(2, 715)) {
        empty.append_point(p);
        EXPECT_TRUE(empty.lattice());
    }
    Geometry g = geometry_of(grid(3, 1));
    g.append({2, 0, 715}, 100, 0.0);
    EXPECT_TRUE(g.lattice());
    g.append({-1, 0, 0}, 101, 0.0);  // x now spans 3, z spans 715
    EXPECT_TRUE(g.lattice());
    g.append({0, 0, 716}, 102, 0.0);  // z spans 716
    EXPECT_FALSE(g.lattice());
    g.append({0, 0, 1}, 103, 0.0);  // never back once left
    EXPECT_FALSE(g.lattice());
    Geometry h = geometry_of(grid(3, 1));
    h.append_point({0.25, 0, 0});
    EXPECT_FALSE(h.lattice());
}

TEST(Lattice, LeftByAnImplicitPointEvenWithIntegerRounding) {
    // From (1, 1, 1) towards (2, 2, 2) by 0 (the integer point itself) and by 2^-60 / 3 (no
    // integer point, but it rounds to (1, 1, 1)): either way the geometry's tests must run on the
    // definitions, which the lattice's plain determinants on rounded coordinates do not.
    for (const double numerator : {0.0, 0x1p-60}) {
        Geometry g = geometry_of(grid(3, 1));
        const auto implicit =
            predicates::segment_parameter_point({1, 1, 1}, {2, 2, 2}, numerator, 3.0);
        ASSERT_TRUE(implicit.has_value());
        g.append_implicit(*implicit, {1, 1, 1}, 100);
        EXPECT_TRUE(g.has_implicit());
        EXPECT_FALSE(g.lattice());
    }
}

// Random tests on a coarse grid at the largest span (many exact ties, and the largest
// intermediates): the uncounted route (plain determinants, lattice tie-break) against the counted
// one (staged predicates and perturbation), for insphere, ghost and orient3d tests.
TEST(Lattice, FastTestsDecideAsTheStagedPredicates) {
    auto points = grid(6, 143);
    std::mt19937_64 rng(17);
    std::shuffle(points.begin(), points.end(), rng);  // keys in a random spatial order
    const Geometry g = geometry_of(points);
    ASSERT_TRUE(g.lattice());
    std::uniform_int_distribution<VertexId> pick(0, static_cast<VertexId>(points.size() - 1));
    Counters counted;
    Uncounted uncounted;
    std::size_t ties = 0;
    for (int i = 0; i < 200'000; ++i) {
        const TetVertices t{pick(rng), pick(rng), pick(rng), pick(rng)};
        const VertexId u = pick(rng);
        const Sign orientation = g.orient3d(t[0], t[1], t[2], t[3], counted);
        ASSERT_EQ(g.orient3d(t[0], t[1], t[2], t[3], uncounted), orientation);
        ASSERT_EQ(g.orient3d_in_box(
                      g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3]), uncounted),
                  orientation);
        if (orientation != Sign::kPos) {
            continue;  // the conflict tests are defined on positively oriented tetrahedra
        }
        if (std::find(t.begin(), t.end(), u) != t.end()) {
            continue;
        }
        ties += predicates::insphere_on_lattice(
                    g.point(t[0]), g.point(t[1]), g.point(t[2]), g.point(t[3]), g.point(u)) ==
                Sign::kZero;
        ASSERT_EQ(g.conflicts_solid(t, u), g.conflicts_solid(t, u, counted)) << i;
    }
    EXPECT_GT(ties, 1000u);  // not vacuous: the tie-break is exercised
    // A point off the lattice in the box (the straight walk's source) takes the exact route.
    const Point3 off{357.5, 0.25, 100};
    for (int i = 0; i < 10'000; ++i) {
        const Point3 a = g.point(pick(rng)), b = g.point(pick(rng)), c = g.point(pick(rng));
        ASSERT_EQ(g.orient3d_in_box(a, b, c, off, uncounted), predicates::orient3d(a, b, c, off));
    }
}

}  // namespace
}  // namespace cavity::core
