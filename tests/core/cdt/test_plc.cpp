// The PLC itself: validity (how polygons, segments and vertices meet), TetGen's hole rule for facet
// regions, protection points on edges with decimal coordinates, and ids in messages numbered as
// the file numbers them.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>
#include <utility>
#include <variant>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/edge_protection.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/predicates/orient3d.h"
#include "plc_builders.h"
// White-box: the region rule is internal to the core.
#include "../../../core/cdt/src/exact_plane.h"
#include "../../../core/cdt/src/polygon_region.h"
#include "../../../core/cdt/src/split_triangle.h"

namespace cavity::core {
namespace {

using test::Loops;
using test::make_plc;

std::vector<std::array<std::uint32_t, 4>> delaunay(const Plc& plc) {
    std::vector<std::uint32_t> seq(plc.points.size());
    std::iota(seq.begin(), seq.end(), 0u);
    return triangulate(plc.points, seq, TriangulateOptions{}).tets;
}

/// The violations of the PLC once edge-protected (the precondition of plc_violations).
std::vector<std::string> violations(Plc plc) {
    protect_edges(plc, 10000);
    return plc_violations(plc, delaunay(plc));
}

bool mentions(const std::vector<std::string>& messages, const std::string& what) {
    for (const auto& m : messages) {
        if (m.find(what) != std::string::npos) {
            return true;
        }
    }
    return false;
}

std::string joined(const std::vector<std::string>& messages) {
    std::string s;
    for (const auto& m : messages) {
        s += m + "\n";
    }
    return s;
}

/// The 8 corners of [0,4]^3 (indices 0-7) and its 6 sides.
std::vector<Point3> cube_points() {
    return {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 4}, {4, 0, 4}, {4, 4, 4}, {0, 4, 4}};
}

std::vector<Loops> cube_sides() {
    return {{{0, 1, 2, 3}},
            {{4, 5, 6, 7}},
            {{0, 1, 5, 4}},
            {{1, 2, 6, 5}},
            {{2, 3, 7, 6}},
            {{3, 0, 4, 7}}};
}

/// The cube with the square [0.5,3.5]^2 at height 2 (corners 8-11), as facet 6.
Plc cube_with_square() {
    const double z = 2;
    const double x0 = 0.5;
    const double x1 = 3.5;
    auto pts = cube_points();
    const auto n = static_cast<std::uint32_t>(pts.size());
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{x0, x0}, {x1, x0}, {x1, x1}, {x0, x1}}) {
        pts.push_back({x, y, z});
    }
    auto facets = cube_sides();
    facets.push_back({{n, n + 1, n + 2, n + 3}});
    return make_plc(pts, facets);
}

/// plc_edges against the obvious construction (every segment and loop side as {min, max}, sorted,
/// duplicates dropped) on random PLCs: segments in both directions, loops sharing sides with each
/// other and with segments, sides repeated within one loop, and points no edge uses.
TEST(PlcEdges, SortedOnceEachAsTheComparisonSortGivesThem) {
    Random random(20261128);
    for (int trial = 0; trial < 200; ++trial) {
        Plc plc;
        const auto points = static_cast<std::uint32_t>(1 + random.below(40));
        for (std::uint32_t i = 0; i < points; ++i) {
            plc.points.points.push_back({static_cast<double>(i), 0.0, 0.0});
        }
        const auto pick = [&] { return static_cast<std::uint32_t>(random.below(points)); };
        for (std::uint64_t s = random.below(6); s > 0; --s) {
            plc.segments.push_back({pick(), pick()});
        }
        for (std::uint64_t f = random.below(8); f > 0; --f) {
            PlcFacet facet;
            for (std::uint64_t l = 1 + random.below(2); l > 0; --l) {
                std::vector<std::uint32_t> loop;
                for (std::uint64_t k = 3 + random.below(5); k > 0; --k) {
                    loop.push_back(pick());
                }
                facet.loops.push_back(loop);
            }
            plc.facets.push_back(facet);
        }
        // The oracle: an ordered set of {min, max} pairs (loop sides read end to start).
        std::set<std::array<std::uint32_t, 2>> expected;
        std::vector<std::array<std::uint32_t, 2>> sides(plc.segments.begin(), plc.segments.end());
        for (const auto& facet : plc.facets) {
            for (const auto& loop : facet.loops) {
                for (std::size_t i = 0; i < loop.size(); ++i) {
                    sides.push_back({loop[(i + 1) % loop.size()], loop[i]});
                }
            }
        }
        for (const auto& [p, q] : sides) {
            expected.insert({std::min(p, q), std::max(p, q)});
        }
        const std::vector<std::array<std::uint32_t, 2>> sorted(expected.begin(), expected.end());
        EXPECT_EQ(plc_edges(plc), sorted) << "trial " << trial;
    }
}

TEST(PlcValidity, ValidPlcsAreAccepted) {
    EXPECT_TRUE(violations(make_plc(cube_points(), cube_sides())).empty());
    // A box with a hole: a square ring through the cube.
    Plc ring = cube_with_square();
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}) {
        ring.points.points.push_back({x, y, 2});
    }
    ring.facets.back().loops.push_back({12, 13, 14, 15});
    ring.facets.back().holes.push_back({2, 2, 2});
    EXPECT_TRUE(violations(ring).empty()) << joined(violations(ring));
    // Stacked prisms: each level the one below translated, sharing its cap.
    std::vector<Point3> pts;
    std::vector<Loops> facets;
    const std::array<std::array<double, 2>, 3> tri{{{0, 0}, {4, 0.5}, {1.5, 3.75}}};
    for (int level = 0; level < 3; ++level) {
        for (const auto& c : tri) {
            pts.push_back({c[0] + 0.125 * level, c[1], static_cast<double>(level)});
        }
        const auto b = static_cast<std::uint32_t>(3 * level);
        facets.push_back({{b, b + 1, b + 2}});
        for (std::uint32_t k = 0; level > 0 && k < 3; ++k) {
            facets.push_back({{b - 3 + k, b - 3 + (k + 1) % 3, b + (k + 1) % 3, b + k}});
        }
    }
    EXPECT_TRUE(violations(make_plc(pts, facets)).empty());
}

TEST(PlcValidity, VertexInsideAPolygonIsAccepted) {
    Plc plc = cube_with_square();
    plc.points.points.push_back({1.5, 2.5, 2});  // an isolated vertex of the middle square
    EXPECT_TRUE(violations(plc).empty());
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(cdt.plc, cdt.tets).ok());
    bool used = false;
    for (const auto& f : cdt.faces) {
        used = used || f.v[0] == 12 || f.v[1] == 12 || f.v[2] == 12;
    }
    EXPECT_TRUE(used) << "the vertex is not a corner of the square's triangles";
}

TEST(PlcValidity, EdgeThroughATriangle) {
    // A triangular polygon is crossed inside when the edge turns the same way around its three
    // sides (no rational crossing point); through the triangle's plane outside it, it is not.
    for (const bool inside : {true, false}) {
        const double x = inside ? 1.0 : 3.0;
        Plc plc = make_plc({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}, {x, x, 1}, {x, x, -1}},
                           {Loops{{0, 1, 2}}, Loops{{0, 1, 3}}, Loops{{0, 2, 3}}, Loops{{1, 2, 3}}},
                           {{4, 5}});
        const auto found = violations(plc);
        if (inside) {
            ASSERT_EQ(found.size(), 1u) << joined(found);
            EXPECT_TRUE(mentions(found, "test: facet 0: edge 4-5 (a segment) crosses it"))
                << found[0];
        } else {
            EXPECT_TRUE(found.empty()) << joined(found);
        }
    }
}

TEST(PlcValidity, EdgeThroughAPolygon) {
    Plc plc = cube_with_square();
    plc.points.points.push_back({1.5, 2, 1});
    plc.points.points.push_back({2, 1.5, 3});
    plc.segments.push_back({12, 13});
    const auto found = violations(plc);
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_TRUE(mentions(found, "test: facet 6: edge 1")) << found[0];
    EXPECT_TRUE(mentions(found, "(a segment) crosses it")) << found[0];
    // Beside the square it crosses nothing.
    plc.points.points[12] = {3.75, 3.75, 1};
    plc.points.points[13] = {3.75, 3.875, 3};
    EXPECT_TRUE(violations(plc).empty()) << joined(violations(plc));
}

