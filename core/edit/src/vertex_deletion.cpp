#include "cavity/core/edit/vertex_deletion.h"

#include <algorithm>
#include <string>

#include "cavity/core/base/assert.h"
#include "cavity/core/base/error.h"
#include "cavity/core/check/complex_from_tets.h"
#include "cavity/core/edit/gift_wrap.h"
#include "cavity/core/geometry/bootstrap.h"
#include "cavity/core/mesh/replace_tetrahedra.h"
#include "cavity/core/mesh/star.h"

namespace cavity::core {

std::vector<TetId> delete_vertex(ArrayStorage& storage,
                                 const Geometry& geometry,
                                 VertexId v,
                                 std::span<const VertexId> submerged,
                                 RetriangulationCounters& counters) {
    const std::vector<TetId> star = vertex_star(storage, v);
    if (v == kGhostVertex || star.empty()) {
        throw Error(v < geometry.size() ? "point " + std::to_string(geometry.key(v)) +
                                              " is not a vertex of the triangulation"
                                        : std::string("the ghost vertex cannot be deleted"));
    }
    std::vector<TetVertices> boundary;
    std::vector<VertexId> candidates(submerged.begin(), submerged.end());
    bool on_hull = false;
    for (TetId t : star) {
        const TetVertices& w = storage.vertices(t);
        on_hull = on_hull || is_ghost(w);
        const HalfFacet h = storage.adjacent(t, slot_of(w, v));
        // The tetrahedron outside, rotated so that its facet on the cavity is facet 3.
        const TetVertices& o = storage.vertices(tet_of(h));
        const auto tri = facet_vertices(o, facet_of(h));
        boundary.push_back({tri[0], tri[1], tri[2], o[static_cast<std::size_t>(facet_of(h))]});
        for (VertexId x : w) {
            if (x != v && x != kGhostVertex &&
                std::find(candidates.begin(), candidates.end(), x) == candidates.end()) {
                candidates.push_back(x);
            }
        }
    }
    const std::vector<TetVertices> fresh =
        gift_wrap_cavity(geometry, boundary, candidates, on_hull, counters);
    std::vector<TetId> ids = replace_tetrahedra(storage, star, fresh);
    if (ids.empty()) {
        throw Error("deleting point " + std::to_string(geometry.key(v)) +
                    ": the gift-wrapped cavity does not match its boundary");
    }
    CAVITY_EXPENSIVE_CHECK(check_complex(storage, geometry), "the complex after a deletion");
    ++counters.vertices_deleted;
    counters.tets_deleted += star.size();
    return ids;
}

}  // namespace cavity::core
