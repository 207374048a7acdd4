// CDTs of PLCs (Cheng, Dey & Shewchuk §5.8): the .poly reader, edge protection, flip-based
// polygon insertion, and the independent validator.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <numeric>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/live/triangulate.h"
#include "plc_builders.h"

namespace cavity::core {
namespace {

using test::box_corners;
using test::dyadic_grid_points;
using test::make_plc;

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
    auto path = std::filesystem::temp_directory_path() / ("cavity_cdt_" + name);
    std::ofstream(path) << text;
    return path;
}

/// Builds the CDT, and checks it again with the validator from outside.
Cdt checked_cdt(const Plc& plc, bool protect) {
    Cdt cdt = build_cdt(plc, CdtOptions{protect});
    const CdtValidation v = validate_cdt(cdt.plc, cdt.tets);
    EXPECT_TRUE(v.ok()) << (v.problems.empty() ? "" : v.problems.front());
    EXPECT_EQ(v.polygon_triangles, cdt.faces.size());
    return cdt;
}

std::vector<std::array<std::uint32_t, 4>> delaunay(const Plc& plc) {
    std::vector<std::uint32_t> seq(plc.points.size());
    std::iota(seq.begin(), seq.end(), 0u);
    return triangulate(plc.points, seq, TriangulateOptions{}).tets;
}

TEST(ReadPoly, FacetsHolesSegmentsAndSeparateNode) {
    const auto node = write_temp("sep.node", "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n");
    const auto poly = write_temp("sep.poly",
                                 "0 3 0 0\n# facets\n2 1\n1 1 5\n3 1 2 3\n1 0.2 0.2 0\n"
                                 "1 0 0\n2 1 4\n0\n");
    const Plc plc = read_poly(poly);
    EXPECT_EQ(plc.points.size(), 4u);
    EXPECT_EQ(plc.points.index_base, 1);
    ASSERT_EQ(plc.facets.size(), 1u);
    EXPECT_EQ(plc.facets[0].marker, 5);
    ASSERT_EQ(plc.segments.size(), 1u);
    EXPECT_EQ(plc.segments[0], (std::array<std::uint32_t, 2>{0, 3}));
    EXPECT_EQ(plc_edges(plc).size(), 4u);
    std::filesystem::remove(node);
    std::filesystem::remove(poly);
}

TEST(ReadPoly, ErrorsNameFileAndLine) {
    const auto bad_corner =
        write_temp("bad1.poly", "3 3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n1\n1\n3 0 1 7\n");
    try {
        read_poly(bad_corner);
        FAIL() << "accepted a corner that is not a point";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("bad1.poly:7"), std::string::npos) << e.what();
    }
    const auto not_planar =
        write_temp("bad2.poly", "4 3\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n1\n1\n4 0 1 2 3\n");
    EXPECT_THROW(read_poly(not_planar), Error);
    const auto truncated = write_temp("bad3.poly", "3 3\n0 0 0 0\n1 1 0 0\n");
    EXPECT_THROW(read_poly(truncated), Error);
    for (const auto& p : {bad_corner, not_planar, truncated}) {
        std::filesystem::remove(p);
    }
}

TEST(Cdt, CubeWithInteriorPointsAndMiddleSquare) {
    auto pts = box_corners(4, 4, 0, 4);
    const std::vector<Point3> mid{
        {0, 0, 2.03125}, {4, 0, 2.03125}, {4, 4, 2.03125}, {0, 4, 2.03125}};
    pts.insert(pts.end(), mid.begin(), mid.end());
    const auto inner = dyadic_grid_points(40, 7);
    pts.insert(pts.end(), inner.begin(), inner.end());
    const Plc plc = make_plc(pts, {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{8, 9, 10, 11}}});
    const Cdt cdt = checked_cdt(plc, true);
    EXPECT_GT(
        cdt.counters.flips.flip_count(FlipKind::k23) + cdt.counters.flips.flip_count(FlipKind::k32),
        0u);
    // Proposition 5.5: fewer than m^2 flips per polygon.
    std::uint64_t flips = 0;
    for (auto f : cdt.counters.flips.flips) {
        flips += f;
    }
    EXPECT_LT(flips,
              cdt.counters.max_region_vertices * cdt.counters.max_region_vertices *
                  cdt.plc.facets.size());
}