/// True when the CDT has the edge between the points at a and b.
bool has_edge(const Cdt& cdt, const Point3& a, const Point3& b) {
    const auto& pts = cdt.plc.points.points;
    const auto at = [&](std::uint32_t v, const Point3& p) {
        return pts[v].x == p.x && pts[v].y == p.y && pts[v].z == p.z;
    };
    for (const auto& t : cdt.tets) {
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = 0; j < 4; ++j) {
                if (at(t[i], a) && at(t[j], b)) {
                    return true;
                }
            }
        }
    }
    return false;
}

TEST(PlcValidity, SlitAndWallInAPolygonAreAccepted) {
    Plc plc = cube_with_square();
    const Point3 a{1, 1, 2};
    const Point3 b{3, 2, 2};
    plc.points.points.push_back(a);
    plc.points.points.push_back(b);
    plc.segments.push_back({12, 13});  // a slit: a segment in the square
    EXPECT_TRUE(violations(plc).empty()) << joined(violations(plc));
    const Cdt slit = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(slit.plc, slit.tets).ok());
    EXPECT_TRUE(has_edge(slit, a, b));
    // A wall standing on the square along the same edge.
    plc.segments.clear();
    plc.points.points.push_back({1, 1, 3});
    plc.points.points.push_back({3, 2, 3});
    plc.facets.push_back({});
    plc.facets.back().loops = {{12, 13, 15, 14}};
    EXPECT_TRUE(violations(plc).empty()) << joined(violations(plc));
    const Cdt wall = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(wall.plc, wall.tets).ok());
    EXPECT_TRUE(has_edge(wall, a, b));
}

TEST(PlcValidity, CoplanarFacetsOverlap) {
    // A small square inside the middle square, as a facet of its own.
    Plc plc = cube_with_square();
    const auto n = static_cast<std::uint32_t>(plc.points.size());
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}) {
        plc.points.points.push_back({x, y, 2});
    }
    plc.facets.push_back({});
    plc.facets.back().loops = {{n, n + 1, n + 2, n + 3}};
    const auto found = violations(plc);
    EXPECT_TRUE(mentions(found, "test: facet 6: edge 1")) << joined(found);
    EXPECT_TRUE(
        mentions(found, ", a side of facet 7, lies inside it: the two coplanar facets overlap"))
        << joined(found);
    // A triangle on two sides of the square: its third side is the square's diagonal.
    Plc half = cube_with_square();
    half.facets.push_back({});
    half.facets.back().loops = {{8, 9, 10}};
    EXPECT_TRUE(
        mentions(violations(half), "test: facet 6: edge 8-10, a side of facet 7, lies inside it"))
        << joined(violations(half));
}

TEST(PlcValidity, LoopsCrossInAFacet) {
    // The square [0,2]^2 and the triangle (0,0) (2,2) (3,-1) meet only at two corners, yet each
    // overlaps the other without nesting.
    auto pts = cube_points();
    for (auto& p : pts) {
        p = {p.x * 2 - 2, p.y * 2 - 2, p.z - 2};  // the cube [-2,6]^2 x [-2,2]
    }
    const std::vector<Point3> flat{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {3, -1, 0}};
    pts.insert(pts.end(), flat.begin(), flat.end());
    Plc plc = make_plc(pts, {{{8, 9, 10, 11}, {8, 10, 12}}});
    const auto found = violations(plc);
    EXPECT_TRUE(
        mentions(found, "polygon 1 (corners 8 9 10 11) and polygon 2 (corners 8 10 12) cross"))
        << joined(found);
    // Nested (the triangle inside the square, on two of its sides) is fine.
    plc.facets[0].loops[1] = {8, 9, 10};
    EXPECT_TRUE(violations(plc).empty()) << joined(violations(plc));
}

TEST(PlcValidity, HolePointOnASide) {
    Plc plc = cube_with_square();
    plc.facets.back().holes.push_back({2, 0.5, 2});
    EXPECT_TRUE(mentions(violations(plc), "hole point 0 lies on a side of polygon 1"));
}

TEST(PlcValidity, CrossingEdgesStopProtection) {
    Plc plc = make_plc(cube_points(), cube_sides());
    plc.points.points.push_back({1, 1, 1});
    plc.points.points.push_back({3, 3, 3});
    plc.points.points.push_back({1, 3, 3});
    plc.points.points.push_back({3, 1, 1});
    plc.segments = {{8, 9}, {10, 11}};
    try {
        protect_edges(plc, 1000);
        FAIL() << "protected two crossing segments";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_TRUE(what.find("edges 8-9 and 10-11 cross") != std::string::npos ||
                    what.find("edges 10-11 and 8-9 cross") != std::string::npos)
            << what;
    }
    plc.segments = {{8, 9}, {0, 6}};  // the cube's diagonal passes through both points
    try {
        protect_edges(plc, 1000);
        FAIL() << "protected an edge with a point inside it";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("point 8 lies inside edge 0-6"), std::string::npos)
            << e.what();
    }
}

/// edge_violations takes its candidates from grids of boxes: on a lattice of 1728 points (a grid
/// of 12 cells a side) it still finds every point inside a long diagonal edge and a short one,
/// and the edges that cross, each once and in index order.
TEST(PlcValidity, EdgeViolationsOnALatticeInIndexOrder) {
    constexpr std::uint32_t kSide = 12;
    std::vector<Point3> points;
    const auto index = [&](std::uint32_t x, std::uint32_t y, std::uint32_t z) {
        return (x * kSide + y) * kSide + z;
    };
    for (std::uint32_t x = 0; x < kSide; ++x) {
        for (std::uint32_t y = 0; y < kSide; ++y) {
            for (std::uint32_t z = 0; z < kSide; ++z) {
                points.push_back(
                    {static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)});
            }
        }
    }
    const Edge diagonal{index(0, 0, 0), index(11, 11, 11)};
    const Edge short_edge{index(3, 7, 2), index(5, 7, 2)};
    const Edge crossing{index(8, 1, 9), index(9, 2, 9)};
    const Edge crossed{index(9, 1, 9), index(8, 2, 9)};
    const Plc plc = make_plc(points, {}, {diagonal, short_edge, crossing, crossed});
    const std::vector<Edge> asked{short_edge, diagonal, crossing};
    std::vector<std::string> expected;
    const auto id = [](std::uint32_t i) { return std::to_string(i); };
    expected.push_back("test: point " + id(index(4, 7, 2)) + " lies inside edge " +
                       id(short_edge[0]) + "-" + id(short_edge[1]));
    for (std::uint32_t k = 1; k < kSide - 1; ++k) {
        expected.push_back("test: point " + id(index(k, k, k)) + " lies inside edge " +
                           id(diagonal[0]) + "-" + id(diagonal[1]));
    }
    expected.push_back("test: edges " + id(crossing[0]) + "-" + id(crossing[1]) + " and " +
                       id(crossed[1]) + "-" + id(crossed[0]) + " cross");
    EXPECT_EQ(edge_violations(plc, asked), expected);
}

TEST(PlcValidity, ProtectedEntryReportsTheSame) {
    // build_cdt finds the edges protected itself, then skips that search in plc_violations: the
    // same violations, in the same order, whether or not the PLC is valid.
    Plc crossed = cube_with_square();
    crossed.points.points.push_back({1.5, 2, 1});
    crossed.points.points.push_back({2, 1.5, 3});
    crossed.segments.push_back({12, 13});
    for (Plc plc : {make_plc(cube_points(), cube_sides()), cube_with_square(), crossed}) {
        protect_edges(plc, 10000);
        const auto tets = delaunay(plc);
        ASSERT_TRUE(unprotected_edges(plc, tets).empty());
        EXPECT_EQ(protected_plc_violations(plc), plc_violations(plc, tets));
    }
    protect_edges(crossed, 10000);
    EXPECT_EQ(protected_plc_violations(crossed).size(), 1u);
    EXPECT_THROW(require_valid_protected_plc(crossed), Error);
    Plc square = cube_with_square();
    protect_edges(square, 10000);
    EXPECT_NO_THROW(require_valid_protected_plc(square));
}

TEST(PlcValidity, PreconditionIsChecked) {
    Plc plc = make_plc(cube_points(), cube_sides());
    plc.points.points.push_back({2, 2, 2.25});  // in the diametral ball of the diagonal 1-7
    plc.segments.push_back({0, 6});
    ASSERT_FALSE(unprotected_edges(plc).empty());
    const auto found = plc_violations(plc, delaunay(plc));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NE(found[0].find("cannot check the PLC: 1 edge(s) are not Delaunay edges of its points "
                            "(protect them first): 0-6"),
              std::string::npos)
        << found[0];
}

