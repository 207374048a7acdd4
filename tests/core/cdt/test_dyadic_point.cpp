// The 128-bit integer answer to "is a + (k / 2^j)(b - a) a double point?" (dyadic_point.h),
// against the GMP rationals that split_point asked before (the oracle): whenever it decides, the
// answer and the point are the rationals' ones, and it decides whenever the coordinates' binades
// are near enough.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "../../../core/cdt/src/dyadic_point.h"
#include "../../../core/cdt/src/exact_plane.h"
#include "cavity/predicates/generic_point.h"

namespace cavity::core {
namespace {

/// The rationals' answer: the exact point, and whether it is a double (its rounding is itself).
struct Oracle {
    bool is_double;
    Point3 point;
};

Oracle oracle(const Point3& a, const Point3& b, std::int64_t k, int j) {
    const auto s =
        predicates::segment_parameter_point(a, b, static_cast<double>(k), std::ldexp(1.0, j));
    EXPECT_TRUE(s);
    const predicates::GenericPoint3 g(*s);
    const Point3 r = rounded_point(g);
    return {exact_point(r) == exact_point(g), r};
}

/// Checks every k of 2^j for j <= 4, and a spread of k beyond; returns how many were undecided.
int check_segment(const Point3& a, const Point3& b) {
    int undecided = 0;
    for (int j = 1; j <= 10; ++j) {
        const std::int64_t steps = std::int64_t{1} << j;
        const std::int64_t stride = j <= 4 ? 1 : steps / 16 + 1;
        for (std::int64_t k = 1; k < steps; k += stride) {
            const DyadicPoint fast = dyadic_point(a, b, k, j);
            if (!fast.decided) {
                ++undecided;
                continue;
            }
            const Oracle exact = oracle(a, b, k, j);
            EXPECT_EQ(fast.is_double, exact.is_double) << "k " << k << " j " << j;
            if (fast.is_double && exact.is_double) {
                EXPECT_EQ(fast.point.x, exact.point.x);
                EXPECT_EQ(fast.point.y, exact.point.y);
                EXPECT_EQ(fast.point.z, exact.point.z);
                EXPECT_FALSE(std::signbit(fast.point.x) && fast.point.x == 0);
            }
        }
    }
    return undecided;
}

TEST(DyadicPoint, MatchesTheRationalsOnSimpleSegments) {
    EXPECT_EQ(check_segment({0, 0, 0}, {1, 1, 1}), 0);
    EXPECT_EQ(check_segment({0, 0, 0}, {3, 5, 7}), 0);
    EXPECT_EQ(check_segment({0.1, 0.2, 0.3}, {0.7, -0.2, 1e-3}), 0);
    // Exactly degenerate: equal coordinates, a zero crossing at the midpoint, equal points.
    EXPECT_EQ(check_segment({1, 2, 3}, {1, 2, 4}), 0);
    EXPECT_EQ(check_segment({-1, -0.5, 0.25}, {1, 0.5, -0.25}), 0);
    EXPECT_EQ(check_segment({0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}), 0);
    EXPECT_EQ(check_segment({-0.0, 0.0, -0.0}, {0.0, -0.0, 1.0}), 0);
}

TEST(DyadicPoint, MidpointOfConsecutiveDoublesIsNoDouble) {
    const double up = 1 + 0x1p-52;
    const DyadicPoint m = dyadic_point({1, 1, 1}, {up, 1, 1}, 1, 1);
    ASSERT_TRUE(m.decided);
    EXPECT_FALSE(m.is_double);
    const DyadicPoint n = dyadic_point({1, 1, 1}, {1 + 0x1p-51, 1, 1}, 1, 1);
    ASSERT_TRUE(n.decided);
    ASSERT_TRUE(n.is_double);
    EXPECT_EQ(n.point.x, up);
}

TEST(DyadicPoint, ExtremeExponents) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double huge = std::numeric_limits<double>::max();
    // Subnormals: 4 ulps is the midpoint of 3 and 5, 3.5 ulps no double.
    EXPECT_EQ(check_segment({3 * tiny, 0, 0}, {5 * tiny, tiny, -tiny}), 0);
    const DyadicPoint quarter = dyadic_point({3 * tiny, 0, 0}, {5 * tiny, 0, 0}, 1, 2);
    ASSERT_TRUE(quarter.decided);
    EXPECT_FALSE(quarter.is_double);
    EXPECT_EQ(check_segment({0x1p-1022, -0x1p-1000, 0}, {0x1p-1030, 0x1p-1010, tiny}), 0);
    // The largest doubles: no overflow, the point stays between the ends.
    EXPECT_EQ(check_segment({huge, -huge, 0x1p1000}, {0x1p1000, huge, 0x1p1010}), 0);
    // Binades 2^100 apart do not fit the integers: undecided, unless another coordinate decides.
    EXPECT_GT(check_segment({1, 1, 1}, {0x1p-100 + 0x1p-152, 1, 1}), 0);
    const DyadicPoint far = dyadic_point({1, 1, 1}, {0x1p-100, 1, 1}, 1, 1);
    EXPECT_FALSE(far.decided);
    const DyadicPoint decided_elsewhere = dyadic_point({1, 1, 1}, {0x1p-100, 1 + 0x1p-52, 1}, 1, 1);
    ASSERT_TRUE(decided_elsewhere.decided);
    EXPECT_FALSE(decided_elsewhere.is_double);
}

TEST(DyadicPoint, MatchesTheRationalsOnRandomSegments) {
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> exponent(-70, 70);
    std::uniform_int_distribution<int> bits(0, 52);
    int undecided = 0;
    for (int n = 0; n < 300; ++n) {
        // Coordinates with few significant bits make many dyadic points doubles.
        const auto coordinate = [&] {
            const int keep = bits(random);
            const double x = std::ldexp(std::round(std::ldexp(unit(random), keep)), -keep);
            return std::ldexp(x, exponent(random) / (n % 3 == 0 ? 1 : 10));
        };
        const Point3 a{coordinate(), coordinate(), coordinate()};
        const Point3 b{coordinate(), coordinate(), coordinate()};
        undecided += check_segment(a, b);
    }
    EXPECT_LT(undecided, 300 * 60);  // most segments fit the integers
}

/// rounded_dyadic_point against the rationals' rounding (exact_plane's rounded_point): the same
/// doubles whenever it answers; on random segments it answers for nearly every parameter.
int check_rounding(const Point3& a, const Point3& b, std::mt19937_64& random) {
    int undecided = 0;
    for (int j = 1; j <= 53; ++j) {
        std::uniform_int_distribution<std::int64_t> numerator(1, (std::int64_t{1} << j) - 1);
        for (int i = 0; i < 4; ++i) {
            const auto n = static_cast<double>(numerator(random));
            const auto s = predicates::segment_parameter_point(a, b, n, std::ldexp(1.0, j));
            EXPECT_TRUE(s);
            const std::optional<Point3> fast = rounded_dyadic_point(*s);
            if (!fast) {
                ++undecided;
                continue;
            }
            const Point3 exact = rounded_point(predicates::GenericPoint3(*s));
            EXPECT_EQ(fast->x, exact.x) << "n " << n << " j " << j;
            EXPECT_EQ(fast->y, exact.y) << "n " << n << " j " << j;
            EXPECT_EQ(fast->z, exact.z) << "n " << n << " j " << j;
            EXPECT_EQ(std::signbit(fast->x), std::signbit(exact.x));
        }
    }
    return undecided;
}

TEST(RoundedDyadicPoint, MatchesTheRationalsRounding) {
    std::mt19937_64 random(16);
    std::uniform_int_distribution<int> digits(-99999, 99999);
    std::uniform_int_distribution<int> exponent(-30, 30);
    int undecided = 0;
    for (int n = 0; n < 100; ++n) {
        // Decimal coordinates, as surface models have them, then mixed binades.
        const auto coordinate = [&] {
            return digits(random) / 1e5 * (n % 2 == 0 ? 1.0 : std::ldexp(1.0, exponent(random)));
        };
        const Point3 a{coordinate(), coordinate(), coordinate()};
        const Point3 b{coordinate(), coordinate(), coordinate()};
        undecided += check_rounding(a, b, random);
    }
    // Far binades with long parameters pass 128 bits: about a sixth of these, none of the decimals.
    std::printf("rounded_dyadic_point left %d of %d to the rationals\n", undecided, 100 * 53 * 4);
    EXPECT_LT(undecided, 100 * 53 * 4 / 5);
}

TEST(RoundedDyadicPoint, TiesAndExtremesAreLeftToTheRationals) {
    std::mt19937_64 random(17);
    // The midpoint of consecutive doubles is a tie.
    const auto tie = predicates::segment_parameter_point({1, 1, 1}, {1 + 0x1p-52, 1, 1}, 1, 2);
    EXPECT_FALSE(rounded_dyadic_point(*tie));
    // Exact points, zeros of either sign, subnormals, the largest doubles, far binades.
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double huge = std::numeric_limits<double>::max();
    check_rounding({-0.0, 0.0, 1}, {0.0, -0.0, 3}, random);
    check_rounding({-1, -0.5, 0.25}, {1, 0.5, -0.25}, random);
    check_rounding({3 * tiny, 0x1p-1022, -tiny}, {5 * tiny, 0x1p-1000, 0x1p-1021}, random);
    check_rounding({huge, -huge, 0x1p1000}, {0x1p1000, huge, 0x1p1010}, random);
    EXPECT_GT(check_rounding({1, 1, 1}, {0x1p-100 + 0x1p-152, 1, 1}, random), 0);
    // Parameters that are not n / 2^j with 0 < n < 2^j.
    EXPECT_FALSE(rounded_dyadic_point({{0, 0, 0}, {1, 1, 1}, 1, 3}));
    EXPECT_FALSE(rounded_dyadic_point({{0, 0, 0}, {1, 1, 1}, 5, 4}));
    EXPECT_FALSE(rounded_dyadic_point({{0, 0, 0}, {1, 1, 1}, 0.5, 4}));
}

}  // namespace
}  // namespace cavity::core
