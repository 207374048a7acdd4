// The PLC itself: validity (how polygons, segments and vertices meet), TetGen's hole rule for facet
// regions, protection points on edges with decimal coordinates, and ids in messages numbered as
// the file numbers them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numeric>

#include "cavity/core/cdt.h"
#include "cavity/core/cdt_validate.h"
#include "cavity/core/edge_protection.h"
#include "cavity/core/error.h"
#include "cavity/core/plc_validity.h"
#include "cavity/core/random.h"
#include "cavity/core/triangulate.h"
// White-box: the region rule is internal to the core.
#include "../../core/src/exact_plane.h"

namespace cavity::core {
namespace {

using Loops = std::vector<std::vector<std::uint32_t>>;

Plc make_plc(std::vector<Point3> points, std::vector<Loops> facets) {
    Plc plc;
    plc.source = "test";
    plc.points.points = std::move(points);
    for (auto& loops : facets) {
        PlcFacet f;
        f.loops = std::move(loops);
        plc.facets.push_back(std::move(f));
    }
    return plc;
}

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
    return {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{0, 1, 5, 4}},
            {{1, 2, 6, 5}}, {{2, 3, 7, 6}}, {{3, 0, 4, 7}}};
}

/// The cube with the square [0.5,3.5]^2 at height 2 (corners 8-11), as facet 6.
Plc cube_with_square() {
    const double z = 2;
    const double x0 = 0.5;
    const double x1 = 3.5;
    auto pts = cube_points();
    const auto n = static_cast<std::uint32_t>(pts.size());
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{x0, x0}, {x1, x0}, {x1, x1}, {x0, x1}}) {
        pts.push_back({x, y, z});
    }
    auto facets = cube_sides();
    facets.push_back({{n, n + 1, n + 2, n + 3}});
    return make_plc(pts, facets);
}

TEST(PlcValidity, ValidPlcsAreAccepted) {
    EXPECT_TRUE(violations(make_plc(cube_points(), cube_sides())).empty());
    // A box with a hole: a square ring through the cube.
    Plc ring = cube_with_square();
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}) {
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
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{1, 1}, {3, 1}, {3, 3}, {1, 3}}) {
        plc.points.points.push_back({x, y, 2});
    }
    plc.facets.push_back({});
    plc.facets.back().loops = {{n, n + 1, n + 2, n + 3}};
    const auto found = violations(plc);
    EXPECT_TRUE(mentions(found, "test: facet 6: edge 1")) << joined(found);
    EXPECT_TRUE(mentions(found, ", a side of facet 7, lies inside it: the two coplanar facets overlap"))
        << joined(found);
    // A triangle on two sides of the square: its third side is the square's diagonal.
    Plc half = cube_with_square();
    half.facets.push_back({});
    half.facets.back().loops = {{8, 9, 10}};
    EXPECT_TRUE(mentions(violations(half), "test: facet 6: edge 8-10, a side of facet 7, lies inside it"))
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
    EXPECT_TRUE(mentions(found, "polygon 1 (corners 8 9 10 11) and polygon 2 (corners 8 10 12) cross"))
        << joined(found);
    // Nested (the triangle inside the square, on two of its sides) is fine.
    plc.facets[0].loops[1] = {8, 9, 10};
    EXPECT_TRUE(violations(plc).empty()) << joined(violations(plc));
}

TEST(PlcValidity, HolePointOnASide) {
    Plc plc = cube_with_square();
    plc.facets.back().holes.push_back({2, 0.5, 2});
    EXPECT_TRUE(mentions(violations(plc), "hole point 1 lies on a side of polygon 1"));
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

}  // namespace
}  // namespace cavity::core
