#pragma once

#include <cstdint>
#include <span>

#include "cavity/core/input/point_set.h"
#include "cavity/core/io/tet_adjacency.h"

/// Exact point location in the view a triangulation leaves the program as (io/tet_adjacency.h):
/// scipy.spatial.Delaunay.find_simplex, decided by exact orient3d instead of a tolerance.
namespace cavity::core {

/// Locates points among `simplices` (positive right-hand volume) with `neighbors` (-1 on the
/// hull), as Adjacency holds them. Keeps references: the arrays must outlive it. Thread-safe (no
/// state between calls).
class SimplexLocator {
public:
    SimplexLocator(std::span<const Point3> points,
                   std::span<const Tet> simplices,
                   std::span<const std::int32_t> neighbors);

    /// The lowest-numbered simplex whose closure holds p, or -1 when p is outside the convex hull
    /// of the vertices. The rule for a point on a face shared by several simplices (a facet, an
    /// edge or a vertex) is therefore independent of the walk and of `start`. The walk is the
    /// visibility walk of §5.5 from `start` (any simplex index; out of range: simplex 0); it ends
    /// in a regular triangulation, perturbed or not, because the "in front of" relation is
    /// acyclic there (Edelsbrunner 1990). Leaving through a hull facet with p strictly beyond it
    /// proves p outside, since the hull is convex.
    std::int32_t find(const Point3& p, std::int32_t start) const;

private:
    /// A simplex whose closure holds p, or -1 outside: the walk.
    std::int32_t walk(const Point3& p, std::int32_t start) const;
    /// From a simplex holding p, the lowest-numbered one that does: the simplices whose closure
    /// holds p are connected through the facets that hold it (they form the star of the face whose
    /// relative interior holds p), so a search across those facets visits all of them.
    std::int32_t lowest_holding(const Point3& p, std::int32_t holding) const;

    std::span<const Point3> points_;
    std::span<const Tet> simplices_;
    std::span<const std::int32_t> neighbors_;
};

}  // namespace cavity::core
