#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/mesh/array_storage.h"
#include "concurrent_mesh.h"

namespace cavity::core {

/// Moves the live tetrahedra of `mesh` into `storage` in an order that depends only on the
/// triangulation, not on which thread made which tetrahedron or in which slot: so the files and
/// arrays of a parallel construction are the same, byte for byte, for every number of threads.
///
/// The order: by the highest vertex id (the last inserted of the four: tetrahedra then follow the
/// space-filling insertion order, and neighbours stay near in memory), then by the other ids,
/// higher first, the ghost vertex below every vertex. Within a record, the vertices are rotated by
/// an even permutation (orientation kept) to start at the lowest id, the next slot holding the
/// lowest of the other three; a ghost keeps the ghost vertex in slot 3 and starts at its lowest
/// vertex. Neighbour half-facets are renumbered to follow. `mesh` is emptied; `vertices` is the
/// number of vertex ids; `threads` threads share the work.
void store_canonically(ConcurrentMesh& mesh,
                       ArrayStorage& storage,
                       std::size_t vertices,
                       unsigned threads);

/// The live slots in canonical order, and for each slot its rotation, stored inverted (old slot g
/// of a record becomes new slot (renumber >> 2g) & 3), with its new position above bit 8.
struct CanonicalOrder {
    std::vector<TetId> order;
    std::vector<std::uint64_t> renumber;
};

CanonicalOrder canonical_order(ConcurrentMesh& mesh, std::size_t vertices, unsigned threads);

}  // namespace cavity::core
