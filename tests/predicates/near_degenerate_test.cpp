// Agreement of the staged predicates with the exact oracle on near-degenerate inputs whose
// coordinate differences are inexact, the inputs that reach the tail stage C and the exact
// expansion stage D: decimal grids (integer degenerate sets times 0.1, rounded), points on a
// rounded unit sphere (and rounded planes and paraboloid lifts), degenerate integer sets moved 1-4
// ulps, small integer spacings on huge offsets, and exactly singular matrices (equal x and y
// columns) of coordinates spread over 2^-20..2^40, whose differences are inexact: those always
// reach the exact stage.
//
// CAVITY_NEAR_DEGENERATE_QUERIES sets the number of queries per predicate and family (default
// 20000; the `long` label runs 10^6). A mismatch prints the query in hex-float.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "cavity/predicates/insphere.h"
#include "cavity/predicates/oracle.h"
#include "cavity/predicates/orient3d.h"
#include "cavity/predicates/orient4d.h"
#include "random_source.h"

namespace cavity::predicates {
namespace {

std::size_t queries_per_family() {
    const char* text = std::getenv("CAVITY_NEAR_DEGENERATE_QUERIES");
    return text != nullptr && *text != '\0' ? std::strtoull(text, nullptr, 0) : 20000;
}

enum class Family { kDecimalGrid, kRoundedSphere, kUlpMoves, kHugeOffset, kEqualColumns };

const char* family_name(Family f) {
    switch (f) {
        case Family::kDecimalGrid:
            return "DecimalGrid";
        case Family::kRoundedSphere:
            return "RoundedSphere";
        case Family::kUlpMoves:
            return "UlpMoves";
        case Family::kHugeOffset:
            return "HugeOffset";
        case Family::kEqualColumns:
            return "EqualColumns";
    }
    return "?";
}

using Source = testing::RandomSource;

/// A point of an integer degenerate configuration (coplanar, cospherical or cohyperplanar after
/// lifting) mapped to doubles by the family: scaled by 0.1, moved by ulps, or offset.
struct Mapping {
    Family family;
    double offset;  // kHugeOffset: added to every coordinate

    double coordinate(Source& s, int v) const {
        switch (family) {
            case Family::kDecimalGrid:
                return v * 0.1;
            case Family::kUlpMoves:
                return s.integer(0, 3) == 0 ? s.nudged(v) : double(v);
            case Family::kHugeOffset:
                return offset + v * 0.5;
            case Family::kRoundedSphere:
            case Family::kEqualColumns:
                break;
        }
        return v;
    }
};

std::string hex(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%a", v);
    return buffer;
}

/// Counts the stages and the mismatches; reports the first few mismatches.
struct Tally {
    std::size_t mismatches = 0;
    std::size_t stage[kStageCount] = {};

    void check(Verdict v, Sign exact, const std::string& query) {
        ++stage[static_cast<int>(v.stage)];
        if (v.sign != exact && ++mismatches <= 5) {
            ADD_FAILURE() << "sign " << to_int(v.sign) << " (stage " << stage_name(v.stage)
                          << "), oracle " << to_int(exact) << ": " << query;
        }
    }
};

class NearDegenerate : public ::testing::TestWithParam<Family> {
protected:
    Mapping mapping(Source& s) const {
        // Offsets from 2^20 to 2^50 with a fractional part, so that the spacing 0.5 leaves
        // differences that are exact only some of the time.
        const double offset = std::ldexp(1.0 + s.unit() * 0.5, s.integer(20, 50)) + 0.3;
        return {GetParam(), offset};
    }

    void expect_exact_stage_reached(const Tally& t, std::size_t n) const {
        // The families are built to defeat the filter; the exactly singular ones must all reach
        // the exact stage (B and C cannot certify a zero with inexact differences).
        EXPECT_LT(t.stage[static_cast<int>(Stage::kFilter)], n);
        if (GetParam() == Family::kEqualColumns) {
            EXPECT_GT(t.stage[static_cast<int>(Stage::kExact)], n / 2);
        }
    }