/// The unit squares of a 12 x 12 x 12 grid of cubes: 5616 facets; a segment through one square
/// is the only violation. Bounding boxes keep the exact tests to the few edges near each square.
TEST(PlcValidity, GridOfCubes) {
    constexpr std::uint32_t n = 12;
    std::vector<Point3> pts;
    const auto id = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
        return (i * (n + 1) + j) * (n + 1) + k;
    };
    for (std::uint32_t i = 0; i <= n; ++i) {
        for (std::uint32_t j = 0; j <= n; ++j) {
            for (std::uint32_t k = 0; k <= n; ++k) {
                pts.push_back(
                    {static_cast<double>(i), static_cast<double>(j), static_cast<double>(k)});
            }
        }
    }
    std::vector<Loops> facets;
    for (std::uint32_t i = 0; i <= n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            for (std::uint32_t k = 0; k < n; ++k) {
                facets.push_back(
                    {{id(i, j, k), id(i, j + 1, k), id(i, j + 1, k + 1), id(i, j, k + 1)}});
                facets.push_back(
                    {{id(j, i, k), id(j + 1, i, k), id(j + 1, i, k + 1), id(j, i, k + 1)}});
                facets.push_back(
                    {{id(j, k, i), id(j + 1, k, i), id(j + 1, k + 1, i), id(j, k + 1, i)}});
            }
        }
    }
    Plc plc = make_plc(pts, facets);
    ASSERT_EQ(plc.facets.size(), 3u * n * n * (n + 1));
    const auto a = static_cast<std::uint32_t>(plc.points.size());
    plc.points.points.push_back({5.5, 6.5, 7.5});
    plc.points.points.push_back({5.5, 6.5, 8.5});
    auto tets = delaunay(plc);
    EXPECT_TRUE(plc_violations(plc, tets).empty());
    plc.segments.push_back({a, a + 1});
    const auto found = plc_violations(plc, tets);
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find("edge 2197-2198 (a segment) crosses it"), std::string::npos)
        << found[0];
}

// --- TetGen's hole rule -------------------------------------------------------------------------

/// Squares centred at (2,2) in the plane z = 0 with half-widths 2, 1 and 0.5 (corners 0-3, 4-7,
/// 8-11), as loops of one facet.
struct NestedSquares {
    Plc plc;
    PlcFacet facet;
    ExactPlane plane;

    NestedSquares() : plane(*ExactPlane::of_facet(square_plc(), square_facet())) {
        plc = square_plc();
        facet = square_facet();
    }

    static Plc square_plc() {
        Plc p;
        for (double h : {2.0, 1.0, 0.5}) {
            for (const auto& [x, y] :
                 std::vector<std::pair<double, double>>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
                p.points.points.push_back({2 + h * x, 2 + h * y, 0});
            }
        }
        return p;
    }

    static PlcFacet square_facet() {
        PlcFacet f;
        f.loops = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}};
        return f;
    }

    bool in(double x, double y) const {
        return FacetRegion(plc, facet, plane).contains(exact_point({x, y, 0}));
    }

    Rational area2() const { return facet_region_area2(plc, facet, plane); }
};

TEST(HoleRule, NestedLoopWithoutAHolePointSubdividesTheRegion) {
    const NestedSquares s;
    EXPECT_TRUE(s.in(0.5, 0.5));
    EXPECT_TRUE(s.in(1.2, 2));  // between the middle and the inner square: even-odd says outside
    EXPECT_TRUE(s.in(2, 2));
    EXPECT_FALSE(s.in(5, 5));
    EXPECT_EQ(s.area2(), Rational(2 * 16));
}

TEST(HoleRule, HolePointRemovesOnlyItsFace) {
    NestedSquares s;
    s.facet.holes = {{1.2, 1.2, 0}};  // between the middle and the inner square
    EXPECT_TRUE(s.in(0.5, 0.5));
    EXPECT_FALSE(s.in(1.2, 2));
    EXPECT_TRUE(s.in(2, 2));  // the inner square is an island in the hole
    EXPECT_EQ(s.area2(), Rational(2 * (16 - 4 + 1)));
    s.facet.holes = {{2, 2, 0}};  // in the inner square
    EXPECT_TRUE(s.in(1.2, 2));
    EXPECT_FALSE(s.in(2, 2));
    EXPECT_EQ(s.area2(), Rational(2 * (16 - 1)));
    s.facet.holes = {{1.2, 1.2, 0}, {2, 2, 0}};
    EXPECT_FALSE(s.in(2, 2));
    EXPECT_EQ(s.area2(), Rational(2 * (16 - 4)));
    s.facet.holes = {{7, 7, 0}};  // outside every loop: removes nothing
    EXPECT_EQ(s.area2(), Rational(2 * 16));
}

TEST(HoleRule, LoopsSharingSides) {
    NestedSquares s;
    // A triangle on the bottom side of the outer square, with a hole point in it.
    s.plc.points.points.push_back({2, 1.5, 0});
    s.facet.loops = {{0, 1, 2, 3}, {0, 1, 12}};
    s.facet.holes = {{2, 1, 0}};
    EXPECT_FALSE(s.in(2, 0.5));
    EXPECT_TRUE(s.in(2, 3));
    EXPECT_EQ(s.area2(), Rational(2 * 16 - 4 * 1.5));
    // Two squares side by side: the union.
    s.plc.points.points.push_back({6, 0, 0});
    s.plc.points.points.push_back({6, 4, 0});
    s.facet.loops = {{0, 1, 2, 3}, {1, 13, 14, 2}};
    s.facet.holes.clear();
    EXPECT_TRUE(s.in(5, 1));
    EXPECT_EQ(s.area2(), Rational(2 * 24));
}

/// Twice the area of the CDT's polygon triangles whose centroids are inside [1,3]^2.
double inner_face_area2(const Cdt& cdt) {
    double area = 0;
    for (const auto& f : cdt.faces) {
        const auto& p = cdt.plc.points.points;
        const Point3& a = p[f.v[0]];
        const Point3& b = p[f.v[1]];
        const Point3& c = p[f.v[2]];
        const double cx = (a.x + b.x + c.x) / 3;
        const double cy = (a.y + b.y + c.y) / 3;
        if (a.z == 2 && b.z == 2 && c.z == 2 && cx > 1 && cx < 3 && cy > 1 && cy < 3) {
            area += std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        }
    }
    return area;
}

TEST(HoleRule, CdtOfANestedLoopWithAndWithoutAHolePoint) {
    Plc plc = cube_with_square();  // the square [0.5,3.5]^2 at z = 2, corners 8-11
    for (const auto& [x, y] :
         std::vector<std::pair<double, double>>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}) {
        plc.points.points.push_back({x, y, 2});
    }
    plc.facets.back().loops.push_back({12, 13, 14, 15});
    const Cdt filled = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(filled.plc, filled.tets).ok());
    EXPECT_EQ(inner_face_area2(filled), 8.0);  // the nested square is part of the polygon
    plc.facets.back().holes.push_back({2, 2, 2});
    const Cdt holed = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(holed.plc, holed.tets).ok());
    EXPECT_EQ(inner_face_area2(holed), 0.0);
    EXPECT_LT(holed.faces.size(), filled.faces.size());
}

// --- Protection points ---------------------------------------------------------------------------

/// A coordinate with three decimals in [0, 10), as a .poly file would give it.
double decimal(Random& random) {
    return static_cast<double>(random.below(10000)) / 1000;
}