TEST(Cdt, BoxWithAHole) {
    auto pts = box_corners(4, 4, 0, 4);
    const std::vector<Point3> ring{{0, 0, 1.96875},
                                   {4, 0, 1.96875},
                                   {4, 4, 1.96875},
                                   {0, 4, 1.96875},
                                   {1, 1, 1.96875},
                                   {3, 1, 1.96875},
                                   {3, 3, 1.96875},
                                   {1, 3, 1.96875}};
    pts.insert(pts.end(), ring.begin(), ring.end());
    const auto inner = dyadic_grid_points(30, 11);
    pts.insert(pts.end(), inner.begin(), inner.end());
    Plc plc = make_plc(pts, {{{8, 9, 10, 11}, {12, 13, 14, 15}}});
    plc.facets[0].holes.push_back({2, 2, 1.96875});
    const Cdt cdt = checked_cdt(plc, true);
    // The hole stays open: no polygon triangle has its centroid inside [1,3]^2.
    for (const auto& f : cdt.faces) {
        double cx = 0;
        double cy = 0;
        for (auto v : f.v) {
            cx += cdt.plc.points.points[v].x / 3;
            cy += cdt.plc.points.points[v].y / 3;
        }
        EXPECT_FALSE(cx > 1 && cx < 3 && cy > 1 && cy < 3);
    }
}

TEST(Cdt, StackedPrisms) {
    std::vector<Point3> pts;
    std::vector<std::vector<std::vector<std::uint32_t>>> facets;
    const std::array<std::array<double, 2>, 3> tri{{{0, 0}, {4, 0.5}, {1.5, 3.75}}};
    for (int level = 0; level < 4; ++level) {
        for (const auto& c : tri) {
            pts.push_back({c[0] + 0.125 * level, c[1], static_cast<double>(level)});
        }
        const auto b = static_cast<std::uint32_t>(3 * level);
        facets.push_back({{b, b + 1, b + 2}});
        if (level > 0) {
            for (std::uint32_t k = 0; k < 3; ++k) {
                facets.push_back({{b - 3 + k, b - 3 + (k + 1) % 3, b + (k + 1) % 3, b + k}});
            }
        }
    }
    // Each level is the one below translated, so the side quadrilaterals are planar.
    const Cdt cdt = checked_cdt(make_plc(pts, facets), true);
    EXPECT_EQ(cdt.plc.facets.size(), 13u);
}

TEST(Cdt, NeedsProtection) {
    auto pts = dyadic_grid_points(40, 3);
    const auto box = box_corners(4, 4, 0, 4);
    pts.insert(pts.end(), box.begin(), box.end());
    const auto n = static_cast<std::uint32_t>(pts.size());
    pts.push_back({0.5, 0.5, 1.0});
    pts.push_back({3.5, 1.0, 2.0});
    pts.push_back({1.0, 3.5, 3.0});
    const Plc plc = make_plc(pts, {{{n, n + 1, n + 2}}});
    ASSERT_FALSE(unprotected_edges(plc).empty());
    try {
        build_cdt(plc, CdtOptions{false});
        FAIL() << "built a CDT of a PLC that is not edge-protected";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("not edge-protected"), std::string::npos);
    }
    const Cdt cdt = checked_cdt(plc, true);
    EXPECT_FALSE(cdt.protection.inserted.empty());
    EXPECT_TRUE(unprotected_edges(cdt.plc).empty());
    // The validator can fail: the plain Delaunay triangulation crosses the polygon. Its faces
    // found around the polygon's corners do not cover it, so the validator falls back to testing
    // every tetrahedron, which names the crossing ones.
    const CdtValidation crossed = validate_cdt(cdt.plc, delaunay(cdt.plc));
    EXPECT_FALSE(crossed.ok());
    const auto names_crossing = [](const std::string& p) {
        return p.find(" crosses ") != std::string::npos;
    };
    EXPECT_TRUE(std::any_of(crossed.problems.begin(), crossed.problems.end(), names_crossing));
}

