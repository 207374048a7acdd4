// The in-place exact stage (predicates/src/homogeneous_exact.h) against the value-semantics code
// of homogeneous.h over the same integers, its oracle: the determinants on random rows from a few
// bits to a few thousand (GMP must grow past every size hint), negative and zero W, and exactly
// singular matrices (a repeated row, a row that is a combination of others, five cospherical
// points); the rows of segment points at extreme exponents, zeros and subnormals included.

#include "homogeneous_exact.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "cavity/predicates/dyadic.h"
#include "homogeneous.h"

namespace cavity::predicates::detail {
namespace {

using Row = Homogeneous<ExactInteger>;

/// A random integer of up to `bits` bits, either sign, zero included.
ExactInteger random_integer(std::mt19937_64& random, unsigned bits) {
    ExactInteger x(0);
    for (unsigned done = 0; done < bits; done += 32) {
        x <<= 32;
        x += ExactInteger(static_cast<unsigned long>(random() & 0xffffffffu));
    }
    x >>= static_cast<unsigned>((bits + 31) / 32 * 32 - bits);
    return (random() & 1u) != 0 ? ExactInteger(-x) : x;
}

Row random_row(std::mt19937_64& random, unsigned bits) {
    return {random_integer(random, bits),
            random_integer(random, bits),
            random_integer(random, bits),
            random_integer(random, bits)};
}

int sign_of(const ExactInteger& x) {
    return x.sign();
}

int oracle_orient3d(const std::array<Row, 4>& rows) {
    int w_signs = 1;
    Matrix<ExactInteger, 4> m;
    for (std::size_t i = 0; i < 4; ++i) {
        w_signs *= sign_of(rows[i].w);
        m[i] = {rows[i].x, rows[i].y, rows[i].z, rows[i].w};
    }
    return w_signs == 0 ? 0 : w_signs * sign_of(determinant<ExactInteger, 4>(m));
}

int oracle_insphere(const std::array<Row, 5>& rows) {
    Matrix<ExactInteger, 5> m;
    for (std::size_t i = 0; i < 5; ++i) {
        const Row& h = rows[i];
        m[i] = {ExactInteger(h.x * h.w),
                ExactInteger(h.y * h.w),
                ExactInteger(h.z * h.w),
                ExactInteger(h.x * h.x + h.y * h.y + h.z * h.z),
                ExactInteger(h.w * h.w)};
    }
    return sign_of(determinant<ExactInteger, 5>(m));
}

TEST(HomogeneousExact, RandomRowsOfEverySizeMatchTheExpansion) {
    std::mt19937_64 random(15);
    int nonzero = 0;
    for (const unsigned bits : {1u, 3u, 30u, 64u, 65u, 200u, 1100u, 3000u}) {
        for (int trial = 0; trial < 200; ++trial) {
            std::array<Row, 5> five;
            for (Row& r : five) {
                r = random_row(random, bits);
            }
            // Rows of unequal sizes: one large row among small ones overflows the size hints.
            if (trial % 3 == 0) {
                five[trial % 5] = random_row(random, 4 * bits + 7);
            }
            const int s = homogeneous_insphere_sign(five);
            EXPECT_EQ(s, oracle_insphere(five)) << bits << " bits, trial " << trial;
            const std::array<Row, 4> four{five[0], five[1], five[2], five[3]};
            EXPECT_EQ(homogeneous_orient3d_sign(four), oracle_orient3d(four))
                << bits << " bits, trial " << trial;
            nonzero += s != 0 ? 1 : 0;
        }
    }
    EXPECT_GT(nonzero, 1000);  // the random queries are mostly not degenerate
}

TEST(HomogeneousExact, SingularMatricesAreZero) {
    std::mt19937_64 random(16);
    for (const unsigned bits : {2u, 60u, 500u}) {
        for (int trial = 0; trial < 50; ++trial) {
            std::array<Row, 5> five;
            for (Row& r : five) {
                r = random_row(random, bits);
            }
            // A repeated point: two equal rows of both matrices.
            std::array<Row, 5> repeated = five;
            repeated[4] = repeated[1];
            EXPECT_EQ(homogeneous_insphere_sign(repeated), 0);
            std::array<Row, 4> four{repeated[1], repeated[2], repeated[3], repeated[4]};
            EXPECT_EQ(homogeneous_orient3d_sign(four), 0);
            // The same point with its coordinates scaled by -3: the insphere rows are
            // proportional (by 9), and orient3d's rows too.
            repeated[4] = {ExactInteger(-3 * five[1].x),
                           ExactInteger(-3 * five[1].y),
                           ExactInteger(-3 * five[1].z),
                           ExactInteger(-3 * five[1].w)};
            EXPECT_EQ(homogeneous_insphere_sign(repeated), 0);
            EXPECT_EQ(oracle_insphere(repeated), 0);
            four = {repeated[1], repeated[2], repeated[3], repeated[4]};
            EXPECT_EQ(homogeneous_orient3d_sign(four), 0);
            // A fourth row that is the sum of the other three: orient3d is exactly zero.
            four[3] = {ExactInteger(four[0].x + four[1].x + four[2].x),
                       ExactInteger(four[0].y + four[1].y + four[2].y),
                       ExactInteger(four[0].z + four[1].z + four[2].z),
                       ExactInteger(four[0].w + four[1].w + four[2].w)};
            EXPECT_EQ(homogeneous_orient3d_sign(four), oracle_orient3d(four));
            EXPECT_EQ(oracle_orient3d(four), 0);
        }
    }
}

TEST(HomogeneousExact, CosphericalPointsAreZeroAndTheirNeighboursAreNot) {
    // Five vertices of the octahedron (+-1, 0, 0), (0, +-1, 0), (0, 0, +-1), no four of them
    // coplanar, lie on the unit sphere; written homogeneously with W = -2^k, huge X, Y, Z.
    for (const unsigned k : {0u, 40u, 700u}) {
        const ExactInteger w = -(ExactInteger(1) << k);
        const auto row = [&](int x, int y, int z) {
            return Row{ExactInteger(x * w), ExactInteger(y * w), ExactInteger(z * w), w};
        };
        std::array<Row, 5> five{
            row(1, 0, 0), row(-1, 0, 0), row(0, 1, 0), row(0, 0, 1), row(0, 0, -1)};
        EXPECT_EQ(homogeneous_insphere_sign(five), 0);
        EXPECT_EQ(oracle_insphere(five), 0);
        five[4].z += ExactInteger(1);  // just off the sphere
        EXPECT_NE(homogeneous_insphere_sign(five), 0);
        EXPECT_EQ(homogeneous_insphere_sign(five), oracle_insphere(five));
        // A zero W leaves orient3d undecided, as the value-semantics stage does.
        std::array<Row, 4> four{five[0], five[2], five[4], five[1]};
        four[2].w = 0;
        EXPECT_EQ(homogeneous_orient3d_sign(four), 0);
    }
}

/// A double of random sign and mantissa at 2^exponent, or one of the special values.
double random_double(std::mt19937_64& random, int low, int high) {
    switch (random() % 8) {
        case 0:
            return 0.0;
        case 1:
            return std::numeric_limits<double>::denorm_min() * static_cast<double>(random() % 100);
        default: {
            std::uniform_real_distribution<double> mantissa(1.0, 2.0);
            const int exponent =
                low + static_cast<int>(random() % static_cast<unsigned>(high - low));
            const double x = std::ldexp(mantissa(random), exponent);
            return (random() & 1u) != 0 ? -x : x;
        }
    }
}

int least_spacing(std::initializer_list<double> values) {
    int scale = std::numeric_limits<int>::max();
    for (const double v : values) {
        if (v != 0.0) {
            scale = std::min(scale, spacing_exponent(v));
        }
    }
    return scale == std::numeric_limits<int>::max() ? 0 : scale;
}

TEST(HomogeneousExact, SegmentRowsMatchTheValueSemanticsRows) {
    std::mt19937_64 random(17);
    for (const auto& [low, high] : {std::pair{-3, 3}, std::pair{-60, 60}, std::pair{-1074, 1000}}) {
        for (int trial = 0; trial < 500; ++trial) {
            const SegmentParameterPoint s{
                {random_double(random, low, high),
                 random_double(random, low, high),
                 random_double(random, low, high)},
                {random_double(random, low, high),
                 random_double(random, low, high),
                 random_double(random, low, high)},
                random_double(random, low, high),
                trial % 4 == 0 ? std::ldexp(1.0, trial % 40) : random_double(random, low, high)};
            // Scales at the least spacing of the query, as exact_rows takes them, or below it.
            const int scale = least_spacing({s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z}) -
                              static_cast<int>(random() % 3);
            const int parameter_scale =
                least_spacing({s.numerator, s.denominator}) - static_cast<int>(random() % 3);
            const Row expected = homogeneous<ExactInteger>(
                GenericPoint3(s),
                [&](const Point3& p) {
                    return std::array<ExactInteger, 3>{scaled_to_integer<ExactInteger>(p.x, scale),
                                                       scaled_to_integer<ExactInteger>(p.y, scale),
                                                       scaled_to_integer<ExactInteger>(p.z, scale)};
                },
                [&](double x) { return scaled_to_integer<ExactInteger>(x, parameter_scale); });
            const Row row = segment_row(s, scale, parameter_scale);
            EXPECT_EQ(row.x, expected.x) << low << " " << trial;
            EXPECT_EQ(row.y, expected.y) << low << " " << trial;
            EXPECT_EQ(row.z, expected.z) << low << " " << trial;
            EXPECT_EQ(row.w, expected.w) << low << " " << trial;
        }
    }
}

}  // namespace
}  // namespace cavity::predicates::detail
