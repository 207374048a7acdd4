#pragma once

#include <span>
#include <vector>

#include "cavity/core/base/handedness.h"
#include "cavity/core/input/point_set.h"

/// The floating-point per-simplex arrays of scipy's interface, derived from the exact
/// triangulation: the barycentric transforms and the lifted hyperplanes. Plain double arithmetic,
/// as scipy computes them (they are outputs for numerical use, not decisions).
namespace cavity::python {

/// scipy's `transform`, (m, 4, 3) row-major: rows 0-2 the inverse of T = [v0 - v3, v1 - v3,
/// v2 - v3] (as columns), row 3 the vertex v3. NaN where det T rounds to 0 (scipy's rule for
/// degenerate simplices: a tetrahedron exact arithmetic calls solid can be too thin for doubles).
std::vector<double> barycentric_transforms(std::span<const core::Point3> points,
                                           std::span<const core::Tet> simplices);

/// scipy's `equations`, (m, 5) row-major: the unit normal (pointing down: its last coordinate is
/// negative) and offset of the hyperplane through each simplex's vertices lifted to
/// z = scale |x|^2 + shift.
std::vector<double> lifted_hyperplanes(std::span<const core::Point3> points,
                                       std::span<const core::Tet> simplices,
                                       double scale,
                                       double shift);

}  // namespace cavity::python