bool strictly_inside(const Point3& a, const Point3& b, const Point3& p) {
    const ExactPoint ea = exact_point(a);
    const ExactPoint eb = exact_point(b);
    const ExactPoint ep = exact_point(p);
    std::array<Rational, 3> d{};
    std::array<Rational, 3> w{};
    for (std::size_t k = 0; k < 3; ++k) {
        d[k] = eb[k] - ea[k];
        w[k] = ep[k] - ea[k];
    }
    const bool collinear =
        w[1] * d[2] == w[2] * d[1] && w[2] * d[0] == w[0] * d[2] && w[0] * d[1] == w[1] * d[0];
    const Rational s = w[0] * d[0] + w[1] * d[1] + w[2] * d[2];
    return collinear && s > 0 && s < d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

bool midpoint_exact(const Point3& a, const Point3& b) {
    const Point3 m{0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y, 0.5 * a.z + 0.5 * b.z};
    const ExactPoint ea = exact_point(a);
    const ExactPoint eb = exact_point(b);
    const ExactPoint em = exact_point(m);
    return 2 * em[0] == ea[0] + eb[0] && 2 * em[1] == ea[1] + eb[1] && 2 * em[2] == ea[2] + eb[2];
}

/// Prints how often a protection point exists on random edges with decimal coordinates: general
/// edges, edges in an axis-parallel plane (one coordinate shared), axis-parallel edges (two
/// shared).
TEST(ProtectionPoint, SuccessOnDecimalEdges) {
    constexpr int kEdges = 2000;
    Random random(2024);
    for (int shared = 0; shared <= 2; ++shared) {
        int found = 0;
        int midpoints = 0;
        int tested = 0;
        for (int i = 0; i < kEdges; ++i) {
            const Point3 a{decimal(random), decimal(random), decimal(random)};
            Point3 b{decimal(random), decimal(random), decimal(random)};
            if (shared >= 1) {
                b.z = a.z;
            }
            if (shared >= 2) {
                b.y = a.y;
            }
            if (a.x == b.x && a.y == b.y && a.z == b.z) {
                continue;
            }
            ++tested;
            const auto p = protection_point(a, b);
            if (p) {
                ++found;
                ASSERT_TRUE(strictly_inside(a, b, *p));
            }
            midpoints += midpoint_exact(a, b) ? 1 : 0;
            // The midpoint is the first candidate.
            if (midpoint_exact(a, b)) {
                ASSERT_TRUE(p && 2 * p->x == a.x + b.x);
            }
        }
        std::printf(
            "edges with %d shared coordinate(s): protection point %d/%d (%.1f%%), exact "
            "midpoint %d/%d (%.1f%%)\n",
            shared,
            found,
            tested,
            100.0 * found / tested,
            midpoints,
            tested,
            100.0 * midpoints / tested);
        EXPECT_GT(found, midpoints);
    }
}

/// Every point a + t(b - a) with t = k/2^j, j <= 6, whose coordinates are doubles: an independent
/// (incomplete) search that protection_point must never beat.
bool dyadic_point_exists(const Point3& a, const Point3& b) {
    const ExactPoint ea = exact_point(a);
    const ExactPoint eb = exact_point(b);
    for (int j = 1; j <= 6; ++j) {
        for (int k = 1; k < (1 << j); k += 2) {
            const Rational t(k, 1 << j);
            bool exact = true;
            for (std::size_t c = 0; c < 3 && exact; ++c) {
                const Rational v = ea[c] + t * (eb[c] - ea[c]);
                exact = Rational(v.convert_to<double>()) == v;
            }
            if (exact) {
                return true;
            }
        }
    }
    return false;
}

TEST(ProtectionPoint, FindsWhateverADyadicSearchFinds) {
    Random random(77);
    int found = 0;
    for (int i = 0; i < 200; ++i) {
        // Coordinates of both signs and mixed binades, so that pieces cross zero and binades.
        const auto coordinate = [&] {
            return (decimal(random) - 5) * std::ldexp(1.0, -static_cast<int>(random.below(8)));
        };
        const Point3 a{coordinate(), coordinate(), coordinate()};
        const Point3 b{coordinate(), coordinate(), coordinate()};
        if (a.x == b.x && a.y == b.y && a.z == b.z) {
            continue;
        }
        const auto p = protection_point(a, b);
        if (p) {
            ASSERT_TRUE(strictly_inside(a, b, *p));
            ++found;
        } else {
            ASSERT_FALSE(dyadic_point_exists(a, b));
        }
    }
    EXPECT_GT(found, 10);
}

TEST(ProtectionPoint, EdgesCrossingZero) {
    const std::vector<std::array<Point3, 2>> edges{
        {{{-0.3, -0.7, -0.1}, {0.3, 0.7, 0.1}}},  // through the origin: the midpoint
        {{{-1.1, -1.3, -1}, {1.7, -1.3, -1}}},    // axis-parallel, crossing x = 0
        {{{-std::ldexp(1.0, -1000), 0.5, 0.25}, {std::ldexp(3.0, -1000), -0.5, 0.75}}}};  // tiny x
    for (const auto& e : edges) {
        const auto p = protection_point(e[0], e[1]);
        ASSERT_TRUE(p);
        EXPECT_TRUE(strictly_inside(e[0], e[1], *p));
    }
    const Point3 origin = *protection_point(edges[0][0], edges[0][1]);
    EXPECT_TRUE(origin.x == 0 && origin.y == 0 && origin.z == 0);
}

/// A box with decimal corners, 30 decimal interior points, two axis-aligned rectangles with decimal
/// corners (corners 38-41, 42-45), and, when `triangle`, a triangle with decimal corners below them
/// (46-48).
Plc decimal_plc(std::uint64_t seed, bool triangle) {
    Random random(seed);
    std::vector<Point3> pts{{0.1, 0.2, 0.3},
                            {9.7, 0.2, 0.3},
                            {9.7, 9.9, 0.3},
                            {0.1, 9.9, 0.3},
                            {0.1, 0.2, 9.1},
                            {9.7, 0.2, 9.1},
                            {9.7, 9.9, 9.1},
                            {0.1, 9.9, 9.1}};
    for (int i = 0; i < 30; ++i) {
        pts.push_back(
            {1 + decimal(random) * 0.8, 1 + decimal(random) * 0.8, 1 + decimal(random) * 0.8});
    }
    const std::vector<Point3> rectangles{{1.3, 1.1, 2.7},
                                         {8.6, 1.1, 2.7},
                                         {8.6, 7.9, 2.7},
                                         {1.3, 7.9, 2.7},
                                         {2.1, 1.7, 3.4},
                                         {2.1, 8.3, 3.4},
                                         {2.1, 8.3, 8.8},
                                         {2.1, 1.7, 8.8}};
    pts.insert(pts.end(), rectangles.begin(), rectangles.end());
    auto facets = cube_sides();
    facets.push_back({{38, 39, 40, 41}});
    facets.push_back({{42, 43, 44, 45}});
    if (triangle) {
        for (int i = 0; i < 3; ++i) {  // below the rectangles
            pts.push_back({1 + decimal(random) * 0.8,
                           1 + decimal(random) * 0.8,
                           0.5 + decimal(random) * 0.2});
        }
        facets.push_back({{46, 47, 48}});
    }
    return make_plc(pts, facets);
}

TEST(ProtectionPoint, AxisAlignedDecimalPlcsGetValidCdts) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const Plc plc = decimal_plc(seed, false);
        ASSERT_FALSE(unprotected_edges(plc).empty()) << "seed " << seed;
        const Cdt cdt = build_cdt(plc, CdtOptions{true});
        EXPECT_FALSE(cdt.protection.inserted.empty());
        EXPECT_TRUE(validate_cdt(cdt.plc, cdt.tets).ok()) << "seed " << seed;
    }
}

/// Decimal PLCs with a general triangle (sides in no axis plane): before implicit Steiner points
/// 10 of 20 were refused ("no point strictly inside it has coordinates that are doubles"); now
/// every one gets a CDT, those edges split at implicit points, validated exactly.
TEST(ProtectionPoint, DecimalPlcsWithAGeneralTriangle) {
    constexpr int kPlcs = 20;
    int with_implicit = 0;
    for (std::uint64_t seed = 1; seed <= kPlcs; ++seed) {
        const Plc plc = decimal_plc(seed, true);
        const Cdt cdt = build_cdt(plc, CdtOptions{true});
        EXPECT_TRUE(validate_cdt(cdt.plc, cdt.tets).ok()) << "seed " << seed;
        with_implicit += cdt.plc.points.exact.empty() ? 0 : 1;
    }
    std::printf("decimal PLCs with a general triangle: %d/%d needed implicit points\n",
                with_implicit,
                kPlcs);
    EXPECT_GT(with_implicit, 0);
}

TEST(ExactPlaneSide, AgreesWithTheRationalOffset) {
    const Plc plc = decimal_plc(3, true);
    for (const PlcFacet& facet : plc.facets) {
        const ExactPlane plane = *ExactPlane::of_facet(plc, facet);
        for (const Point3& p : plc.points.points) {
            const Rational d = plane.offset(exact_point(p));
            const int expected = d > 0 ? 1 : d < 0 ? -1 : 0;
            EXPECT_EQ(static_cast<int>(plane.side(p)), expected);
        }
    }
}

