// Vertex insertion into a CDT (Cheng, Dey & Shewchuk §5.7). Under cavity's perturbation the CDT
// of a PLC is unique, so inserting v must give exactly the tetrahedra build_cdt makes from scratch
// for the PLC with v appended (and its edges split where v lies on them); a refused vertex must
// leave everything as it was.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "canonical.h"
#include "cavity/core/base/error.h"
#include "cavity/core/base/random.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/cdt_vertex_insertion.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/io/write_poly.h"
#include "plc_builders.h"

namespace cavity::core {
namespace {

using test::box_corners;
using test::dyadic_grid_points;
using test::Loops;
using test::make_plc;

/// The six faces of a box made by box_corners starting at point `b`.
std::vector<Loops> box_faces(std::uint32_t b) {
    return {{{b, b + 3, b + 2, b + 1}},
            {{b + 4, b + 5, b + 6, b + 7}},
            {{b, b + 1, b + 5, b + 4}},
            {{b + 1, b + 2, b + 6, b + 5}},
            {{b + 2, b + 3, b + 7, b + 6}},
            {{b + 3, b, b + 4, b + 7}}};
}

Point3 random_point(Random& random, double lo, double hi) {
    return {random.uniform(lo, hi), random.uniform(lo, hi), random.uniform(lo, hi)};
}

/// A cube [0,4]^3 whose top, bottom and a middle square are polygons, with grid points inside.
Plc cube_with_middle_square() {
    auto pts = box_corners(4, 4, 0, 4);
    const std::vector<Point3> mid{
        {0, 0, 2.03125}, {4, 0, 2.03125}, {4, 4, 2.03125}, {0, 4, 2.03125}};
    pts.insert(pts.end(), mid.begin(), mid.end());
    const auto inner = dyadic_grid_points(40, 7);
    pts.insert(pts.end(), inner.begin(), inner.end());
    return make_plc(pts, {{{0, 1, 2, 3}}, {{4, 5, 6, 7}}, {{8, 9, 10, 11}}});
}

/// A closed box: its six faces are polygons (the hull is constrained), with grid points inside.
Plc closed_box() {
    auto pts = box_corners(4, 4, 0, 4);
    const auto inner = dyadic_grid_points(25, 5);
    pts.insert(pts.end(), inner.begin(), inner.end());
    return make_plc(pts, box_faces(0));
}

using Face = std::array<std::uint32_t, 4>;  // sorted corners, then the marker

std::vector<Face> canonical_faces(const std::vector<CdtFace>& faces) {
    std::vector<Face> out;
    for (const auto& f : faces) {
        std::array<std::uint32_t, 3> v = f.v;
        std::sort(v.begin(), v.end());
        out.push_back({v[0], v[1], v[2], static_cast<std::uint32_t>(f.marker)});
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Everything a refusal must leave unchanged.
struct State {
    std::vector<std::array<std::uint32_t, 4>> tets;
    std::vector<Face> faces;
    std::size_t points;
    std::vector<std::uint32_t> edges;
    bool operator==(const State&) const = default;
};

State state_of(const LiveCdt& live) {
    State s{
        test::canonical(live.tets()), canonical_faces(live.faces()), live.plc().points.size(), {}};
    for (const auto& e : plc_edges(live.plc())) {
        s.edges.push_back(e[0]);
        s.edges.push_back(e[1]);
    }
    return s;
}

/// Checks the live CDT from outside, then against build_cdt run on its PLC. Returns false when
/// the rebuild is impossible because the augmented PLC is not edge-protected (the flip-based
/// construction cannot start; the insertion can still be right, and validate() checked it).
bool matches_rebuild(const LiveCdt& live) {
    EXPECT_NO_THROW(live.validate());
    EXPECT_TRUE(check_complex(live.storage(), live.geometry()).empty());
    Cdt rebuilt;
    try {
        rebuilt = build_cdt(live.plc(), CdtOptions{false});
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("not edge-protected"), std::string::npos) << e.what();
        return false;
    }
    EXPECT_EQ(test::canonical(live.tets()), test::canonical(rebuilt.tets));
    EXPECT_EQ(canonical_faces(live.faces()), canonical_faces(rebuilt.faces));
    return true;
}

/// Inserts p, which must be accepted, and compares with the rebuild.
std::uint32_t insert_and_compare(LiveCdt& live, const Point3& p) {
    const std::size_t n = live.plc().points.size();
    const CdtInsertion r = live.insert_vertex(p);
    EXPECT_TRUE(r.inserted()) << r.message;
    EXPECT_EQ(r.vertex, n);
    EXPECT_TRUE(matches_rebuild(live));
    return r.vertex;
}

TEST(CdtVertexInsertion, InteriorPointsMatchRebuild) {
    LiveCdt live(cube_with_middle_square(), CdtOptions{true});
    Random random(11);
    std::size_t inserted = 0;
    std::size_t compared = 0;
    for (int i = 0; i < 40; ++i) {
        const State before = state_of(live);
        const CdtInsertion r = live.insert_vertex(random_point(random, 0.05, 3.95));
        if (!r.inserted()) {
            EXPECT_NE(r.status, CdtInsertionStatus::kDuplicate);
            EXPECT_EQ(state_of(live), before) << r.message;
            continue;
        }
        ++inserted;
        compared += matches_rebuild(live) ? 1 : 0;
    }
    EXPECT_GE(inserted, 30u);
    EXPECT_GE(compared, 20u);
    EXPECT_EQ(live.counters().inserted, inserted);
    EXPECT_EQ(live.inserted().size(), inserted);
    EXPECT_GT(live.counters().tets_deleted, 0u);
    EXPECT_GT(live.counters().tets_created, live.counters().tets_deleted);
    EXPECT_GE(live.counters().conflict_tests, live.counters().tets_deleted);
    EXPECT_GT(live.counters().face_tests, 0u);
}

/// Inserts each point; an accepted one must match the rebuild, a refused one change nothing.
/// Returns how many were accepted.
std::size_t insert_all(LiveCdt& live, const std::vector<Point3>& points) {
    std::size_t accepted = 0;
    for (const Point3& p : points) {
        const State before = state_of(live);
        const CdtInsertion r = live.insert_vertex(p);
        if (r.inserted()) {
            ++accepted;
            matches_rebuild(live);
        } else {
            EXPECT_EQ(state_of(live), before) << r.message;
        }
    }
    return accepted;
}

/// A convex polytope whose hull triangles are polygons (no four cocircular corners), with points
/// inside.
Plc closed_polytope() {
    Random random(17);
    std::vector<Point3> pts;
    for (int i = 0; i < 12; ++i) {
        // Points near a sphere of radius 4 around (2, 2, 2), on a binary grid.
        const double t = random.uniform(0, 6.283185307179586);
        const double z = random.uniform(-1, 1);
        const double r = std::sqrt(1 - z * z);
        pts.push_back({std::round(64 * (2 + 4 * r * std::cos(t))) / 64,
                       std::round(64 * (2 + 4 * r * std::sin(t))) / 64,
                       std::round(64 * (2 + 4 * z)) / 64});
    }
    const Plc hull = make_plc(pts, {});
    const auto tets = test::triangulate_in_input_order(hull.points).tets;
    std::map<std::array<std::uint32_t, 3>, int> count;
    for (const auto& t : tets) {
        for (int f = 0; f < 4; ++f) {
            auto g = facet_vertices(t, f);
            std::sort(g.begin(), g.end());
            ++count[{g[0], g[1], g[2]}];
        }
    }
    std::vector<Loops> facets;
    for (const auto& [g, c] : count) {
        if (c == 1) {
            facets.push_back({{g[0], g[1], g[2]}});
        }
    }
    for (const Point3& p : dyadic_grid_points(20, 23)) {
        pts.push_back({p.x / 2 + 1, p.y / 2 + 1, p.z / 2 + 1});
    }
    return make_plc(pts, facets);
}

TEST(CdtVertexInsertion, OutsideTheHull) {
    const std::vector<Point3> outside{{9, 2, 2},
                                      {-4, -3, -1},
                                      {2, 2, 9},
                                      {100, 50, -30},
                                      {7.5, 7.5, 2},
                                      {2, -4.5, 1},
                                      {-5, 2, 2.5},
                                      {8, 8, 8},
                                      {2.5, 2.5, -5},
                                      {-9, -9, 9}};
    // The hull triangles are polygons: the outer points see them but cannot dig through them.
    LiveCdt closed(closed_polytope(), CdtOptions{true});
    EXPECT_GE(insert_all(closed, outside), 7u);
    EXPECT_GT(closed.counters().ghosts_deleted, 0u);
    EXPECT_GT(closed.counters().ghosts_created, 0u);
    // Without polygons on the hull, outer points dig into the solid tetrahedra too.
    LiveCdt open(cube_with_middle_square(), CdtOptions{true});
    EXPECT_GE(insert_all(open, outside), 5u);
}

TEST(CdtVertexInsertion, OnAPolygon) {
    LiveCdt live(cube_with_middle_square(), CdtOptions{true});
    const std::size_t faces = live.faces().size();
    // Inside the middle square (a polygon crossing the cube), then inside the top square (a
    // polygon on the hull).
    insert_and_compare(live, {1.3, 2.7, 2.03125});
    EXPECT_EQ(live.counters().on_polygon, 1u);
    EXPECT_EQ(live.faces().size(), faces + 2);  // one or two triangles split into three or four
    insert_and_compare(live, {2.6, 1.1, 4});
    insert_and_compare(live, {0.7, 0.9, 0});
    EXPECT_EQ(live.counters().on_polygon, 3u);
    EXPECT_EQ(live.counters().on_plc_edge, 0u);
    // The new triangles keep their polygon's marker.
    for (const CdtFace& f : live.faces()) {
        for (std::uint32_t v : f.v) {
            if (v == live.inserted()[0]) {
                EXPECT_EQ(f.marker, 3);
            }
        }
    }
}

TEST(CdtVertexInsertion, OnAPolygonEdgeAndASegment) {
    auto plc = cube_with_middle_square();
    // A short dangling segment inside the cube (short enough not to need protection).
    const auto a = static_cast<std::uint32_t>(plc.points.size());
    plc.points.points.push_back({1, 1, 0.5});
    plc.points.points.push_back({1.375, 1.375, 0.6875});
    plc.segments.push_back({a, a + 1});
    LiveCdt live(std::move(plc), CdtOptions{true});
    // A third of the way along, exactly on it.
    const std::uint32_t m = insert_and_compare(live, {1.125, 1.125, 0.5625});
    EXPECT_EQ(live.counters().on_plc_edge, 1u);
    const auto edges = plc_edges(live.plc());
    EXPECT_TRUE(std::binary_search(edges.begin(), edges.end(), std::array<std::uint32_t, 2>{a, m}));
    EXPECT_TRUE(
        std::binary_search(edges.begin(), edges.end(), std::array<std::uint32_t, 2>{a + 1, m}));
    EXPECT_FALSE(
        std::binary_search(edges.begin(), edges.end(), std::array<std::uint32_t, 2>{a, a + 1}));
    // A side of the middle square (also on the hull) and a side of the bottom square (a hull edge).
    const std::uint32_t s = insert_and_compare(live, {4, 1.75, 2.03125});
    insert_and_compare(live, {1.25, 0, 0});
    EXPECT_EQ(live.counters().on_plc_edge, 3u);
    EXPECT_EQ(live.counters().on_polygon, 2u);
    const auto& loop = live.plc().facets[2].loops[0];
    EXPECT_NE(std::find(loop.begin(), loop.end(), s), loop.end());
    EXPECT_EQ(loop.size(), 5u);
}

TEST(CdtVertexInsertion, GridDegeneratePlc) {
    // Every point on the integer grid 0..4: cospherical and coplanar sets everywhere, decided by
    // the perturbation alone. Polygons: the box's faces and a middle square; then half-integer
    // points, on and off the polygons.
    std::vector<Point3> pts;
    for (int x = 0; x <= 4; ++x) {
        for (int y = 0; y <= 4; ++y) {
            for (int z = 0; z <= 4; ++z) {
                pts.push_back(
                    {static_cast<double>(x), static_cast<double>(y), static_cast<double>(z)});
            }
        }
    }
    const auto id = [](int x, int y, int z) {
        return static_cast<std::uint32_t>(25 * x + 5 * y + z);
    };
    // A square's loop lists every grid point on its sides (a point inside an edge is no PLC).
    const auto square = [&](int z) {
        std::vector<std::uint32_t> loop;
        loop.reserve(16);
        for (int k = 0; k < 4; ++k) {
            loop.push_back(id(k, 0, z));
        }
        for (int k = 0; k < 4; ++k) {
            loop.push_back(id(4, k, z));
        }
        for (int k = 4; k > 0; --k) {
            loop.push_back(id(k, 4, z));
        }
        for (int k = 4; k > 0; --k) {
            loop.push_back(id(0, k, z));
        }
        return loop;
    };
    std::vector<Loops> facets{{square(2)}, {square(0)}};
    LiveCdt live(make_plc(pts, facets), CdtOptions{true});
    Random random(3);
    std::size_t compared = 0;
    for (int i = 0; i < 25; ++i) {
        const Point3 p{0.5 * static_cast<double>(random.below(9)),
                       0.5 * static_cast<double>(random.below(9)),
                       0.5 * static_cast<double>(random.below(9))};
        const State before = state_of(live);
        const CdtInsertion r = live.insert_vertex(p);
        if (!r.inserted()) {
            EXPECT_EQ(state_of(live), before) << r.message;
            continue;
        }
        compared += matches_rebuild(live) ? 1 : 0;
    }
    EXPECT_GT(live.counters().duplicates, 0u);
    EXPECT_GT(live.counters().on_polygon, 0u);
    EXPECT_GE(compared, 5u);
}

/// Many points in and around the cube. Each refusal is checked against the rebuild too: the CDT
/// is unique, so had the PLC with v a CDT that build_cdt can make, insertion would have had to
/// find it (the refused points sit near the long hull edges of the polygons and spoil their
/// protection).
TEST(CdtVertexInsertion, ManyRandomPoints) {
    LiveCdt live(cube_with_middle_square(), CdtOptions{true});
    Random random(29);
    std::size_t refused = 0;
    for (int i = 0; i < 400; ++i) {
        const Point3 p = random_point(random, -0.5, 4.5);
        const CdtInsertion r = live.insert_vertex(p);
        if (!r.inserted()) {
            ++refused;
            Plc augmented = live.plc();
            augmented.points.points.push_back(p);
            EXPECT_THROW(build_cdt(augmented, CdtOptions{false}), Error) << r.message;
        }
        if ((i + 1) % 100 == 0) {
            matches_rebuild(live);
        }
    }
    EXPECT_EQ(live.counters().attempts, 400u);
    EXPECT_EQ(live.counters().inserted + refused, 400u);
    EXPECT_EQ(refused,
              live.counters().refused_not_star_shaped + live.counters().refused_through_cavity +
                  live.counters().refused_not_delaunay);
    EXPECT_GT(live.counters().inserted, 250u);
}

TEST(CdtVertexInsertion, DuplicateIsReported) {
    LiveCdt live(closed_box(), CdtOptions{true});
    const State before = state_of(live);
    const CdtInsertion r = live.insert_vertex(live.plc().points.points[9]);
    EXPECT_EQ(r.status, CdtInsertionStatus::kDuplicate);
    EXPECT_EQ(r.vertex, 9u);
    EXPECT_NE(r.message.find("vertex 9"), std::string::npos) << r.message;
    EXPECT_EQ(state_of(live), before);
    EXPECT_EQ(live.counters().duplicates, 1u);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(live.insert_vertex({1, inf, 1}), Error);
}

/// A dangling segment, and a vertex next to its middle: every ball through the segment's ends
/// holds the segment, so every tetrahedron around it conflicts and the segment would vanish.
TEST(CdtVertexInsertion, RefusedSegmentThroughTheCavity) {
    auto plc = cube_with_middle_square();
    plc.points.index_base = 1;
    const auto a = static_cast<std::uint32_t>(plc.points.size());
    plc.points.points.push_back({1, 1, 0.5});
    plc.points.points.push_back({1.375, 1.375, 0.6875});
    plc.segments.push_back({a, a + 1});
    LiveCdt live(std::move(plc), CdtOptions{true});
    ASSERT_TRUE(live.plc().segments == (std::vector<std::array<std::uint32_t, 2>>{{a, a + 1}}));
    const State before = state_of(live);
    const CdtInsertion r = live.insert_vertex({1.1875, 1.1876, 0.59375});
    EXPECT_EQ(r.status, CdtInsertionStatus::kThroughCavity);
    EXPECT_EQ(r.vertex, kNoVertex);
    const std::string edge = std::to_string(a + 1) + "-" + std::to_string(a + 2);  // 1-based
    EXPECT_NE(r.message.find("PLC edge " + edge), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("cannot be inserted"), std::string::npos);
    EXPECT_EQ(state_of(live), before);
    EXPECT_EQ(live.counters().refused_through_cavity, 1u);
    // The triangulation still takes other vertices, and the next one gets the next index.
    EXPECT_EQ(insert_and_compare(live, {0.5, 3.5, 3.5}), a + 2);
}

/// The middle square's side 8-11 lies on the hull face x = 0. A point just outside that face,
/// below the square, sees round the side into the tetrahedra above the square: they conflict,
/// and the square's triangles face it from the wrong side.
TEST(CdtVertexInsertion, RefusedNotStarShaped) {
    LiveCdt live(cube_with_middle_square(), CdtOptions{true});
    const State before = state_of(live);
    const CdtInsertion r = live.insert_vertex({-0.0625, 2, 1.75});
    EXPECT_EQ(r.status, CdtInsertionStatus::kNotStarShaped) << r.message;
    EXPECT_NE(r.message.find("not star-shaped"), std::string::npos) << r.message;
    EXPECT_NE(r.message.find("negative orientation"), std::string::npos) << r.message;
    EXPECT_EQ(state_of(live), before);
    EXPECT_EQ(live.counters().refused_not_star_shaped, 1u);
    EXPECT_GT(live.counters().conflict_tests, 0u);
}

/// The middle square's side 8-11 is a hull edge. A point outside the hull off that side, above
/// the square's plane, sees the hull triangles above and below the side: the two new tetrahedra
/// over them share the face (v, 8, 11), and a vertex below the square, hidden by the square from
/// the tetrahedra above, lies in the upper one's circumball. The cavity is star-shaped and
/// nothing runs through it, yet the face is not locally Delaunay: no CDT keeps the rest.
TEST(CdtVertexInsertion, RefusedNotDelaunay) {
    LiveCdt live(cube_with_middle_square(), CdtOptions{true});
    const State before = state_of(live);
    const Point3 p{-1.75, -0.625, 2.625};
    const CdtInsertion r = live.insert_vertex(p);
    EXPECT_EQ(r.status, CdtInsertionStatus::kNotDelaunay) << r.message;
    EXPECT_NE(r.message.find("not locally Delaunay"), std::string::npos) << r.message;
    EXPECT_EQ(state_of(live), before);
    EXPECT_EQ(live.counters().refused_not_delaunay, 1u);
    Plc augmented = live.plc();
    augmented.points.points.push_back(p);
    EXPECT_THROW(build_cdt(augmented, CdtOptions{false}), Error);
}

/// PREFIX.poly is what `cavity check --poly` reads: written after insertions that split a loop
/// side and a segment, it must read back to the same PLC.
TEST(CdtVertexInsertion, WrittenPlcReadsBack) {
    auto plc = cube_with_middle_square();
    plc.points.index_base = 1;
    const auto a = static_cast<std::uint32_t>(plc.points.size());
    plc.points.points.push_back({1, 1, 0.5});
    plc.points.points.push_back({1.375, 1.375, 0.6875});
    plc.segments.push_back({a, a + 1});
    plc.facets[0].holes.push_back({2, 2, 0});
    plc.volume_holes.push_back({{-1, -1, -1}});
    LiveCdt live(std::move(plc), CdtOptions{true});
    ASSERT_TRUE(live.insert_vertex({1.125, 1.125, 0.5625}).inserted());
    ASSERT_TRUE(live.insert_vertex({4, 1.75, 2.03125}).inserted());
    ASSERT_TRUE(live.insert_vertex({0.1, 0.2, 0.3}).inserted());
    const auto path = std::filesystem::temp_directory_path() / "cavity_cdtvi_roundtrip.poly";
    {
        AtomicFileGroup group;
        write_poly(group.add(path), live.plc());
        group.commit();
    }
    const Plc back = read_poly(path);
    std::filesystem::remove(path);
    const Plc& plc0 = live.plc();
    EXPECT_EQ(back.points.index_base, 1);
    ASSERT_EQ(back.points.size(), plc0.points.size());
    for (std::size_t i = 0; i < plc0.points.size(); ++i) {
        EXPECT_EQ(back.points.points[i].x, plc0.points.points[i].x);
        EXPECT_EQ(back.points.points[i].y, plc0.points.points[i].y);
        EXPECT_EQ(back.points.points[i].z, plc0.points.points[i].z);
    }
    EXPECT_EQ(back.segments, plc0.segments);
    ASSERT_EQ(back.facets.size(), plc0.facets.size());
    for (std::size_t f = 0; f < plc0.facets.size(); ++f) {
        EXPECT_EQ(back.facets[f].loops, plc0.facets[f].loops);
        EXPECT_EQ(back.facets[f].marker, plc0.facets[f].marker);
        EXPECT_EQ(back.facets[f].holes.size(), plc0.facets[f].holes.size());
    }
    EXPECT_EQ(back.volume_holes.size(), 1u);
    EXPECT_EQ(plc_edges(back), plc_edges(plc0));
    EXPECT_TRUE(validate_cdt(back, live.tets()).ok());
}

/// Sequences on the three PLCs, a third of the points on a quarter grid (on polygons and edges,
/// cospherical with the box corners): every accepted insertion leaves a valid CDT equal to the
/// rebuild whenever the rebuild can start, and no refused point has a CDT build_cdt can make.
TEST(CdtVertexInsertion, SequencesAgainstRebuild) {
    std::size_t accepted = 0;
    std::size_t compared = 0;
    std::size_t refused = 0;
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        LiveCdt live(seed % 3 == 0   ? closed_polytope()
                     : seed % 3 == 1 ? cube_with_middle_square()
                                     : closed_box(),
                     CdtOptions{true});
        Random random(1000 + seed);
        for (int i = 0; i < 100; ++i) {
            Point3 p = random_point(random, -1, 5);
            if (i % 3 == 0) {
                p = {std::round(4 * p.x) / 4, std::round(4 * p.y) / 4, std::round(4 * p.z) / 4};
            }
            const CdtInsertion r = live.insert_vertex(p);
            Plc augmented = live.plc();
            if (r.status == CdtInsertionStatus::kDuplicate) {
                continue;
            }
            if (!r.inserted()) {
                ++refused;
                augmented.points.points.push_back(p);
                EXPECT_THROW(build_cdt(augmented, CdtOptions{false}), Error) << r.message;
                continue;
            }
            ++accepted;
            ASSERT_TRUE(validate_cdt(live.plc(), live.tets()).ok())
                << "seed " << seed << " point " << i;
            ASSERT_TRUE(check_complex(live.storage(), live.geometry()).empty());
            try {
                const Cdt rebuilt = build_cdt(augmented, CdtOptions{false});
                EXPECT_EQ(test::canonical(rebuilt.tets), test::canonical(live.tets()));
                ++compared;
            } catch (const Error& e) {
                EXPECT_NE(std::string(e.what()).find("not edge-protected"), std::string::npos)
                    << e.what();
            }
        }
    }
    EXPECT_GT(accepted, 250u);
    EXPECT_GT(compared, 80u);
    EXPECT_GT(refused, 0u);
}

}  // namespace
}  // namespace cavity::core
