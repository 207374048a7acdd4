// insphere's scaled-integer evaluation (predicates/src/scaled_integers.h) against the exact oracle:
// exactly cospherical points with fractional coordinates (the exact zeros it exists for) and the
// same moved a few ulps, nearby points on a rounded sphere, coordinates at the edge of its range
// (differences near 2^62, where a product or a sum one bit wider would overflow), and the inputs
// it must refuse. The staged predicate, which calls it, is checked on the same inputs.

#include "scaled_integers.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cospherical_queries.h"

namespace cavity::predicates::detail {
namespace {

using Query = std::array<Point3, 5>;

struct Tally {
    std::size_t answered = 0;
    std::size_t wrong = 0;
    std::array<std::size_t, 3> signs{};  // -1, 0, +1 among the answered
};

void check(const Query& q, Tally& tally) {
    const Sign exact = oracle::insphere(q[0], q[1], q[2], q[3], q[4]);
    if (insphere(q[0], q[1], q[2], q[3], q[4]) != exact && ++tally.wrong <= 10) {
        ADD_FAILURE() << "insphere disagrees with the oracle";
    }
    const std::optional<Sign> s = insphere_scaled_integers(q);
    if (!s) {
        return;
    }
    ++tally.answered;
    ++tally.signs[static_cast<std::size_t>(static_cast<int>(*s) + 1)];
    if (*s != exact && ++tally.wrong <= 10) {
        ADD_FAILURE() << "the scaled integers say " << static_cast<int>(*s)
                      << ", the exact sign is " << static_cast<int>(exact) << " for " << q[0].x
                      << " " << q[0].y << " " << q[0].z << " ...";
    }
}

// Five of twelve points at distance 9 (cospherical_queries.h), times 2^scale about a centre with up
// to 40 significant bits: fractional, exactly cospherical coordinates whose differences are exact
// (the expansion stage B's inputs), and the same with coordinates moved 1-4 ulps (their differences
// are then inexact: stage D).
TEST(ScaledIntegers, CosphericalFractionalPointsAgreeWithTheOracle) {
    std::mt19937_64 rng(8101);
    std::uniform_int_distribution<std::int64_t> centre(-(std::int64_t{1} << 40),
                                                       std::int64_t{1} << 40);
    Tally exact_zero;
    Tally moved;
    for (const int scale : {-60, -20, 0, 30}) {
        for (int i = 0; i < 5000; ++i) {
            const double ox = static_cast<double>(centre(rng));
            const double oy = static_cast<double>(centre(rng));
            const double oz = static_cast<double>(centre(rng));
            Query q = testing::cospherical_query(rng, ox, oy, oz, scale);
            check(q, exact_zero);
            testing::move_a_few_ulps(q, rng);
            check(q, moved);
        }
    }
    EXPECT_EQ(exact_zero.wrong, 0u);
    EXPECT_EQ(moved.wrong, 0u);
    // Every exact one is in range (centres below 2^41) and zero; a moved one is out of range
    // only when a coordinate near 0 gets a far lower last bit (rare); both signs occur.
    EXPECT_EQ(exact_zero.answered, 20000u);
    EXPECT_EQ(exact_zero.signs[1], 20000u);
    EXPECT_GT(moved.answered, 19900u);
    EXPECT_GT(moved.signs[0] + moved.signs[2], 5000u);
}

// Five rounded points of a sphere of radius 1/16 near each other: full 53-bit significands of
// nearby magnitudes, as a CAD model's, mostly decided by their nonzero sign.
TEST(ScaledIntegers, NearbyPointsOnARoundedSphereAgreeWithTheOracle) {
    std::mt19937_64 rng(8102);
    std::normal_distribution<double> normal;
    Tally tally;
    for (const double cap : {1e-2, 1e-5, 1e-9}) {
        for (int i = 0; i < 5000; ++i) {
            const double cx = normal(rng), cy = normal(rng), cz = normal(rng);
            Query q{};
            for (Point3& p : q) {
                const double x = cx + cap * normal(rng), y = cy + cap * normal(rng),
                             z = cz + cap * normal(rng);
                const double r = 16 * std::sqrt(x * x + y * y + z * z);
                p = {x / r, y / r, z / r};
            }
            check(q, tally);
        }
    }
    EXPECT_EQ(tally.wrong, 0u);
    // Not vacuous: coordinates near zero widen the span past 61 bits in some queries, not most.
    EXPECT_GT(tally.answered, 10000u);
    EXPECT_GT(tally.signs[0], 1000u);
    EXPECT_GT(tally.signs[2], 1000u);
}

// Coordinates from {+-(2^53 - 1) 2^8, +-(2^52 + 1) 2^8, 2^60, -2^30, +-1, 0}: their scaled
// integers span bits 0 to 60, the most accepted, and differences reach 2^62 - 2^9, so the
// products and sums run as close to the widths the bound gives them as any input can.
TEST(ScaledIntegers, CoordinatesAtTheEdgeOfTheRangeAgreeWithTheOracle) {
    const double top = std::ldexp(0x1.fffffffffffffp52, 8);  // (2^53 - 1) 2^8 < 2^61
    const double near_top = std::ldexp(0x1.0000000000001p52, 8);
    const std::array<double, 9> values = {
        top, -top, near_top, -near_top, 0x1p60, -0x1p30, 1, -1, 0};
    std::mt19937_64 rng(8103);
    std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
    Tally tally;
    for (int i = 0; i < 20000; ++i) {
        Query q{};
        for (Point3& p : q) {
            p = {values[pick(rng)], values[pick(rng)], values[pick(rng)]};
        }
        check(q, tally);
    }
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_EQ(tally.answered, 20000u);
    EXPECT_GT(tally.signs[0], 1000u);
    EXPECT_GT(tally.signs[1], 100u);  // degenerate: repeated values
    EXPECT_GT(tally.signs[2], 1000u);
}

TEST(ScaledIntegers, RefusesSpansOfMoreThan61BitsAndNonFiniteValues) {
    const Query base = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, 0, 0}}};
    EXPECT_TRUE(insphere_scaled_integers(base).has_value());
    Query q = base;
    q[4].x = 0x1p61;  // bits 0 to 61: 62 bits
    EXPECT_FALSE(insphere_scaled_integers(q).has_value());
    q[4].x = 0x1p60;  // bits 0 to 60: the widest accepted
    EXPECT_TRUE(insphere_scaled_integers(q).has_value());
    q = base;
    q[2].z = 0x1p-1074;  // the least subnormal beside 1: 1075 bits
    EXPECT_FALSE(insphere_scaled_integers(q).has_value());
    q = base;
    q[1].y = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(insphere_scaled_integers(q).has_value());
    q[1].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(insphere_scaled_integers(q).has_value());
    // Subnormals among themselves are in range: every determinant is scaled exactly.
    const double tiny = 0x1p-1074;
    const Query subnormal = {
        {{tiny, 0, 0}, {0, tiny, 0}, {0, 0, tiny}, {-tiny, 0, 0}, {3 * tiny, 5 * tiny, 0}}};
    const std::optional<Sign> s = insphere_scaled_integers(subnormal);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(
        *s, oracle::insphere(subnormal[0], subnormal[1], subnormal[2], subnormal[3], subnormal[4]));
}

}  // namespace
}  // namespace cavity::predicates::detail