TEST(ExactPlaneSide, InputCornersAmongImplicitPointsGiveTheRationalPlane) {
    // Facets of a PLC with implicit points whose loops start with repeated and collinear corners,
    // input or implicit, in every exponent range: of_facet decides a triple by exact signs on
    // input points (its own, or the ends of segments its split points are inside) when it can,
    // and in rationals otherwise. The oracle is the first non-collinear triple found in
    // rationals, and the side of every point must be its rational offset's sign (the same plane,
    // with the same orientation).
    Random random(20261127);
    const auto pick = [&](int n) {
        return static_cast<int>(random.below(static_cast<unsigned>(n)));
    };
    int planes = 0;
    int collinear = 0;
    for (const int exponent : {-1060, -1000, -300, 0, 300, 960}) {
        for (int trial = 0; trial < 60; ++trial) {
            const auto scaled = [&](int x, int y, int z) {
                return Point3{
                    std::ldexp(x, exponent), std::ldexp(y, exponent), std::ldexp(z, exponent)};
            };
            // Points o + s u + t v (+ k w off the plane) with small integers: exact doubles.
            const std::array<int, 3> u{pick(5) - 2, pick(5) - 2, pick(3)};
            const std::array<int, 3> v{pick(5) - 2, pick(3) - 1, pick(5) - 2};
            const std::array<int, 3> w{pick(3) - 1, pick(3) - 1, 1};
            const auto at = [&](int s, int t, int k) {
                return scaled(s * u[0] + t * v[0] + k * w[0],
                              s * u[1] + t * v[1] + k * w[1],
                              s * u[2] + t * v[2] + k * w[2]);
            };
            Plc plc;
            const auto add = [&](const predicates::GenericPoint3& g) {
                plc.points.exact.push_back(g);
                plc.points.points.push_back(rounded_point(g));
                return static_cast<std::uint32_t>(plc.points.exact.size() - 1);
            };
            std::vector<std::uint32_t> loop;
            loop.push_back(add(at(0, 0, 0)));
            for (int k = 0; k < 6; ++k) {
                // Repeats of the first corner, corners on the line along u, points of segments
                // from the first corner (either end, inside or beyond) or between others, on
                // that line or off it, and corners anywhere in the plane.
                const int kind = pick(6);
                const int s = pick(5) - 2;
                const int t = pick(5) - 2;
                const std::array<std::array<double, 2>, 4> parameters{
                    {{1, 3}, {-1, -3}, {2, 3}, {4, 3}}};
                const auto& [numerator, denominator] =
                    parameters[static_cast<std::size_t>(pick(4))];
                if (kind == 0) {
                    loop.push_back(add(at(0, 0, 0)));
                } else if (kind == 1) {
                    loop.push_back(add(at(s, 0, 0)));
                } else if (kind == 2 || kind == 3) {
                    const Point3 end = at(s, kind == 2 ? 0 : t, 0);
                    const bool first_end = pick(2) == 0;
                    loop.push_back(
                        add(*predicates::segment_parameter_point(first_end ? at(0, 0, 0) : end,
                                                                 first_end ? end : at(0, 0, 0),
                                                                 numerator,
                                                                 denominator)));
                } else if (kind == 4) {
                    loop.push_back(add(*predicates::segment_parameter_point(
                        at(s, pick(2) * t, 0), at(t, pick(3) - 1, 0), numerator, denominator)));
                } else {
                    loop.push_back(add(at(s, t, 0)));
                }
            }
            std::vector<std::uint32_t> off;
            for (int k = 0; k < 8; ++k) {
                off.push_back(add(at(pick(5) - 2, pick(5) - 2, pick(5) - 2)));
            }
            off.push_back(
                add(*predicates::segment_parameter_point(at(1, 0, 1), at(0, 1, -1), 1, 3)));
            PlcFacet facet;
            facet.loops = {loop};
            plc.facets = {facet};
            // The oracle: the first triple of corners with a non-zero rational normal.
            std::optional<std::pair<ExactPoint, ExactPoint>> expected;
            const ExactPoint a = exact_point(plc.points, loop[0]);
            for (std::size_t i = 1; i < loop.size() && !expected; ++i) {
                const ExactPoint b = exact_point(plc.points, loop[i]);
                for (std::size_t j = i + 1; j < loop.size() && !expected && b != a; ++j) {
                    const ExactPoint n =
                        cross(minus(b, a), minus(exact_point(plc.points, loop[j]), a));
                    if (!is_zero(n)) {
                        expected.emplace(a, n);
                    }
                }
            }
            const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
            ASSERT_EQ(plane.has_value(), expected.has_value()) << exponent << " " << trial;
            if (!plane) {
                ++collinear;
                continue;
            }
            ++planes;
            const ExactPoint& n = expected->second;
            EXPECT_NE(n[static_cast<std::size_t>(plane->dropped_axis())], 0);
            for (std::uint32_t i = 0; i < plc.points.exact.size(); ++i) {
                const Rational d = dot(n, minus(exact_point(plc.points, i), expected->first));
                const int sign = d > 0 ? 1 : d < 0 ? -1 : 0;
                EXPECT_EQ(static_cast<int>(plane->side(plc.points.exact[i])), sign)
                    << exponent << " " << trial << " point " << i;
                EXPECT_EQ(plane->offset(exact_point(plc.points, i)).sign(), sign);
            }
        }
    }
    EXPECT_GT(planes, 200);
    EXPECT_GT(collinear, 5);
}

/// a + t (b - a) in rational arithmetic step by step, t = numerator / denominator or, for a line
/// and a plane, n . (p - a) / n . (b - a): the definition, against exact_point's integers.
ExactPoint point_by_definition(const predicates::GenericPoint3& g) {
    const auto rational = [](const Point3& p) {
        return ExactPoint{Rational(p.x), Rational(p.y), Rational(p.z)};
    };
    ExactPoint a;
    ExactPoint b;
    Rational t;
    if (const auto* s = std::get_if<predicates::SegmentParameterPoint>(&g)) {
        a = rational(s->a);
        b = rational(s->b);
        t = Rational(s->numerator) / Rational(s->denominator);
    } else {
        const auto& l = std::get<predicates::LinePlanePoint>(g);
        a = rational(l.a);
        b = rational(l.b);
        const ExactPoint p = rational(l.p);
        const ExactPoint n = cross(minus(rational(l.q), p), minus(rational(l.r), p));
        t = dot(n, minus(p, a)) / dot(n, minus(b, a));
    }
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

TEST(ExactPoint, ImplicitPointsEqualTheirDefinitionInEveryExponentRange) {
    Random random(20261127);
    // Doubles of random sign and mantissa over exponents from subnormal to near overflow (kept
    // far enough below it that no difference or cross product of the definition overflows a
    // double's range: the rationals have no range, but the test's inputs should be points).
    const auto value = [&](int lo, int hi) {
        if (random.below(8) == 0) {
            return 0.0;
        }
        const double m = 1 + static_cast<double>(random.below(1ull << 52)) * 0x1p-52;
        const int e = lo + static_cast<int>(random.below(static_cast<std::uint64_t>(hi - lo + 1)));
        return (random.below(2) == 0 ? m : -m) * std::ldexp(1.0, e);
    };
    for (const auto& range : {std::pair{-1074, -1000},
                              std::pair{-60, 60},
                              std::pair{-8, 8},
                              std::pair{900, 1000},
                              std::pair{-1074, 1000}}) {
        // Named, not a structured binding: clang before 16 cannot capture bindings in a lambda.
        const int lo = range.first;
        const int hi = range.second;
        for (int i = 0; i < 300; ++i) {
            const auto point = [&] { return Point3{value(lo, hi), value(lo, hi), value(lo, hi)}; };
            double numerator = value(-40, 40);
            double denominator = value(-40, 40);
            if (denominator == 0) {
                denominator = 3;
            }
            const predicates::GenericPoint3 s =
                predicates::SegmentParameterPoint{point(), point(), numerator, denominator};
            EXPECT_EQ(exact_point(s), point_by_definition(s));
            const predicates::LinePlanePoint l{point(), point(), point(), point(), point()};
            const ExactPoint n = cross(minus(exact_point(l.q), exact_point(l.p)),
                                       minus(exact_point(l.r), exact_point(l.p)));
            if (dot(n, minus(exact_point(l.b), exact_point(l.a))) != 0) {
                EXPECT_EQ(exact_point(predicates::GenericPoint3(l)), point_by_definition(l));
            }
        }
    }
}

// --- Ids in messages, numbered as the file numbers them
// -------------------------------------------

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
    auto path = std::filesystem::temp_directory_path() / ("cavity_plc_" + name);
    std::ofstream(path) << text;
    return path;
}

