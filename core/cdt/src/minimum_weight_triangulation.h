#pragma once

// The triangulation of a simple polygon whose diagonals are shortest in total (Gilbert 1979,
// Klincsek 1980), for cutting a warped face. Every diagonal a reader adds to a surface mesh
// becomes a segment that edge protection must make a Delaunay edge, and long diagonals across a
// face are the ones that other vertices encroach: on the bench's mpi.off ear clipping's diagonals
// took 434 of its 857 protecting points.

#include <cstddef>
#include <optional>
#include <vector>

#include "cavity/core/input/point_set.h"
#include "triangle_intersection.h"

namespace cavity::core {

/// Loops with more corners than this are not searched: the dynamic program takes O(n^3) time and
/// O(n^2) memory.
inline constexpr std::size_t kMinimumWeightCorners = 256;

/// A triangulation of the loop (corners indexing `points`, projecting to a simple polygon that
/// turns `turn`, the sign orient2d_projected gives its corners in order, when axis `drop` is
/// dropped) by its own corners that minimises the sum of the diagonals' lengths in space. What is a
/// triangulation is decided exactly (every triangle turns the loop's way in the projection); only
/// the choice among them rests on floating-point lengths, with ties going to the lowest corner, so
/// the result depends on the input alone. Nothing when the loop has more than
/// kMinimumWeightCorners corners or no such triangulation exists (a projection that is not simple
/// may have none).
std::optional<std::vector<Triangle>> minimum_weight_triangulation(
    const std::vector<Point3>& points, const std::vector<std::uint32_t>& loop, int drop, int turn);

}  // namespace cavity::core
