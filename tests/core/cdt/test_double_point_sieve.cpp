// The sieve in front of protection_point's search (double_point_sieve.h), against the search by
// GMP rationals alone as the oracle: whenever the search finds a point, the sieve lets the segment
// through, and protection_point (sieve, then search) answers exactly as the search alone. Segments
// of every kind: decimal coordinates (a point is rare), short binary fractions (points abound),
// shared coordinates, coordinates crossing zero and binades inside the window, and extreme
// exponents.

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>

#include <gtest/gtest.h>

#include "../../../core/cdt/src/double_point_sieve.h"
#include "../../../core/cdt/src/protection_point.h"
#include "cavity/core/cdt/edge_protection.h"

namespace cavity::core {
namespace {

struct Window {
    double target;
    double lo;
    double hi;
};

/// What the sieve and the search said over runs of check().
struct Tally {
    int sieved = 0;
    int found = 0;
    int total = 0;
};

/// Checks the sieve and protection_point against the search on one segment and window; returns
/// whether the sieve ruled the window out.
bool check(const Point3& a, const Point3& b, const Window& w, Tally* tally = nullptr) {
    const std::optional<Point3> oracle = rational_protection_point(a, b, w.target, w.lo, w.hi);
    const bool maybe = may_hold_double_point(a, b, std::max(w.lo, 0.0), std::min(w.hi, 1.0));
    EXPECT_TRUE(maybe || !oracle) << "sieved out a window with a point: " << std::hexfloat << a.x
                                  << " " << a.y << " " << a.z << " -> " << b.x << " " << b.y << " "
                                  << b.z << " [" << w.lo << ", " << w.hi << "]";
    const std::optional<Point3> answer = protection_point(a, b, w.target, w.lo, w.hi);
    EXPECT_EQ(answer.has_value(), oracle.has_value());
    if (answer && oracle) {
        EXPECT_EQ(answer->x, oracle->x);
        EXPECT_EQ(answer->y, oracle->y);
        EXPECT_EQ(answer->z, oracle->z);
    }
    if (tally != nullptr) {
        tally->sieved += maybe ? 0 : 1;
        tally->found += oracle ? 1 : 0;
        ++tally->total;
    }
    return !maybe;
}

/// The windows split_point asks about: around the middle, around an aim in [0.2, 0.8], and a
/// shell's narrow one.
Window window(std::mt19937_64& random, int kind) {
    std::uniform_real_distribution<double> aim(0.2, 0.8);
    const double t = aim(random);
    switch (kind % 3) {
        case 0:
            return {0.5, 0.45, 0.55};
        case 1:
            return {t, t - 0.05, t + 0.05};
        default:
            return {t, t - t * 0x1p-30, t + t * 0x1p-30};
    }
}

TEST(DoublePointSieve, DecimalSegmentsAreMostlySievedOut) {
    std::mt19937_64 random(2026);
    std::uniform_int_distribution<int> digits(-9999, 9999);
    const auto decimal = [&] { return digits(random) / 1000.0; };
    for (int shared = 0; shared <= 2; ++shared) {
        Tally tally;
        for (int i = 0; i < 300; ++i) {
            const Point3 a{decimal(), decimal(), decimal()};
            Point3 b{decimal(), decimal(), decimal()};
            if (shared >= 1) {
                b.z = a.z;
            }
            if (shared >= 2) {
                b.y = a.y;
            }
            check(a, b, window(random, i), &tally);
        }
        std::printf("%d shared coordinate(s): %d of %d windows sieved out, %d hold a point\n",
                    shared,
                    tally.sieved,
                    tally.total,
                    tally.found);
        // Where the search finds nothing, the sieve must mostly see it: a coordinate that
        // crosses zero in the window stops constraining, so not always.
        EXPECT_GE(tally.sieved, (tally.total - tally.found) * 4 / 5);
    }
}

TEST(DoublePointSieve, ShortBinaryFractionsKeepTheirPoints) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::uniform_int_distribution<int> bits(1, 52);
    std::uniform_int_distribution<int> exponent(-8, 8);
    int found = 0;
    for (int i = 0; i < 600; ++i) {
        // Few significant bits and mixed binades and signs: many double points, pieces that cross
        // zero and binades.
        const int keep = bits(random);
        const auto coordinate = [&] {
            return std::ldexp(std::round(std::ldexp(unit(random), keep)), exponent(random) - keep);
        };
        const Point3 a{coordinate(), coordinate(), coordinate()};
        const Point3 b{coordinate(), coordinate(), coordinate()};
        const Window w = window(random, i);
        check(a, b, w);
        found += rational_protection_point(a, b, w.target, w.lo, w.hi) ? 1 : 0;
    }
    EXPECT_GT(found, 100);
}

TEST(DoublePointSieve, ExactlyDegenerateSegments) {
    const Window middle{0.5, 0.45, 0.55};
    // Equal coordinates, a point, axis-parallel, through the origin at the window's middle.
    for (const auto& [a, b] : {std::pair<Point3, Point3>{{1, 2, 3}, {1, 2, 4}},
                               {{0.3, 0.3, 0.3}, {0.3, 0.3, 0.3}},
                               {{0.1, 0.2, 0.3}, {0.7, 0.2, 0.3}},
                               {{-0.3, -0.7, -0.1}, {0.3, 0.7, 0.1}},
                               {{-1.1, -1.3, -1}, {1.7, -1.3, -1}},
                               {{0, 0, 0}, {0.1, 0.2, 0.3}},
                               {{-0.0, 0.0, 1}, {0.0, -0.0, 3}},
                               {{1, 1, 1}, {1 + 0x1p-52, 1, 1}},
                               {{1, 1, 1}, {1 + 0x1p-51, 1 + 0x1p-51, 1}}}) {
        check(a, b, middle);
        check(a, b, {0.5, 0.0, 1.0});
        check(a, b, {0.25, 0.0, 0.3});
        check(a, b, {0.9, 0.8, 1.0});
    }
    // Consecutive doubles have no double between them: sieved out.
    EXPECT_TRUE(check({1, 1, 1}, {1 + 0x1p-52, 1, 1}, {0.5, 0.0, 1.0}));
    // A window ending where a coordinate is zero, and one on a binade's edge.
    check({-1, 0.3, 0.7}, {1, 0.9, 0.1}, {0.45, 0.4, 0.5});
    check({0.1, 0.3, 0.7}, {0.3, 0.9, 0.1}, {0.75, 0.7, 0.8});
}

TEST(DoublePointSieve, ExtremeExponents) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    const double huge = std::numeric_limits<double>::max();
    std::mt19937_64 random(99);
    for (int i = 0; i < 30; ++i) {
        const Window w = window(random, i);
        // Subnormals, the largest doubles, and binades too far apart for 128 bits.
        check({3 * tiny, 0, 0}, {5 * tiny, tiny, -tiny}, w);
        check({0x1p-1022, -0x1p-1000, 0}, {0x1p-1030, 0x1p-1010, tiny}, w);
        check({huge, -huge, 0x1p1000}, {0x1p1000, huge, 0x1p1010}, w);
        check({1, 1, 1}, {0x1p-100 + 0x1p-152, 1, 1}, w);
        check({0.1, 0.2, 0.3}, {0x1p-90, 0.7, 0x1p80}, w);
        check({-std::ldexp(1.0, -1000), 0.5, 0.25}, {std::ldexp(3.0, -1000), -0.5, 0.75}, w);
    }
}

}  // namespace
}  // namespace cavity::core
