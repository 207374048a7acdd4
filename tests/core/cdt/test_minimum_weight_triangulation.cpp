// The shortest-diagonal triangulation of a polygon (minimum_weight_triangulation.h), checked
// against every triangulation of small polygons enumerated by brute force with an independent,
// integer validity test, and as the cut of a warped face (warped_facets.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "plc_builders.h"
// White-box: the triangulation is internal to the core.
#include "../../../core/cdt/src/minimum_weight_triangulation.h"
#include "../../../core/cdt/src/warped_facets.h"

namespace cavity::core {
namespace {

using Polygon = std::vector<std::array<std::int64_t, 2>>;

std::int64_t cross(const Polygon& p, std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
}

/// The oracle's test of a triangle of a counter-clockwise polygon with small integer corners: it
/// turns left and no other corner lies in it or on its sides. A triangulation of a simple polygon
/// by its corners is exactly a set of such triangles chosen recursively on a side.
bool empty_left_triangle(const Polygon& p, std::size_t a, std::size_t b, std::size_t c) {
    if (cross(p, a, b, c) <= 0) {
        return false;
    }
    for (std::size_t k = 0; k < p.size(); ++k) {
        if (k != a && k != b && k != c && cross(p, a, b, k) >= 0 && cross(p, b, c, k) >= 0 &&
            cross(p, c, a, k) >= 0) {
            return false;
        }
    }
    return true;
}

double side(const Polygon& p, std::size_t a, std::size_t b) {
    return std::hypot(static_cast<double>(p[a][0] - p[b][0]),
                      static_cast<double>(p[a][1] - p[b][1]));
}

/// The least total diagonal length over every triangulation of the sub-polygon i..j, by
/// enumeration (no memo): infinite when it has none.
double brute_force(const Polygon& p, std::size_t i, std::size_t j) {
    if (j - i < 2) {
        return 0;
    }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = i + 1; k < j; ++k) {
        if (!empty_left_triangle(p, i, k, j)) {
            continue;
        }
        const double left = brute_force(p, i, k) + (k - i > 1 ? side(p, i, k) : 0);
        const double right = brute_force(p, k, j) + (j - k > 1 ? side(p, k, j) : 0);
        best = std::min(best, left + right);
    }
    return best;
}

struct Cut {
    std::vector<Point3> points;
    std::vector<std::uint32_t> loop;
    std::optional<std::vector<Triangle>> triangles;
};

/// The polygon in the plane z = 0 (corner k at index k), cut with axis z dropped,
/// counter-clockwise.
Cut cut(const Polygon& p) {
    Cut c;
    for (std::size_t k = 0; k < p.size(); ++k) {
        c.points.push_back({static_cast<double>(p[k][0]), static_cast<double>(p[k][1]), 0.0});
        c.loop.push_back(static_cast<std::uint32_t>(k));
    }
    // The sign orient2d_projected gives a counter-clockwise turn in this projection.
    const int left = orient2d_projected({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2);
    c.triangles = minimum_weight_triangulation(c.points, c.loop, 2, left);
    return c;
}

/// Checks that `t` triangulates the polygon: n - 2 triangles, each empty and turning left, whose
/// areas sum to the polygon's, with diagonals whose total length is the brute force's minimum.
void expect_minimum_triangulation(const Polygon& p, const std::vector<Triangle>& t) {
    ASSERT_EQ(t.size(), p.size() - 2);
    std::int64_t area = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        area += p[k][0] * p[(k + 1) % p.size()][1] - p[(k + 1) % p.size()][0] * p[k][1];
    }
    std::int64_t covered = 0;
    double diagonals = 0;
    for (const Triangle& tri : t) {
        EXPECT_TRUE(empty_left_triangle(p, tri[0], tri[1], tri[2]));
        covered += cross(p, tri[0], tri[1], tri[2]);
        for (int e = 0; e < 3; ++e) {
            const std::size_t a = tri[e];
            const std::size_t b = tri[(e + 1) % 3];
            const std::size_t gap = std::max(a, b) - std::min(a, b);
            if (gap != 1 && gap != p.size() - 1) {
                diagonals += side(p, a, b) / 2;  // each diagonal has a triangle on both sides
            }
        }
    }
    EXPECT_EQ(covered, area);
    EXPECT_NEAR(diagonals, brute_force(p, 0, p.size() - 1), 1e-9);
}

TEST(MinimumWeightTriangulation, RandomConvexPolygonsMatchEnumeration) {
    std::mt19937_64 random(20261127);
    for (int trial = 0; trial < 40; ++trial) {
        // Corners on an ellipse, rounded to integers, kept while they stay strictly convex.
        const std::size_t n = 4 + trial % 6;
        std::uniform_real_distribution<double> stretch(1, 8);
        const double a = 1000 * stretch(random);
        const double b = 1000;
        Polygon p;
        for (std::size_t k = 0; k < n; ++k) {
            const double angle = 6.283185307179586 *
                                 (static_cast<double>(k) + 0.3 * stretch(random) / 8) /
                                 static_cast<double>(n);
            p.push_back({std::llround(a * std::cos(angle)), std::llround(b * std::sin(angle))});
        }
        const Cut c = cut(p);
        ASSERT_TRUE(c.triangles) << "trial " << trial;
        expect_minimum_triangulation(p, *c.triangles);
    }
}

TEST(MinimumWeightTriangulation, NonConvexPolygonsUseOnlyInteriorDiagonals) {
    // A comb (reflex corners, diagonals that would leave the polygon), an L with three collinear
    // corners on one side (the diagonal through the middle one runs along the boundary), and a
    // spiral-like hook.
    const std::vector<Polygon> polygons = {{{0, 0},
                                            {10, 0},
                                            {10, 10},
                                            {8, 10},
                                            {8, 2},
                                            {6, 2},
                                            {6, 10},
                                            {4, 10},
                                            {4, 2},
                                            {2, 2},
                                            {2, 10},
                                            {0, 10}},
                                           {{0, 0}, {4, 0}, {8, 0}, {8, 3}, {3, 3}, {3, 8}, {0, 8}},
                                           {{0, 0},
                                            {9, 0},
                                            {9, 9},
                                            {2, 9},
                                            {2, 4},
                                            {6, 4},
                                            {6, 6},
                                            {4, 6},
                                            {4, 7},
                                            {7, 7},
                                            {7, 2},
                                            {0, 2}}};
    for (const Polygon& p : polygons) {
        const Cut c = cut(p);
        ASSERT_TRUE(c.triangles);
        expect_minimum_triangulation(p, *c.triangles);
    }
}

TEST(MinimumWeightTriangulation, RefusesWhatIsNoSimplePolygon) {
    // A bow tie: its sides cross, so no diagonal set triangulates it.
    EXPECT_FALSE(cut({{0, 0}, {4, 4}, {4, 0}, {0, 4}}).triangles);
    // The wrong turn: the square traversed clockwise has no left-turning triangle.
    EXPECT_FALSE(cut({{0, 0}, {0, 4}, {4, 4}, {4, 0}}).triangles);
    // Too many corners for the cubic search.
    Polygon big;
    for (std::size_t k = 0; k <= kMinimumWeightCorners; ++k) {
        const double angle = 6.283185307179586 * static_cast<double>(k) /
                             static_cast<double>(kMinimumWeightCorners + 1);
        big.push_back({std::llround(1e6 * std::cos(angle)), std::llround(1e6 * std::sin(angle))});
    }
    EXPECT_FALSE(cut(big).triangles);
}

TEST(MinimumWeightTriangulation, AWarpedStripIsCutAcrossItsWidth) {
    // A 1 x 10 strip with corners every unit along its long sides, one corner lifted 2^-30 off the
    // plane: the shortest cut uses diagonals about sqrt(2) long, never one along the strip (ear
    // clipping from corner 0 fans out to the far end).
    std::vector<Point3> pts;
    for (int x = 0; x <= 10; ++x) {
        pts.push_back({static_cast<double>(x), 0.0, 0.0});
    }
    for (int x = 10; x >= 0; --x) {
        pts.push_back({static_cast<double>(x), 1.0, x == 5 ? 0x1p-30 : 0.0});
    }
    std::vector<std::uint32_t> loop;
    for (std::uint32_t k = 0; k < pts.size(); ++k) {
        loop.push_back(k);
    }
    Plc plc = test::make_plc(pts, {{loop}});
    ASSERT_EQ(split_warped_facets(plc), 1u);
    ASSERT_EQ(plc.facets.size(), pts.size() - 2);
    for (const PlcFacet& f : plc.facets) {
        const auto& t = f.loops[0];
        for (int e = 0; e < 3; ++e) {
            const Point3& a = pts[t[e]];
            const Point3& b = pts[t[(e + 1) % 3]];
            EXPECT_LE(std::fabs(a.x - b.x), 1.0) << t[0] << " " << t[1] << " " << t[2];
        }
    }
}

}  // namespace
}  // namespace cavity::core
