#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/plc.h"

/// Edge protection (Cheng, Dey & Shewchuk §4.5, §5.8): the flip-based CDT construction needs
/// every PLC edge to be an edge of the Delaunay triangulation of the PLC's vertices. cavity reads
/// "Delaunay" under its symbolic perturbation (keyed on the input index), so the condition is
/// decided exactly and consistently with the triangulation the CDT starts from.
namespace cavity::core {

using Edge = std::array<std::uint32_t, 2>;

/// The PLC edges (plc_edges) that are not edges of `tets`, the Delaunay triangulation of the
/// PLC's points (0-based indices). Sorted.
std::vector<Edge> unprotected_edges(const Plc& plc, std::span<const std::array<std::uint32_t, 4>> tets);

/// The PLC edges that are not edges of the Delaunay triangulation of its points.
/// \throws Error when the points have no 3D triangulation or two points coincide.
std::vector<Edge> unprotected_edges(const Plc& plc);

/// What protect_edges did.
struct Protection {
    std::vector<std::uint32_t> inserted;  ///< indices of the new points, in insertion order
    std::size_t rounds = 0;               ///< Delaunay triangulations computed
};

/// Splits unprotected PLC edges at their midpoints (appended to plc.points, replacing the edge in
/// its segment and in every loop that has it) until every edge is protected. A midpoint is used
/// only when it is exactly representable (2m == a + b exactly): that holds for any two doubles
/// whose sum neither overflows nor loses bits, e.g. all inputs on a binary grid.
/// \throws Error naming the edge when its midpoint is not exact, or after `max_points` insertions.
Protection protect_edges(Plc& plc, std::size_t max_points);

}  // namespace cavity::core
