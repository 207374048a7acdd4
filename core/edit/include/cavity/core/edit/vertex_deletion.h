#pragma once

#include <cstdint>
#include <span>

#include "cavity/core/edit/retriangulation_counters.h"
#include "cavity/core/geometry/geometry.h"
#include "cavity/core/mesh/array_storage.h"

/// Vertex deletion from a (weighted) Delaunay triangulation (Cheng, Dey & Shewchuk §5.6 and its
/// notes): the star of the vertex is removed and the cavity is gift-wrapped with the link vertices
/// only, under the same symbolic perturbation, so the result is the perturbed Delaunay
/// triangulation of the remaining points. A hull vertex's star holds ghost tetrahedra; the cavity
/// then reaches the point at infinity, and facets with no vertex in front become new hull
/// triangles (ghosts). Weighted: a deletion can uncover redundant (submerged) points, which join
/// the link as candidates; exactly those inside the cavity whose lifted point reaches the new lower
/// hull become vertices.
namespace cavity::core {

/// Deletes vertex v from a live complex with ghosts (the live triangulation's, or one from
/// complex_from_tets; vertex ids index `geometry`). `submerged` lists weighted points that are not
/// vertices (may be empty). Returns the ids of the new tetrahedra. \throws Error when v is not a
/// vertex or the cavity cannot be filled (the storage is then unchanged).
std::vector<TetId> delete_vertex(ArrayStorage& storage,
                                 const Geometry& geometry,
                                 VertexId v,
                                 std::span<const VertexId> submerged,
                                 RetriangulationCounters& counters);

}  // namespace cavity::core