/// The cube with the middle square (facet 7, header on line 30) and a segment through the square
/// (points 13 and 14, in facet 8), numbered from 1.
const char* const kOneBasedPoly =
    "# points\n"
    "14 3 0 0\n"
    "1 0 0 0\n2 4 0 0\n3 4 4 0\n4 0 4 0\n5 0 0 4\n6 4 0 4\n7 4 4 4\n8 0 4 4\n"
    "9 0.5 0.5 2\n10 3.5 0.5 2\n11 3.5 3.5 2\n12 0.5 3.5 2\n"
    "13 1.5 2 1\n14 2 1.5 3\n"
    "8\n"
    "1\n4 1 2 3 4\n1\n4 5 6 7 8\n1\n4 1 2 6 5\n"
    "1\n4 2 3 7 6\n1\n4 3 4 8 7\n1\n4 4 1 5 8\n"
    "1\n4 9 10 11 12\n"
    "1\n2 13 14\n"
    "0\n";

TEST(Messages, PlcViolationsNameFileLineAndFileIds) {
    const auto path = write_temp("one_based.poly", kOneBasedPoly);
    Plc plc = read_poly(path);
    ASSERT_EQ(plc.points.index_base, 1);
    const auto found = violations(plc);
    ASSERT_EQ(found.size(), 1u) << joined(found);
    EXPECT_NE(found[0].find(path.string() + ":30: facet 7: edge 13-14 (a segment) crosses it"),
              std::string::npos)
        << found[0];
    ASSERT_TRUE(unprotected_edges(plc).empty());  // so violations() inserted no point
    try {
        require_valid_plc(plc, delaunay(plc));
        FAIL() << "accepted a segment through a polygon";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "not a piecewise linear complex (1 violation(s)):\n  " + found[0]),
                  std::string::npos)
            << e.what();
    }
    std::filesystem::remove(path);
}

TEST(Messages, ReaderRefusesAHolePointOnASide) {
    std::string text = kOneBasedPoly;
    // Facet 7 gets a hole point on its side 9-10.
    const std::string square = "1\n4 9 10 11 12\n";
    text.replace(text.find(square), square.size(), "1 1\n4 9 10 11 12\n1 2 0.5 2\n");
    const auto path = write_temp("hole_on_side.poly", text);
    try {
        read_poly(path);
        FAIL() << "accepted a hole point on a polygon side";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() +
                                             ":30: facet 7: hole point 1 lies on a polygon side"),
                  std::string::npos)
            << e.what();
    }
    std::filesystem::remove(path);
}

TEST(Messages, ValidatorFindsTetrahedraCrossingATriangle) {
    // A triangle and two points above and below it, nearly over its inside: the Delaunay
    // triangulation of the five points has the edge between the two, which crosses the triangle
    // inside it when the points are over its inside and misses it when they are over the
    // outside (the crossing of a triangular polygon is decided by orientations, without the
    // rational crossing point; the square facets of ValidatorNamesFileIds take the other path).
    for (const bool inside : {true, false}) {
        const double x = inside ? 1.0 : 3.0;
        const Plc plc =
            make_plc({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {x, x, 1}, {x, x, -1}}, {Loops{{0, 1, 2}}});
        const auto tets = delaunay(plc);
        const CdtValidation result = validate_cdt(plc, tets, CdtDomain::kConvexHull);
        EXPECT_EQ(mentions(result.problems, "crosses facet"), inside) << joined(result.problems);
    }
}

TEST(Messages, ValidatorNamesFileIds) {
    const auto path = write_temp("one_based_valid.poly", kOneBasedPoly);
    Plc plc = read_poly(path);
    plc.segments.clear();
    // A valid mesh passes with the file's numbering (no spurious problem from the shift).
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    EXPECT_TRUE(validate_cdt(cdt.plc, cdt.tets).ok());
    // The Delaunay triangulation crosses the square: named with the file's ids and facet number.
    auto tets = delaunay(plc);
    const CdtValidation crossing = validate_cdt(plc, tets);
    ASSERT_FALSE(crossing.ok());
    EXPECT_TRUE(mentions(crossing.problems, "crosses facet 7 (line 30)"))
        << joined(crossing.problems);
    // A tetrahedron turned inside out: the complex check names it by the file's ids too.
    const auto t = tets.front();
    std::swap(tets.front()[0], tets.front()[1]);
    const CdtValidation inverted = validate_cdt(plc, tets);
    const std::string name = "(" + std::to_string(t[1] + 1) + " " + std::to_string(t[0] + 1) + " " +
                             std::to_string(t[2] + 1) + " " + std::to_string(t[3] + 1) + ")";
    EXPECT_TRUE(mentions(inverted.problems, name + ": volume not positive (right-hand rule)"))
        << name << "\n"
        << joined(inverted.problems);
    // An edge needing protection, named by the file's ids.
    Plc needs = read_poly(path);
    needs.points.points[12] = {1, 1, 1};
    needs.points.points[13] = {3, 3, 3};
    needs.segments = {{12, 13}, {0, 6}};  // file ids 13-14 and 1-7: the diagonal holds 13 and 14
    try {
        protect_edges(needs, 100);
        FAIL() << "protected a diagonal through two points";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("point 13 lies inside edge 1-7"), std::string::npos)
            << e.what();
    }
    std::filesystem::remove(path);
}

// --- a triangle whose sides edge protection split (split_triangle.h) ---------------------------

/// Triangle A B C in the plane z = 0 with implicit points inside its sides (t = 1/4 on AB, 1/2 on
/// BC, 1/3 on CA: the last has no double), its loop in `order` (indices into A, P, B, Q, C, R).
Plc split_triangle_plc(const std::vector<std::uint32_t>& order) {
    using predicates::SegmentParameterPoint;
    const Point3 a{0, 0, 0};
    const Point3 b{4, 0, 0};
    const Point3 c{0, 4, 0};
    Plc plc;
    plc.points.exact = {a,
                        SegmentParameterPoint{a, b, 1, 4},
                        b,
                        SegmentParameterPoint{b, c, 1, 2},
                        c,
                        SegmentParameterPoint{c, a, 1, 3}};
    for (const auto& g : plc.points.exact) {
        plc.points.points.push_back(rounded_point(g));
    }
    PlcFacet facet;
    facet.loops = {order};
    plc.facets = {facet};
    return plc;
}

TEST(SplitTriangle, FoundOnlyWhenEveryOtherCornerIsInsideASide) {
    const Plc plc = split_triangle_plc({0, 1, 2, 3, 4, 5});
    const auto corners = split_triangle_corners(plc.points, plc.facets[0].loops[0]);
    ASSERT_TRUE(corners.has_value());
    EXPECT_EQ((*corners)[1].x, 4.0);
    // The reverse order is the same triangle.
    EXPECT_TRUE(split_triangle_corners(plc.points, {5, 4, 3, 2, 1, 0}).has_value());
    // Out of order (side P-B-A doubles back), or a split point between corners it is not on.
    EXPECT_FALSE(split_triangle_corners(plc.points, {0, 2, 1, 3, 4, 5}).has_value());
    EXPECT_FALSE(split_triangle_corners(plc.points, {0, 1, 2, 5, 4, 3}).has_value());
    // One side split is enough; a parameter at an end is not inside; no implicit corner at all.
    EXPECT_TRUE(split_triangle_corners(plc.points, {0, 1, 2, 4}).has_value());
    Plc at_end = split_triangle_plc({0, 1, 2, 3, 4, 5});
    at_end.points.exact[1] = predicates::SegmentParameterPoint{{0, 0, 0}, {4, 0, 0}, 4, 4};
    EXPECT_FALSE(split_triangle_corners(at_end.points, {0, 1, 2, 3, 4, 5}).has_value());
    Plc explicit_only = split_triangle_plc({0, 2, 4});
    explicit_only.points.exact.clear();
    EXPECT_FALSE(split_triangle_corners(explicit_only.points, {0, 2, 4}).has_value());
}

TEST(SplitTriangle, CrossingsAgreeWithTheRationalRegion) {
    // Segments from below to above z = 0 on a grid of quarter steps: many pass exactly through a
    // corner, a split point or a side. The three orientations must answer as the region does at
    // the rational crossing point (a point on the boundary is outside).
    const Plc plc = split_triangle_plc({0, 1, 2, 3, 4, 5});
    const PlcFacet& facet = plc.facets[0];
    const auto plane = ExactPlane::of_facet(plc, facet);
    ASSERT_TRUE(plane.has_value());
    const FacetRegion region(plc, facet, *plane);
    const auto corners = split_triangle_corners(plc.points, facet.loops[0]);
    ASSERT_TRUE(corners.has_value());
    Random random(7);
    int inside = 0;
    int outside = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const auto coordinate = [&] { return 0.25 * static_cast<double>(random.below(21)) - 0.5; };
        const Point3 p{
            coordinate(), coordinate(), -1.0 - 0.25 * static_cast<double>(random.below(4))};
        const Point3 q{
            coordinate(), coordinate(), 1.0 + 0.25 * static_cast<double>(random.below(4))};
        const predicates::Sign first = predicates::orient3d(p, q, (*corners)[0], (*corners)[1]);
        const bool by_orientation =
            first != predicates::Sign::kZero &&
            predicates::orient3d(p, q, (*corners)[1], (*corners)[2]) == first &&
            predicates::orient3d(p, q, (*corners)[2], (*corners)[0]) == first;
        const bool by_region = region.contains(plane->crossing(exact_point(p), exact_point(q)));
        EXPECT_EQ(by_orientation, by_region) << p.x << " " << p.y << " -> " << q.x << " " << q.y;
        (by_region ? inside : outside) += 1;
    }
    EXPECT_GT(inside, 100);
    EXPECT_GT(outside, 100);
}

