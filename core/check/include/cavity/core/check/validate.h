#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "cavity/core/input/point_set.h"

namespace cavity::core {

/// The outcome of validate(): the problems found (the first few, each naming tetrahedra or point
/// indices) and the counts the checks derived.
struct ValidationReport {
    std::vector<std::string> problems;
    std::size_t problem_count = 0;
    std::size_t vertices = 0;
    std::size_t edges = 0;
    std::size_t triangles = 0;
    std::size_t hull_triangles = 0;
    std::size_t tets = 0;
    std::size_t duplicates = 0;
    std::size_t redundant = 0;

    bool ok() const { return problem_count == 0; }
};

/// Checks, exactly, that `tets` (0-based input indices) is the (weighted) Delaunay triangulation of
/// `points` under cavity's symbolic perturbation (keyed on the input index), independently of how
/// it was built:
///  - every tetrahedron has four distinct valid vertices and positive volume by the right-hand rule
///    (orient3d < 0), as triangulate() lists them;
///  - every triangle has at most two tetrahedra, on opposite sides;
///  - the boundary triangles form a closed surface, locally convex at every edge, and the Euler
///    characteristic V - E + F - T is 1 (a triangulated ball): the convex hull;
///  - every interior triangle is locally (weighted) Delaunay under the perturbation, and so is
///    every pair of coplanar hull triangles within their plane: locally Delaunay everywhere
///    implies Delaunay;
///  - every point is a vertex, or repeats a vertex (same coordinates, and same weight when
///    weighted), or (weighted) is redundant: not in conflict with any tetrahedron around it, or is
///    listed in `absent` (deleted points: they must not be vertices, and no check involves them).
ValidationReport validate(const PointSet& points,
                          std::span<const std::array<std::uint32_t, 4>> tets,
                          std::span<const std::uint32_t> absent = {});

}  // namespace cavity::core
