// Two rarely taken paths of the CDT code, reached on purpose or shown out of reach.
//
// 1. polygon_region.cpp, step 1: the walk through the star of a side's end u toward its other end
//    v is a visibility walk toward a point just beyond u on the side. In a regular star (every
//    face through u locally Delaunay) it cannot cycle (Edelsbrunner's acyclicity theorem), but in
//    an arbitrary triangulation it can, and then step 1 falls back to searching the whole star.
//    A pyramid whose base is a "pinwheel" (Devillers, Pion & Teillaud, Walking in a
//    triangulation) makes the walk cycle. In build_cdt, only polygons inserted earlier through u
//    make u's star irregular; a search over pinwheels of polygon fins found no cycle there, so
//    the complex is built by hand and handed to polygon_region.
// 2. cdt_vertex_insertion.cpp: the refusal of a vertex all of whose tetrahedra conflict with the
//    new point. It is out of reach (see the comment on the sweep below); the sweep guards the
//    argument.
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/random.h"
#include "cavity/core/cdt/cdt_vertex_insertion.h"
#include "cavity/core/cdt/polygon_insertion.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/predicates/orient3d.h"

namespace cavity::core {
namespace {

using Quad = std::array<std::uint32_t, 4>;

// The pyramid: apex 0 under the plane z = 1, which holds the base. Vertex 1 (the target) sits
// over the apex, inside the inner triangle 2 3 4; the outer triangle 5 6 7 is turned by 10
// degrees against it, so that the ring between the two is triangulated as a pinwheel.
constexpr std::uint32_t kApex = 0;
constexpr std::uint32_t kTarget = 1;
constexpr std::uint32_t kA0 = 2;
constexpr std::uint32_t kA1 = 3;
constexpr std::uint32_t kA2 = 4;
constexpr std::uint32_t kB0 = 5;
constexpr std::uint32_t kB1 = 6;
constexpr std::uint32_t kB2 = 7;

PointSet pinwheel_points() {
    PointSet points;
    points.points = {{0, 0, 0},
                     {0, 0, 1},
                     {0, 1, 1},
                     {-0.875, -0.5, 1},
                     {0.875, -0.5, 1},
                     {-0.5, 2.9375, 1},
                     {-2.3125, -1.9375, 1},
                     {2.8125, -1.0, 1}};
    return points;
}

/// The tetrahedron over base triangle (first, b, c) with `first` in storage slot 0 and the apex in
/// slot 3, b and c swapped if needed for positive orientation. The walk tries facets in slot order,
/// so it leaves across the facet opposite `first` whenever the target is beyond that facet.
/// complex_from_tets takes positive right-hand volume and mirrors it by swapping slots 0 and 1, so
/// the list gives the mirror image.
Quad over(const PointSet& points, std::uint32_t first, std::uint32_t b, std::uint32_t c) {
    const auto& p = points.points;
    if (predicates::orient3d(p[first], p[b], p[c], p[kApex]) != predicates::Sign::kPos) {
        std::swap(b, c);
    }
    return {b, first, c, kApex};
}

/// The cone from the apex over the base triangulation: the target's fan (three triangles), and
/// the ring of six triangles between the inner and outer triangles. From each ring triangle the
/// target lies beyond the edge it shares with the next one round the ring; from the three that
/// touch the inner triangle it also lies beyond that edge (into the fan). `cycle` lists, for each
/// ring tetrahedron, the vertex opposite the shared edge first, so the walk goes round the ring
/// forever; otherwise the inner triangles list the vertex opposite the fan edge first, and the
/// walk reaches the fan.
std::vector<Quad> pinwheel_tets(const PointSet& points, bool cycle) {
    std::vector<Quad> tets{over(points, kTarget, kA0, kA1),
                           over(points, kTarget, kA1, kA2),
                           over(points, kTarget, kA2, kA0)};
    // Ring order: (B1 A1 A0) -> (B1 B2 A1) -> (B2 A2 A1) -> (B2 B0 A2) -> (B0 A0 A2) -> (B0 B1 A0).
    tets.push_back(cycle ? over(points, kA0, kB1, kA1) : over(points, kB1, kA1, kA0));
    tets.push_back(over(points, kB1, kB2, kA1));
    tets.push_back(cycle ? over(points, kA1, kB2, kA2) : over(points, kB2, kA2, kA1));
    tets.push_back(over(points, kB2, kB0, kA2));
    tets.push_back(cycle ? over(points, kA2, kB0, kA0) : over(points, kB0, kA0, kA2));
    tets.push_back(over(points, kB0, kB1, kA0));
    return tets;
}

/// Step 1 of polygon_region for the triangle (apex, target, A0), whose sides are all edges of
/// the pyramid; returns the work record.
PolygonWork region_work(bool cycle) {
    Plc plc;
    plc.source = "pinwheel";
    plc.points = pinwheel_points();
    PlcFacet facet;
    facet.loops = {{kApex, kTarget, kA0}};
    facet.marker = 1;
    plc.facets.push_back(facet);
    const ArrayStorage storage = complex_from_tets(pinwheel_tets(plc.points, cycle));
    const Geometry geometry = geometry_by_index(plc.points);
    EXPECT_TRUE(check_complex(storage, geometry).empty());
    PolygonWork work;
    // The triangle is a face of the complex: no tetrahedron crosses it.
    EXPECT_TRUE(polygon_region(storage, geometry, plc, 0, &work).empty());
    return work;
}

// The walk from the apex toward the target starts behind the last ghost at the apex, a ring
// tetrahedron, and with the cyclic slot order goes round the six ring tetrahedra until it comes
// back; step 1 then searches the apex's star, finds a tetrahedron with the edge, and goes on.
// The same complex with the other slot order reaches the fan directly: the extra steps are the
// cycle and the search (each tetrahedron the walk or the search looks at counts one step).
TEST(CdtRarePaths, RotaryWalkCyclesAndFallsBackToTheStar) {
    const PolygonWork direct = region_work(false);
    const PolygonWork cycled = region_work(true);
    EXPECT_EQ(direct.region_tets, 0u);
    EXPECT_EQ(cycled.region_tets, 0u);
    // The two runs differ only on side 0-1, where the direct walk looks at 3 tetrahedra. A walk
    // never looks at a tetrahedron twice, and the apex's star has 9: without the search, the
    // cyclic order could add at most 6 steps. It adds the 6 of the cycle and the search's.
    EXPECT_GT(cycled.rotary_steps, direct.rotary_steps + 6);
}

/// A box with an inner polygon and points close to it on both sides.
Plc box_with_square(Random& random) {
    Plc plc;
    plc.source = "sweep";
    auto& p = plc.points.points;
    for (int i = 0; i < 8; ++i) {
        p.push_back({(i & 1) * 4.0, ((i >> 1) & 1) * 4.0, ((i >> 2) & 1) * 4.0});
    }
    const double h = 1 + static_cast<double>(random.below(33)) / 16;
    const double lo = 0.5 + static_cast<double>(random.below(8)) / 8;
    const double hi = 3.5 - static_cast<double>(random.below(8)) / 8;
    const auto b = static_cast<std::uint32_t>(p.size());
    p.insert(p.end(), {{lo, lo, h}, {hi, lo, h}, {hi, hi, h}, {lo, hi, h}});
    PlcFacet square;
    square.loops = {{b, b + 1, b + 2, b + 3}};
    square.marker = 1;
    plc.facets.push_back(square);
    const std::uint64_t near = 1 + random.below(4);
    for (std::uint64_t i = 0; i < near; ++i) {
        const double dz =
            static_cast<double>(random.below(64) + 1) / 256 * (random.below(2) != 0 ? 1 : -1);
        p.push_back({random.uniform(lo, hi), random.uniform(lo, hi), h + dz});
    }
    return plc;
}

// Why no vertex w can vanish: the check runs after retriangulate_polygons, and every
// tetrahedron at w in the cavity means every polygon triangle at w has both sides in it. If one
// is in a polygon the new point u is not on, retriangulate_polygons refuses first; if w is on
// the boundary of a polygon u is on, that polygon's sides at w are used once and lie on no cavity
// face (all of w's tetrahedra are gone), so it refuses first as well. Left: w on no polygon, or
// inside the one polygon u lies on. Then, on each side, every face through w is locally
// Delaunay, so the lifted star is convex near w: the tangent plane of the paraboloid at w is a
// subgradient, i.e. w is a convex combination of the circumcentres c_T of the tetrahedra at w
// (plus outward normals n of the hull or of the polygon's plane). u in every circumball means
// (u - w).(c_T - w) > |u - w|^2 / 2 > 0 for every T, and (u - w).n >= 0 (u in front of the hull
// triangles, or on the polygon): the combination would give 0 > 0. The sweep inserts points on
// and near a polygon and near vertices, the likeliest places, and checks that no refusal names
// a vanishing vertex and every refusal leaves the mesh as it was.
TEST(CdtRarePaths, NoVertexVanishesInsideACavity) {
    std::size_t refused = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        Random random(seed);
        Plc plc = box_with_square(random);
        const double h = plc.points.points[8].z;
        const double lo = plc.points.points[8].x;
        const double hi = plc.points.points[10].x;
        LiveCdt live(std::move(plc), CdtOptions{true});
        for (int k = 0; k < 60; ++k) {
            Point3 p{random.uniform(0, 4), random.uniform(0, 4), random.uniform(0, 4)};
            const auto& points = live.plc().points.points;
            if (k % 3 == 1) {  // on the square, where it splits triangles
                p = {lo + static_cast<double>(random.below(65)) / 64 * (hi - lo),
                     lo + static_cast<double>(random.below(65)) / 64 * (hi - lo),
                     h};
            } else if (k % 3 == 2) {  // near a vertex
                const Point3& q = points[random.below(points.size())];
                p = {q.x + random.uniform(-0.25, 0.25),
                     q.y + random.uniform(-0.25, 0.25),
                     q.z + random.uniform(-0.25, 0.25)};
            }
            const std::vector<Quad> before = live.tets();
            const CdtInsertion r = live.insert_vertex(p);
            EXPECT_EQ(r.message.find("would vanish"), std::string::npos)
                << "seed " << seed << " point " << k << ": " << r.message;
            if (!r.inserted() && r.status != CdtInsertionStatus::kDuplicate) {
                ++refused;
                EXPECT_EQ(live.tets(), before) << "seed " << seed << " point " << k;
            }
        }
        EXPECT_NO_THROW(live.validate()) << "seed " << seed;
    }
    // The sweep must reach the refusals it guards, not only easy insertions.
    EXPECT_GT(refused, 20u);
}

}  // namespace
}  // namespace cavity::core
