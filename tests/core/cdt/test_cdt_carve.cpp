// Carving the domain a PLC bounds out of its CDT (TetGen's -p): the exterior and the volume holes
// removed, regions kept, hole points refused by .poly line; and validate_cdt of carved meshes.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_carve.h"
#include "cavity/core/cdt/cdt_validate.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/predicates/orient3d.h"
#include "plc_builders.h"

namespace cavity::core {
namespace {

/// Six times the right-hand volume of t. Exact in doubles for the small integer and half-integer
/// coordinates below (products of three such numbers, summed, stay far inside 53 bits).
double six_volume(const std::vector<Point3>& p, const Tet& t) {
    const Point3& a = p[t[0]];
    const Point3 u{p[t[1]].x - a.x, p[t[1]].y - a.y, p[t[1]].z - a.z};
    const Point3 v{p[t[2]].x - a.x, p[t[2]].y - a.y, p[t[2]].z - a.z};
    const Point3 w{p[t[3]].x - a.x, p[t[3]].y - a.y, p[t[3]].z - a.z};
    return u.x * (v.y * w.z - v.z * w.y) - u.y * (v.x * w.z - v.z * w.x) +
           u.z * (v.x * w.y - v.y * w.x);
}

double six_volume(const std::vector<Point3>& p, const std::vector<Tet>& tets) {
    double sum = 0;
    for (const Tet& t : tets) {
        sum += six_volume(p, t);
    }
    return sum;
}

void expect_positive(const std::vector<Point3>& p, const std::vector<Tet>& tets) {
    for (const Tet& t : tets) {
        EXPECT_EQ(predicates::orient3d(p[t[0]], p[t[1]], p[t[2]], p[t[3]]), predicates::Sign::kNeg);
    }
}

Point3 centroid(const std::vector<Point3>& p, const Tet& t) {
    Point3 c{0, 0, 0};
    for (std::uint32_t v : t) {
        c = {c.x + p[v].x / 4, c.y + p[v].y / 4, c.z + p[v].z / 4};
    }
    return c;
}

/// The prism over the L [0,1]^2 minus [1/2,1]^2, from z = 0 to 1: volume 3/4, hull 7/8.
Plc l_prism() {
    const double loop[6][2] = {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
    Plc plc;
    for (double z : {0.0, 1.0}) {
        for (const auto& c : loop) {
            plc.points.points.push_back({c[0], c[1], z});
        }
    }
    plc.facets.push_back({{{0, 1, 2, 3, 4, 5}}, {}, 1});
    plc.facets.push_back({{{6, 7, 8, 9, 10, 11}}, {}, 2});
    for (std::uint32_t i = 0; i < 6; ++i) {
        const std::uint32_t j = (i + 1) % 6;
        plc.facets.push_back({{{i, j, j + 6, i + 6}}, {}, 3});
    }
    return plc;
}

Cdt nested_cdt(const std::string& name, const std::string& tail) {
    const auto path = std::filesystem::temp_directory_path() / ("cavity_carve_" + name);
    std::ofstream(path) << test::nested_cubes_poly(tail);
    return build_cdt(read_poly(path), CdtOptions{true});
}

TEST(CdtCarve, LShapedPrismKeepsThreeQuartersOfItsHull) {
    const Cdt cdt = build_cdt(l_prism(), CdtOptions{true});
    ASSERT_TRUE(cdt.protection.inserted.empty());  // half-integer points: volumes exact
    const auto& p = cdt.plc.points.points;
    const CarvedCdt domain = carve_cdt(cdt, false);
    EXPECT_EQ(six_volume(p, domain.tets), 4.5);  // 6 * 3/4, exactly
    EXPECT_EQ(six_volume(p, cdt.tets), 5.25);    // the hull, 6 * 7/8
    EXPECT_GT(domain.removed, 0u);
    EXPECT_EQ(domain.tets.size() + domain.removed, cdt.tets.size());
    EXPECT_EQ(domain.regions, std::vector<std::int32_t>(domain.tets.size(), 0));
    expect_positive(p, domain.tets);
    for (const Tet& t : domain.tets) {
        const Point3 c = centroid(p, t);
        EXPECT_FALSE(c.x > 0.5 && c.y > 0.5) << "a tetrahedron of the notch is kept";
    }
    // The carved mesh is a CDT of the domain, not of the hull; the hull is not the domain.
    EXPECT_TRUE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kCarved).ok());
    EXPECT_FALSE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kConvexHull).ok());
    const CdtValidation hull = validate_cdt(cdt.plc, cdt.tets, CdtDomain::kCarved);
    ASSERT_FALSE(hull.ok());
    EXPECT_NE(hull.problems[0].find("bounds the carved domain but is in no polygon"),
              std::string::npos)
        << hull.problems[0];
    // One tetrahedron less leaves a boundary triangle in no polygon.
    std::vector<Tet> fewer(domain.tets.begin() + 1, domain.tets.end());
    EXPECT_FALSE(validate_cdt(cdt.plc, fewer, CdtDomain::kCarved).ok());
}