TEST(SplitTriangle, FacesOnThePlaneAgreeWithTheRationalCentroid) {
    // Vertices, edges and triangles of points of the plane z = 0 (input points on a grid of
    // quarter steps, split points and line-plane points among them), against a split triangle
    // and a plain one: FacetGeometry decides them by orientations against the triangle's sides,
    // and must answer as the region does at the rational centroid. Only faces that a complex can
    // hold are asked: none crosses a side (all vertices in the closed triangle, or all on the
    // far side of one side's line), and none lies on one side's line.
    for (const bool split : {true, false}) {
        Plc plc = split_triangle_plc(split ? std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}
                                           : std::vector<std::uint32_t>{0, 2, 4});
        const auto add = [&](const predicates::GenericPoint3& g) {
            plc.points.exact.push_back(g);
            plc.points.points.push_back(rounded_point(g));
            return static_cast<VertexId>(plc.points.exact.size() - 1);
        };
        Random random(split ? 11 : 12);
        const auto grid = [&] {
            return Point3{0.25 * static_cast<double>(random.below(25)) - 1.0,
                          0.25 * static_cast<double>(random.below(25)) - 1.0,
                          0.0};
        };
        std::vector<VertexId> on;
        for (VertexId v = 0; v < 6; ++v) {
            on.push_back(v);
        }
        for (int k = 0; k < 30; ++k) {
            on.push_back(add(grid()));
            on.push_back(add(*predicates::segment_parameter_point(grid(), grid(), 1, 3)));
        }
        for (int k = 0; k < 6; ++k) {
            const Point3 p = grid();
            const Point3 q = grid();
            if (const auto x = predicates::line_plane_point(
                    {p.x, p.y, -1.0}, {q.x, q.y, 1.0}, {0, 0, 0}, {4, 0, 0}, {0, 4, 0})) {
                on.push_back(add(*x));
            }
        }
        const VertexId top = add(Point3{1, 1, 1});
        const VertexId top2 = add(Point3{2, 1, 3});
        const VertexId top3 = add(Point3{1, 2, 2});
        std::vector<std::uint32_t> keys(plc.points.size());
        std::iota(keys.begin(), keys.end(), 0u);
        const Geometry geometry(plc.points.points, keys, {}, plc.points.exact);
        const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
        const FacetRegion region(plc, plc.facets[0], *plane);
        // Twice the signed area of (c_i, c_{i+1}, p): positive inside side i's line.
        const std::array<ExactPoint, 3> c{exact_point(Point3{0, 0, 0}),
                                          exact_point(Point3{4, 0, 0}),
                                          exact_point(Point3{0, 4, 0})};
        const auto inward = [&](std::size_t i, const ExactPoint& p) {
            const ExactPoint& u = c[i];
            const ExactPoint& w = c[(i + 1) % 3];
            return Rational((w[0] - u[0]) * (p[1] - u[1]) - (w[1] - u[1]) * (p[0] - u[0])).sign();
        };
        int inside = 0;
        int outside = 0;
        for (int trial = 0; trial < 4000; ++trial) {
            const std::size_t size = 1 + random.below(3);
            std::vector<VertexId> face;
            for (std::size_t k = 0; k < size; ++k) {
                face.push_back(on[random.below(on.size())]);
            }
            std::vector<ExactPoint> points;
            for (VertexId v : face) {
                points.push_back(exact_point(plc.points.exact[v]));
            }
            bool closed = true;   // every vertex in the closed triangle
            bool beyond = false;  // every vertex on the far side of one side's line, or on it
            bool along = false;   // every vertex on one side's line
            for (std::size_t i = 0; i < 3; ++i) {
                bool all_beyond = true;
                bool all_along = true;
                for (const ExactPoint& p : points) {
                    closed = closed && inward(i, p) >= 0;
                    all_beyond = all_beyond && inward(i, p) <= 0;
                    all_along = all_along && inward(i, p) == 0;
                }
                beyond = beyond || all_beyond;
                along = along || all_along;
            }
            std::vector<VertexId> sorted = face;
            std::sort(sorted.begin(), sorted.end());
            const bool distinct = std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
            bool degenerate = false;
            if (size == 3) {
                degenerate =
                    Rational((points[1][0] - points[0][0]) * (points[2][1] - points[0][1]) -
                             (points[1][1] - points[0][1]) * (points[2][0] - points[0][0]))
                        .sign() == 0;
            } else if (size == 2) {
                degenerate = points[0] == points[1];
            }
            if (!distinct || degenerate || along || !(closed || beyond)) {
                continue;
            }
            ExactPoint centroid{0, 0, 0};
            for (const ExactPoint& p : points) {
                for (std::size_t k = 0; k < 3; ++k) {
                    centroid[k] += p[k] / static_cast<int>(size);
                }
            }
            const bool expected = region.contains(centroid);
            // A FacetGeometry per face: it takes what it learns of a face for every face that
            // shares a vertex or edge off the loops, true of the faces of a complex (no vertex in
            // a loop side) but not of these, whose vertices may lie inside the sides.
            FacetGeometry facet(geometry, plc, plc.facets[0]);
            // A tetrahedron on the face, its other vertices above the plane: it touches the
            // polygon exactly when the face is in the region.
            const std::array<VertexId, 3> tops{top, top2, top3};
            TetVertices t{};
            for (std::size_t k = 0; k < 4; ++k) {
                t[k] = k < size ? face[k] : tops[k - size];
            }
            const bool touches = facet.contact(t) == FacetGeometry::Contact::kTouches;
            EXPECT_EQ(touches, expected) << "trial " << trial;
            if (size == 3) {
                EXPECT_EQ(facet.holds_triangle({face[0], face[1], face[2]}), expected);
            }
            (expected ? inside : outside) += 1;
        }
        EXPECT_GT(inside, 50);
        EXPECT_GT(outside, 200);
    }
}

}  // namespace
}  // namespace cavity::core

namespace cavity::core {
namespace {

/// When p and q lie strictly on either side of the plane: the integer crossing must be the rational
/// one in the two kept coordinates. Returns whether they did (and were compared).
bool crossing_compared(const ExactPlane& plane,
                       const predicates::GenericPoint3& p,
                       const predicates::GenericPoint3& q) {
    const auto sp = plane.side(p);
    const auto sq = plane.side(q);
    if (sp == predicates::Sign::kZero || sq == predicates::Sign::kZero || sp == sq) {
        return false;
    }
    const auto fast = plane.projected_crossing(p, q);
    EXPECT_TRUE(fast.has_value());
    if (!fast) {
        return true;
    }
    const ExactPoint slow = plane.crossing(exact_point(p), exact_point(q));
    for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<int>(k) != plane.dropped_axis()) {
            EXPECT_EQ((*fast)[k], slow[k]);
        }
    }
    return true;
}