/// The validator finds a one-loop polygon's triangles by a flood from its first side, checked
/// by the flood's boundary being the loop; the scan of every simplex (what a carved domain gets)
/// is the oracle. An L-shaped prism whose bottom is two polygons sharing a side, each listed from
/// that side, so one of them is first flooded from the other's triangle (its boundary runs into
/// the bottom's notch, outside the domain) and must be found from its own.
TEST(Cdt, OneLoopPolygonsFoundFromTheirSidesAsByTheScan) {
    std::vector<Point3> pts;
    for (double z : {0.0, 4.0}) {
        for (const auto& [x, y] : std::vector<std::array<double, 2>>{
                 {0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}, {0, 2}}) {
            pts.push_back({x, y, z});
        }
    }
    for (const Point3& p : dyadic_grid_points(60, 5)) {
        if (p.x != 2 && p.y != 2) {  // off the walls and the split of the bottom
            pts.push_back(p);
        }
    }
    const Plc plc = make_plc(pts,
                             {{{6, 3, 4, 5}},
                              {{3, 6, 0, 1, 2}},
                              {{7, 8, 9, 10, 11, 12, 13}},
                              {{0, 1, 8, 7}},
                              {{1, 2, 9, 8}},
                              {{2, 3, 10, 9}},
                              {{3, 4, 11, 10}},
                              {{4, 5, 12, 11}},
                              {{5, 6, 13, 12}},
                              {{6, 0, 7, 13}}});
    const Cdt cdt = checked_cdt(plc, true);
    const CdtValidation scanned = validate_cdt(cdt.plc, cdt.tets, CdtDomain::kCarved);
    EXPECT_EQ(scanned.polygon_triangles, cdt.faces.size());
}

/// A flood that closes is not enough: its boundary must be the whole loop. The polygon here is two
/// triangles touching at a corner, listed as one loop through it; the mesh is the CDT of a PLC
/// with only the first triangle as a polygon and the second's sides as segments, plus a segment
/// through the second, so the flood from the first side covers the first triangle and stops, and
/// the second is crossed.
TEST(Cdt, OneLoopPolygonFloodMustReachEveryLoopSide) {
    auto pts = box_corners(4, 4, 0, 4);
    const double z = 2.03125;  // off the grid below
    const std::vector<Point3> lobes{
        {2, 2, z}, {3.5, 2, z}, {3.5, 3.5, z}, {0.5, 2, z}, {0.5, 0.5, z}};
    pts.insert(pts.end(), lobes.begin(), lobes.end());
    const auto inner = dyadic_grid_points(40, 7);
    pts.insert(pts.end(), inner.begin(), inner.end());
    pts.push_back({1.03125, 1.46875, 1});
    pts.push_back({1.03125, 1.46875, 3});
    const Plc plc = make_plc(pts, {{{8, 9, 10}}}, {{8, 11}, {11, 12}, {12, 8}, {53, 54}});
    const Cdt cdt = checked_cdt(plc, true);
    // The second triangle's sides as protection left them: the pieces of the segments, walked
    // round from corner 8 (either way) back to it.
    std::vector<std::uint32_t> second;
    std::uint32_t at = 8;
    std::uint32_t from = ~0u;
    for (std::size_t steps = 0; steps < cdt.plc.segments.size() && (second.empty() || at != 8);
         ++steps) {
        for (const auto& s : cdt.plc.segments) {
            const std::uint32_t other = s[0] == at ? s[1] : s[1] == at ? s[0] : at;
            if (other != at && other != from) {
                second.push_back(other);
                from = at;
                at = other;
                break;
            }
        }
    }
    ASSERT_EQ(at, 8u);
    Plc touching = cdt.plc;
    auto& loop = touching.facets[0].loops[0];
    std::rotate(loop.begin(), std::find(loop.begin(), loop.end(), 8u), loop.end());
    // Through 8 again, round the second triangle, and back to 8 (the loop's start: not listed).
    loop.push_back(8);
    loop.insert(loop.end(), second.begin(), second.end() - 1);
    ASSERT_TRUE(unprotected_edges(touching, cdt.tets).empty());
    const CdtValidation v = validate_cdt(touching, cdt.tets);
    EXPECT_FALSE(v.ok());
    EXPECT_TRUE(std::any_of(v.problems.begin(), v.problems.end(), [](const std::string& p) {
        return p.find(" crosses ") != std::string::npos;
    }));
}

