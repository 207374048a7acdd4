// orient2d against the oracle's orient3d of the points lifted to z = 0 with (0, 0, 1), on the
// inputs that reach each of its paths: general position (the filter), collinear points whose
// differences are exact (the product difference) or not, near-collinear ones, and magnitudes
// outside the fast path's range (the fallback), down to subnormals and up to overflowing
// differences.

#include "cavity/predicates/orient2d.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "cavity/predicates/oracle.h"
#include "random_source.h"

namespace cavity::predicates::testing {

namespace {

Sign oracle_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
    return negate(oracle::orient3d({ax, ay, 0.0}, {bx, by, 0.0}, {cx, cy, 0.0}, {0.0, 0.0, 1.0}));
}

/// orient2d and the oracle agree on a, b, c and on every permutation (the sign flips with each
/// transposition, which the oracle checks on its own).
void expect_agrees(double ax, double ay, double bx, double by, double cx, double cy) {
    const Sign expected = oracle_orient2d(ax, ay, bx, by, cx, cy);
    EXPECT_EQ(orient2d(ax, ay, bx, by, cx, cy), expected)
        << ax << " " << ay << " " << bx << " " << by << " " << cx << " " << cy;
    EXPECT_EQ(orient2d(bx, by, ax, ay, cx, cy), negate(expected));
    EXPECT_EQ(orient2d(bx, by, cx, cy, ax, ay), expected);
}

TEST(Orient2d, FixesTheConvention) {
    EXPECT_EQ(orient2d(0, 0, 1, 0, 0, 1), Sign::kPos);
    EXPECT_EQ(orient2d(0, 0, 0, 1, 1, 0), Sign::kNeg);
    EXPECT_EQ(orient2d(0, 0, 1, 1, 2, 2), Sign::kZero);
}

TEST(Orient2d, AgreesWithTheOracleInGeneralPosition) {
    RandomSource random(11);
    for (int i = 0; i < 20000; ++i) {
        expect_agrees(random.spread(),
                      random.spread(),
                      random.spread(),
                      random.spread(),
                      random.spread(),
                      random.spread());
    }
}

TEST(Orient2d, AgreesWithTheOracleOnCollinearAndNearlyCollinearPoints) {
    RandomSource random(12);
    for (int i = 0; i < 20000; ++i) {
        // Points on a line through a grid, scaled by a power of two: exact differences, an exact
        // zero or a turn of one unit in the last place.
        const double scale = std::ldexp(1.0, random.integer(-60, 60));
        const double x0 = random.integer(-1000, 1000), y0 = random.integer(-1000, 1000);
        const double dx = random.integer(-50, 50), dy = random.integer(-50, 50);
        const int s = random.integer(-40, 40), t = random.integer(-40, 40);
        double cx = (x0 + t * dx) * scale;
        double cy = (y0 + t * dy) * scale;
        if (i % 3 == 1) {
            cy = random.nudged(cy);
        }
        if (i % 3 == 2) {
            // Inexact coordinates on a line: 0.1-steps are not doubles.
            cx = (x0 + t * dx) * 0.1;
            cy = (y0 + t * dy) * 0.1;
        }
        expect_agrees(x0 * scale, y0 * scale, (x0 + s * dx) * scale, (y0 + s * dy) * scale, cx, cy);
    }
}

TEST(Orient2d, AgreesWithTheOracleAtEveryMagnitude) {
    RandomSource random(13);
    for (int i = 0; i < 20000; ++i) {
        const Point3 a = random.point(-1074, 1023);
        const Point3 b = random.point(-1074, 1023);
        const Point3 c = random.point(-1074, 1023);
        expect_agrees(a.x, a.y, b.x, b.y, c.x, c.y);
        // Collinear through the origin at the same magnitudes: c = 2a in doubles, exactly.
        expect_agrees(a.x, a.y, 0.0, 0.0, 2 * a.x, 2 * a.y);
    }
    const double big = std::numeric_limits<double>::max();
    const double tiny = std::numeric_limits<double>::denorm_min();
    expect_agrees(big, -big, -big, big, 0.0, 0.0);
    expect_agrees(big, big, -big, -big, big, -big);
    expect_agrees(tiny, 0.0, 0.0, tiny, 2 * tiny, 0.0);
    expect_agrees(tiny, tiny, 3 * tiny, 3 * tiny, 0x1p-1000, 0x1p-1000);
    expect_agrees(0x1p-451, 0.0, 0.0, 0x1p-451, 0x1p-451, 0x1p-451);
}

}  // namespace

}  // namespace cavity::predicates::testing
