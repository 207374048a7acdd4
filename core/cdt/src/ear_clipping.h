#pragma once

// Triangles of a planar polygon by ear clipping (Meisters' two-ears theorem), decided exactly in
// a projection: how the surface check tests polygons for intersection (surface_validity.cpp).

#include <optional>
#include <vector>

#include "cavity/core/input/point_set.h"
#include "triangle_intersection.h"

namespace cavity::core {

/// A triangulation of the loop (corners indexing `points`, coplanar, projecting one-to-one when
/// axis `drop` is dropped) by its own corners, every triangle with area; nothing when the loop is
/// not a simple polygon with area (no ear is found). O(n^3) exact orientation tests for n corners.
std::optional<std::vector<Triangle>> ear_clipping(const std::vector<Point3>& points,
                                                  const std::vector<std::uint32_t>& loop,
                                                  int drop);

}  // namespace cavity::core
