// A surface mesh's exactly coplanar neighbouring faces merged into the polygons of the solid's flat
// faces (coplanar_facets.h): loops, hole points, interior corners, pinches and markers, and the
// CDTs of the merged PLCs, checked by volume and the exact validator.
#include <algorithm>
#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_carve.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/plc_validity.h"
#include "cavity/core/cdt/read_plc.h"
#include "plc_builders.h"
#include "temp_dir.h"
// White-box: the merge is internal to the core.
#include "../../../core/cdt/src/coplanar_facets.h"
#include "../../../core/cdt/src/exact_plane.h"

namespace cavity::core {
namespace {

using test::Loops;
using test::make_plc;

/// An OFF surface made of quads, each written as the two triangles (a, b, c) and (a, c, d).
class OffBuilder {
public:
    std::uint32_t point(double x, double y, double z) {
        points_ << x << ' ' << y << ' ' << z << '\n';
        return count_++;
    }

    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }

    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        faces_ << "3 " << a << ' ' << b << ' ' << c << '\n';
        ++faces_count_;
    }

    std::string text() const {
        return "OFF\n" + std::to_string(count_) + ' ' + std::to_string(faces_count_) + " 0\n" +
               points_.str() + faces_.str();
    }

private:
    std::ostringstream points_;
    std::ostringstream faces_;
    std::uint32_t count_ = 0;
    std::uint32_t faces_count_ = 0;
};

/// The plate [0,3]^2 x [0,1] with the square hole [1,2]^2 through it, on the unit grid: the top
/// and bottom each 8 squares, the outer walls 3 squares a side, the hole's walls one each; 64
/// triangles turning outwards, 10 flat faces, volume 8. `shear` adds shear * (x + 2y) to z:
/// the top and bottom tilt, and the volume stays.
std::string plate_with_hole_off(double shear = 0) {
    OffBuilder off;
    std::array<std::array<std::array<std::uint32_t, 2>, 4>, 4> v{};
    for (int k = 0; k < 2; ++k) {
        for (int j = 0; j < 4; ++j) {
            for (int i = 0; i < 4; ++i) {
                v[i][j][k] = off.point(i, j, k + shear * (i + 2 * j));
            }
        }
    }
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            if (i == 1 && j == 1) {
                continue;
            }
            off.quad(v[i][j][1], v[i + 1][j][1], v[i + 1][j + 1][1], v[i][j + 1][1]);
            off.quad(v[i][j][0], v[i][j + 1][0], v[i + 1][j + 1][0], v[i + 1][j][0]);
        }
    }
    for (int s = 0; s < 3; ++s) {
        off.quad(v[s][0][0], v[s + 1][0][0], v[s + 1][0][1], v[s][0][1]);
        off.quad(v[s][3][0], v[s][3][1], v[s + 1][3][1], v[s + 1][3][0]);
        off.quad(v[0][s][0], v[0][s][1], v[0][s + 1][1], v[0][s + 1][0]);
        off.quad(v[3][s][0], v[3][s + 1][0], v[3][s + 1][1], v[3][s][1]);
    }
    off.quad(v[1][1][0], v[1][2][0], v[1][2][1], v[1][1][1]);
    off.quad(v[2][1][0], v[2][1][1], v[2][2][1], v[2][2][0]);
    off.quad(v[1][1][0], v[1][1][1], v[2][1][1], v[2][1][0]);
    off.quad(v[1][2][0], v[2][2][0], v[2][2][1], v[1][2][1]);
    return off.text();
}

/// The cube [0,2]^3 as two triangles a face, but its top as four around its centre (1, 1, 2).
std::string cube_with_fan_top_off() {
    OffBuilder off;
    std::array<std::uint32_t, 8> c{};
    for (std::uint32_t i = 0; i < 8; ++i) {
        c[i] = off.point(2.0 * (i & 1), 2.0 * ((i >> 1) & 1), 2.0 * ((i >> 2) & 1));
    }
    const std::uint32_t centre = off.point(1, 1, 2);
    off.quad(c[0], c[2], c[3], c[1]);  // bottom
    off.quad(c[0], c[1], c[5], c[4]);  // y = 0
    off.quad(c[2], c[6], c[7], c[3]);  // y = 2
    off.quad(c[0], c[4], c[6], c[2]);  // x = 0
    off.quad(c[1], c[3], c[7], c[5]);  // x = 2
    off.triangle(c[4], c[5], centre);
    off.triangle(c[5], c[7], centre);
    off.triangle(c[7], c[6], centre);
    off.triangle(c[6], c[4], centre);
    return off.text();
}

