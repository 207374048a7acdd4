#pragma once

#include <array>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cavity/core/base/random.h"
#include "cavity/core/input/plc.h"

namespace cavity::test {

using Loops = std::vector<std::vector<std::uint32_t>>;

/// A PLC built in code (no file, so messages carry no line): facet k gets marker k + 1.
inline core::Plc make_plc(std::vector<core::Point3> points,
                          std::vector<Loops> facets,
                          std::vector<std::array<std::uint32_t, 2>> segments = {}) {
    core::Plc plc;
    plc.source = "test";
    plc.points.points = std::move(points);
    for (auto& loops : facets) {
        core::PlcFacet f;
        f.loops = std::move(loops);
        f.marker = static_cast<int>(plc.facets.size()) + 1;
        plc.facets.push_back(std::move(f));
    }
    plc.segments = std::move(segments);
    return plc;
}

/// The eight corners of the box [0, x] × [0, y] × [z0, z1]: the bottom face counter-clockwise
/// from the origin, then the top face in the same order.
inline std::vector<core::Point3> box_corners(double x, double y, double z0, double z1) {
    return {{0, 0, z0},
            {x, 0, z0},
            {x, y, z0},
            {0, y, z0},
            {0, 0, z1},
            {x, 0, z1},
            {x, y, z1},
            {0, y, z1}};
}

/// n points of the binary grid of spacing 1/16 strictly inside (0, 4)^3: dyadic, so the PLC
/// edges through them have exact split points and the grid's degeneracies exercise the
/// perturbation.
inline std::vector<core::Point3> dyadic_grid_points(std::size_t n, std::uint64_t seed) {
    core::Random random(seed);
    std::vector<core::Point3> pts;
    for (std::size_t i = 0; i < n; ++i) {
        pts.push_back({static_cast<double>(1 + random.below(63)) / 16,
                       static_cast<double>(1 + random.below(63)) / 16,
                       static_cast<double>(1 + random.below(63)) / 16});
    }
    return pts;
}

/// A .poly file's text: the cube [0,4]^3 holding the cube [1,3]^3 (points 0-7 and 8-15; the 6
/// squares of each, markers 1 and 9), then `tail`, the hole and region lists. The hole list's
/// first point is on line 44.
inline std::string nested_cubes_poly(const std::string& tail) {
    std::ostringstream poly;
    poly << "16 3 0 0\n";
    for (int i = 0; i < 16; ++i) {
        const int s = i < 8 ? 4 : 2;
        const int o = i < 8 ? 0 : 1;
        poly << i << ' ' << o + (i & 1) * s << ' ' << o + ((i >> 1) & 1) * s << ' '
             << o + ((i >> 2) & 1) * s << '\n';
    }
    const int squares[6][4] = {
        {0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    poly << "12 1\n";
    for (int offset : {0, 8}) {
        for (const auto& q : squares) {
            poly << "1 0 " << offset + 1 << "\n4 " << q[0] + offset << ' ' << q[1] + offset << ' '
                 << q[2] + offset << ' ' << q[3] + offset << '\n';
        }
    }
    poly << tail;
    return poly.str();
}

}  // namespace cavity::test
