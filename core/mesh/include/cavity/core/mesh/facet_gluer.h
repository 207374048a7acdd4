#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "cavity/core/base/pod_stack.h"
#include "cavity/core/mesh/tetrahedron.h"

namespace cavity::core {

/// Pairs up the new faces around a freshly inserted vertex u, by a hash table on the directed edge.
/// Every new tetrahedron's face through u, rotated to (u, p, q), meets another new tetrahedron's
/// face (u, q, p) across the directed edge (p, q). The cavities of Bowyer–Watson use it only when
/// they are too large for CavityGluer's matrix (cavity_gluer.h); the CDT pairs the faces of a
/// vertex's star with it. The state is cleared by undoing its own writes.
class FacetGluer {
public:
    /// Registers half-facet h whose face, rotated to start at u, is (u, p, q). Returns the
    /// partner's half-facet if (u, q, p) was registered before, else kNoHalfFacet.
    HalfFacet match_hashed(VertexId p, VertexId q, HalfFacet h);

    /// Forgets the faces registered so far, ready for the next vertex.
    void end();

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    struct Entry {
        std::uint64_t edge;
        HalfFacet value;
    };

    std::size_t slot(std::uint64_t edge) const;
    void grow();

    std::vector<Entry> table_ = std::vector<Entry>(64, Entry{kEmpty, kNoHalfFacet});
    PodStack<std::size_t> table_touched_;
};

}  // namespace cavity::core
