// The floating-point stage of the facet region test (core/cdt/src/rounded_region.h) against the
// exact one: its points lie within their bounds of the exact points, and its loop walk, whenever
// it answers, answers as the exact walk does, for every exact point within the bounds, including
// points on corners and sides and level with them.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "../../../core/cdt/src/exact_plane.h"
#include "../../../core/cdt/src/rounded_region.h"
#include "cavity/core/base/random.h"
#include "cavity/predicates/generic_filter.h"
#include "plc_builders.h"

namespace cavity::core {
namespace {

using predicates::GenericPoint3;
using predicates::Point3;
using predicates::RoundedPoint;
using predicates::SegmentParameterPoint;

RoundedPoint rounded_of(const GenericPoint3& g) {
    const Point3 r = rounded_point(g);
    return {r, predicates::rounding_error(g, r)};
}

/// |exact - x| <= error, exactly.
bool within(const Rational& exact, double x, double error) {
    return abs(exact - Rational(x)) <= Rational(error);
}

std::size_t u_axis(int drop) {
    return drop == 0 ? 1 : 0;
}

std::size_t v_axis(int drop) {
    return drop == 2 ? 1 : 2;
}

/// Points on a coarse grid at `scale` (many crossings land exactly on corners and sides), and
/// points on segments between them at parameters that round.
struct Points {
    Random random;
    double scale;

    Point3 input() {
        const auto c = [&] { return scale * (static_cast<double>(random.below(33)) - 16) / 8; };
        return Point3{c(), c(), c()};
    }

