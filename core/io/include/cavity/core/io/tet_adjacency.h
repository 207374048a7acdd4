#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "cavity/core/io/mesh_io.h"
#include "cavity/core/mesh/tetrahedron.h"

/// The combinatorial views of a triangulation that leave the program (TetGen's .neigh and .face,
/// scipy.spatial.Delaunay's attributes), derived from the bare list of tetrahedra that
/// triangulate() returns.
namespace cavity::core {

struct Adjacency {
    /// The tetrahedra (input ids, positive volume by the right-hand rule, each as given),
    /// renumbered along the rank order: sorted by
    /// their lowest-ranked vertex, so that tetrahedra near in space are near in the array.
    std::vector<Tet> simplices;
    /// neighbors[4t + i]: the tetrahedron across the facet opposite vertex i of simplices[t], or
    /// -1 on the convex hull (scipy's convention).
    std::vector<std::int32_t> neighbors;
    /// Hull triangles, each counter-clockwise seen from outside the hull.
    std::vector<std::array<std::int32_t, 3>> hull;
    /// For each input point, one tetrahedron having it as a vertex, or -1 (repeats, redundant).
    std::vector<std::int32_t> vertex_to_simplex;
};

/// The facet opposite vertex i of `tet` (positive right-hand volume) as a hull triangle,
/// counter-clockwise seen from outside: kFacetVertices lists facet i with the opposite vertex on
/// its orient3d-positive side, which for such a tetrahedron is clockwise seen from outside, so the
/// listing is reversed.
inline std::array<std::int32_t, 3> hull_triangle(const Tet& tet, std::size_t i) {
    const auto& s = kFacetVertices[i];
    return {static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[0])]),
            static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[2])]),
            static_cast<std::int32_t>(tet[static_cast<std::size_t>(s[1])])};
}

/// The facet matcher: neighbors[4t + i] is the tetrahedron sharing the facet opposite vertex i of
/// tets[t], or -1 where no other has it (vertex ids < point_count, any orientation). Half-facets
/// are bucketed by their lowest vertex (counting sort) and paired inside each bucket (hashing):
/// O(m) expected time, 12 bytes per half-facet. \throws Error if a triangle has more than two
/// tetrahedra (not a manifold), naming the tetrahedron as `names` lists it (default: `tets`).
std::vector<std::int32_t> match_facets(std::span<const Tet> tets,
                                       std::size_t point_count,
                                       std::span<const Tet> names = {});

/// Renumbers `tets` (positive right-hand volume, vertex ids < rank.size()) and matches their facets
/// in O(m) expected time: facets are bucketed by their lowest-ranked vertex (counting sort) and
/// paired inside each bucket (hashing), where the two other vertices identify them. `rank` is a
/// permutation of the point ids along a space-filling curve (the insertion order). Sorting the
/// tetrahedra by rank first makes every later pass nearly sequential: input ids of random points
/// are random in space, and the engine's storage slots are recycled, so neither order is local.
/// Memory: 12 bytes per half-facet and the renumbered copy besides the output. \throws Error if a
/// triangle has more than two tetrahedra (not a manifold).
Adjacency build_adjacency(std::span<const Tet> tets, std::span<const std::uint32_t> rank);

/// scipy's vertex_neighbor_vertices: the neighbours of vertex v (the vertices sharing an edge with
/// it) are indices[indptr[v] .. indptr[v + 1]), increasing; points that are no vertex have none.
struct VertexNeighbors {
    std::vector<std::int32_t> indptr;   ///< point_count + 1 offsets
    std::vector<std::int32_t> indices;  ///< each edge twice
};

/// The edges of `tets` (vertex ids < point_count), per vertex: its tetrahedra by a counting sort,
/// then the other vertices of each, sorted and made unique. O(m log d) for vertex degree d;
/// 16 bytes per tetrahedron of scratch. \throws Error when an edge count exceeds the int32 range.
VertexNeighbors vertex_neighbors(std::span<const Tet> tets, std::size_t point_count);

}  // namespace cavity::core
