#pragma once

#include <array>
#include <cstdint>
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

}  // namespace cavity::test