    GenericPoint3 generic() {
        static constexpr std::array<std::array<double, 2>, 4> kParameters{
            {{1, 3}, {-1, -7}, {0x1p-30, 1}, {2, 3}}};
        if (random.below(2) == 0) {
            return input();
        }
        const auto& t = kParameters[random.below(kParameters.size())];
        return SegmentParameterPoint{input(), input(), t[0], t[1]};
    }
};

TEST(RoundedRegion, CrossingIsWithinItsBoundOfTheExactCrossing) {
    int compared = 0;
    int decided = 0;
    for (const double scale : {1.0, 3.0e-7, 0x1p-120, 0x1p+120}) {
        Points points{Random(41), scale};
        for (int plane_trial = 0; plane_trial < 20; ++plane_trial) {
            const Plc plc =
                test::make_plc({points.input(), points.input(), points.input()}, {{{0, 1, 2}}});
            const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
            if (!plane) {
                continue;  // collinear corners
            }
            for (int trial = 0; trial < 60; ++trial) {
                const GenericPoint3 p = points.generic();
                const GenericPoint3 q = points.generic();
                const auto sp = plane->side(p);
                const auto sq = plane->side(q);
                if (sp == predicates::Sign::kZero || sq == predicates::Sign::kZero || sp == sq) {
                    continue;
                }
                ++compared;
                const auto x = plane->rounded_crossing(rounded_of(p), rounded_of(q));
                if (!x) {
                    continue;
                }
                ++decided;
                const ExactPoint exact = plane->crossing(exact_point(p), exact_point(q));
                const int drop = plane->dropped_axis();
                EXPECT_TRUE(within(exact[u_axis(drop)], x->u, x->error_u)) << "scale " << scale;
                EXPECT_TRUE(within(exact[v_axis(drop)], x->v, x->error_v)) << "scale " << scale;
            }
        }
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GT(decided, compared * 9 / 10);
}

TEST(RoundedRegion, CentroidIsWithinItsBoundOfTheExactCentroid) {
    Points points{Random(43), 1.0};
    for (int trial = 0; trial < 2000; ++trial) {
        const std::size_t n = 1 + points.random.below(3);
        std::vector<RoundedPoint> rounded;
        ExactPoint exact{0, 0, 0};
        for (std::size_t i = 0; i < n; ++i) {
            const GenericPoint3 g = points.generic();
            rounded.push_back(rounded_of(g));
            const ExactPoint e = exact_point(g);
            for (std::size_t k = 0; k < 3; ++k) {
                exact[k] += e[k] / static_cast<int>(n);
            }
        }
        const int drop = static_cast<int>(trial % 3);
        const auto c = rounded_centroid(rounded, drop);
        ASSERT_TRUE(c.has_value());
        EXPECT_TRUE(within(exact[u_axis(drop)], c->u, c->error_u));
        EXPECT_TRUE(within(exact[v_axis(drop)], c->v, c->error_v));
    }
}

/// A PLC in the plane z = 0 (drop 2) holding a comb-shaped orthogonal loop on the integer grid
/// (many corners level with one another and with the grid points asked about), the same with
/// implicit corners a third of the way along its sides, and a star-shaped loop of random corners.
struct Loops {
    Plc plc;
    std::vector<std::vector<std::uint32_t>> loops;

    std::uint32_t add(const GenericPoint3& g) {
        plc.points.exact.push_back(g);
        plc.points.points.push_back(rounded_point(g));
        return static_cast<std::uint32_t>(plc.points.points.size() - 1);
    }

    Loops() {
        // The comb: teeth of width 1 and height 3 on a base of height 1, from x = 0 to 7.
        const std::vector<std::array<double, 2>> comb{{0, 0},
                                                      {7, 0},
                                                      {7, 4},
                                                      {6, 4},
                                                      {6, 1},
                                                      {5, 1},
                                                      {5, 4},
                                                      {4, 4},
                                                      {4, 1},
                                                      {3, 1},
                                                      {3, 4},
                                                      {2, 4},
                                                      {2, 1},
                                                      {1, 1},
                                                      {1, 4},
                                                      {0, 4}};
        std::vector<std::uint32_t> plain;
        std::vector<std::uint32_t> split;
        for (std::size_t i = 0; i < comb.size(); ++i) {
            const Point3 a{comb[i][0], comb[i][1], 0};
            const auto& next = comb[(i + 1) % comb.size()];
            const Point3 b{next[0], next[1], 0};
            plain.push_back(add(a));
            split.push_back(plain.back());
            split.push_back(add(SegmentParameterPoint{a, b, 1, 3}));
        }
        loops.push_back(plain);
        loops.push_back(split);
        Random random(47);
        std::vector<std::uint32_t> star;
        for (int i = 0; i < 40; ++i) {
            const double angle = 2 * 3.141592653589793 * i / 40;
            const double radius = random.uniform(1.0, 3.0);
            star.push_back(add(Point3{3.5 + radius * std::cos(angle),
                                      2 + radius * std::sin(angle),
                                      random.uniform(-1.0, 1.0)}));
        }
        loops.push_back(star);
    }
};

TEST(RoundedRegion, LoopWalkAnswersAsTheExactWalk) {
    // Exact points X on a grid of quarter steps (on corners, on sides, level with corners) and
    // at random, each given as doubles moved off X by up to a slack within the stated error.
    const Loops fixture;
    Random random(53);
    int decided = 0;
    int undecided = 0;
    for (const auto& loop : fixture.loops) {
        const auto rounded = rounded_loop(fixture.plc, loop, 2);
        ASSERT_TRUE(rounded.has_value());
        for (int trial = 0; trial < 4000; ++trial) {
            const bool grid = trial % 2 == 0;
            const double xu = grid ? 0.25 * static_cast<double>(random.below(33)) - 0.5
                                   : random.uniform(-0.5, 7.5);
            const double xv = grid ? 0.25 * static_cast<double>(random.below(21)) - 0.5
                                   : random.uniform(-0.5, 4.5);
            const LoopPosition exact =
                loop_position(fixture.plc, loop, 2, exact_point(Point3{xu, xv, 0}));
            const std::array<double, 4> slacks{0.0, 0x1p-45, 1e-9, 0.05};
            const double slack = slacks[random.below(slacks.size())];
            RoundedPoint2 x{
                xu + random.uniform(-slack, slack), xv + random.uniform(-slack, slack), 0.0, 0.0};
            // The error the doubles are given with: their exact distance to X, rounded up.
            x.error_u = std::nextafter(std::abs(x.u - xu), 1.0);
            x.error_v = std::nextafter(std::abs(x.v - xv), 1.0);
            if (x.u == xu && x.v == xv && random.below(2) == 0) {
                x.error_u = 0.0;
                x.error_v = 0.0;
            }
            const std::optional<bool> inside = inside_loop_rounded(*rounded, x);
            if (!inside) {
                ++undecided;
                continue;
            }
            ++decided;
            EXPECT_NE(exact, LoopPosition::kOnBoundary) << xu << " " << xv;
            EXPECT_EQ(*inside, exact == LoopPosition::kInside) << xu << " " << xv;
        }
    }
    EXPECT_GT(decided, 8000);
    EXPECT_GT(undecided, 500);  // the grid's points on and level with the comb's corners
}

TEST(RoundedRegion, FacetRegionAnswersAsTheExactRegion) {
    // Nested squares (half-widths 2, 1 and 0.5 about (2, 2)) with a hole point in the innermost:
    // the region is the outer two rings, by TetGen's rule, and the hole's face is asked exactly.
    Plc plc;
    for (double h : {2.0, 1.0, 0.5}) {
        for (const auto& [x, y] :
             std::vector<std::array<double, 2>>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
            plc.points.points.push_back({2 + h * x, 2 + h * y, 0});
        }
    }
    PlcFacet facet;
    facet.loops = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}};
    facet.holes = {Point3{2, 2, 0}};
    plc.facets = {facet};
    const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
    ASSERT_TRUE(plane.has_value());
    const FacetRegion region(plc, plc.facets[0], *plane);
    Random random(59);
    int inside = 0;
    int outside = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const double u = 0.125 * static_cast<double>(random.below(41)) - 0.5;
        const double v = 0.125 * static_cast<double>(random.below(41)) - 0.5;
        const bool expected = region.contains(exact_point(Point3{u, v, 0}));
        // Twice the slack: the sums below round.
        const double slack = trial % 3 == 0 ? 0.0 : 1e-6;
        const std::optional<bool> answer =
            region.contains_rounded(RoundedPoint2{u + slack, v - slack, 2 * slack, 2 * slack});
        if (answer) {
            EXPECT_EQ(*answer, expected) << u << " " << v;
            (*answer ? inside : outside) += 1;
        }
    }
    EXPECT_GT(inside, 500);
    EXPECT_GT(outside, 500);
}

}  // namespace
}  // namespace cavity::core