TEST(ExactPlane, IntegerCrossingIsTheRationalCrossing) {
    // Planes through three input corners at scales from subnormal to huge, and segments between
    // input points and points on segments (parameters of either sign, near 0 and 1) strictly on
    // opposite sides: projected_crossing, in integers, must give crossing()'s rational point on
    // every coordinate the projection keeps, including crossings exactly at a corner.
    using predicates::SegmentParameterPoint;
    Random random(31);
    int tested = 0;
    for (const double scale : {1.0, 3.0e-7, 0x1p-1060, 0x1p+900}) {
        const auto point = [&] {
            const auto c = [&] { return scale * (static_cast<double>(random.below(33)) - 16) / 8; };
            return Point3{c(), c(), c()};
        };
        for (int plane_trial = 0; plane_trial < 20; ++plane_trial) {
            Plc plc;
            plc.points.points = {point(), point(), point()};
            PlcFacet facet;
            facet.loops = {{0, 1, 2}};
            plc.facets = {facet};
            const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
            if (!plane) {
                continue;  // collinear corners
            }
            const Point3 corner = plc.points.points[0];
            const std::array<std::array<double, 2>, 5> parameters{
                {{1, 3}, {-1, -4}, {0x1p-30, 1}, {1 - 0x1p-40, 1}, {5, 7}}};
            const auto generic = [&]() -> predicates::GenericPoint3 {
                if (random.below(2) == 0) {
                    return point();
                }
                const auto& t = parameters[random.below(parameters.size())];
                return SegmentParameterPoint{point(), point(), t[0], t[1]};
            };
            for (int trial = 0; trial < 60; ++trial) {
                predicates::GenericPoint3 p = generic();
                predicates::GenericPoint3 q = generic();
                if (trial % 10 == 0) {
                    // Through the corner exactly: p and q symmetric about it.
                    const Point3 d = point();
                    p = Point3{corner.x + d.x, corner.y + d.y, corner.z + d.z};
                    q = Point3{corner.x - d.x, corner.y - d.y, corner.z - d.z};
                }
                if (crossing_compared(*plane, p, q)) {
                    ++tested;
                }
            }
        }
    }
    EXPECT_GT(tested, 500);
}

TEST(ExactPlane, CopiesCrossAsTheOriginalBeforeAndAfterUse) {
    // projected_crossing works in integers the plane keeps from call to call; a copy gets its own
    // (empty) ones. Copies made before and after the original's first crossing, and the original
    // asked again after its copies, must all give crossing()'s point, for segment points whose
    // integers are longer than the input points' (the kept integers grow, then hold short values).
    using predicates::SegmentParameterPoint;
    Plc plc;
    plc.points.points = {Point3{0, 0, 0}, Point3{4, 1, 0}, Point3{1, 3, 0.5}};
    PlcFacet facet;
    facet.loops = {{0, 1, 2}};
    plc.facets = {facet};
    const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
    ASSERT_TRUE(plane.has_value());
    const ExactPlane before = *plane;
    const std::array<std::pair<predicates::GenericPoint3, predicates::GenericPoint3>, 3> segments{{
        {SegmentParameterPoint{Point3{0.1, 0.3, -7}, Point3{1e-9, 2, 3}, 1, 3}, Point3{1, 1, 9}},
        {Point3{1, 1, 2}, Point3{2, 1, -2}},
        {SegmentParameterPoint{Point3{-3, 0x1p-40, 5}, Point3{2, 1, -1}, 1 - 0x1p-40, 1},
         SegmentParameterPoint{Point3{1, 1, 5}, Point3{0.5, 0x1p-30, 1}, 5, 7}},
    }};
    for (const auto& [p, q] : segments) {
        EXPECT_TRUE(crossing_compared(*plane, p, q));
    }
    const ExactPlane after = *plane;
    for (const ExactPlane* asked : {&before, &after, &*plane}) {
        for (const auto& [p, q] : segments) {
            EXPECT_TRUE(crossing_compared(*asked, p, q));
        }
    }
}

TEST(ExactPlane, IntegerCrossingAtAFinerScaleThanTheCorners) {
    // The plane keeps its corners and normal in integers at the corners' own scale; segments whose
    // ends have finer doubles (offsets down to 2^-48, exact in the sums) ask for a finer scale.
    Random random(37);
    int tested = 0;
    const auto coordinate = [&](double unit) {
        return unit * (static_cast<double>(random.below(33)) - 16) / 8;
    };
    for (int plane_trial = 0; plane_trial < 40; ++plane_trial) {
        Plc plc;
        for (int i = 0; i < 3; ++i) {
            plc.points.points.push_back(Point3{coordinate(4), coordinate(4), coordinate(4)});
        }
        PlcFacet facet;
        facet.loops = {{0, 1, 2}};
        plc.facets = {facet};
        const auto plane = ExactPlane::of_facet(plc, plc.facets[0]);
        if (!plane) {
            continue;
        }
        for (int trial = 0; trial < 40; ++trial) {
            const double fine = trial % 2 == 0 ? 0x1p-30 : 0x1p-45;
            const auto point = [&] {
                return Point3{coordinate(4) + coordinate(fine),
                              coordinate(4) + coordinate(fine),
                              coordinate(4) + coordinate(fine)};
            };
            const predicates::GenericPoint3 p = point();
            const predicates::GenericPoint3 q =
                predicates::SegmentParameterPoint{point(), point(), 0x1p-20 * 3, 1};
            if (crossing_compared(*plane, p, q)) {
                ++tested;
            }
        }
    }
    EXPECT_GT(tested, 200);
}

TEST(ExactPlane, CrossComponentSignIsTheRationalSign) {
    // Points on grids (differences exact: the doubles decide), collinear triples among them (a
    // zero component), and points whose differences round (orient3d decides), at scales from
    // subnormal to huge: every component's sign must be that of the rational cross product.
    Random random(43);
    int zeros = 0;
    for (const double scale : {1.0, 0.1, 0x1p-1060, 0x1p-420, 0x1p+390, 0x1p+900}) {
        const auto coordinate = [&] {
            const double grid = scale * (static_cast<double>(random.below(33)) - 16) / 8;
            return random.below(4) == 0 ? grid + scale * 0x1p-60 : grid;
        };
        const auto point = [&] { return Point3{coordinate(), coordinate(), coordinate()}; };
        for (int trial = 0; trial < 300; ++trial) {
            const Point3 a = point();
            const Point3 b = point();
            Point3 c = point();
            if (trial % 3 == 0) {
                // On line ab, when the doubles allow: a + 2 (b - a).
                c = Point3{a.x + 2 * (b.x - a.x), a.y + 2 * (b.y - a.y), a.z + 2 * (b.z - a.z)};
            }
            const ExactPoint n =
                cross(minus(exact_point(b), exact_point(a)), minus(exact_point(c), exact_point(a)));
            for (int k = 0; k < 3; ++k) {
                const int expected = n[static_cast<std::size_t>(k)].sign();
                zeros += expected == 0 ? 1 : 0;
                EXPECT_EQ(predicates::to_int(cross_component_sign(a, b, c, k)), expected)
                    << "scale " << scale << " trial " << trial << " axis " << k;
            }
        }
    }
    EXPECT_GT(zeros, 500);
}

TEST(ExactPlane, IntegerCentroidIsTheRationalCentroid) {
    // One to three input points and points on segments, at scales from subnormal to huge and
    // mixed: projected_centroid must equal the mean of the rational points on every kept
    // coordinate, and refuse a line-plane point.
    using predicates::SegmentParameterPoint;
    Random random(41);
    const std::array<std::array<double, 2>, 4> parameters{{{1, 3}, {-1, -4}, {0x1p-30, 1}, {5, 7}}};
    int tested = 0;
    for (const double scale : {1.0, 3.0e-7, 0x1p-1060, 0x1p+900}) {
        const auto point = [&] {
            const double unit = random.below(2) == 0 ? scale : scale * 0x1p-20;
            const auto c = [&] { return unit * (static_cast<double>(random.below(33)) - 16) / 8; };
            return Point3{c(), c(), c()};
        };
        for (int trial = 0; trial < 200; ++trial) {
            std::vector<predicates::GenericPoint3> points;
            const std::size_t count = 1 + random.below(3);
            for (std::size_t i = 0; i < count; ++i) {
                if (random.below(2) == 0) {
                    points.emplace_back(point());
                } else {
                    const auto& t = parameters[random.below(parameters.size())];
                    points.emplace_back(SegmentParameterPoint{point(), point(), t[0], t[1]});
                }
            }
            const int drop = static_cast<int>(random.below(3));
            const auto fast = projected_centroid(points, drop);
            ASSERT_TRUE(fast.has_value());
            for (std::size_t k = 0; k < 3; ++k) {
                if (static_cast<int>(k) == drop) {
                    continue;
                }
                Rational sum = 0;
                for (const auto& g : points) {
                    sum += exact_point(g)[k];
                }
                EXPECT_EQ((*fast)[k], sum / static_cast<int>(count)) << "trial " << trial;
            }
            ++tested;
        }
    }
    EXPECT_EQ(tested, 800);
    const predicates::LinePlanePoint crossing{
        {0, 0, -1}, {0, 0, 1}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const std::vector<predicates::GenericPoint3> with_line_plane{Point3{1, 2, 3}, crossing};
    EXPECT_FALSE(projected_centroid(with_line_plane, 2).has_value());
}

}  // namespace
}  // namespace cavity::core
