#pragma once

#include <cstdint>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::experiments {

/// Exercise 1's adversary, greedily: after the bootstrap (the first four affinely independent
/// points in input order), always insert next the uninserted point whose cavity is largest now,
/// the one in conflict with the most tetrahedra (ghosts included), ties to the lowest input index.
/// The full conflict graph keeps every point's conflicts, so the choice costs a heap operation per
/// conflict created. Returns the insertion sequence (input indices, a permutation of all points
/// but exact repeats, which follow at the end in input order).
/// \throws core::Error for weighted points (a redundant point has no cavity) or when the points
/// have no 3D triangulation.
std::vector<std::uint32_t> greedy_order(const core::PointSet& points);

}  // namespace cavity::experiments