    /// Fills x, y = x and z with spread-out values (equal columns make the determinant zero).
    template <typename P>
    static void equal_columns(Source& s, P& r) {
        r.x = s.spread();
        r.y = r.x;
        r.z = s.spread();
    }
};

TEST_P(NearDegenerate, Orient3d) {
    Source s(101 + static_cast<std::uint64_t>(GetParam()));
    Tally t;
    const std::size_t n = queries_per_family();
    for (std::size_t q = 0; q < n; ++q) {
        const Mapping m = mapping(s);
        std::array<Point3, 4> p;
        if (GetParam() == Family::kEqualColumns) {
            for (Point3& r : p) {
                equal_columns(s, r);
            }
        } else if (GetParam() == Family::kRoundedSphere) {
            // Points on a rounded plane through the origin: z = fl(a x + b y).
            const double a = s.unit(), b = s.unit();
            for (Point3& r : p) {
                r.x = s.unit();
                r.y = s.unit();
                r.z = a * r.x + b * r.y;
            }
        } else {
            const int a = s.integer(-5, 5), b = s.integer(-5, 5), c = s.integer(-50, 50);
            for (Point3& r : p) {
                const int x = s.integer(-60, 60), y = s.integer(-60, 60);
                r = {m.coordinate(s, x), m.coordinate(s, y), m.coordinate(s, a * x + b * y + c)};
            }
        }
        std::string text;
        for (const Point3& r : p) {
            text += hex(r.x) + " " + hex(r.y) + " " + hex(r.z) + "  ";
        }
        t.check(orient3d_staged(p[0], p[1], p[2], p[3]),
                oracle::orient3d(p[0], p[1], p[2], p[3]),
                "orient3d " + text);
    }
    EXPECT_EQ(t.mismatches, 0u) << "of " << n;
    expect_exact_stage_reached(t, n);
}

TEST_P(NearDegenerate, Insphere) {
    Source s(202 + static_cast<std::uint64_t>(GetParam()));
    Tally t;
    const std::size_t n = queries_per_family();
    constexpr int kSphere[][3] = {
        {9, 12, 20}, {12, 9, 20}, {20, 9, 12}, {0, 0, 25}, {15, 20, 0}, {20, 0, 15}, {0, 7, 24}};
    for (std::size_t q = 0; q < n; ++q) {
        const Mapping m = mapping(s);
        std::array<Point3, 5> p;
        if (GetParam() == Family::kEqualColumns) {
            for (Point3& r : p) {
                equal_columns(s, r);
            }
        } else if (GetParam() == Family::kRoundedSphere) {
            for (Point3& r : p) {
                const auto d = s.direction();
                r = {d[0], d[1], d[2]};
            }
        } else {
            // Integer points of the sphere of radius 25 about an integer centre.
            const int cx = s.integer(-40, 40), cy = s.integer(-40, 40), cz = s.integer(-40, 40);
            for (Point3& r : p) {
                const auto& k = kSphere[s.integer(0, 6)];
                const int sx = s.integer(0, 1) * 2 - 1, sy = s.integer(0, 1) * 2 - 1,
                          sz = s.integer(0, 1) * 2 - 1;
                r = {m.coordinate(s, cx + sx * k[0]),
                     m.coordinate(s, cy + sy * k[1]),
                     m.coordinate(s, cz + sz * k[2])};
            }
        }
        std::string text;
        for (const Point3& r : p) {
            text += hex(r.x) + " " + hex(r.y) + " " + hex(r.z) + "  ";
        }
        t.check(insphere_staged(p[0], p[1], p[2], p[3], p[4]),
                oracle::insphere(p[0], p[1], p[2], p[3], p[4]),
                "insphere " + text);
    }
    EXPECT_EQ(t.mismatches, 0u) << "of " << n;
    expect_exact_stage_reached(t, n);
}

TEST_P(NearDegenerate, Orient4d) {
    Source s(303 + static_cast<std::uint64_t>(GetParam()));
    Tally t;
    const std::size_t n = queries_per_family();
    for (std::size_t q = 0; q < n; ++q) {
        const Mapping m = mapping(s);
        std::array<WeightedPoint3, 5> p;
        // Weights w = |p|^2 - (a x + b y + c z + d) put the lifted points on one hyperplane; they
        // are computed in doubles from the mapped coordinates, so they are rounded.
        const double a = s.integer(-9, 9), b = s.integer(-9, 9), c = s.integer(-9, 9);
        const double d = s.integer(-99, 99);
        for (WeightedPoint3& r : p) {
            if (GetParam() == Family::kEqualColumns) {
                equal_columns(s, r);
                r.w = s.spread() * s.spread();
                continue;
            }
            if (GetParam() == Family::kDecimalGrid) {
                // The integer configuration scaled by 0.1, its weights by 0.01: degenerate in the
                // reals, near-degenerate after rounding.
                const int x = s.integer(-60, 60), y = s.integer(-60, 60), z = s.integer(-60, 60);
                const double w = x * x + y * y + z * z - (a * x + b * y + c * z + d);
                r = {x * 0.1, y * 0.1, z * 0.1, w * 0.01};
                continue;
            }
            if (GetParam() == Family::kRoundedSphere) {
                const auto dir = s.direction();
                r = {dir[0], dir[1], dir[2], 0.0};
            } else {
                r = {m.coordinate(s, s.integer(-60, 60)),
                     m.coordinate(s, s.integer(-60, 60)),
                     m.coordinate(s, s.integer(-60, 60)),
                     0.0};
            }
            r.w = r.x * r.x + r.y * r.y + r.z * r.z - (a * r.x + b * r.y + c * r.z + d);
        }
        std::string text;
        for (const WeightedPoint3& r : p) {
            text += hex(r.x) + " " + hex(r.y) + " " + hex(r.z) + " " + hex(r.w) + "  ";
        }
        t.check(orient4d_staged(p[0], p[1], p[2], p[3], p[4]),
                oracle::orient4d(p[0], p[1], p[2], p[3], p[4]),
                "orient4d " + text);
    }
    EXPECT_EQ(t.mismatches, 0u) << "of " << n;
    expect_exact_stage_reached(t, n);
}

INSTANTIATE_TEST_SUITE_P(Predicates,
                         NearDegenerate,
                         ::testing::Values(Family::kDecimalGrid,
                                           Family::kRoundedSphere,
                                           Family::kUlpMoves,
                                           Family::kHugeOffset,
                                           Family::kEqualColumns),
                         [](const ::testing::TestParamInfo<Family>& p) {
                             return std::string(family_name(p.param));
                         });

}  // namespace
}  // namespace cavity::predicates
