#pragma once

#include <cstdint>
#include <span>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// Reorders `indices` (into `points`) along a 3D Hilbert curve adapted to the points: the curve's
/// recursive octant splits happen at medians, not at the midpoints of a bounding box (CGAL's
/// "median" Hilbert sort policy). Only comparisons of coordinates are made, never arithmetic, so
/// any finite doubles work: 1e-300 next to 1e300, huge offsets, flat or duplicated sets. Ties are
/// broken by index, which makes the order a function of the input alone, on every platform.
/// O(n log n) time. Up to `threads` threads share large sets; the order is the same for every
/// count. \throws Error naming the first point with a non-finite coordinate.
void hilbert_sort(std::span<const Point3> points,
                  std::span<std::uint32_t> indices,
                  unsigned threads = 1);

/// Reorders `indices` in Morton (Z-) order, with the same median splits as hilbert_sort and a
/// fixed x, y, z split cycle; on a 2^k grid it equals sorting by interleaved bits (x highest).
/// Threads as for hilbert_sort.
/// \throws Error naming the first point with a non-finite coordinate.
void morton_sort(std::span<const Point3> points,
                 std::span<std::uint32_t> indices,
                 unsigned threads = 1);

}  // namespace cavity::core
