// The oracle is the reference for every other predicate test, so it is checked on its own: against
// the difference forms of the documented determinants (the sign identities stated in oracle.cpp),
// computed here in 128-bit integers on small integer points, and against hand-made cases that fix
// the sign conventions.

#include "cavity/predicates/oracle.h"

#include <array>
#include <cmath>
#include <cstdint>

#include <gtest/gtest.h>

#include "query.h"
#include "query_generators.h"

namespace cavity::predicates::testing {

namespace {

__extension__ typedef __int128 Int;  // wide enough for the small-integer determinants
using Row4 = std::array<Int, 4>;

Sign sign_of(Int x) {
    return x > 0 ? Sign::kPos : (x < 0 ? Sign::kNeg : Sign::kZero);
}

Int det3(const std::array<Int, 3>& r0, const std::array<Int, 3>& r1, const std::array<Int, 3>& r2) {
    return r0[0] * (r1[1] * r2[2] - r1[2] * r2[1]) - r0[1] * (r1[0] * r2[2] - r1[2] * r2[0]) +
           r0[2] * (r1[0] * r2[1] - r1[1] * r2[0]);
}

// Laplace expansion along the first row.
Int det4(const std::array<Row4, 4>& m) {
    Int result = 0;
    for (std::size_t col = 0; col < 4; ++col) {
        std::array<std::array<Int, 3>, 3> minor{};
        for (std::size_t r = 1; r < 4; ++r) {
            std::size_t k = 0;
            for (std::size_t c = 0; c < 4; ++c) {
                if (c != col) {
                    minor[r - 1][k++] = m[r][c];
                }
            }
        }
        const Int term = m[0][col] * det3(minor[0], minor[1], minor[2]);
        result += col % 2 == 0 ? term : -term;
    }
    return result;
}

Int value(const Query& q, std::size_t point, std::size_t j) {
    return static_cast<Int>(q.v[stride(q.kind) * point + j]);
}

// sign det[a-d; b-d; c-d], sign det[p-e, |p-e|^2] or sign det[p-e, h_p-h_e], h = |p|^2 - w.
Sign difference_form(const Query& q) {
    const std::size_t last = point_count(q.kind) - 1;
    const auto diff = [&](std::size_t p, std::size_t j) {
        return value(q, p, j) - value(q, last, j);
    };
    if (q.kind == Kind::kOrient3d) {
        return sign_of(det3({diff(0, 0), diff(0, 1), diff(0, 2)},
                            {diff(1, 0), diff(1, 1), diff(1, 2)},
                            {diff(2, 0), diff(2, 1), diff(2, 2)}));
    }
    const auto height = [&](std::size_t p) {
        const Int norm = value(q, p, 0) * value(q, p, 0) + value(q, p, 1) * value(q, p, 1) +
                         value(q, p, 2) * value(q, p, 2);
        return q.kind == Kind::kOrient4d ? norm - value(q, p, 3) : norm;
    };
    std::array<Row4, 4> m{};
    for (std::size_t p = 0; p < 4; ++p) {
        const Int dx = diff(p, 0), dy = diff(p, 1), dz = diff(p, 2);
        m[p] = {dx,
                dy,
                dz,
                q.kind == Kind::kInsphere ? dx * dx + dy * dy + dz * dz : height(p) - height(last)};
    }
    return sign_of(det4(m));
}

// Small integers (|x| <= bound, weights |w| <= bound^2) so that the 128-bit forms cannot overflow.
Query small_integer_query(Kind k, Rng& rng, std::int64_t bound) {
    Query q{k};
    for (std::size_t i = 0; i < value_count(k); ++i) {
        const std::int64_t b = is_weight(k, i) ? bound * bound : bound;
        q.v[i] = static_cast<double>(rng.integer(-b, b));
    }
    return q;
}

// Coordinates times 2^e and weights times 2^2e: every determinant is multiplied by a positive
// power of two, so its sign is kept (the scalings below are exact for these integers).
Query scaled(Query q, int e) {
    for (std::size_t i = 0; i < value_count(q.kind); ++i) {
        q.v[i] = std::ldexp(q.v[i], is_weight(q.kind, i) ? 2 * e : e);
    }
    return q;
}

class OracleIdentity : public ::testing::TestWithParam<Kind> {};

TEST_P(OracleIdentity, LiftedDeterminantHasTheSignOfTheDifferenceForm) {
    Rng rng(7);
    int mismatches = 0;
    std::array<int, 3> seen{};  // signs -1, 0, 1: the identity is tested on all three
    for (int i = 0; i < 30000; ++i) {
        // Bound 1 gives many exact zeros; 4096 gives typical nonzero determinants.
        const Query q = small_integer_query(GetParam(), rng, i % 2 == 0 ? 1 : 4096);
        const Sign expected = difference_form(q);
        const int slot = to_int(expected) + 1;  // -1, 0, +1 -> 0, 1, 2
        ++seen[static_cast<std::size_t>(slot)];
        const Sign got = evaluate_oracle(q);
        if (got != expected && ++mismatches <= 5) {
            ADD_FAILURE() << "oracle " << to_int(got) << ", difference form " << to_int(expected)
                          << ": " << to_line(q);
        }
    }
    EXPECT_EQ(mismatches, 0);
    EXPECT_GT(seen[0], 1000);
    EXPECT_GT(seen[1], 1000);
    EXPECT_GT(seen[2], 1000);
}

TEST_P(OracleIdentity, PowerOfTwoScalingKeepsTheSign) {
    Rng rng(11);
    // orient4d squares the scale for its weights, so its exponents stay within +-512.
    const std::array<int, 6> exponents =
        GetParam() == Kind::kOrient4d ? std::array<int, 6>{-512, -300, -1, 1, 300, 500}
                                      : std::array<int, 6>{-1074, -1000, -600, 500, 900, 1000};
    int mismatches = 0;
    for (int i = 0; i < 3000; ++i) {
        const Query q = small_integer_query(GetParam(), rng, i % 2 == 0 ? 3 : 1000);
        const Sign expected = difference_form(q);
        for (const int e : exponents) {
            const Query s = scaled(q, e);
            if (evaluate_oracle(s) != expected && ++mismatches <= 5) {
                ADD_FAILURE() << "scaled by 2^" << e << ": " << to_line(s);
            }
        }
    }
    EXPECT_EQ(mismatches, 0);
}

INSTANTIATE_TEST_SUITE_P(Predicates,
                         OracleIdentity,
                         ::testing::Values(Kind::kOrient3d, Kind::kInsphere, Kind::kOrient4d),
                         [](const ::testing::TestParamInfo<Kind>& p) {
                             return std::string(kind_name(p.param));
                         });

// a, b, c counter-clockwise seen from above (+z), d below their plane: positive (Shewchuk).
TEST(OracleConventions, Orient3dIsPositiveForAPointBelowACounterClockwiseTriangle) {
    const Point3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 0};
    EXPECT_EQ(oracle::orient3d(a, b, c, {0, 0, -1}), Sign::kPos);
    EXPECT_EQ(oracle::orient3d(a, b, c, {0, 0, 1}), Sign::kNeg);
    EXPECT_EQ(oracle::orient3d(a, b, c, {5, -7, 0}), Sign::kZero);
    EXPECT_EQ(oracle::orient3d(a, b, c, {0, 0, -0x1p-1074}), Sign::kPos);
    EXPECT_EQ(oracle::orient3d(a, b, c, {0x1p1000, 0x1p1000, 0x1p-1074}), Sign::kNeg);
}

// The tetrahedron below is positively oriented; its circumsphere is centred at (1/2, 1/2, -1/2)
// with squared radius 3/4.
TEST(OracleConventions, InsphereIsPositiveInsideThePositiveTetrahedronsSphere) {
    const Point3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 0}, d{0, 0, -1};
    ASSERT_EQ(oracle::orient3d(a, b, c, d), Sign::kPos);
    EXPECT_EQ(oracle::insphere(a, b, c, d, {0.5, 0.5, -0.5}), Sign::kPos);
    EXPECT_EQ(oracle::insphere(a, b, c, d, {1, 1, -1}), Sign::kZero);
    EXPECT_EQ(oracle::insphere(a, b, c, d, {1, 1, std::nextafter(-1.0, 0.0)}), Sign::kPos);
    EXPECT_EQ(oracle::insphere(a, b, c, d, {1, 1, std::nextafter(-1.0, -2.0)}), Sign::kNeg);
    EXPECT_EQ(oracle::insphere(b, a, c, d, {0.5, 0.5, -0.5}), Sign::kNeg);  // odd permutation
}

// With the same tetrahedron, e = (5, 5, 5) has power 70 with respect to the circumsphere: e is in
// conflict exactly when its weight exceeds 70 (weights of a..d zero), and exactly on the
// orthogonal sphere at 70.
TEST(OracleConventions, Orient4dIsPositiveWhenTheWeightedPointEncroaches) {
    const WeightedPoint3 a{1, 0, 0, 0}, b{0, 1, 0, 0}, c{0, 0, 0, 0}, d{0, 0, -1, 0};
    EXPECT_EQ(oracle::orient4d(a, b, c, d, {5, 5, 5, 0}), Sign::kNeg);
    EXPECT_EQ(oracle::orient4d(a, b, c, d, {5, 5, 5, 70}), Sign::kZero);
    EXPECT_EQ(oracle::orient4d(a, b, c, d, {5, 5, 5, 75}), Sign::kPos);
    EXPECT_EQ(oracle::orient4d(a, b, c, d, {5, 5, 5, std::nextafter(70.0, 0.0)}), Sign::kNeg);
    EXPECT_EQ(oracle::orient4d(a, b, c, d, {0.5, 0.5, -0.5, 0x1p-1074}), Sign::kPos);
}

}  // namespace

}  // namespace cavity::predicates::testing
