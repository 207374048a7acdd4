// Surface meshes that bound no solid are refused before meshing, naming their facets: open and
// non-manifold edges, degenerate facets and facets meeting improperly, the last by exact orient3d
// signs (triangle_intersection.h).
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/cdt/read_plc.h"
#include "cavity/core/cdt/surface_validity.h"
#include "cavity/core/io/surface_mesh.h"
#include "cavity/predicates/orient3d.h"
#include "plc_builders.h"
#include "temp_dir.h"
// White-box: the triangle tests are internal to the core.
#include "../../../core/cdt/src/ear_clipping.h"
#include "../../../core/cdt/src/triangle_intersection.h"
#include "../../../core/cdt/src/warped_facets.h"

namespace cavity::core {
namespace {

using test::Loops;
using test::make_plc;

/// The L-shaped prism: the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) at z = 0 (points 0-5) and z = 1
/// (6-11), as 20 outward triangles: bottom 0-3, top 4-7, sides 8-19 (two per side).
Plc l_prism(std::vector<Loops> extra = {}) {
    const double l[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    std::vector<Point3> pts;
    for (const double z : {0.0, 1.0}) {
        for (const auto& p : l) {
            pts.push_back({p[0], p[1], z});
        }
    }
    std::vector<Loops> facets = {{{0, 2, 1}},
                                 {{0, 3, 2}},
                                 {{0, 4, 3}},
                                 {{0, 5, 4}},
                                 {{6, 7, 8}},
                                 {{6, 8, 9}},
                                 {{6, 9, 10}},
                                 {{6, 10, 11}}};
    for (std::uint32_t i = 0; i < 6; ++i) {
        const std::uint32_t j = (i + 1) % 6;
        facets.push_back({{i, j, 6 + j}});
        facets.push_back({{i, 6 + j, 6 + i}});
    }
    for (auto& f : extra) {
        facets.push_back(std::move(f));
    }
    return make_plc(std::move(pts), std::move(facets));
}

TEST(SurfaceValidity, AClosedNonConvexSolidHasNoDefects) {
    const SurfaceDefects d = surface_defects(l_prism());
    EXPECT_TRUE(d.empty()) << describe_defects(l_prism(), d, 10);
}

TEST(SurfaceValidity, OpenEdgesNameTheirOnlyFacet) {
    Plc plc = l_prism();
    plc.facets.erase(plc.facets.begin() + 8);  // the side triangle 0 1 7
    const SurfaceDefects d = surface_defects(plc);
    ASSERT_EQ(d.open_edges.size(), 3u);
    EXPECT_TRUE(d.non_manifold_edges.empty());
    EXPECT_TRUE(d.degenerate.empty());
    EXPECT_TRUE(d.intersecting.empty());
    // Edge 0-1 is left to bottom triangle 0, edge 0-7 to side triangle 8 (formerly 9).
    EXPECT_EQ(d.open_edges[0].edge, (std::array<std::uint32_t, 2>{0, 1}));
    EXPECT_EQ(d.open_edges[0].facets, (std::vector<std::size_t>{0}));
    EXPECT_EQ(d.open_edges[1].edge, (std::array<std::uint32_t, 2>{0, 7}));
    EXPECT_EQ(d.open_edges[1].facets, (std::vector<std::size_t>{8}));
    const std::string text = describe_defects(plc, d, 10);
    EXPECT_NE(text.find("3 open edges"), std::string::npos) << text;
    EXPECT_NE(text.find("edge 0-1: only facet 0"), std::string::npos) << text;
}

TEST(SurfaceValidity, NonManifoldEdgesNameEveryFacet) {
    // Two tetrahedra sharing edge 0-1 and nothing else.
    const Plc plc = make_plc({{0, 0, 0}, {1, 0, 0}, {0, 1, 1}, {0, 1, 2}, {0, -1, 1}, {0, -1, 2}},
                             {{{0, 1, 2}},
                              {{0, 1, 3}},
                              {{0, 2, 3}},
                              {{1, 2, 3}},
                              {{0, 1, 4}},
                              {{0, 1, 5}},
                              {{0, 4, 5}},
                              {{1, 4, 5}}});
    const SurfaceDefects d = surface_defects(plc);
    EXPECT_TRUE(d.open_edges.empty());
    ASSERT_EQ(d.non_manifold_edges.size(), 1u);
    EXPECT_EQ(d.non_manifold_edges[0].facets, (std::vector<std::size_t>{0, 1, 4, 5}));
    EXPECT_TRUE(d.intersecting.empty()) << describe_defects(plc, d, 10);
    EXPECT_NE(describe_defects(plc, d, 10).find("edge 0-1: 4 facets, facet 0, facet 1, facet 4"),
              std::string::npos);
}

TEST(SurfaceValidity, DegenerateFacetsSayWhy) {
    Plc plc = l_prism({{{0, 1, 1}}, {{0, 12, 1}}, {{0, 1, 2, 13}}, {{0, 14, 1}}});
    plc.points.points.push_back({1, 0, 0});      // 12: inside edge 0-1, collinear
    plc.points.points.push_back({0.5, 0.5, 1});  // 13: off the plane of 0 1 2
    plc.points.points.push_back({2, 0, 0});      // 14: a second point where point 1 is
    const SurfaceDefects d = surface_defects(plc);
    ASSERT_EQ(d.degenerate.size(), 4u);
    EXPECT_EQ(d.degenerate[0].facet, 20u);
    EXPECT_EQ(d.degenerate[0].why, "corner 1 is listed twice");
    EXPECT_EQ(d.degenerate[1].why, "its corners are collinear (zero area)");
    EXPECT_EQ(d.degenerate[2].why, "corner 13 is not in the plane of the others");
    EXPECT_EQ(d.degenerate[3].why, "corners 14 and 1 are the same point");
}

TEST(SurfaceValidity, CoincidentCornersAreNamedNotMerged) {
    // Bottom triangle 0 uses point 12, a copy of point 0 (with -0.0 for 0.0): the surface is open
    // along 0-1 and 0-2 by index, and the message says why.
    Plc plc = l_prism();
    plc.points.points.push_back({-0.0, 0, -0.0});
    plc.facets[0].loops[0][0] = 12;
    const SurfaceDefects d = surface_defects(plc);
    EXPECT_EQ(d.coincident_points, (std::vector<std::array<std::uint32_t, 2>>{{0, 12}}));
    EXPECT_FALSE(d.open_edges.empty());
    const std::string text = describe_defects(plc, d, 10);
    EXPECT_NE(text.find("1 pairs of facet corners at the same coordinates"), std::string::npos)
        << text;
    EXPECT_NE(text.find("points 0 and 12"), std::string::npos) << text;
    // An unreferenced copy is no corner: left to the CDT, which refuses coincident points.
    Plc spare = l_prism();
    spare.points.points.push_back({0, 0, 0});
    EXPECT_TRUE(surface_defects(spare).empty());
}

/// The pairs of facets reported as intersecting.
std::vector<std::array<std::size_t, 2>> intersecting(const Plc& plc) {
    return surface_defects(plc).intersecting;
}

TEST(SurfaceValidity, FacetsMeetingImproperlyAreNamedInPairs) {
    // A triangle from outside the L into it through the side x = 0, below that side's diagonal:
    // it crosses side triangle 18 only.
    Plc plc = l_prism({{{12, 13, 14}}});
    plc.points.points.push_back({-1, 0.5, 0.5});
    plc.points.points.push_back({0.5, 0.5, 0.25});
    plc.points.points.push_back({0.5, 0.6, 0.75});
    EXPECT_EQ(intersecting(plc), (std::vector<std::array<std::size_t, 2>>{{18, 20}}));
    // The same triangle twice.
    Plc twice = l_prism({{{0, 2, 1}}});
    EXPECT_EQ(intersecting(twice), (std::vector<std::array<std::size_t, 2>>{{0, 20}}));
}

TEST(SurfaceValidity, PolygonsAreTestedByTheirEars) {
    // The unit square at z = 0.5 around the L's corner (0, 0): it crosses the side y = 0 above its
    // diagonal (triangle 9) and the side x = 0 below its diagonal (triangle 18).
    Plc plc = l_prism({{{12, 13, 14, 15}}});
    for (const auto& [x, y] : {std::pair{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}) {
        plc.points.points.push_back({x, y, 0.5});
    }
    EXPECT_EQ(intersecting(plc), (std::vector<std::array<std::size_t, 2>>{{9, 20}, {18, 20}}));
    // Made non-convex, with corner 14 pulled in to (-0.25, -0.25), it stays out of the L, though
    // its convex hull (and the fan from corner 13) touches the L's edge x = y = 0.
    plc.points.points[14] = {-0.25, -0.25, 0.5};
    EXPECT_TRUE(intersecting(plc).empty());
    // Below y = 0 with a reflex corner at (0.25, -0.25): apart; that corner moved to (0.25, 0.25),
    // the polygon reaches into the L through both sides again.
    plc.points.points[14] = {0.25, -0.25, 0.5};
    plc.points.points[15] = {-0.5, -0.25, 0.5};
    EXPECT_TRUE(intersecting(plc).empty());
    plc.points.points[14] = {0.25, 0.25, 0.5};
    EXPECT_EQ(intersecting(plc), (std::vector<std::array<std::size_t, 2>>{{9, 20}, {18, 20}}));
}

TEST(SurfaceValidity, ASelfCrossingLoopIsDegenerate) {
    // A bow tie: its sides 12-13 and 14-15 cross.
    Plc plc = l_prism({{{12, 13, 14, 15}}});
    for (const auto& [x, y] : {std::pair{5.0, 5.0}, {6.0, 6.0}, {6.0, 5.0}, {5.0, 6.0}}) {
        plc.points.points.push_back({x, y, 0.5});
    }
    const SurfaceDefects d = surface_defects(plc);
    ASSERT_EQ(d.degenerate.size(), 1u);
    EXPECT_EQ(d.degenerate[0].facet, 20u);
    EXPECT_EQ(d.degenerate[0].why, "its loop is not a simple polygon (no ear to clip)");
}

TEST(SurfaceValidity, MessageCountsAndBoundsEachKind) {
    Plc plc = l_prism();
    plc.facets.resize(8);  // bottom and top only: every side edge of the L is open
    plc.source = "l.off";
    try {
        require_valid_surface(plc);
        FAIL() << "an open surface was accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.rfind("l.off: the surface mesh does not bound a solid", 0), 0u) << m;
        EXPECT_NE(m.find("12 open edges"), std::string::npos) << m;
        EXPECT_NE(m.find("and 2 more"), std::string::npos) << m;
    }
}

TEST(SurfaceValidity, ReadPlcChecksSurfacesButNotPoly) {
    test::TempDir dir;
    // The L-prism without its last side triangle, as OFF: refused naming facet and line.
    const Plc l = l_prism();
    std::string off = "OFF\n12 19 0\n";
    for (const Point3& p : l.points.points) {
        off += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
    }
    for (std::size_t f = 0; f < 19; ++f) {
        const auto& c = l.facets[f].loops[0];
        off += "3 " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " +
               std::to_string(c[2]) + "\n";
    }
    try {
        read_plc(dir.write("open.off", off));
        FAIL() << "an open OFF surface was accepted";
    } catch (const Error& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("open.off: "), std::string::npos) << m;
        EXPECT_NE(m.find("edge 5-6: only facet 18 (line 33)"), std::string::npos) << m;
    }
    // The same single triangle as a .poly is a valid (dangling) facet.
    const Plc poly =
        read_plc(dir.write("one.poly", "3 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n1 0\n1\n3 0 1 2\n"));
    EXPECT_EQ(poly.facets.size(), 1u);
}

// --- warped faces ---------------------------------------------------------------------------

/// The unit cube as OFF with six quads, outward; corner 6 (1,1,1) moved to (1,1,1+dz) and corner
/// 2's x to 1+dx. Face k is on line 11 + k.
std::string warped_cube_off(const std::string& dz, const std::string& dx) {
    return "OFF\n8 6 0\n0 0 0\n1 0 0\n" + dx + " 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 " + dz +
           "\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
}

TEST(WarpedFacets, NonCoplanarFacesAreReadAsTheirTriangles) {
    test::TempDir dir;
    // 2^-40 off the plane: a rounded quad, as CAD exports have them. Of the faces at corner 6, the
    // top (1) is warped; the right and back ones (x = 1, y = 1) stay planar, as do the others.
    SurfaceReading reading;
    const Plc plc =
        read_plc(dir.write("warped.off", warped_cube_off("1.0000000000009095", "1")), &reading);
    EXPECT_EQ(reading.warped_faces, 1u);
    EXPECT_EQ(reading.merged_faces, 0u);
    ASSERT_EQ(plc.facets.size(), 7u);
    std::size_t quads = 0;
    for (const PlcFacet& f : plc.facets) {
        ASSERT_EQ(f.loops.size(), 1u);
        quads += f.loops[0].size() == 4 ? 1 : 0;
        // Every piece is planar and keeps the face's number and line.
        ASSERT_TRUE(f.number);
        EXPECT_EQ(f.line, 11 + *f.number);
    }
    EXPECT_EQ(quads, 5u);
    EXPECT_TRUE(surface_defects(plc).empty());
    // The pieces of face 1 cover it: same corners, each triangle turning the face's way.
    std::vector<std::uint32_t> corners;
    for (const PlcFacet& f : plc.facets) {
        if (f.number == 1) {
            corners.insert(corners.end(), f.loops[0].begin(), f.loops[0].end());
            const auto& p = plc.points.points;
            const auto& t = f.loops[0];
            EXPECT_GT((p[t[1]].x - p[t[0]].x) * (p[t[2]].y - p[t[0]].y) -
                          (p[t[1]].y - p[t[0]].y) * (p[t[2]].x - p[t[0]].x),
                      0);
        }
    }
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    EXPECT_EQ(corners, (std::vector<std::uint32_t>{4, 5, 6, 7}));
    // A planar cube is left alone.
    const Plc flat = read_plc(dir.write("flat.off", warped_cube_off("1", "1")), &reading);
    EXPECT_EQ(reading.warped_faces, 0u);
    EXPECT_EQ(flat.facets.size(), 6u);
}

TEST(WarpedFacets, AFaceWithNoSimpleProjectionIsStillRefused) {
    test::TempDir dir;
    // Corner 2 pulled across the bottom face (x = -1, far below the others' plane too): the bottom
    // quad 0 3 2 1 folds over itself in every projection and is named, not cut.
    Plc plc = read_surface_mesh(dir.write("folded.off", warped_cube_off("1", "-1")));
    plc.points.points[2].z = -0.5;
    split_warped_facets(plc);
    const SurfaceDefects d = surface_defects(plc);
    ASSERT_FALSE(d.degenerate.empty()) << describe_defects(plc, d, 10);
    EXPECT_EQ(d.degenerate[0].facet, 0u);
    EXPECT_NE(d.degenerate[0].why.find("not in the plane"), std::string::npos);
}

// --- ear clipping ---------------------------------------------------------------------------

/// Twice the area of triangle abc in the plane z = 0, signed (exact for these small integers).
double area2(const std::vector<Point3>& p, const Triangle& t) {
    const Point3& a = p[t[0]];
    const Point3& b = p[t[1]];
    const Point3& c = p[t[2]];
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

TEST(EarClipping, SimplePolygonsGiveTriangulationsOfTheirArea) {
    // A comb (reflex corners), with collinear corners on its base, in both orientations.
    std::vector<Point3> pts = {{0, 0, 0},
                               {2, 0, 0},
                               {4, 0, 0},
                               {6, 0, 0},
                               {6, 4, 0},
                               {5, 4, 0},
                               {5, 1, 0},
                               {4, 1, 0},
                               {4, 4, 0},
                               {1, 4, 0},
                               {1, 1, 0},
                               {0, 1, 0}};
    std::vector<std::uint32_t> loop(pts.size());
    std::iota(loop.begin(), loop.end(), 0u);
    for (const bool reversed : {false, true}) {
        if (reversed) {
            std::reverse(loop.begin(), loop.end());
        }
        const auto ears = ear_clipping(pts, loop, 2);
        ASSERT_TRUE(ears.has_value());
        EXPECT_EQ(ears->size(), loop.size() - 2);
        double total = 0;
        for (const Triangle& t : *ears) {
            const double a = area2(pts, t);
            EXPECT_NE(a, 0.0);
            EXPECT_EQ(a > 0, !reversed);  // every triangle turns the loop's way
            total += a;
        }
        EXPECT_EQ(std::abs(total), 2 * (6 * 1 + 1 * 3 + 3 * 3));
    }
    // A self-crossing loop (sides 0-4 and 3-9 cross) has no triangulation by its corners.
    EXPECT_FALSE(ear_clipping(pts, {0, 4, 3, 9}, 2).has_value());
}

// --- the triangle tests -------------------------------------------------------------------

bool meet(std::vector<Point3> pts, Triangle s, Triangle t) {
    return triangles_meet_improperly(pts, s, t);
}

TEST(TriangleIntersection, EachSharingCase) {
    // s = 0 1 2 in the plane z = 0.
    const std::vector<Point3> base = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
    const auto with = [&](std::vector<Point3> more) {
        auto pts = base;
        pts.insert(pts.end(), more.begin(), more.end());
        return pts;
    };
    // No corner shared: crossing, apart, a corner touching the interior, coplanar overlap.
    EXPECT_TRUE(meet(with({{1, 1, -1}, {1, 1, 1}, {5, 5, 1}}), {0, 1, 2}, {3, 4, 5}));
    EXPECT_FALSE(meet(with({{1, 1, 1}, {2, 1, 1}, {1, 2, 3}}), {0, 1, 2}, {3, 4, 5}));
    EXPECT_TRUE(meet(with({{1, 1, 0}, {1, 1, 1}, {2, 1, 1}}), {0, 1, 2}, {3, 4, 5}));
    EXPECT_TRUE(meet(with({{1, 1, 0}, {6, 1, 0}, {1, 6, 0}}), {0, 1, 2}, {3, 4, 5}));
    EXPECT_FALSE(meet(with({{3, 3, 0}, {6, 1, 0}, {1, 6, 0}}), {0, 1, 2}, {3, 4, 5}));
    // One corner shared: apart, the opposite side crossing, coplanar wedges overlapping or not.
    EXPECT_FALSE(meet(with({{0, -4, 1}, {-4, 0, 1}}), {0, 1, 2}, {0, 3, 4}));
    EXPECT_TRUE(meet(with({{1, 1, -1}, {1, 1, 1}}), {0, 1, 2}, {0, 3, 4}));
    EXPECT_TRUE(meet(with({{4, 4, 0}, {8, 1, 0}}), {0, 1, 2}, {0, 3, 4}));
    EXPECT_FALSE(meet(with({{0, -4, 0}, {-4, 0, 0}}), {0, 1, 2}, {0, 3, 4}));
    // Two corners shared: a fold, coplanar on the other side, coplanar on the same side.
    EXPECT_FALSE(meet(with({{1, 1, 3}}), {0, 1, 2}, {0, 1, 3}));
    EXPECT_FALSE(meet(with({{1, -1, 0}}), {0, 1, 2}, {0, 1, 3}));
    EXPECT_TRUE(meet(with({{1, 1, 0}}), {0, 1, 2}, {1, 0, 3}));
    // All three: the same triangle twice.
    EXPECT_TRUE(meet(base, {0, 1, 2}, {2, 0, 1}));
}

TEST(TriangleIntersection, TheProjectionAxisKeepsEveryTriangleATriangle) {
    // Axis-parallel planes (two projections degenerate), tilted ones, and a sliver whose normal
    // estimate is dominated by rounding: the axis returned always projects the triangle onto a
    // triangle (exact orientation not zero).
    const std::vector<std::array<Point3, 3>> triangles = {
        {{{0, 0, 5}, {3, 0, 5}, {0, 2, 5}}},
        {{{1, 7, 0}, {1, 7, 3}, {4, 7, 1}}},
        {{{2, 0, 0}, {2, 5, 1}, {2, 1, 4}}},
        {{{0, 0, 0}, {1, 1, 1}, {1, 0, 2}}},
        {{{0.1, 0.2, 0.3}, {0.1 + 0x1p-50, 0.2, 0.3}, {0.1, 0.2 + 0x1p-50, 0.3 + 0x1p-52}}},
    };
    for (const auto& [a, b, c] : triangles) {
        ASSERT_FALSE(is_degenerate_triangle(a, b, c));
        const int drop = projection_axis(a, b, c);
        EXPECT_NE(orient2d_projected(a, b, c, drop), 0) << "drop " << drop;
    }
    // Random small-integer triangles, mostly near axis-parallel.
    Random random(21);
    for (int trial = 0; trial < 2000; ++trial) {
        std::array<Point3, 3> t;
        for (Point3& p : t) {
            p = {static_cast<double>(random.below(3)),
                 static_cast<double>(random.below(3)),
                 static_cast<double>(random.below(2))};
        }
        if (is_degenerate_triangle(t[0], t[1], t[2])) {
            continue;
        }
        EXPECT_NE(orient2d_projected(t[0], t[1], t[2], projection_axis(t[0], t[1], t[2])), 0);
    }
}

TEST(TriangleIntersection, ExactWithinAnUlpOfAPlane) {
    // s spans the plane x + y + z = 0.3 (in the doubles as given); t rises from a corner p near
    // (0.1, 0.1, 0.1), which the doubles put a few ulps off that plane. t meets s exactly when p
    // is not strictly above the plane (on t's upper side): walking p's z across the plane one ulp
    // at a time, the answer follows the exact side, with both answers met and no tolerance band.
    const Point3 a{0.3, 0, 0};
    const Point3 b{0, 0.3, 0};
    const Point3 c{0, 0, 0.3};
    const Point3 up{0.1, 0.1, 1};
    std::vector<Point3> pts = {a, b, c, {0.1, 0.1, 0.1}, up, {0.2, 0.1, 1}};
    for (int k = 0; k < 8; ++k) {
        pts[3].z = std::nextafter(pts[3].z, -1.0);
    }
    bool seen[2] = {false, false};
    for (int k = 0; k < 16; ++k) {
        const bool above =
            predicates::orient3d(a, b, c, pts[3]) == predicates::orient3d(a, b, c, up);
        const bool r = meet(pts, {0, 1, 2}, {3, 4, 5});
        EXPECT_EQ(r, !above) << "z = " << pts[3].z;
        seen[r ? 1 : 0] = true;
        pts[3].z = std::nextafter(pts[3].z, 1.0);
    }
    EXPECT_TRUE(seen[0] && seen[1]);
}

TEST(TriangleIntersection, SymmetricUnderSwapsAndCornerOrder) {
    // Small integer coordinates make coplanar, collinear and touching cases common.
    Random random(15);
    int met = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        std::vector<Point3> pts;
        for (int i = 0; i < 6; ++i) {
            pts.push_back({static_cast<double>(random.below(4)),
                           static_cast<double>(random.below(4)),
                           static_cast<double>(random.below(3))});
        }
        // Share corners by index in a third of the trials.
        Triangle s{0, 1, 2};
        Triangle t{3, 4, 5};
        if (trial % 3 == 1) {
            t[0] = 0;
        } else if (trial % 3 == 2) {
            t[0] = 0;
            t[1] = 1;
        }
        if (is_degenerate_triangle(pts[s[0]], pts[s[1]], pts[s[2]]) ||
            is_degenerate_triangle(pts[t[0]], pts[t[1]], pts[t[2]])) {
            continue;
        }
        const bool r = meet(pts, s, t);
        met += r ? 1 : 0;
        EXPECT_EQ(meet(pts, t, s), r);
        EXPECT_EQ(meet(pts, {s[1], s[2], s[0]}, {t[2], t[1], t[0]}), r);
        EXPECT_EQ(meet(pts, {s[2], s[1], s[0]}, {t[1], t[2], t[0]}), r);
    }
    EXPECT_GT(met, 100);
}

// The definition, side by side: two triangles sharing at most one corner meet improperly when a
// side of one meets the other anywhere but at that corner. Written from segment_meets_triangle
// alone, with no coplanar shortcut, as the reference the shortcuts are checked against.
bool meet_by_sides(const std::vector<Point3>& pts, const Triangle& s, const Triangle& t) {
    std::vector<std::uint32_t> shared;
    std::vector<std::uint32_t> s_own;
    std::vector<std::uint32_t> t_own;
    for (const std::uint32_t v : s) {
        (std::find(t.begin(), t.end(), v) != t.end() ? shared : s_own).push_back(v);
    }
    for (const std::uint32_t v : t) {
        if (std::find(s.begin(), s.end(), v) == s.end()) {
            t_own.push_back(v);
        }
    }
    const auto side_meets = [&](std::uint32_t p, std::uint32_t q, const Triangle& other) {
        return segment_meets_triangle(pts[p], pts[q], pts[other[0]], pts[other[1]], pts[other[2]]);
    };
    switch (shared.size()) {
        case 1:
            return side_meets(s_own[0], s_own[1], t) || side_meets(t_own[0], t_own[1], s);
        case 0:
            return side_meets(s[0], s[1], t) || side_meets(s[1], s[2], t) ||
                   side_meets(s[2], s[0], t) || side_meets(t[0], t[1], s) ||
                   side_meets(t[1], t[2], s) || side_meets(t[2], t[0], s);
        default:
            ADD_FAILURE() << "only triangles sharing at most one corner are compared";
            return false;
    }
}

TEST(TriangleIntersection, CoplanarShortcutsAgreeWithTheSideTests) {
    // Points of one tilted plane (z = x - 2y + 1/2 on a half-unit grid, so the coordinates are
    // fractional and every orient3d among them is an exact zero) and a few just off it: coplanar
    // triangles overlapping, touching at corners and along sides, nested and apart, with no corner
    // and with one corner shared by index, against the definition by side tests.
    Random random(33);
    std::array<int, 2> met{};
    std::array<int, 2> apart{};
    for (int trial = 0; trial < 20000; ++trial) {
        std::vector<Point3> pts;
        for (int i = 0; i < 6; ++i) {
            const double x = 0.5 * static_cast<double>(random.below(5));
            const double y = 0.5 * static_cast<double>(random.below(5));
            const double lift = random.below(8) == 0 ? 0.5 : 0.0;
            pts.push_back({x, y, x - 2 * y + 0.5 + lift});
        }
        Triangle s{0, 1, 2};
        Triangle t{3, 4, 5};
        const std::size_t shared = trial % 2;
        if (shared == 1) {
            t[random.below(3)] = s[random.below(3)];
        }
        if (is_degenerate_triangle(pts[s[0]], pts[s[1]], pts[s[2]]) ||
            is_degenerate_triangle(pts[t[0]], pts[t[1]], pts[t[2]])) {
            continue;
        }
        const bool r = meet(pts, s, t);
        ASSERT_EQ(r, meet_by_sides(pts, s, t)) << "trial " << trial;
        ++(r ? met : apart)[shared];
    }
    // Both answers, with and without a shared corner.
    EXPECT_GT(met[0], 1000);
    EXPECT_GT(met[1], 1000);
    EXPECT_GT(apart[0], 500);
    EXPECT_GT(apart[1], 500);
}

}  // namespace
}  // namespace cavity::core
