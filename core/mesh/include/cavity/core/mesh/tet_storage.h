#pragma once

#include <concepts>
#include <cstddef>

#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// What the engine asks of a tetrahedron store: the dictionary of §5.1 (Figure 5.1), as
/// tetrahedra with their four vertices and, across each face, the adjacent half-facet. Pure
/// topology: a store never sees a coordinate. ArrayStorage keeps neighbours in flat arrays;
/// FaceHashStorage answers adjacency from the book's face hash table, and its `glue` is a no-op.
/// Ids of deleted tetrahedra are reused only after `end_operation` (one insertion's cavity is dug
/// and filled before any of its ids recycles).
template <class S>
concept TetStorage = requires(S store,
                              const S& view,
                              TetId t,
                              HalfFacet h,
                              VertexId v,
                              const TetVertices& vertices,
                              std::size_t count) {
    store.reserve(count);
    { store.add_tetrahedron(vertices) } -> std::same_as<TetId>;
    store.delete_tetrahedron(t);
    store.glue(h, h);
    store.end_operation();
    { view.vertices(t) } -> std::same_as<const TetVertices&>;
    { view.adjacent(t, 0) } -> std::same_as<HalfFacet>;
    view.prefetch_neighbours(t);  // a memory hint ahead of reading t's neighbours
    { view.alive(t) } -> std::same_as<bool>;
    { view.tet_at_vertex(v) } -> std::same_as<TetId>;
    { view.capacity() } -> std::convertible_to<std::size_t>;
    { view.live_count() } -> std::convertible_to<std::size_t>;
    { view.bytes() } -> std::convertible_to<std::size_t>;
    store.drain([](const TetVertices&) {});  // hands out every live tetrahedron, then empties
};

}  // namespace cavity::core