double six_volume(const std::vector<Point3>& p, const std::vector<Tet>& tets) {
    double sum = 0;
    for (const Tet& t : tets) {
        const Point3& a = p[t[0]];
        const Point3 u{p[t[1]].x - a.x, p[t[1]].y - a.y, p[t[1]].z - a.z};
        const Point3 v{p[t[2]].x - a.x, p[t[2]].y - a.y, p[t[2]].z - a.z};
        const Point3 w{p[t[3]].x - a.x, p[t[3]].y - a.y, p[t[3]].z - a.z};
        sum += u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) +
               u.z * (v.x * w.y - v.y * w.x);
    }
    return sum;
}

/// The points of the unit grid on [0,3]^2 at z = 0 and the two triangles of each of its squares
/// but those listed in `without` (as {i, j}, the square [i, i+1] x [j, j+1]); one marker for all.
Plc grid_squares(const std::vector<std::array<int, 2>>& without) {
    std::vector<Point3> points;
    for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
            points.push_back({static_cast<double>(i), static_cast<double>(j), 0});
        }
    }
    std::vector<Loops> facets;
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            if (std::find(without.begin(), without.end(), std::array<int, 2>{i, j}) !=
                without.end()) {
                continue;
            }
            const auto at = [](int x, int y) { return static_cast<std::uint32_t>(4 * y + x); };
            facets.push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1)}});
            facets.push_back({{at(i, j), at(i + 1, j + 1), at(i, j + 1)}});
        }
    }
    Plc plc = make_plc(points, facets);
    for (PlcFacet& f : plc.facets) {
        f.marker = 1;
    }
    return plc;
}

TEST(CoplanarFacets, EachFlatFaceOfAPlateWithAHoleBecomesOnePolygon) {
    test::TempDir dir;
    SurfaceReading reading;
    const Plc plc = read_plc(dir.write("plate.off", plate_with_hole_off(0.375)), &reading);
    EXPECT_EQ(reading.merged_faces, 64u);
    EXPECT_EQ(reading.merged_polygons, 10u);
    ASSERT_EQ(plc.facets.size(), 10u);
    std::size_t with_hole = 0;
    for (const PlcFacet& f : plc.facets) {
        if (f.loops.size() == 1) {
            EXPECT_TRUE(f.loops[0].size() == 4 || f.loops[0].size() == 8) << f.loops[0].size();
            EXPECT_TRUE(f.holes.empty());
            continue;
        }
        // The top or the bottom: the outer loop first (its 12 grid points), then the hole's 4,
        // with a hole point strictly inside the hole.
        ++with_hole;
        ASSERT_EQ(f.loops.size(), 2u);
        EXPECT_EQ(f.loops[0].size(), 12u);
        EXPECT_EQ(f.loops[1].size(), 4u);
        ASSERT_EQ(f.holes.size(), 1u);
        EXPECT_GT(f.holes[0].x, 1);
        EXPECT_LT(f.holes[0].x, 2);
        EXPECT_GT(f.holes[0].y, 1);
        EXPECT_LT(f.holes[0].y, 2);
        // On the tilted plane exactly, as a .poly hole point must be.
        EXPECT_EQ(ExactPlane::of_facet(plc, f)->side(f.holes[0]), predicates::Sign::kZero);
    }
    EXPECT_EQ(with_hole, 2u);
    // Faces are numbered as in the file: each polygon keeps its first face's number.
    EXPECT_EQ(plc.facets[0].number, 0u);
}

