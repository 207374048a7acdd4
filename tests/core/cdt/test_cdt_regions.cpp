// Region markers of a CDT (TetGen's region list): read from and written to .poly, spread from
// each region point without crossing a polygon, and refused outside the mesh by file and line.

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "cavity/core/base/error.h"
#include "cavity/core/cdt/cdt.h"
#include "cavity/core/cdt/cdt_regions.h"
#include "cavity/core/cdt/read_poly.h"
#include "cavity/core/io/write_poly.h"
#include "plc_builders.h"

namespace cavity::core {
namespace {

/// The nested cubes (plc_builders.h) with no hole and the region list `regions`.
std::string nested_cubes(const std::string& regions) {
    return test::nested_cubes_poly("0\n" + regions);
}

std::filesystem::path write_temp(const std::string& name, const std::string& text) {
    auto path = std::filesystem::temp_directory_path() / ("cavity_regions_" + name);
    std::ofstream(path) << text;
    return path;
}

TEST(CdtRegions, EachSideOfAClosedSurfaceTakesItsRegionsMarker) {
    const Plc plc =
        read_poly(write_temp("nested.poly", nested_cubes("2\n0 2 2 2 7\n1 0.5 0.5 0.5 3 0.1\n")));
    ASSERT_EQ(plc.regions.size(), 2u);
    EXPECT_EQ(plc.regions[0].marker, 7);
    EXPECT_EQ(plc.regions[1].line, 46u);
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    const std::vector<std::int32_t> markers = region_markers(cdt.plc, cdt.tets, cdt.faces);
    ASSERT_EQ(markers.size(), cdt.tets.size());
    std::size_t inner = 0;
    for (std::size_t t = 0; t < cdt.tets.size(); ++t) {
        Point3 c{0, 0, 0};
        for (std::uint32_t v : cdt.tets[t]) {
            const Point3& p = cdt.plc.points.points[v];
            c = {c.x + p.x / 4, c.y + p.y / 4, c.z + p.z / 4};
        }
        const bool inside = c.x > 1 && c.x < 3 && c.y > 1 && c.y < 3 && c.z > 1 && c.z < 3;
        EXPECT_EQ(markers[t], inside ? 7 : 3) << "tetrahedron " << t;
        inner += inside;
    }
    EXPECT_GT(inner, 0u);
}

TEST(CdtRegions, UnreachedTetrahedraHaveNoRegionAndTheFirstRegionWins) {
    const Plc plc =
        read_poly(write_temp("inner.poly", nested_cubes("2\n0 2 2 2 7\n1 2.5 2.5 2.5 9\n")));
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    const std::vector<std::int32_t> markers = region_markers(cdt.plc, cdt.tets, cdt.faces);
    EXPECT_NE(std::find(markers.begin(), markers.end(), 0), markers.end());  // the outer shell
    EXPECT_NE(std::find(markers.begin(), markers.end(), 7), markers.end());
    EXPECT_EQ(std::find(markers.begin(), markers.end(), 9), markers.end());
}

TEST(CdtRegions, ErrorsNameTheFileAndLine) {
    const auto outside = write_temp("outside.poly", nested_cubes("1\n0 9 9 9 1\n"));
    const Plc plc = read_poly(outside);
    const Cdt cdt = build_cdt(plc, CdtOptions{true});
    try {
        region_markers(cdt.plc, cdt.tets, cdt.faces);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(outside.string() + ":45"), std::string::npos)
            << e.what();
    }
    for (const char* bad : {"1\n0 1 1 1 2.5\n", "1\n0 1 1 1 1e12\n", "1\n0 1 1 1\n"}) {
        EXPECT_THROW(read_poly(write_temp("bad.poly", nested_cubes(bad))), Error) << bad;
    }
}

TEST(CdtRegions, WritePolyKeepsTheRegions) {
    const Plc plc = read_poly(write_temp("keep.poly", nested_cubes("1\n0 2 2 2 -4\n")));
    AtomicFileGroup group;
    const auto out = std::filesystem::temp_directory_path() / "cavity_regions_out.poly";
    write_poly(group.add(out), plc);
    group.commit();
    const Plc back = read_poly(out);
    ASSERT_EQ(back.regions.size(), 1u);
    EXPECT_EQ(back.regions[0].marker, -4);
    EXPECT_EQ(back.regions[0].point.x, 2.0);
}

}  // namespace
}  // namespace cavity::core
