#pragma once

#include <vector>

#include "cavity/core/mesh/array_storage.h"

namespace cavity::core {

/// The tetrahedra around edge (t[i], t[j]) of tetrahedron t, in rotary order starting at t, and the
/// ring of vertices around the edge: ring[k] and ring[k+1] (cyclically) are the two other vertices
/// of tets[k]. Needs a closed ring (ghost tetrahedra present), as in a triangulation of the
/// 3-sphere.
struct EdgeRing {
    VertexId u;
    VertexId v;
    std::vector<TetId> tets;
    std::vector<VertexId> ring;
};

/// \throws Error when the ring does not close (a complex without ghosts, or a corrupt one).
EdgeRing edge_ring(const ArrayStorage& storage, TetId t, int i, int j);

/// The live tetrahedra with vertex v (solid and ghost), found by a search across the facets that
/// contain v, starting at Adjacent2Vertex(v). Empty when v is not a vertex.
std::vector<TetId> vertex_star(const ArrayStorage& storage, VertexId v);

/// The slot of vertex v in t, or -1.
int slot_of(const TetVertices& t, VertexId v);

}  // namespace cavity::core
