#pragma once

// A polygon that is a triangle whose sides edge protection split: its loop is three input corners
// and points inside the sides between them, so a segment crosses its region exactly when it
// crosses the triangle of the three corners, which three orientations decide without the
// rational crossing point.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// The three corners of `loop` (indices into `points`) when every other corner is a
/// SegmentParameterPoint strictly inside the segment between two of them (0 < t < 1, its ends
/// those corners' coordinates), the three are not collinear, and each side of the loop joins two
/// corners on one side of their triangle; nullopt otherwise. Then a simple loop runs once around
/// the triangle's boundary (a simple closed curve in a circle is the whole circle), so its region
/// is the triangle. Exact: the parameters and coordinates are compared as given.
std::optional<std::array<Point3, 3>> split_triangle_corners(const PointSet& points,
                                                            const std::vector<std::uint32_t>& loop);

}  // namespace cavity::core
