#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "cavity/core/plc.h"
#include "cavity/core/random.h"

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
