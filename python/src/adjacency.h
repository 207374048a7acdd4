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

/// Matches the facets of `tets` (positively oriented, vertex ids < rank.size()) in O(m) time:
/// facets are bucketed by their lowest-ranked vertex (counting sort) and paired inside each
/// bucket, where the two other vertices identify them. `rank` is a permutation of the point ids
/// along a space-filling curve (the insertion order): tetrahedra near in space then land in
/// buckets near in memory, which makes the passes cache-friendly (input ids of random points are
/// random in space). Memory: 12 bytes per half-facet besides the output.
/// \throws cavity::core::Error if a triangle has more than two tetrahedra (not a manifold).
Adjacency build_adjacency(std::span<const std::array<std::uint32_t, 4>> tets,
                          std::span<const std::uint32_t> rank);

}  // namespace cavity::python