TEST(CdtCarve, CarvedValidationRefusesAPlcPointHiddenInTheDomain) {
    const Cdt cdt = build_cdt(l_prism(), CdtOptions{true});
    const CarvedCdt domain = carve_cdt(cdt, false);
    // The same mesh against the PLC with one more point: in the notch (removed exterior) it may
    // be missing; inside the L it would have had to be a vertex.
    Plc plc = cdt.plc;
    plc.points.points.push_back({0.75, 0.75, 0.5});
    EXPECT_TRUE(validate_cdt(plc, domain.tets, CdtDomain::kCarved).ok());
    plc.points.points.back() = {0.25, 0.25, 0.5};
    const CdtValidation hidden = validate_cdt(plc, domain.tets, CdtDomain::kCarved);
    ASSERT_EQ(hidden.problem_count, 1u);
    EXPECT_NE(hidden.problems[0].find("point 12 is not a vertex of the carved mesh but lies in"),
              std::string::npos)
        << hidden.problems[0];
}

TEST(CdtCarve, ConvexHullKeepsEveryTetrahedron) {
    const Cdt cdt = build_cdt(l_prism(), CdtOptions{true});
    const CarvedCdt hull = carve_cdt(cdt, true);
    EXPECT_EQ(hull.tets, cdt.tets);
    EXPECT_EQ(hull.removed, 0u);
}

TEST(CdtCarve, HolePointRemovesTheInnerCube) {
    const Cdt cdt = nested_cdt("hole.poly", "1\n0 2 2 2\n");
    ASSERT_EQ(cdt.plc.volume_holes.size(), 1u);
    EXPECT_EQ(cdt.plc.volume_holes[0].line, 44u);
    const auto& p = cdt.plc.points.points;
    const CarvedCdt domain = carve_cdt(cdt, false);
    EXPECT_EQ(six_volume(p, domain.tets), 6.0 * (64 - 8));
    expect_positive(p, domain.tets);
    for (const Tet& t : domain.tets) {
        const Point3 c = centroid(p, t);
        EXPECT_FALSE(c.x > 1 && c.x < 3 && c.y > 1 && c.y < 3 && c.z > 1 && c.z < 3);
    }
    EXPECT_TRUE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kCarved).ok());
    // The whole mesh, its boundary all polygons, is refused as the domain: the hole is in it.
    const CdtValidation uncarved = validate_cdt(cdt.plc, cdt.tets, CdtDomain::kCarved);
    ASSERT_EQ(uncarved.problem_count, 1u);
    EXPECT_NE(uncarved.problems[0].find("volume hole point 0 (line 44) lies in tetrahedron"),
              std::string::npos)
        << uncarved.problems[0];
    // The hull keeps everything, the hole too.
    EXPECT_EQ(carve_cdt(cdt, true).tets, cdt.tets);
    // Without the hole point the inner cube stays.
    const Cdt whole = nested_cdt("nohole.poly", "0\n");
    EXPECT_EQ(six_volume(whole.plc.points.points, carve_cdt(whole, false).tets), 6.0 * 64);
}

TEST(CdtCarve, RegionsKeepTheirMarkersOnTheKeptTetrahedra) {
    // A hole in the shell, regions in the shell (first) and the inner cube.
    const Cdt cdt = nested_cdt("regions.poly", "1\n0 0.5 0.5 0.5\n2\n0 0.5 3.5 0.5 5\n1 2 2 2 9\n");
    const CarvedCdt domain = carve_cdt(cdt, false);
    ASSERT_EQ(domain.regions.size(), domain.tets.size());
    EXPECT_EQ(six_volume(cdt.plc.points.points, domain.tets), 6.0 * 8);
    EXPECT_EQ(domain.regions, std::vector<std::int32_t>(domain.tets.size(), 9));
    // The outer cube's squares have removed tetrahedra on both sides: no longer in the mesh.
    EXPECT_TRUE(validate_cdt(cdt.plc, domain.tets, CdtDomain::kCarved).ok());
    const CarvedCdt hull = carve_cdt(cdt, true);
    EXPECT_EQ(hull.tets, cdt.tets);
    EXPECT_EQ(std::count(hull.regions.begin(), hull.regions.end(), 9),
              static_cast<std::ptrdiff_t>(domain.tets.size()));
    EXPECT_EQ(std::count(hull.regions.begin(), hull.regions.end(), 5),
              static_cast<std::ptrdiff_t>(cdt.tets.size() - domain.tets.size()));
}

TEST(CdtCarve, HolePointsOutsideOrOnAPolygonAreRefusedByLine) {
    struct Case {
        const char* name;
        const char* holes;
        const char* message;
    };

    for (const Case& c : {Case{"outside.poly",
                               "2\n0 2 2 2\n1 5 2 2\n",
                               ":45: volume hole point lies "
                               "outside"},
                          Case{"onface.poly",
                               "1\n0 2 2 3\n",
                               ":44: volume hole point lies on a "
                               "polygon"},
                          Case{"oncorner.poly",
                               "1\n0 1 1 1\n",
                               ":44: volume hole point lies on "
                               "a polygon"}}) {
        const Cdt cdt = nested_cdt(c.name, c.holes);
        try {
            carve_cdt(cdt, true);
            ADD_FAILURE() << c.name << " accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(std::string(c.name) + c.message),
                      std::string::npos)
                << e.what();
        }
    }
}

}  // namespace
}  // namespace cavity::core