TEST(CoplanarFacets, TheMergedPlateNeedsNoProtectionAndKeepsItsVolume) {
    test::TempDir dir;
    for (const bool merge : {true, false}) {
        SCOPED_TRACE(merge ? "merged" : "--keep-faces");
        const auto file = dir.write("plate.off", plate_with_hole_off());
        SurfaceReading reading;
        const Cdt cdt = build_cdt(read_plc(file, &reading, merge), CdtOptions{true});
        EXPECT_EQ(cdt.plc.facets.size(), merge ? 10u : 64u);
        // The unit grid's sides are strongly Delaunay: only the squares' diagonals, cospherical
        // with the other two corners, can be missing, and merged they are no constraints.
        if (merge) {
            EXPECT_TRUE(cdt.protection.inserted.empty());
        }
        const CarvedCdt domain = carve_cdt(cdt, false);
        if (cdt.protection.inserted.empty()) {
            EXPECT_EQ(six_volume(cdt.plc.points.points, domain.tets), 48.0);  // 6 * 8, exactly
        }
        EXPECT_TRUE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kCarved).ok());
    }
    // Tilted, merged: still one polygon per flat face, meshed and valid.
    const Cdt tilted =
        build_cdt(read_plc(dir.write("tilted.off", plate_with_hole_off(0.375))), CdtOptions{true});
    EXPECT_EQ(tilted.plc.facets.size(), 10u);
    EXPECT_TRUE(validate_cdt(tilted.plc, carve_cdt(tilted, false).tets, CdtDomain::kCarved).ok());
}

TEST(CoplanarFacets, AnInteriorCornerStaysAPointInsideItsPolygon) {
    test::TempDir dir;
    SurfaceReading reading;
    const Plc plc = read_plc(dir.write("fan.off", cube_with_fan_top_off()), &reading);
    EXPECT_EQ(reading.merged_faces, 14u);
    EXPECT_EQ(reading.merged_polygons, 6u);
    ASSERT_EQ(plc.facets.size(), 6u);
    for (const PlcFacet& f : plc.facets) {
        ASSERT_EQ(f.loops.size(), 1u);
        EXPECT_EQ(f.loops[0].size(), 4u);  // the centre is on no loop
    }
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    const CarvedCdt domain = carve_cdt(cdt, false);
    ASSERT_TRUE(cdt.protection.inserted.empty());
    EXPECT_EQ(six_volume(cdt.plc.points.points, domain.tets), 48.0);
    EXPECT_TRUE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kCarved).ok());
    // The centre (point 8) is a vertex of the mesh, on the top polygon's triangles.
    EXPECT_TRUE(std::any_of(domain.tets.begin(), domain.tets.end(), [](const Tet& t) {
        return std::find(t.begin(), t.end(), 8u) != t.end();
    }));
}

TEST(CoplanarFacets, AnAnnulusGetsAHolePointAndAPinchedOneStaysAsItsFaces) {
    Plc annulus = grid_squares({{1, 1}});
    const CoplanarMerge merged = merge_coplanar_facets(annulus);
    EXPECT_EQ(merged.faces, 16u);
    EXPECT_EQ(merged.polygons, 1u);
    ASSERT_EQ(annulus.facets.size(), 1u);
    ASSERT_EQ(annulus.facets[0].loops.size(), 2u);
    ASSERT_EQ(annulus.facets[0].holes.size(), 1u);
    // Without the corner square too, the hole touches the outside at the grid point (1, 1): four
    // boundary sides meet there, and no loop through it is simple.
    Plc pinched = grid_squares({{1, 1}, {0, 0}});
    const CoplanarMerge none = merge_coplanar_facets(pinched);
    EXPECT_EQ(none.faces, 0u);
    EXPECT_EQ(none.polygons, 0u);
    EXPECT_EQ(pinched.facets.size(), 14u);
}

TEST(CoplanarFacets, OnlyFacesWithTheSameMarkerAndPlaneAreMerged) {
    const std::vector<Point3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    // make_plc numbers the markers 1 and 2: two polygons stay two.
    Plc marked = make_plc(square, {{{0, 1, 2}}, {{0, 2, 3}}});
    EXPECT_EQ(merge_coplanar_facets(marked).polygons, 0u);
    EXPECT_EQ(marked.facets.size(), 2u);
    marked.facets[1].marker = marked.facets[0].marker;
    EXPECT_EQ(merge_coplanar_facets(marked).polygons, 1u);
    ASSERT_EQ(marked.facets.size(), 1u);
    EXPECT_EQ(marked.facets[0].loops[0].size(), 4u);
    // The last corner 2^-40 above the plane: folded, not flat.
    std::vector<Point3> folded = square;
    folded[3].z = 0x1p-40;
    Plc bent = make_plc(folded, {{{0, 1, 2}}, {{0, 2, 3}}});
    bent.facets[1].marker = bent.facets[0].marker;
    EXPECT_EQ(merge_coplanar_facets(bent).polygons, 0u);
    EXPECT_EQ(bent.facets.size(), 2u);
}

