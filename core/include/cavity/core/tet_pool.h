#pragma once

#include <cstddef>
#include <vector>

#include "cavity/core/tetrahedron.h"

namespace cavity::core {

/// The part both storages share: four vertex ids per tetrahedron slot, liveness, a free list, and
/// the per-vertex "most recently added tetrahedron" that answers Adjacent2Vertex (Cheng, Dey &
/// Shewchuk §5.1).
///
/// A deleted tetrahedron keeps its vertices and adjacency readable until end_operation(): the
/// cavity search reads the far side of facets of tetrahedra it has already deleted, and a slot
/// must not be handed to a new tetrahedron of the same cavity before that.
class TetPool {
public:
    void reserve(std::size_t tets, std::size_t vertices);

    const TetVertices& vertices(TetId t) const { return vertices_[t]; }

    bool alive(TetId t) const { return alive_[t] != 0; }

    /// Number of slots ever allocated (live, deleted and free).
    std::size_t capacity() const { return vertices_.size(); }

    std::size_t live_count() const { return live_; }

    /// Adjacent2Vertex: a live tetrahedron with vertex v, or kNoTet. Constant time unless the most
    /// recently added tetrahedron at v has since been deleted (then a scan, as the book warns).
    TetId tet_at_vertex(VertexId v) const;

    std::size_t bytes() const;

protected:
    TetId allocate(const TetVertices& v);
    void release(TetId t);
    void recycle_released();

private:
    std::vector<TetVertices> vertices_;
    std::vector<unsigned char> alive_;
    std::vector<TetId> free_;
    std::vector<TetId> released_;  // deleted during the current operation
    std::vector<TetId> vertex_tet_;
    std::size_t live_ = 0;
};

}  // namespace cavity::core
