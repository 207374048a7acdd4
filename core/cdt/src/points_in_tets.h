#pragma once

// Which tetrahedra hold given points, for checks of a carved mesh: a point that should be outside
// every kept tetrahedron (a volume hole point, a PLC point that is no vertex of the kept mesh).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// For each probe, a tetrahedron (positive right-hand volume) whose closure holds it, exactly, or
/// none. The probes are bucketed in a uniform grid of about one probe per cell, and each
/// tetrahedron is tested only against the probes in the cells its bounding box meets: O(T + P)
/// plus the candidates, instead of O(T P). Exact on implicit points (the tests see their
/// definitions); the grid uses rounded coordinates, which only prune (rounding is monotone).
std::vector<std::optional<std::uint32_t>> points_in_tets(
    const PointSet& points,
    std::span<const std::array<std::uint32_t, 4>> tets,
    std::span<const predicates::GenericPoint3> probes);

}  // namespace cavity::core
