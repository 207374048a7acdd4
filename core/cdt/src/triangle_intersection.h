#pragma once

// Exact intersection tests of triangles and segments, by signs of orient3d alone (no constructed
// point, no epsilon): the self-intersection check of surface meshes (surface_validity.h).

#include <array>
#include <cstdint>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

using Triangle = std::array<std::uint32_t, 3>;

/// The orientation (-1, 0, 1) of the projections of a, b, c on the coordinate plane that drops
/// axis `drop` (0, 1, 2), up to one sign per axis: compare signs within one projection only.
int orient2d_projected(const Point3& a, const Point3& b, const Point3& c, int drop);

/// An axis whose projection keeps the triangle abc (not degenerate) a triangle.
int projection_axis(const Point3& a, const Point3& b, const Point3& c);

/// True when the corners are collinear (or two coincide): the triangle has zero area. Exact.
bool is_degenerate_triangle(const Point3& a, const Point3& b, const Point3& c);

/// True when the closed segment pq and the closed triangle abc (not degenerate) share a point:
/// the side test by which triangles_meet_improperly is defined (its tests check the coplanar
/// shortcuts against it).
bool segment_meets_triangle(
    const Point3& p, const Point3& q, const Point3& a, const Point3& b, const Point3& c);

/// True when two non-degenerate triangles (corners indexing `points`) meet other than in the
/// corners they share by index and the side joining two shared corners: the intersection a
/// surface mesh must not have (a crossing, a touching vertex, an overlap of coplanar triangles,
/// the same triangle twice). Corners at equal coordinates under different indices count as
/// different points, so two triangles meeting there are reported.
bool triangles_meet_improperly(const std::vector<Point3>& points,
                               const Triangle& s,
                               const Triangle& t);

}  // namespace cavity::core
