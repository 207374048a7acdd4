#pragma once

#include <cstddef>
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

/// vertex_star, with the caller keeping track of the tetrahedra reached, stopping early, and
/// filling the caller's `star` (cleared first): `first_reach(star, t)` returns whether t is reached
/// for the first time (the tetrahedra so far are `star`) and remembers it; the search gives up,
/// returning false, at the first tetrahedron t of the star (in search order) for which `stop(t)`
/// holds. vertex_star looks t up in `star`, quadratic in the star's size; a caller that gathers
/// many large stars (edge protection) marks tetrahedra instead, keeps one vector for them (growing
/// a fresh one per search cost three quarters as much as the search), and one that only needs the
/// star when some vertex is not in it (is uv an edge?) stops there. Same order either way.
template <class FirstReach, class Stop>
bool vertex_star_into(const ArrayStorage& storage,
                      VertexId v,
                      FirstReach&& first_reach,
                      Stop&& stop,
                      std::vector<TetId>& star) {
    star.clear();
    const TetId start = storage.tet_at_vertex(v);
    if (start == kNoTet) {
        return true;
    }
    first_reach(star, start);
    star.push_back(start);
    for (std::size_t k = 0; k < star.size(); ++k) {
        const TetId t = star[k];
        if (stop(t)) {
            return false;
        }
        const TetVertices& w = storage.vertices(t);
        for (int f = 0; f < 4; ++f) {
            if (w[static_cast<std::size_t>(f)] == v) {
                continue;  // the facet opposite v leaves the star
            }
            const HalfFacet h = storage.adjacent(t, f);
            if (h != kNoHalfFacet && first_reach(star, tet_of(h))) {
                star.push_back(tet_of(h));
            }
        }
    }
    return true;
}

/// The slot of vertex v in t, or -1.
int slot_of(const TetVertices& t, VertexId v);

}  // namespace cavity::core
