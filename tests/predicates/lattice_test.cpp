// The lattice predicates (lattice.h) against the exact oracle: on integer points spanning at most
// kLatticeMaxSpan along each axis, the plain insphere and orient3d determinants have the exact
// sign. Random, extreme (coordinates at the box's faces, which maximises every intermediate of the
// evaluation) and degenerate-rich queries, at large integer offsets too; and the detector accepts
// exactly the integer points and the boxes of the bound. The counting engine's lattice route gives
// orient3d_staged's verdict, stage included.

#include "cavity/predicates/lattice.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "query_generators.h"

namespace cavity::predicates::testing {

namespace {

constexpr double kSpan = kLatticeMaxSpan;

TEST(Lattice, IntegralIsExactlyTheIntegers) {
    for (const double v : {0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           715.0,
                           0x1p52 - 1,
                           -0x1p52 + 1,
                           0x1p52,
                           0x1p53,
                           1e15,
                           -1e300,
                           std::numeric_limits<double>::max()}) {
        EXPECT_TRUE(is_integral(v)) << v;
    }
    for (const double v : {0.5,
                           -0.5,
                           0x1p52 - 0.5,
                           -0x1p51 - 0.5,
                           1e-300,
                           5e-324,
                           0.1,
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::quiet_NaN()}) {
        EXPECT_FALSE(is_integral(v)) << v;
    }
}

TEST(Lattice, BoxAcceptsTheBoundAndRefusesBeyondIt) {
    EXPECT_TRUE(is_lattice_box({0, 0, 0}, {kSpan, kSpan, kSpan}));
    EXPECT_TRUE(is_lattice_box({-1e15, 3, 0x1p53}, {-1e15 + kSpan, 3 + kSpan, 0x1p53 + 714}));
    EXPECT_FALSE(is_lattice_box({0, 0, 0}, {kSpan + 1, kSpan, kSpan}));
    EXPECT_FALSE(is_lattice_box({0, 0, 0}, {kSpan, kSpan + 1, kSpan}));
    EXPECT_FALSE(is_lattice_box({0, 0, 0}, {kSpan, kSpan, kSpan + 1}));
    EXPECT_FALSE(is_lattice_box({0, 0, -std::numeric_limits<double>::infinity()}, {1, 1, 1}));
    // The bound is the largest span that keeps 48 S^5 <= 2^53 (lattice.h).
    EXPECT_LE(48.0 * std::pow(kSpan, 5), 0x1p53);
    EXPECT_GT(48.0 * std::pow(kSpan + 1, 5), 0x1p53);
}

/// A coordinate of the lattice box [offset, offset + kSpan].
using Draw = double (*)(Rng&);

double uniform(Rng& rng) {
    return static_cast<double>(rng.integer(0, static_cast<std::int64_t>(kSpan)));
}

// The faces of the box and their neighbours: differences of +-715 and +-714 everywhere, the
// largest lifts and minors the bound allows.
double extreme(Rng& rng) {
    constexpr std::array<double, 4> kValues{0, 1, kSpan - 1, kSpan};
    return kValues[static_cast<std::size_t>(rng.integer(0, 3))];
}

// A coarse sublattice: many coplanar and cospherical queries, so many exact zeros.
double coarse(Rng& rng) {
    return 143.0 * static_cast<double>(rng.integer(0, 5));
}

struct Tally {
    std::size_t zeros = 0;
    std::size_t wrong = 0;
};

void check_family(std::uint64_t seed, Draw draw, Tally& tally) {
    Rng rng(seed);
    // Offsets that keep every coordinate an integer below 2^53, the largest ones included.
    const std::array<double, 5> offsets{0, -357, 1e9, 0x1p52 - kSpan, -0x1p53};
    for (int i = 0; i < 20'000; ++i) {
        const double offset = offsets[static_cast<std::size_t>(i) % offsets.size()];
        std::array<Point3, 5> p{};
        for (Point3& q : p) {
            q = {offset + draw(rng), offset + draw(rng), offset + draw(rng)};
        }
        const Sign o_exact = oracle::orient3d(p[0], p[1], p[2], p[3]);
        const Sign i_exact = oracle::insphere(p[0], p[1], p[2], p[3], p[4]);
        tally.zeros += i_exact == Sign::kZero;
        const bool ok = orient3d_on_lattice(p[0], p[1], p[2], p[3]) == o_exact &&
                        insphere_on_lattice(p[0], p[1], p[2], p[3], p[4]) == i_exact;
        if (!ok && ++tally.wrong <= 5) {
            ADD_FAILURE() << "a lattice determinant disagrees with the oracle at offset " << offset
                          << ": (" << p[0].x << " " << p[0].y << " " << p[0].z << ") ...";
        }
    }
}

TEST(Lattice, PlainDeterminantsAgreeWithTheOracleUpToTheSpan) {
    Tally tally;
    check_family(71, uniform, tally);
    check_family(72, extreme, tally);
    check_family(73, coarse, tally);
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_GT(tally.zeros, 1000u);  // not vacuous: exact ties are checked too
}

// Every query on the eight corners of the box [0, 715]^3, repeats included: the lifts and 3x3
// minors reach their maxima (3 S^2 and 4 S^3) there.
TEST(Lattice, EveryCornerQueryAgreesWithTheOracle) {
    std::array<Point3, 8> corner{};
    for (int i = 0; i < 8; ++i) {
        corner[static_cast<std::size_t>(i)] = {
            (i & 1) * kSpan, ((i >> 1) & 1) * kSpan, ((i >> 2) & 1) * kSpan};
    }
    std::size_t wrong = 0;
    for (int code = 0; code < 8 * 8 * 8 * 8 * 8; ++code) {
        std::array<Point3, 5> p{};
        for (int k = 0, c = code; k < 5; ++k, c /= 8) {
            p[static_cast<std::size_t>(k)] = corner[static_cast<std::size_t>(c % 8)];
        }
        wrong += insphere_on_lattice(p[0], p[1], p[2], p[3], p[4]) !=
                 oracle::insphere(p[0], p[1], p[2], p[3], p[4]);
        wrong +=
            orient3d_on_lattice(p[0], p[1], p[2], p[3]) != oracle::orient3d(p[0], p[1], p[2], p[3]);
    }
    EXPECT_EQ(wrong, 0u);
}

// The counting engine's orient3d on grids must count the stage orient3d_staged reports: the same
// sign and stage on random, extreme and degenerate-rich queries, at the largest offsets the route
// takes (coordinates just inside kLatticeStagedMagnitude).
TEST(Lattice, StagedRouteGivesTheStagedVerdict) {
    const std::array<double, 5> offsets{
        0, -357, 1e9, kLatticeStagedMagnitude - 1 - kSpan, -kLatticeStagedMagnitude + 1};
    std::array<std::size_t, kStageCount> stages{};
    std::size_t wrong = 0;
    for (const Draw draw : {uniform, extreme, coarse}) {
        Rng rng(74);
        for (int i = 0; i < 20'000; ++i) {
            const double offset = offsets[static_cast<std::size_t>(i) % offsets.size()];
            std::array<Point3, 4> p{};
            for (Point3& q : p) {
                q = {offset + draw(rng), offset + draw(rng), offset + draw(rng)};
            }
            ASSERT_TRUE(is_staged_lattice_box({offset, offset, offset},
                                              {offset + kSpan, offset + kSpan, offset + kSpan}));
            const Verdict route = orient3d_staged_on_lattice(p[0], p[1], p[2], p[3]);
            const Verdict staged = orient3d_staged(p[0], p[1], p[2], p[3]);
            ++stages[static_cast<std::size_t>(staged.stage)];
            if ((route.sign != staged.sign || route.stage != staged.stage) && ++wrong <= 5) {
                ADD_FAILURE() << "the lattice route's verdict differs at offset " << offset << ": ("
                              << p[0].x << " " << p[0].y << " " << p[0].z << ") ...";
            }
        }
    }
    EXPECT_EQ(wrong, 0u);
    // Not vacuous: both stages the route reports are reached.
    EXPECT_GT(stages[static_cast<std::size_t>(Stage::kFilter)], 1000u);
    EXPECT_GT(stages[static_cast<std::size_t>(Stage::kAdaptive)], 1000u);
}

TEST(Lattice, StagedBoxStopsAtTheMagnitude) {
    const double m = kLatticeStagedMagnitude;
    EXPECT_TRUE(is_staged_lattice_box({-m + 1, -m + 1, -m + 1}, {m - 1, m - 1, m - 1}));
    EXPECT_FALSE(is_staged_lattice_box({-m, 0, 0}, {0, 0, 0}));
    EXPECT_FALSE(is_staged_lattice_box({0, 0, -m}, {0, 0, 0}));
    EXPECT_FALSE(is_staged_lattice_box({0, 0, 0}, {0, m, 0}));
    EXPECT_FALSE(is_staged_lattice_box({0, 0, 0}, {0, 0, m}));
}

}  // namespace
}  // namespace cavity::predicates::testing
