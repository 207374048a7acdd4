#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/order/insertion_order.h"
#include "cavity/core/order/spatial_sort.h"

namespace cavity::core {
namespace {

constexpr std::array<OrderKind, 5> kKinds = {OrderKind::kInput,
                                             OrderKind::kRandom,
                                             OrderKind::kBrio,
                                             OrderKind::kHilbert,
                                             OrderKind::kZOrder};

bool is_permutation_of_indices(const std::vector<std::uint32_t>& sequence, std::size_t n) {
    std::vector<std::uint32_t> sorted = sequence;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint32_t> expected(n);
    std::iota(expected.begin(), expected.end(), 0u);
    return sorted == expected;
}

// The k^3 grid with coordinate values map[0] < map[1] < ... < map[k-1] on every axis, listed in
// a shuffled order; `cell` gives each point's integer grid position.
struct Grid {
    std::vector<Point3> points;
    std::vector<std::array<int, 3>> cell;
};

Grid make_grid(int k, const std::vector<double>& map, std::uint64_t seed) {
    Grid grid;
    for (int i = 0; i < k; ++i) {
        for (int j = 0; j < k; ++j) {
            for (int l = 0; l < k; ++l) {
                grid.cell.push_back({i, j, l});
            }
        }
    }
    Random random(seed);
    for (std::size_t i = grid.cell.size(); i > 1; --i) {
        std::swap(grid.cell[i - 1], grid.cell[random.below(i)]);
    }
    for (const auto& c : grid.cell) {
        grid.points.push_back({map[c[0]], map[c[1]], map[c[2]]});
    }
    return grid;
}

std::vector<double> integers(int k) {
    std::vector<double> map(k);
    std::iota(map.begin(), map.end(), 0.0);
    return map;
}

TEST(InsertionOrder, ParsesNames) {
    EXPECT_EQ(parse_order_kind("input"), OrderKind::kInput);
    EXPECT_EQ(parse_order_kind("random"), OrderKind::kRandom);
    EXPECT_EQ(parse_order_kind("brio"), OrderKind::kBrio);
    EXPECT_EQ(parse_order_kind("hilbert"), OrderKind::kHilbert);
    EXPECT_EQ(parse_order_kind("zorder"), OrderKind::kZOrder);
    EXPECT_THROW(parse_order_kind("Hilbert"), Error);
    EXPECT_THROW(parse_order_kind(""), Error);
}

TEST(InsertionOrder, EveryKindIsAPermutation) {
    std::vector<Point3> duplicates(50, Point3{1.0, 2.0, 3.0});
    const PointSet cube = generate_points("cube", 3000, 1);
    for (const OrderKind kind : kKinds) {
        for (const std::size_t n : {0u, 1u, 2u, 7u, 64u, 3000u}) {
            const std::span<const Point3> points(cube.points.data(), n);
            const InsertionOrder order = make_insertion_order(points, {kind, 11});
            EXPECT_TRUE(is_permutation_of_indices(order.sequence, n))
                << "kind " << static_cast<int>(kind) << " n " << n;
            EXPECT_EQ(order.round_begin.empty(), kind != OrderKind::kBrio || n == 0);
        }
        EXPECT_TRUE(
            is_permutation_of_indices(make_insertion_order(duplicates, {kind}).sequence, 50));
    }
    EXPECT_TRUE(is_permutation_of_indices(
        make_insertion_order(cube.points, {OrderKind::kInput}).sequence, 3000));
    const auto input = make_insertion_order(cube.points, {OrderKind::kInput}).sequence;
    EXPECT_TRUE(std::is_sorted(input.begin(), input.end()));
}

TEST(InsertionOrder, SeedsDecide) {
    const PointSet cube = generate_points("cube", 2000, 2);
    for (const OrderKind kind : {OrderKind::kRandom, OrderKind::kBrio}) {
        const auto a = make_insertion_order(cube.points, {kind, 5});
        const auto b = make_insertion_order(cube.points, {kind, 5});
        const auto c = make_insertion_order(cube.points, {kind, 6});
        EXPECT_EQ(a.sequence, b.sequence);
        EXPECT_EQ(a.round_begin, b.round_begin);
        EXPECT_NE(a.sequence, c.sequence);
    }
    // Curve orders ignore the seed.
    EXPECT_EQ(make_insertion_order(cube.points, {OrderKind::kHilbert, 1}).sequence,
              make_insertion_order(cube.points, {OrderKind::kHilbert, 2}).sequence);
}

TEST(InsertionOrder, CurveOrdersAreTheSameForEveryThreadCount) {
    // Large enough that the sort splits across threads at the first levels (and in BRIO's last
    // rounds), with a flat slab so that ties on one axis are split by index on every thread.
    PointSet ps = generate_points("cube", 120000, 9);
    for (std::size_t i = 0; i < ps.points.size(); i += 3) {
        ps.points[i].z = 0.5;
    }
    for (const OrderKind kind : {OrderKind::kBrio, OrderKind::kHilbert, OrderKind::kZOrder}) {
        OrderOptions options{kind, 4};
        const InsertionOrder one = make_insertion_order(ps.points, options);
        for (unsigned threads : {2u, 3u, 8u}) {
            options.threads = threads;
            const InsertionOrder many = make_insertion_order(ps.points, options);
            EXPECT_EQ(many.sequence, one.sequence) << threads;
            EXPECT_EQ(many.round_begin, one.round_begin) << threads;
        }
    }
}

TEST(InsertionOrder, RandomReachesEveryPermutation) {
    const std::vector<Point3> points(3, Point3{0, 0, 0});
    std::map<std::vector<std::uint32_t>, int> seen;
    for (std::uint64_t seed = 0; seed < 600; ++seed) {
        ++seen[make_insertion_order(points, {OrderKind::kRandom, seed}).sequence];
    }
    ASSERT_EQ(seen.size(), 6u);
    for (const auto& [permutation, count] : seen) {
        EXPECT_GT(count, 60);  // expected 100 each
        EXPECT_LT(count, 140);
    }
}

// On a 2^m grid the median splits fall exactly between grid planes, so the adaptive curve is the
// classical Hilbert curve: consecutive points are grid neighbours. This checks the octant table.
void expect_hilbert_walk(const Grid& grid) {
    std::vector<std::uint32_t> order(grid.points.size());
    std::iota(order.begin(), order.end(), 0u);
    hilbert_sort(grid.points, order);
    for (std::size_t i = 1; i < order.size(); ++i) {
        const auto& a = grid.cell[order[i - 1]];
        const auto& b = grid.cell[order[i]];
        const int step = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
        ASSERT_EQ(step, 1) << "between positions " << i - 1 << " and " << i;
    }
    const auto& first = grid.cell[order.front()];
    EXPECT_EQ(first, (std::array<int, 3>{0, 0, 0}));
}

TEST(HilbertSort, WalksTheGridCellByCell) {
    for (const int k : {2, 4, 8, 16}) {
        SCOPED_TRACE(k);
        expect_hilbert_walk(make_grid(k, integers(k), 1));
    }
}

TEST(HilbertSort, OnlyTheOrderOfCoordinatesMatters) {
    // Wildly spaced, tiny, huge and offset coordinate values: no arithmetic may overflow or lose
    // them, and the curve must be the one of the integer grid.
    const std::vector<std::vector<double>> maps = {
        {-1e300, -1e-300, 0.0, 5e-324, 1e-300, 1.0, 1e200, 1.7976931348623157e308},
        {1e15, 1e15 + 1, 1e15 + 2, 1e15 + 3, 1e15 + 4, 1e15 + 5, 1e15 + 6, 1e15 + 7},
        {-8e-310, -7e-310, -6e-310, -5e-310, -4e-310, -3e-310, -2e-310, -1e-310},
    };
    for (const auto& map : maps) {
        const Grid grid = make_grid(8, map, 3);
        expect_hilbert_walk(grid);
        std::vector<std::uint32_t> adaptive(grid.points.size());
        std::iota(adaptive.begin(), adaptive.end(), 0u);
        hilbert_sort(grid.points, adaptive);
        const Grid plain = make_grid(8, integers(8), 3);
        std::vector<std::uint32_t> reference(plain.points.size());
        std::iota(reference.begin(), reference.end(), 0u);
        hilbert_sort(plain.points, reference);
        EXPECT_EQ(adaptive, reference);
    }
}

TEST(HilbertSort, FlatAndDuplicatedSetsAndDeterminism) {
    std::vector<Point3> flat;
    flat.reserve(1000);
    for (int i = 0; i < 1000; ++i) {
        flat.push_back({static_cast<double>(i % 37), 5.0, static_cast<double>(i % 11)});
    }
    std::vector<std::uint32_t> a(flat.size());
    std::iota(a.begin(), a.end(), 0u);
    std::vector<std::uint32_t> b(a.rbegin(), a.rend());
    hilbert_sort(flat, a);
    hilbert_sort(flat, b);
    EXPECT_TRUE(is_permutation_of_indices(a, flat.size()));
    EXPECT_EQ(a, b) << "the order must not depend on the order of the indices given";
}

TEST(HilbertSort, RejectsNonFinite) {
    std::vector<Point3> points(5, Point3{1, 2, 3});
    points[3].y = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::uint32_t> order = {0, 1, 2, 3, 4};
    try {
        hilbert_sort(points, order);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("point 3"), std::string::npos) << e.what();
    }
    points[3].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(morton_sort(points, order), Error);
    EXPECT_THROW(make_insertion_order(points, {OrderKind::kBrio}), Error);
}

TEST(MortonSort, MatchesInterleavedBitsOnAGrid) {
    const Grid grid = make_grid(8, integers(8), 4);
    std::vector<std::uint32_t> order(grid.points.size());
    std::iota(order.begin(), order.end(), 0u);
    morton_sort(grid.points, order);
    const auto code = [&grid](std::uint32_t i) {
        std::uint32_t c = 0;
        for (int bit = 2; bit >= 0; --bit) {
            for (int axis = 0; axis < 3; ++axis) {
                c = (c << 1) | ((grid.cell[i][axis] >> bit) & 1);
            }
        }
        return c;
    };
    for (std::size_t i = 0; i < order.size(); ++i) {
        ASSERT_EQ(code(order[i]), i);
    }
}

TEST(Brio, RoundsHaveGeometricSizes) {
    const PointSet cube = generate_points("cube", 100000, 8);
    // ρ is the fraction carried into earlier rounds: 1/2 (Amenta-Choi-Rote), 1/8 (CGAL, geogram).
    for (const double ratio : {0.5, 0.25, 0.125}) {
        SCOPED_TRACE(ratio);
        const auto order = make_insertion_order(cube.points, {OrderKind::kBrio, 3, ratio});
        const std::size_t n = cube.size();
        // The last round R is the least with n ρ^R <= 1: 17 for ρ = 1/2 (2^17 > 10^5), 6 for 1/8.
        std::size_t rounds = 0;
        for (double share = static_cast<double>(n); share > 1.0; share *= ratio) {
            ++rounds;
        }
        ASSERT_EQ(order.round_begin.size(), rounds + 1);
        if (ratio == 0.5) {
            EXPECT_EQ(rounds, 17u);
        }
        if (ratio == 0.125) {
            EXPECT_EQ(rounds, 6u);
        }
        EXPECT_EQ(order.round_begin[0], 0u);
        ASSERT_TRUE(std::is_sorted(order.round_begin.begin(), order.round_begin.end()));
        // Round R - j holds each point with probability (1-ρ) ρ^j: check the largest within six
        // standard deviations (the last round holds 7/8 of the points for ρ = 1/8).
        for (std::size_t j = 0; j < std::min<std::size_t>(rounds, 6); ++j) {
            const std::size_t r = rounds - j;
            const std::size_t end = r + 1 < order.round_begin.size() ? order.round_begin[r + 1] : n;
            const double size = static_cast<double>(end - order.round_begin[r]);
            const double q = (1.0 - ratio) * std::pow(ratio, static_cast<double>(j));
            const double mean = static_cast<double>(n) * q;
            const double sigma = std::sqrt(mean * (1.0 - q));
            EXPECT_NEAR(size, mean, 6.0 * sigma) << "round " << r;
        }
    }
}

TEST(Brio, RoundsAreHilbertSortedAndAlternate) {
    const PointSet cube = generate_points("cube", 5000, 1);
    for (const bool alternate : {true, false}) {
        OrderOptions options{OrderKind::kBrio, 17};
        options.reverse_alternate_rounds = alternate;
        const auto order = make_insertion_order(cube.points, options);
        ASSERT_TRUE(is_permutation_of_indices(order.sequence, cube.size()));
        for (std::size_t r = 0; r < order.round_begin.size(); ++r) {
            const std::size_t end =
                r + 1 < order.round_begin.size() ? order.round_begin[r + 1] : cube.size();
            std::vector<std::uint32_t> round(
                order.sequence.begin() + static_cast<std::ptrdiff_t>(order.round_begin[r]),
                order.sequence.begin() + static_cast<std::ptrdiff_t>(end));
            std::vector<std::uint32_t> expected = round;
            hilbert_sort(cube.points, expected);
            if (alternate && r % 2 == 0) {
                std::reverse(expected.begin(), expected.end());
            }
            EXPECT_EQ(round, expected) << "round " << r;
        }
    }
}

TEST(Brio, RejectsBadRatios) {
    const PointSet cube = generate_points("cube", 10, 1);
    for (const double ratio :
         {1.0, -0.5, 1.5, std::numeric_limits<double>::quiet_NaN(), 1.0 - 1e-9}) {
        EXPECT_THROW(make_insertion_order(cube.points, {OrderKind::kBrio, 0, ratio}), Error)
            << ratio;
    }
    // ρ = 0 carries nothing back: the whole set in the last round, along the curve.
    const auto all_last = make_insertion_order(cube.points, {OrderKind::kBrio, 0, 0.0});
    EXPECT_TRUE(is_permutation_of_indices(all_last.sequence, 10));
    EXPECT_EQ(all_last.round_begin.back(), 0u);
}

}  // namespace
}  // namespace cavity::core
