#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

/// The combinatorial views scipy.spatial.Delaunay users expect, derived from the bare list of
/// tetrahedra that cavity::core::triangulate returns.
namespace cavity::python {

struct Adjacency {
    /// neighbors[4t + i]: the tetrahedron across the facet opposite vertex i of tetrahedron t, or
    /// -1 on the convex hull (scipy's convention).
    std::vector<std::int32_t> neighbors;
    /// Hull triangles, each counter-clockwise seen from outside the hull.
    std::vector<std::array<std::int32_t, 3>> hull;
    /// For each input point, one tetrahedron having it as a vertex, or -1 (repeats, redundant).
    std::vector<std::int32_t> vertex_to_simplex;
};

/// Matches the facets of `tets` (positively oriented, vertex ids < point_count) in O(m) expected
/// time: facets are bucketed by their smallest vertex (counting sort) and paired inside each
/// bucket, where the two other vertices identify them. Memory: one 32-bit entry per half-facet.
/// \throws cavity::core::Error if a triangle has more than two tetrahedra (not a manifold).
Adjacency build_adjacency(std::span<const std::array<std::uint32_t, 4>> tets,
                          std::size_t point_count);

}  // namespace cavity::python
