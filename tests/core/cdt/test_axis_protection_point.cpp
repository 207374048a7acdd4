// The search for double points along an axis (core/cdt/src/axis_protection_point.h) against the
// general search in GMP rationals, which it must reproduce bit for bit wherever it answers:
// decimal coordinates as CAD models have them, segments across zero and across many binades,
// ends and windows on powers of two (pieces that meet the aim at their ends, ties of distance),
// windows holding no double point, and aims inside, at the ends of and outside the window.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "../../../core/cdt/src/axis_protection_point.h"
#include "../../../core/cdt/src/protection_point.h"
#include "cavity/core/base/random.h"
#include "cavity/predicates/point.h"

namespace cavity::core {
namespace {

using predicates::Point3;

bool same_bits(double x, double y) {
    return x == y && std::signbit(x) == std::signbit(y);
}

bool same_point(const std::optional<Point3>& p, const std::optional<Point3>& q) {
    if (p.has_value() != q.has_value()) {
        return false;
    }
    return !p || (same_bits(p->x, q->x) && same_bits(p->y, q->y) && same_bits(p->z, q->z));
}

Point3 with(Point3 p, int axis, double v) {
    (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = v;
    return p;
}

struct Draw {
    Random random;

    double pick(const std::vector<double>& options) {
        return options[random.below(options.size())];
    }

    /// A coordinate: a decimal, a power of two or a neighbour of one, at several scales.
    double coordinate() {
        const double scale = pick({1.0, 1e-3, 1e4, 0x1p-20});
        switch (random.below(4)) {
            case 0:
                return scale * (static_cast<double>(random.below(20001)) - 10000) / 1000;
            case 1: {
                const double p = std::ldexp(1.0, static_cast<int>(random.below(9)) - 4);
                return (random.below(2) == 0 ? 1 : -1) * scale * p;
            }
            case 2: {
                const double p = scale * std::ldexp(1.0, static_cast<int>(random.below(9)) - 4);
                return std::nextafter(p, random.below(2) == 0 ? 0.0 : 2 * p);
            }
            default:
                return scale * random.uniform(-8.0, 8.0);
        }
    }

    /// A parameter: one of the window's usual values, a dyadic one or any in [0, 1].
    double parameter() {
        switch (random.below(3)) {
            case 0:
                return pick({0.0, 0.25, 0.5, 0.75, 1.0, 1.0 / 3, 0.1});
            case 1:
                return static_cast<double>(random.below(65)) / 64;
            default:
                return random.uniform01();
        }
    }
};

TEST(AxisProtectionPoint, ReproducesTheRationalSearch) {
    Draw draw{Random(61)};
    int handled = 0;
    int found = 0;
    int trials = 0;
    for (; trials < 20000; ++trials) {
        const int axis = static_cast<int>(draw.random.below(3));
        const Point3 base{draw.coordinate(), draw.coordinate(), draw.coordinate()};
        double from = draw.coordinate();
        double to = draw.coordinate();
        if (trials % 5 == 0) {
            to = std::nextafter(from, draw.random.below(2) == 0 ? 1e300 : -1e300);  // one ulp
            if (draw.random.below(2) == 0) {
                to = std::nextafter(to, 2 * to - from);
            }
        }
        if (from == to) {
            continue;
        }
        double lo = draw.parameter();
        double hi = draw.parameter();
        if (draw.random.below(4) == 0) {
            hi = std::nextafter(lo, 2.0);  // a window with no double point, mostly
        }
        if (lo > hi) {
            std::swap(lo, hi);
        }
        const double target =
            draw.random.below(5) == 0 ? draw.random.uniform(-0.5, 1.5) : draw.parameter();
        const Point3 a = with(base, axis, from);
        const Point3 b = with(base, axis, to);
        const AxisSearch fast = axis_protection_point(a, b, target, lo, hi);
        if (!fast.handled) {
            continue;
        }
        ++handled;
        const std::optional<Point3> slow = rational_protection_point(a, b, target, lo, hi);
        found += slow ? 1 : 0;
        EXPECT_TRUE(same_point(fast.point, slow))
            << std::hexfloat << "from " << from << " to " << to << " window " << lo << " " << hi
            << " target " << target;
    }
    EXPECT_GT(handled, trials * 95 / 100);
    EXPECT_GT(found, handled / 3);
    EXPECT_LT(found, handled);  // some windows hold no double point
}

TEST(AxisProtectionPoint, LeavesOtherSegmentsToTheRationalSearch) {
    const Point3 a{0.1, 0.2, 0.3};
    EXPECT_FALSE(axis_protection_point(a, Point3{0.4, 0.5, 0.3}, 0.5, 0, 1).handled);
    EXPECT_FALSE(axis_protection_point(a, a, 0.5, 0, 1).handled);
    // Coordinates and parameters outside the range the expansions are exact in.
    EXPECT_FALSE(axis_protection_point(a, Point3{0x1p-1000, 0.2, 0.3}, 0.5, 0, 1).handled);
    EXPECT_FALSE(axis_protection_point(a, Point3{1e300, 0.2, 0.3}, 0.5, 0, 1).handled);
    EXPECT_FALSE(axis_protection_point(a, Point3{0.9, 0.2, 0.3}, 0x1p-400, 0, 1).handled);
    EXPECT_FALSE(axis_protection_point(a, Point3{0.9, 0.2, 0.3}, 0.5, std::nan(""), 1).handled);
    EXPECT_TRUE(axis_protection_point(a, Point3{0.9, 0.2, 0.3}, 0.5, 0, 1).handled);
}

TEST(AxisProtectionPoint, NegativeZeroCoordinatesComeOutPositive) {
    // The rational search converts every coordinate from a rational, so -0 comes out +0.
    const Point3 a{-0.0, 1.0, -0.0};
    const Point3 b{-0.0, 3.0, -0.0};
    const AxisSearch fast = axis_protection_point(a, b, 0.5, 0, 1);
    ASSERT_TRUE(fast.handled);
    EXPECT_TRUE(same_point(fast.point, rational_protection_point(a, b, 0.5, 0, 1)));
    ASSERT_TRUE(fast.point.has_value());
    EXPECT_FALSE(std::signbit(fast.point->x));
    EXPECT_EQ(fast.point->y, 2.0);
    // Along a decreasing coordinate through zero, the point at zero: +0 as well.
    const Point3 c{1.0, 5.0, 5.0};
    const Point3 d{-1.0, 5.0, 5.0};
    const AxisSearch down = axis_protection_point(c, d, 0.5, 0, 1);
    ASSERT_TRUE(down.handled && down.point.has_value());
    EXPECT_TRUE(same_point(down.point, rational_protection_point(c, d, 0.5, 0, 1)));
    EXPECT_TRUE(same_bits(down.point->x, 0.0));
}

}  // namespace
}  // namespace cavity::core