// --- the protected PLC check skipped for a checked surface (cdt.cpp) ---------------------------

TEST(CheckedSurface, OnlyAReadSurfaceMeshIsMarked) {
    test::TempDir dir;
    EXPECT_TRUE(read_plc(dir.write("plate.off", plate_with_hole_off())).surface_checked);
    EXPECT_TRUE(
        read_plc(dir.write("fan.off", cube_with_fan_top_off()), nullptr, false).surface_checked);
    EXPECT_FALSE(
        read_plc(dir.write("one.poly", "3 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n1 0\n1\n3 0 1 2\n"))
            .surface_checked);
    // Faces made in memory are marked as the reader's, but not with a segment, which the surface
    // check does not look at; preparing again clears a mark a changed PLC still carries.
    Plc faces = read_plc(dir.write("fan.off", cube_with_fan_top_off()), nullptr, false);
    prepare_surface_mesh(faces);
    EXPECT_TRUE(faces.surface_checked);
    faces.segments.push_back({0, 8});
    prepare_surface_mesh(faces);
    EXPECT_FALSE(faces.surface_checked);
}

TEST(CheckedSurface, TheSkippedCheckFindsNothingOnCheckedSurfaces) {
    // The oracle: protected_plc_violations on the protected PLC of each checked surface, merged
    // or not, with and without split points on its edges.
    test::TempDir dir;
    std::size_t split = 0;
    for (const std::string& off :
         {plate_with_hole_off(), plate_with_hole_off(0.375), cube_with_fan_top_off()}) {
        for (const bool merge : {true, false}) {
            const Plc plc = read_plc(dir.write("surface.off", off), nullptr, merge);
            ASSERT_TRUE(plc.surface_checked);
            const Cdt cdt = build_cdt(plc, CdtOptions{true});
            split += cdt.protection.inserted.size();
            EXPECT_TRUE(cdt.plc.surface_checked);
            EXPECT_EQ(protected_plc_violations(cdt.plc), std::vector<std::string>{});
        }
    }
    EXPECT_GT(split, 0u);  // edge protection's split points are among the cases
}

/// A square facet at z = 0 and a triangle whose side from (2, 2, -1) to (3, 2, 1) pierces it.
Plc pierced_square() {
    return make_plc({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {2, 2, -1}, {3, 2, 1}, {2, 3, 1}},
                    {{{0, 1, 2, 3}}, {{4, 5, 6}}});
}

TEST(CheckedSurface, APolyOrAMarkedPlcWithASegmentIsStillChecked) {
    // Every edge is a Delaunay edge: only the protected PLC check can refuse these.
    const auto refused = [](const Plc& plc) {
        try {
            (void)build_cdt(plc, CdtOptions{true});
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    test::TempDir dir;
    std::string poly =
        "7 3 0 0\n0 0 0 0\n1 4 0 0\n2 4 4 0\n3 0 4 0\n4 2 2 -1\n5 3 2 1\n6 2 3 1\n2 0\n";
    poly += "1\n4 0 1 2 3\n1\n3 4 5 6\n";
    const Plc read = read_plc(dir.write("pierced.poly", poly));
    ASSERT_FALSE(read.surface_checked);
    EXPECT_NE(refused(read).find("10: facet 0: edge 4-5 (a side of facet 1 (line 12)) crosses it"),
              std::string::npos)
        << refused(read);
    // A surface's faces with a segment through one: prepare_surface_mesh does not mark it.
    Plc faces = read_plc(dir.write("fan.off", cube_with_fan_top_off()), nullptr, false);
    const auto low = static_cast<std::uint32_t>(faces.points.size());
    faces.points.points.push_back({1, 1, 1});
    faces.points.points.push_back({1.25, 1.0625, 3.5});
    faces.segments.push_back({low, low + 1});
    prepare_surface_mesh(faces);
    EXPECT_FALSE(faces.surface_checked);
    EXPECT_NE(refused(faces).find("crosses it"), std::string::npos) << refused(faces);
    EXPECT_NE(refused(pierced_square()).find("crosses it"), std::string::npos);
}

}  // namespace
}  // namespace cavity::core
