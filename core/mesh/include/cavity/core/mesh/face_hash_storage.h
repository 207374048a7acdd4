#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/mesh/tet_pool.h"
#include "cavity/core/mesh/tet_storage.h"

namespace cavity::core {

/// The book's storage (Cheng, Dey & Shewchuk §5.1): each tetrahedron uvwx is entered in a hash
/// table four times, keyed on its oriented faces, so Adjacent(u, v, w) is a hash look-up of the
/// face w v u seen from the other side. Nothing is glued: a tetrahedron is adjacent to whatever
/// holds the reversed face. Open addressing with linear probing and backward-shift deletion (no
/// tombstones), load factor at most 1/2.
struct HashRecord {
    TetVertices v;
};

class FaceHashStorage : public TetPool<HashRecord> {
public:
    static constexpr bool kExplicitAdjacency = false;

    void reserve(std::size_t tets);

    TetId add_tetrahedron(const TetVertices& v);

    void delete_tetrahedron(TetId t);

    /// Adjacent: the half-facet holding the reverse of facet f of t, or kNoHalfFacet.
    HalfFacet adjacent(TetId t, int f) const;

    void glue(HalfFacet, HalfFacet) {}

    void end_operation() { recycle_released(); }

    /// Nothing to prefetch: a neighbour is found by a hash look-up, not read from t's record.
    void prefetch_neighbours(TetId) const {}

    std::size_t bytes() const;

    /// Probes made by look-ups so far (a measure of the table's cost).
    std::uint64_t probes() const { return probes_; }

private:
    struct Slot {
        std::array<VertexId, 3> face;  // rotated so the smallest id comes first; kNoVertex: empty
        HalfFacet value;
    };

    static std::array<VertexId, 3> canonical(std::array<VertexId, 3> face);
    std::size_t home(const std::array<VertexId, 3>& face) const;
    void insert(const std::array<VertexId, 3>& face, HalfFacet value);
    void erase(const std::array<VertexId, 3>& face);
    void grow();

    std::vector<Slot> slots_;
    std::size_t used_ = 0;
    mutable std::uint64_t probes_ = 0;
};

static_assert(TetStorage<FaceHashStorage>);

}  // namespace cavity::core
