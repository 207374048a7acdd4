#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/check/orientation.h"
#include "cavity/core/edit/gift_wrap.h"
#include "cavity/core/gen/generate.h"
#include "cavity/core/live/delaunay_triangulation.h"
#include "cavity/core/live/triangulate.h"
#include "cavity/core/order/insertion_order.h"

namespace cavity::core {
namespace {

// The unit tetrahedron o, x, y, z has volume +1/6 by the right-hand rule, and a fifth point in the
// plane z = 0 makes a flat one.
PointSet corner() {
    PointSet set;
    set.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    return set;
}

TEST(Orientation, CountsByRightHandVolume) {
    const std::vector<Tet> tets = {{0, 1, 2, 3}, {1, 0, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 9}};
    const OrientationCount count = count_orientations(corner(), tets);
    EXPECT_EQ(count.positive, 1u);
    EXPECT_EQ(count.negative, 1u);
    EXPECT_EQ(count.flat, 1u);  // the out-of-range one is left to the validator
}

TEST(Orientation, PositiveFilesPass) {
    const std::vector<Tet> file = {{0, 1, 2, 3}, {0, 1, 2, 4}};
    EXPECT_NO_THROW(refuse_inverted_mesh("m.ele", corner(), file));
}

TEST(Orientation, AnInvertedMeshIsRefusedByName) {
    const std::vector<Tet> file = {{1, 0, 2, 3}, {0, 1, 2, 4}};
    try {
        refuse_inverted_mesh("m.ele", corner(), file);
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("m.ele"), std::string::npos) << what;
        EXPECT_NE(what.find("all 1 non-flat tetrahedra have negative volume"), std::string::npos)
            << what;
    }
}

TEST(Orientation, AMixedMeshIsLeftToTheValidator) {
    const std::vector<Tet> file = {{0, 1, 2, 3}, {1, 0, 2, 3}};
    EXPECT_NO_THROW(refuse_inverted_mesh("m.ele", corner(), file));
}

// Every list of tetrahedra the C++ API hands out has positive right-hand volume, the convention of
// TetGen and VTK, whatever built it; and lists go into and out of the live storage unchanged.
TEST(Orientation, EveryApiListHasPositiveVolume) {
    const PointSet points = generate_points("grid", 125, 3);  // cospherical: the perturbation acts
    const InsertionOrder order = make_insertion_order(points.points, {});
    for (const LocateKind locate : {LocateKind::kWalk, LocateKind::kConflictGraph}) {
        TriangulateOptions options;
        options.locate = locate;
        const Triangulation dt = triangulate(points, order.sequence, options);
        EXPECT_EQ(count_orientations(points, dt.tets).positive, dt.tets.size());
    }
    const Triangulation dt = triangulate(points, order.sequence, {});
    const GiftWrapResult wrapped = gift_wrap_delaunay(points);
    EXPECT_EQ(count_orientations(points, wrapped.tets).positive, wrapped.tets.size());

    std::vector<Tet> round_trip = solid_tets(complex_from_tets(dt.tets));
    std::vector<Tet> given = dt.tets;
    std::sort(round_trip.begin(), round_trip.end());
    std::sort(given.begin(), given.end());
    EXPECT_EQ(round_trip, given);

    const std::vector<std::uint32_t> gone = {0, 62, 124};
    DelaunayTriangulation live(points, order.sequence, {});
    live.remove(gone);
    const std::vector<Tet> after = live.tets();
    EXPECT_EQ(count_orientations(points, after).positive, after.size());

    // A box with a square inside it, a polygon the Delaunay tetrahedra cross.
    Plc box;
    for (int i = 0; i < 8; ++i) {
        box.points.points.push_back({(i & 1) * 4.0, ((i >> 1) & 1) * 4.0, ((i >> 2) & 1) * 4.0});
    }
    box.points.points.insert(
        box.points.points.end(),
        {{1, 1, 2}, {3, 1, 2}, {3, 3, 2}, {1, 3, 2}, {2, 2, 2.25}, {2, 2, 1.75}});
    PlcFacet square;
    square.loops = {{8, 9, 10, 11}};
    box.facets.push_back(square);
    const Cdt cdt = build_cdt(box, CdtOptions{true});
    ASSERT_FALSE(cdt.tets.empty());
    EXPECT_EQ(count_orientations(cdt.plc.points, cdt.tets).positive, cdt.tets.size());
}

}  // namespace
}  // namespace cavity::core