/// The validator pairs the tetrahedra on each triangle once, for its own checks and for the
/// complex it glues; a list that is no complex is still refused in the complex builder's words:
/// a tetrahedron listed twice (each triangle then on two, so paired), and one listed twice among
/// others (an inner triangle then on three).
TEST(Cdt, ValidatorRefusesTetrahedraThatAreNoComplex) {
    const auto has = [](const CdtValidation& v, const std::string& what) {
        return std::any_of(v.problems.begin(), v.problems.end(), [&](const std::string& p) {
            return p.find(what) != std::string::npos;
        });
    };
    const Plc one = make_plc({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {});
    auto twice = delaunay(one);
    ASSERT_EQ(twice.size(), 1u);
    ASSERT_TRUE(validate_cdt(one, twice).ok());
    twice.push_back(twice[0]);
    EXPECT_TRUE(has(validate_cdt(one, twice), "is listed twice"));

    auto pts = box_corners(4, 4, 0, 4);
    pts.push_back({1.5, 2.5, 1.75});
    const Plc box = make_plc(pts, {});
    auto tets = delaunay(box);
    ASSERT_TRUE(validate_cdt(box, tets).ok());
    tets.push_back(tets[0]);
    EXPECT_TRUE(has(validate_cdt(box, tets), "has more than two tetrahedra"));
}

/// Schönhardt's polyhedron: a twisted triangular prism whose side quadrilaterals are cut along
/// their reflex diagonals. It has no tetrahedralization, hence no CDT without extra vertices.
TEST(Cdt, Schoenhardt) {
    const std::vector<Point3> pts{
        {4, 0, 0}, {-2, 3.5, 0}, {-2, -3.5, 0}, {3.5, 2, 4}, {-3.5, 2, 4}, {0, -4, 4}};
    Plc hull = make_plc(pts, {});
    // The convex diagonals are hull edges; the polyhedron takes the others.
    std::vector<std::vector<std::vector<std::uint32_t>>> facets{{{0, 1, 2}}, {{3, 4, 5}}};
    const auto tets = delaunay(hull);
    std::map<std::array<std::uint32_t, 2>, int> edges;
    for (const auto& t : tets) {
        for (std::size_t i = 0; i < 4; ++i) {
            for (std::size_t j = i + 1; j < 4; ++j) {
                edges[{std::min(t[i], t[j]), std::max(t[i], t[j])}] = 1;
            }
        }
    }
    for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = k;
        const std::uint32_t b = (k + 1) % 3;
        const std::uint32_t qa = 3 + k;
        const std::uint32_t qb = 3 + (k + 1) % 3;
        const bool ab_convex = edges.contains({std::min(a, qb), std::max(a, qb)}) &&
                               !edges.contains({std::min(b, qa), std::max(b, qa)});
        if (ab_convex) {
            facets.push_back({{a, b, qa}});
            facets.push_back({{b, qb, qa}});
        } else {
            facets.push_back({{a, b, qb}});
            facets.push_back({{a, qb, qa}});
        }
    }
    const Plc plc = make_plc(pts, facets);
    EXPECT_THROW(build_cdt(plc, CdtOptions{false}), Error);
    const Cdt cdt = checked_cdt(plc, true);
    EXPECT_FALSE(cdt.protection.inserted.empty());
}

/// Random PLCs: the hull triangles of a random subset, as polygons among random points.
TEST(Cdt, RandomHullFacePlcs) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        auto pts = dyadic_grid_points(10, 100 + seed);
        const Plc inner = make_plc(pts, {});
        const auto tets = delaunay(inner);
        std::map<std::array<std::uint32_t, 3>, int> count;
        for (const auto& t : tets) {
            for (int f = 0; f < 4; ++f) {
                auto g = facet_vertices(t, f);
                std::sort(g.begin(), g.end());
                ++count[{g[0], g[1], g[2]}];
            }
        }
        std::vector<std::vector<std::vector<std::uint32_t>>> facets;
        for (const auto& [g, c] : count) {
            if (c == 1) {
                facets.push_back({{g[0], g[1], g[2]}});
            }
        }
        const auto outer = dyadic_grid_points(30, 200 + seed);
        pts.insert(pts.end(), outer.begin(), outer.end());
        const Cdt cdt = checked_cdt(make_plc(pts, facets), true);
        EXPECT_EQ(cdt.plc.facets.size(), facets.size()) << "seed " << seed;
    }
}

}  // namespace
}  // namespace cavity::core
