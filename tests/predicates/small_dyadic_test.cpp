// orient3d's small-dyadic evaluation (predicates/src/small_dyadic.h) against the exact oracle:
// coplanar points on coarse grids of every scale and of a height field with decimal heights (the
// exact zeros it exists for), the same moved off their plane, entries at the edges of its 31- and
// 62-bit ranges, and the inputs it must refuse. The
// staged orient3d, which calls it, is checked on the same points.

#include "small_dyadic.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <utility>

#include <gtest/gtest.h>

#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::predicates::detail {
namespace {

struct Tally {
    std::size_t answered = 0;
    std::size_t wrong = 0;
    std::size_t inexact = 0;             // differences not exact: not asked
    std::array<std::size_t, 3> signs{};  // -1, 0, +1 among the answered
};

/// Checks orient3d(a, b, c, d) and, when the differences are exact, the small-dyadic evaluation of
/// them against the oracle.
void check(const Point3& a, const Point3& b, const Point3& c, const Point3& d, Tally& tally) {
    const Sign exact = oracle::orient3d(a, b, c, d);
    if (orient3d(a, b, c, d) != exact && ++tally.wrong <= 10) {
        ADD_FAILURE() << "orient3d disagrees with the oracle";
    }
    const double x[3] = {a.x - d.x, b.x - d.x, c.x - d.x};
    const double y[3] = {a.y - d.y, b.y - d.y, c.y - d.y};
    const double z[3] = {a.z - d.z, b.z - d.z, c.z - d.z};
    // orient3d calls it only on exact differences (every two_diff tail zero).
    const auto exact_difference = [](double p, double q) {
        const double s = p - q;
        const double q_part = p - s;
        const double p_part = s + q_part;
        return (p - p_part) + (q_part - q) == 0.0;
    };
    for (const auto& [p, q] : {std::pair{a, d}, std::pair{b, d}, std::pair{c, d}}) {
        if (!exact_difference(p.x, q.x) || !exact_difference(p.y, q.y) ||
            !exact_difference(p.z, q.z)) {
            ++tally.inexact;
            return;
        }
    }
    const std::optional<Sign> s = orient3d_small_dyadic(x, y, z);
    if (!s) {
        return;
    }
    ++tally.answered;
    ++tally.signs[static_cast<std::size_t>(static_cast<int>(*s) + 1)];
    if (*s != exact && ++tally.wrong <= 10) {
        ADD_FAILURE() << "the small dyadic evaluation says " << static_cast<int>(*s)
                      << ", the exact sign is " << static_cast<int>(exact) << " for " << a.x << " "
                      << a.y << " " << a.z << " ...";
    }
}

// Four points of a plane through an offset origin with small integer normal (n . p = 0 on the
// grid of step 2^scale): exact zeros with fractional coordinates and exact differences, as a height
// field's flat faces and tilted facets give; then one point moved a step off the plane.
TEST(SmallDyadic, PointsOfGridPlanesAgreeWithTheOracle) {
    std::mt19937_64 rng(9101);
    std::uniform_int_distribution<int> coordinate(-4000, 4000);
    std::uniform_int_distribution<int> normal(-3, 3);
    Tally zero;
    Tally moved;
    for (const int scale : {-300, -40, -1, 0, 12, 250}) {
        const double step = std::ldexp(1.0, scale);
        for (int i = 0; i < 3000; ++i) {
            // A plane with normal (nx, ny, 1): z = -(nx x + ny y), on the grid when x, y are.
            const int nx = normal(rng);
            const int ny = normal(rng);
            const Point3 origin{1000.5 * step, -333.25 * step, 7.0 * step};
            std::array<Point3, 4> q{};
            for (Point3& p : q) {
                const int u = coordinate(rng);
                const int v = coordinate(rng);
                p = {origin.x + u * step, origin.y + v * step, origin.z - (nx * u + ny * v) * step};
            }
            check(q[0], q[1], q[2], q[3], zero);
            q[static_cast<std::size_t>(i % 4)].z += step;
            check(q[0], q[1], q[2], q[3], moved);
        }
    }
    EXPECT_EQ(zero.wrong, 0u);
    EXPECT_EQ(moved.wrong, 0u);
    // Differences below 2^15 grid steps: every query is answered; moved points leave the plane
    // unless the other three are collinear (rare).
    EXPECT_EQ(zero.answered, 18000u);
    EXPECT_EQ(zero.signs[1], 18000u);
    EXPECT_EQ(moved.answered, 18000u);
    EXPECT_GT(moved.signs[0], 5000u);
    EXPECT_GT(moved.signs[2], 5000u);
}

// Entries from {+-(2^31 - 1), +-2^30, +-1, 0} times 2^-7: the scaled integers span bits 0 to 30,
// the most a narrow column takes, and the minors run as close to 2^63 as any accepted input's.
TEST(SmallDyadic, EntriesAtTheEdgeOfTheRangeAgreeWithTheOracle) {
    const double top = std::ldexp(2147483647.0, -7);
    const std::array<double, 7> values = {top, -top, 0x1p23, -0x1p23, 0x1p-7, -0x1p-7, 0};
    std::mt19937_64 rng(9102);
    std::uniform_int_distribution<std::size_t> pick(0, values.size() - 1);
    Tally tally;
    const Point3 d{0, 0, 0};
    for (int i = 0; i < 20000; ++i) {
        std::array<Point3, 3> q{};
        for (Point3& p : q) {
            p = {values[pick(rng)], values[pick(rng)], values[pick(rng)]};
        }
        check(q[0], q[1], q[2], d, tally);
    }
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_EQ(tally.answered, 20000u);
    EXPECT_GT(tally.signs[0], 1000u);
    EXPECT_GT(tally.signs[1], 100u);  // repeated values make zeros
    EXPECT_GT(tally.signs[2], 1000u);
}

// Points of a height field: x and y on a half-unit grid, heights decimals with six significant
// digits (OpenSCAD's surface() writes them so), the height a function of y alone, so four points
// over two rows of the grid are exactly coplanar while the height differences are 53-bit
// significands (one wide column); and the same with one height moved an ulp.
TEST(SmallDyadic, HeightFieldPointsAgreeWithTheOracle) {
    std::mt19937_64 rng(9104);
    std::uniform_int_distribution<int> cell(0, 400);
    std::uniform_int_distribution<int> level(16, 247);
    Tally zero;
    Tally moved;
    for (int i = 0; i < 20000; ++i) {
        // Rows y0 and y1 with heights h0 and h1 (100 * level / 255 rounded to six digits).
        const auto height = [](int l) { return std::round(100.0 * l / 255.0 * 1e4) / 1e4; };
        // Neighbouring levels above 16: heights within a factor 2, so their differences are exact
        // (Sterbenz).
        const int l0 = level(rng);
        const double y0 = 0.5 * cell(rng);
        const double y1 = y0 + 0.5 * (1 + cell(rng) % 4);
        const double h0 = height(l0);
        const double h1 = height(l0 + 1 + cell(rng) % 8);
        const Point3 a{0.5 * cell(rng), y0, h0};
        const Point3 b{0.5 * cell(rng), y1, h1};
        const Point3 c{0.5 * cell(rng), y1, h1};
        Point3 d{0.5 * cell(rng), y0, h0};
        check(a, b, c, d, zero);
        d.z = std::nextafter(d.z, 200.0);
        check(a, b, c, d, moved);
    }
    EXPECT_EQ(zero.wrong, 0u);
    EXPECT_EQ(moved.wrong, 0u);
    EXPECT_EQ(zero.answered, 20000u);
    EXPECT_EQ(zero.signs[1], 20000u);
    // Moved by an ulp, the height differences are still exact but span more bits: mostly refused,
    // never wrong.
    EXPECT_EQ(zero.inexact, 0u);
    EXPECT_GT(moved.signs[0] + moved.signs[2] + (20000u - moved.answered), 19000u);
}

// One wide column at the edge of its range, 2^62 - 2^9 (53 significant bits above bit 9, bits 0
// to 61 with the 1 beside it), against narrow columns at +-(2^31 - 1): products of about 2^125
// and sums just below 2^127.
TEST(SmallDyadic, AWideColumnAtTheEdgeOfTheRangeAgreesWithTheOracle) {
    const double wide_top = 0x1p62 - 0x1p9;
    const std::array<double, 5> wide = {wide_top, -wide_top, 1, -1, 0};
    const std::array<double, 5> narrow = {2147483647.0, -2147483647.0, 1, -1, 0};
    std::mt19937_64 rng(9105);
    std::uniform_int_distribution<std::size_t> pick(0, 4);
    Tally tally;
    const Point3 d{0, 0, 0};
    for (int i = 0; i < 20000; ++i) {
        std::array<Point3, 3> q{};
        for (Point3& p : q) {
            p = {narrow[pick(rng)], wide[pick(rng)], narrow[pick(rng)]};
        }
        check(q[0], q[1], q[2], d, tally);
    }
    EXPECT_EQ(tally.wrong, 0u);
    EXPECT_EQ(tally.answered, 20000u);
    EXPECT_GT(tally.signs[0], 1000u);
    EXPECT_GT(tally.signs[2], 1000u);
}

TEST(SmallDyadic, RefusesWiderColumnsAndValuesOffTheNormalRange) {
    double x[3] = {1, 0, 0};
    double y[3] = {0, 1, 0};
    double z[3] = {0, 0, 1};
    EXPECT_EQ(orient3d_small_dyadic(x, y, z), Sign::kPos);
    x[1] = 0x1p30;  // bits 0 to 30: narrow
    EXPECT_TRUE(orient3d_small_dyadic(x, y, z).has_value());
    x[1] = 0x1p31;  // bits 0 to 31: wide, and the only wide column
    EXPECT_TRUE(orient3d_small_dyadic(x, y, z).has_value());
    y[2] = 0x1p31 + 2;  // 2 (2^30 + 1) next to 1: a second wide column
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    y[2] = 0;
    x[1] = 0x1p61;  // bits 0 to 61: the widest accepted
    EXPECT_TRUE(orient3d_small_dyadic(x, y, z).has_value());
    x[1] = 0x1p62;  // bits 0 to 62
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    // Scaled by 1 beside 2^61, -(2^51 + 1/2) is no integer, though adding and subtracting
    // 1.5 * 2^52 (the integer test of values below 2^51) would return it unchanged.
    x[0] = 0x1p61;
    x[1] = -(0x1p51 + 0.5);
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    x[0] = 1;
    x[1] = 0x1p-1000;  // underflows to zero when its column is scaled to 2^1000: refused
    x[0] = 0x1p1000;
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    x[0] = 1;
    x[1] = std::numeric_limits<double>::denorm_min();
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    x[1] = std::numeric_limits<double>::infinity();
    EXPECT_FALSE(orient3d_small_dyadic(x, y, z).has_value());
    const double zeros[3] = {0, 0, 0};
    EXPECT_EQ(orient3d_small_dyadic(zeros, zeros, zeros), Sign::kZero);
    EXPECT_EQ(orient3d_small_dyadic(zeros, y, z), Sign::kZero);
}

}  // namespace
}  // namespace cavity::predicates::detail
