#pragma once

#include <cstddef>
#include <vector>

#include "cavity/core/tet_pool.h"

namespace cavity::core {

/// The compact storage: per tetrahedron four vertex ids and four half-facets, the neighbour across
/// facet f stored as 4 t' + f' so a walk learns the mirror facet for free. Adjacency is explicit,
/// so the insertion code glues new tetrahedra to their neighbours.
class ArrayStorage : public TetPool {
public:
    static constexpr bool kExplicitAdjacency = true;
    static constexpr const char* kName = "array";

    void reserve(std::size_t tets, std::size_t vertices);

    /// AddTetrahedron: v must be positively oriented (ghost vertex, if any, in slot 3). The new
    /// tetrahedron's facets are unglued until glue() is called for them.
    TetId add_tetrahedron(const TetVertices& v);

    /// DeleteTetrahedron. Its data stays readable until end_operation().
    void delete_tetrahedron(TetId t) { release(t); }

    /// Adjacent: the half-facet on the other side of facet f of t, or kNoHalfFacet when the
    /// tetrahedron there has been deleted.
    HalfFacet adjacent(TetId t, int f) const {
        const HalfFacet h = neighbors_[half_facet(t, f)];
        return alive(tet_of(h)) ? h : kNoHalfFacet;
    }

    /// Records that half-facets a and b are the two sides of one triangle.
    void glue(HalfFacet a, HalfFacet b) {
        neighbors_[a] = b;
        neighbors_[b] = a;
    }

    void end_operation() { recycle_released(); }

    std::size_t bytes() const;

private:
    std::vector<HalfFacet> neighbors_;
};

}  // namespace cavity::core
